// viscoroll: the node sets of the line residual's integrals (docs/theory.md section 7).
//
// At each collocation point y the line residual integrates over s = |y' - y| on the two sides
// [0, len], len = l -+ y (the finite part of (34) and both terms of (L6)), and over the memory
// variable t in [0, inf) of (L6); the load (47) integrates over y in [0, l]. LineNodeRule builds
// the nodes (a LineNodes of line_operators.hpp, whose operators then sum over them):
//   - in s, equal panels in w = ln(s/(len - s)) between a first panel on the kernels' scale x0 and
//     a last one on the scale of the nearest pole of G beyond the end (where I0(alpha) = 0, Eq.
//     (37), just beyond +-l when a0/V tau is large; docs/line-operators.md);
//   - in t, equal panels in ln(1 + t/c), c = min(x0/V tau, 1), up to -ln(tol) + 8.
// The panels' width follows from the distance of the singularities in these variables (pi/2) and
// the rule's order, so that every integral is exact to the relative accuracy tol: rounding by
// default (tol = eps), or a stated tolerance (LineOptions::quadrature_tolerance;
// detail/graded_panels.hpp).
#pragma once

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/line/detail/graded_panels.hpp>
#include <viscoroll/line/line_operators.hpp>
#include <viscoroll/line/line_shape.hpp>

namespace viscoroll::line {

/// The node sets of the line residual at N = `terms` Chebyshev terms of the shape, in the
/// expansion variable `basis` (with its scale e of LineBasis::s_mapped, else 0), for V tau > 0 and
/// f > 0. Quadrature: a NodalQuadratureRule.
///
/// Members:
///   - `point(s, y, x0, nd)`: the nodes of one collocation point y with leading edge x0 = a + b > 0
///     into nd (empty on entry): both sides in s and the t-nodes of the memory integral;
///   - `load(s, both, y, w)`: the nodes and weights of an integral over the contact, the load (47)
///     and the like: [0, l] with the weights doubled (a symmetric contact, even integrands), or
///     both halves of [c - l, c + l] (`both`, an asymmetric contact).
template <RealScalar Real, class Quadrature>
requires NodalQuadratureRule<Quadrature, Real>
class LineNodeRule {
 public:
  /// tolerance: the relative accuracy of every integral, tol = max(tolerance, eps) (0, the
  /// default: the scalar's epsilon, every integral exact to rounding).
  LineNodeRule(LineBasis basis, Real scale, int terms, Real vtau, Real f, Real tolerance = Real(0))
      : basis_(basis),
        scale_(scale),
        n_(terms),
        vtau_(vtau),
        f_(f),
        tolerance_(detail::quadrature_tolerance(tolerance)) {
    using std::log;
    t_max_ = -log(tolerance_) + 8;
  }

  /// The relative accuracy the node sets are built for (at least the scalar's epsilon).
  Real tolerance() const { return tolerance_; }

  /// Fills nd with the node set at y for the shape s and leading edge x0 = a(y) + b(y).
  void point(const LineShape<Real>& s, Real y, Real x0, LineNodes<Real>& nd) const {
    nd.clear();
    const Real yc = y - s.centre;  // y itself for a symmetric contact (c = 0)
    nd.d1 = s.l - yc;
    nd.d2 = s.l + yc;
    nd.tolerance = tolerance_;
    const Real c = std::min(Real(x0 / vtau_), Real(1));
    detail::append_log_mapped_nodes<Quadrature>(
        nd.tn, nd.tw, t_max_, c, boost::math::constants::half_pi<Real>(), tolerance_);
    for (int side = 0; side < 2; ++side) {
      nd.side_s.clear();
      nd.side_w.clear();
      append_side_nodes(s, side == 0 ? nd.d1 : nd.d2, side == 0 ? nd.d2 : nd.d1, side == 0 ? 1 : -1,
                        x0, nd.side_s, nd.side_w);
      nd.add_side(y, side == 0 ? 1 : -1, nd.side_s, nd.side_w);
    }
  }

  /// The nodes y and weights w of an integral over the contact (appended): each half is a side's
  /// nodes from the centre, with the other end at distance l and no kernel (its scale taken as l,
  /// so the first panel is l/4). A symmetric contact (both = false) takes the half [0, l] with
  /// its weights doubled (exact: the sum is twice the half's, bit for bit); an asymmetric one
  /// (both) the halves [c, c + l] and [c - l, c], y = c +- s, each with its own end.
  void load(const LineShape<Real>& s, bool both, std::vector<Real>& y, std::vector<Real>& w) const {
    const std::size_t first = y.size();
    append_side_nodes(s, s.l, s.l, 1, s.l, y, w);
    if (!both) {
      for (std::size_t j = first; j < w.size(); ++j) w[j] *= 2;
      return;
    }
    const std::size_t half = y.size();
    append_side_nodes(s, s.l, s.l, -1, s.l, y, w);
    for (std::size_t j = first; j < y.size(); ++j)
      y[j] = j < half ? Real(s.centre + y[j]) : Real(s.centre - y[j]);
  }

 private:
  /// The nodes of one side's integrals over s in [0, len], y' = y +- s (docs/theory.md section 7).
  /// Equal panels in w = ln(s/(len - s)), which puts every singular point of the integrands at
  /// |Im w| >= pi/2 (and all but s = +-i x_t at |Im w| = pi), between two end panels:
  /// - [0, first] keeps off the kernels' singularities at s = +-i x_t (x_t >= x0) and the nearest
  ///   singular point behind s = 0 (the other end of the contact at s = -other, a branch point of
  ///   a(y) in the variable sqrt(1 - t^2); else the poles of G beyond it);
  /// - [len - last, len], in the variable tau = sqrt((len - s)/last) (a branch point at the end is
  ///   regular in tau), is a fifth of the distance to s = 0, a quarter of the distance of the poles
  ///   of G beyond the end (end_width), and of the scale on which the Chebyshev series of a(y),
  ///   b(y) vary at the end: l/(2N) in t^2, l/(2N^2) in sqrt(1 - t^2) (where u + 1 grows as
  ///   sqrt(l - y));
  /// - the equal panels are no wider than 8/N in w, for the same series.
  /// `end` (+1 or -1) is the end of the contact this side runs to (c + l or c - l): its pole
  /// distance, and the other end's behind s = 0 (the same for a symmetric shape).
  void append_side_nodes(const LineShape<Real>& s, Real len, Real other, int end, Real x0,
                         std::vector<Real>& sn, std::vector<Real>& sw) const {
    const Real behind =
        basis_ == LineBasis::t_squared ? Real(other + pole_distance(s, -end)) : Real(other);
    const Real first = std::min({Real(x0 / 2), Real(len / 4), behind});
    const Real series = series_scale(s);
    const Real last = std::min({end_width(s, len, end), Real(len / 5), series});
    detail::append_logit_mapped_nodes<Quadrature>(sn, sw, len, first, last, Real(8) / n_,
                                                  tolerance_);
  }

  /// The distance from an end over which the Chebyshev series of a(y), b(y) vary: where the
  /// expansion variable is 2/N from -1. In t^2, l/(2N); in s = sqrt(1 - t^2), l s^2/2 at s = 1/N;
  /// in the mapped s, at s = e sinh(asinh(1/e)/N), and no more than a quarter of the distance of
  /// the map's branch points s = +-i e (1 - t^2 = -e^2, l e^2/2 beyond the end).
  Real series_scale(const LineShape<Real>& s) const {
    switch (basis_) {
      case LineBasis::t_squared:
        return s.l / (2 * n_);
      case LineBasis::s:
        return s.l / (2 * n_ * n_);
      default: {
        if (LineShape<Real>::mapped_is_identity(scale_)) return s.l / (2 * n_ * n_);
        const Real sn = LineShape<Real>::mapped_s(scale_, Real(1) / n_);
        return std::min(Real(s.l * sn * sn / 2), Real(s.l * scale_ * scale_ / 8));
      }
    }
  }

  /// The distance of the nearest pole of G beyond the end y = c + end l (end = +1, -1), where
  /// (1 + f) a(y) / V tau = +- i j_{0,1} (a^2 < 0 just past the end), Eqs. (36), (37).
  Real pole_distance(const LineShape<Real>& s, int end) const {
    const Real j01 = Real(2.404825557695772768621631879326454643124L);
    const Real a_end = s.a_ref * s.end_factor(end);
    const Real cc = j01 * vtau_ / ((1 + f_) * a_end);
    return s.l * cc * cc / 2;  // 1 - t^2 = -cc^2 at t = 1 + cc^2/2
  }

  /// The last panel toward the end (+1, -1) of a side of length len: a quarter of pole_distance.
  Real end_width(const LineShape<Real>& s, Real len, int end) const {
    return std::max(Real(pole_distance(s, end) / 4),
                    Real(len * std::numeric_limits<Real>::epsilon()));
  }

  LineBasis basis_;
  Real scale_;  ///< e of LineBasis::s_mapped, else 0
  int n_;
  Real vtau_, f_;
  Real tolerance_;  ///< tol, at least eps
  Real t_max_;      ///< the end of the t-range, -ln(tol) + 8 (e^-t below tol e^-8 beyond)
};

}  // namespace viscoroll::line
