// viscoroll: the residual assembly of the line solver.
//
// Panek & Kalker (1980), Sections 5 and 7. The unknowns are the coefficients of a(y) and b(y)
// (line_shape.hpp), ln l and d; the equations, at collocation points y_i = l t_i, are
//   (34)  FP[F0](y) + F0(y) ln[16 (l^2 - y^2)/a^2] + C1 a^2/4 + (C1/2) b (b - 2 V) + C2 y^2/2 - d =
//   0 (LE)  the leading-edge condition, in the form (L6) of docs/theory.md section 4 (default) or
//   as
//         the paper's (44) (LeadingEdgeForm::paper, for comparison only: its small-argument step is
//         exponentially amplified when V tau << a, docs/theory.md section 4)
//   (47)  int F0 dy = C1 a0^2 l0 / 3 = (1 + f) c P
// with G (36), F0 (33), Q (46) pointwise, V = V tau. (L6) reads
//   C1 {a b e^z K1(z) - G e^z K0(z)} = (Lambda - I_x0)[Q](y) - V int_0^inf e^-t d/dx I[Q, x0 + V
//   t](y) dt,
// z = a/V, x0 = a + b, Lambda the near-field operator (24), I the extended operator (41). Both
// integral terms are sums over one set of nodes y' = y +- s per collocation point:
//   (Lambda - I_x)[Q] = int (Q(y') - Q(y)) x^2 / (s h (s + h)) dy'
//                       - Q(y) sum_{d = l -+ y} log1p(x^2 / (2 d (h_d + d))),       h = sqrt(x^2 +
//                       s^2),
//   V int e^-t dI/dx dt = int (Q(y') - Q(y)) K(s) dy' + Q(y) V int e^-t x_t sum_d 1/(h_d (h_d + d))
//   dt, K(s) = -V int_0^inf e^-t x_t (x_t^2 + s^2)^(-3/2) dt,  x_t = x0 + V t,
// every kernel positive or of one sign, so no term is a difference of large numbers.
// Nodes (docs/theory.md section 7): in s, equal panels in ln(s/(len - s)) between a first panel
// on the kernels' scale x0 and a last one on the scale of the nearest pole of G beyond the end
// (where I0(alpha) = 0, just beyond +-l when a0/V tau is large, docs/line-operators.md); in t,
// equal panels in ln(1 + t/c), c = min(x0/V, 1), up to -ln(eps) + 8. The panels' width follows
// from the distance of the singularities in these variables (pi/2) and the rule's order, so that
// every integral is exact to rounding. Far from the point (s beyond ~2.4 (x0 + V) when V << x0),
// K(s) is a series in 1/s^2 with the t-integral done once per point (docs/theory.md section 8).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/detail/graded_panels.hpp>
#include <viscoroll/line/detail/memory_kernel_series.hpp>
#include <viscoroll/line/line_operators.hpp>
#include <viscoroll/line/line_shape.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>
#include <viscoroll/special/bessel_ratio.hpp>

namespace viscoroll {

/// Which leading-edge condition closes the line equations.
enum class LeadingEdgeForm {
  exterior,  ///< (L6), docs/theory.md section 4: (42) with only I[F1, x0] -> Lambda[F1]
  paper,     ///< the paper's (44) (with [gamma - ln V tau]), in the form (L2), times e^{x0/V}
};

/// The scene's constants seen by the residual (V tau > 0, f > 0).
template <RealScalar Real>
struct LineProblem {
  Real c1, c2, vtau, f;
  Real a_ref;        ///< long-term static half width at y = 0 (scale of a, b)
  Real l_ref;        ///< long-term static half length (scale of l)
  Real load_target;  ///< int F0 dy = (1 + f) c P, Eq. (47) with (52)
};

/// Residual of the line equations at collocation points; `Quadrature` a NodalQuadratureRule.
template <RealScalar Real, class Quadrature>
requires NodalQuadratureRule<Quadrature, Real>
class LineResidual {
 public:
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

  /// terms: N >= 1; ln a has N coefficients, b has N + 1, collocation at N + 1 points. The count
  /// balances each block: (34) at N + 1 points and the load (47) fix the N coefficients of a, l and
  /// d; the leading-edge condition at N + 1 points fixes the N + 1 coefficients of b.
  /// oversampling k >= 1: k (N + 1) points instead, an overdetermined system whose least-squares
  /// solution is the paper's (Section 7; docs/theory.md section 10).
  LineResidual(LineProblem<Real> problem, int terms,
               LeadingEdgeForm form = LeadingEdgeForm::exterior,
               LineBasis basis = LineBasis::t_squared, int oversampling = 1)
      : p_(problem),
        n_(terms),
        oversampling_(oversampling),
        form_(form),
        basis_(basis),
        scale_(basis == LineBasis::s_mapped
                   ? LineShape<Real>::mapped_scale(problem.vtau, problem.f, problem.a_ref)
                   : Real(0)) {
    detail::require(terms >= 1 && terms <= 64, "terms", terms, "1 <= terms <= 64");
    detail::require(oversampling >= 1 && oversampling <= 8, "oversampling", oversampling,
                    "1 <= oversampling <= 8");
    using std::cos;
    using std::sqrt;
    const Real pi = boost::math::constants::pi<Real>();
    const int m = points();
    for (int i = 1; i <= m; ++i) {
      // Chebyshev points in the expansion variable v; t = sqrt(1 - w(v)) in (0, 1).
      const Real v = cos(pi * Real(2 * i - 1) / Real(2 * m));
      t_.push_back(sqrt(1 - LineShape<Real>::one_minus_t2_at(basis_, scale_, v)));
    }
    using std::log;
    t_max_ = -log(std::numeric_limits<Real>::epsilon()) + 8;
  }

  int terms() const { return n_; }
  /// Collocation points: (N + 1) times the oversampling (N + 1 for the square system).
  int points() const { return (n_ + 1) * oversampling_; }
  int oversampling() const { return oversampling_; }
  /// Unknowns: alpha_0..alpha_{N-1}, beta_0..beta_N, ln(l / l_ref), d / (C1 a_ref^2).
  int unknowns() const { return 2 * n_ + 3; }
  /// Equations: (34) and the leading-edge condition at each point, then the load (47).
  int equations() const { return 2 * points() + 1; }
  const std::vector<Real>& collocation() const { return t_; }
  const LineProblem<Real>& problem() const { return p_; }

  LineShape<Real> shape(const Vector& x) const {
    using std::exp;
    LineShape<Real> s{p_.a_ref, p_.l_ref * exp(x[2 * n_ + 1]), {}, {}, basis_, scale_};
    for (int k = 0; k < n_; ++k) s.alpha.push_back(x[k]);
    for (int k = 0; k <= n_; ++k) s.beta.push_back(x[n_ + k]);
    return s;
  }
  Real penetration(const Vector& x) const { return x[2 * n_ + 2] * p_.c1 * p_.a_ref * p_.a_ref; }

  /// The unknowns of a shape and penetration.
  Vector pack(const LineShape<Real>& given, Real d) const {
    using std::log;
    // Same variable and no more terms: pad with zeros (exact); otherwise re-expand.
    const bool pad = given.basis == basis_ && given.scale == scale_ &&
                     int(given.alpha.size()) <= n_ && int(given.beta.size()) <= n_ + 1;
    const LineShape<Real> s = pad ? given : given.reexpanded(basis_, n_, scale_);
    Vector x = Vector::Zero(unknowns());
    for (int k = 0; k < n_ && k < int(s.alpha.size()); ++k) x[k] = s.alpha[k];
    for (int k = 0; k <= n_ && k < int(s.beta.size()); ++k) x[n_ + k] = s.beta[k];
    x[2 * n_ + 1] = log(s.l / p_.l_ref);
    x[2 * n_ + 2] = d / (p_.c1 * p_.a_ref * p_.a_ref);
    return x;
  }

  /// Residual r(x), scaled: (34) by C1 a_ref^2 (plus V/a_ref times the leading-edge row, below),
  /// the leading-edge condition by its derivative with respect to b (so that it reads as an error
  /// in b / a_ref), the load by its target. Returns false
  /// (and leaves r unspecified) where the equations are undefined: a leading edge x0 = a + b <= 0
  /// or a non-finite value.
  bool operator()(const Vector& x, Vector& r) const;

  /// int_{-l}^{l} F0 dy (Eq. 47).
  Real load(const LineShape<Real>& s) const {
    std::vector<Real> nodes, weights;
    load_nodes(s, nodes, weights);
    Real sum = 0;
    for (std::size_t j = 0; j < nodes.size(); ++j)
      sum += weights[j] * strip_functions(p_.c1, s.a(nodes[j]), s.b(nodes[j]), p_.vtau, p_.f).f0;
    return 2 * sum;
  }

  /// (34) and the leading-edge residual at one y, |y| < l (scaled as in operator()).
  bool at_point(const LineShape<Real>& s, Real d, Real y, Real& r34, Real& rle) const {
    const Real c1 = p_.c1;
    const auto here = strip_functions(c1, s.a(y), s.b(y), p_.vtau, p_.f);
    if (!(here.a > 0) || !(here.a + here.b > 0)) return false;
    PointNodes nd;
    point_nodes(s, y, here.a + here.b, nd);
    std::vector<Real> df0(nd.yp.size()), dq(nd.yp.size());
    for (std::size_t j = 0; j < nd.yp.size(); ++j) {
      const auto there = strip_functions(c1, s.a(nd.yp[j]), s.b(nd.yp[j]), p_.vtau, p_.f);
      df0[j] = there.f0 - here.f0;
      dq[j] = there.q - here.q;
    }
    const Real right = form_ == LeadingEdgeForm::exterior
                           ? exterior_right(nd, dq, here.q, here.a + here.b)
                           : paper_right(s, y, here.a + here.b);
    point_rows(d, y, here, nd, df0, right, r34, rle);
    return true;
  }

  /// The residual r(x) and its Jacobian J = dr/dx (semi-analytic, docs/theory.md section 6):
  /// the chain rule through a(y), b(y) (line_shape.hpp) and the strip functions (36),
  /// (33), (46), with d(I1/I0)/dx = 1 - (I1/I0)/x - (I1/I0)^2 (DLMF 10.29.2) and
  /// d(e^z K0)/dz = e^z (K0 - K1), d(e^z K1)/dz = e^z (K1 - K0 - K1/z) (DLMF 10.29.3), at nodes
  /// held fixed in t = y/l; the kernels' dependence on the leading edge x0 = a + b and on l is
  /// differentiated in the same pass as the kernels (exterior_right's KernelSlopes). Exterior form
  /// (L6) only; returns false where operator() would, or for the paper's form.
  bool jacobian(const Vector& x, Vector& r, Matrix& jac) const;

 private:
  /// The nodes of one collocation point: y' = y +- s on both sides (panels doubling from x0/2 and
  /// halving toward the ends), and the t-nodes of the eta-integral of (L6).
  struct PointNodes {
    std::vector<Real> yp, dist, weight;  ///< node y', |y' - y| and weight, both sides
    std::vector<Real> tn, tw;            ///< t-nodes on [0, -ln eps + 8] and weights (no e^-t)
    Real d1 = 0, d2 = 0;                 ///< l - y, l + y
  };

  void point_nodes(const LineShape<Real>& s, Real y, Real x0, PointNodes& nd) const {
    nd.d1 = s.l - y;
    nd.d2 = s.l + y;
    const Real c = std::min(Real(x0 / p_.vtau), Real(1));
    detail::append_log_mapped_nodes<Quadrature>(nd.tn, nd.tw, t_max_, c,
                                                boost::math::constants::half_pi<Real>());
    std::vector<Real> sn, sw;
    for (int side = 0; side < 2; ++side) {
      const Real len = side == 0 ? nd.d1 : nd.d2;
      sn.clear();
      sw.clear();
      append_side_nodes(s, len, side == 0 ? nd.d2 : nd.d1, x0, sn, sw);
      for (std::size_t j = 0; j < sn.size(); ++j) {
        const Real yp = side == 0 ? Real(y + sn[j]) : Real(y - sn[j]);
        const Real dist = side == 0 ? Real(yp - y) : Real(y - yp);  // recomputed: rounding of yp
        if (!(dist > 0)) continue;
        nd.yp.push_back(yp);
        nd.dist.push_back(dist);
        nd.weight.push_back(sw[j]);
      }
    }
  }

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
  void append_side_nodes(const LineShape<Real>& s, Real len, Real other, Real x0,
                         std::vector<Real>& sn, std::vector<Real>& sw) const {
    const Real behind =
        basis_ == LineBasis::t_squared ? Real(other + pole_distance(s)) : Real(other);
    const Real first = std::min({Real(x0 / 2), Real(len / 4), behind});
    const Real series = series_scale(s);
    const Real last = std::min({end_width(s, len), Real(len / 5), series});
    detail::append_logit_mapped_nodes<Quadrature>(sn, sw, len, first, last, Real(8) / n_);
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

  /// The derivatives of exterior_right in x0 and in ln l (every distance along y stretched by
  /// lambda, nodes fixed in t), at fixed dq and q (docs/theory.md section 6).
  struct KernelSlopes {
    Real x0 = 0, l = 0;
  };

  /// (Lambda - I_x0)[Q] - V int e^-t dI/dx[Q, x0 + V t] dt, (L6), from dq_j = Q(y'_j) - Q(y) and
  /// q = Q(y). Optionally the weight of each dq_j, the factor of q, and the derivatives in x0 and
  /// ln l (the Jacobian's; in the same pass, docs/theory.md section 6).
  Real exterior_right(const PointNodes& nd, const std::vector<Real>& dq, Real q, Real x0,
                      std::vector<Real>* wq = nullptr, Real* ends = nullptr,
                      KernelSlopes* slopes = nullptr) const {
    using std::exp;
    using std::hypot;
    using std::log1p;
    using std::sqrt;
    const Real v = p_.vtau;
    const std::size_t nt = nd.tn.size();
    // wk: the t-weights W_k with e^-t and V; wtu2 (W u^2) only for the slopes.
    Eigen::Array<Real, Eigen::Dynamic, 1> wk(nt), uk2(nt), wu(nt), wtu2(slopes ? nt : 0), p2(nt);
    std::vector<Real> xk(nt);
    for (std::size_t k = 0; k < nt; ++k) {
      xk[k] = x0 + v * nd.tn[k];
      wk[k] = v * nd.tw[k] * exp(-nd.tn[k]);
      // In units of x0 (u = x_t/x0 >= 1, sigma = s/x0): K(s) x0^2 = -sum w u (u^2 +
      // sigma^2)^(-3/2), a square root per node instead of hypot (3x dearer), free of overflow
      // while s/x0 < 1e150.
      const Real u = xk[k] / x0;
      uk2[k] = u * u;
      wu[k] = wk[k] * u;
      if (slopes != nullptr) wtu2[k] = wk[k] * u * u;
    }
    // s-nodes beyond far.threshold() (~2.4 (x0 + V) when V << x0) take the series in 1/s^2
    // instead of the t-nodes.
    const detail::MemoryKernelSeries<Real> far(x0, v);
    Real s1 = 0, s2 = 0, s_x0 = 0, s_l = 0;
    for (std::size_t j = 0; j < nd.dist.size(); ++j) {
      const Real w = nd.weight[j];
      const Real sigma = nd.dist[j] / x0, sigma2 = sigma * sigma;
      const Real hu = sqrt(1 + sigma2);                      // h / x0
      const Real k1 = w / (x0 * sigma * hu * (sigma + hu));  // x0^2/(s h (s + h)) = 1/s - 1/h
      // k2 and, for the slopes, dk2/dx0 and dk2/dln l.
      Real k2, k2_x0 = 0, k2_l = 0;
      if (nd.dist[j] >= far.threshold()) {
        // Far from the point: the series in 1/s^2 (docs/theory.md section 8), within eps/16.
        if (slopes == nullptr) {
          k2 = -w * far.value(nd.dist[j]);
        } else {
          Real kf = 0, kf_x0 = 0, kf_s = 0;
          far.evaluate(nd.dist[j], kf, kf_x0, kf_s);
          k2 = -w * kf;
          k2_x0 = -w * kf_x0;
          k2_l = k2 - w * kf_s;
        }
      } else {
        // P = (u^2 + sigma^2)^(-1/2), k2 = -w sum W u P^3 / x0^2 (W = wk): packed divisions and
        // square roots, a tree-ordered sum; the same operations with and without the slopes, so
        // that the Jacobian's residual is operator()'s bit for bit.
        p2 = (uk2 + sigma2).inverse();
        k2 = -w * (wu * (p2 * p2.sqrt())).sum() / (x0 * x0);
        if (slopes != nullptr) {
          // dk2/dx0 = -w sum W (sigma^2 - 2 u^2) P^5 / x0^3,
          // dk2/dln l = k2 + 3 w sigma^2 sum W u P^5 / x0^2.
          const Eigen::Array<Real, Eigen::Dynamic, 1> p5 = p2 * p2 * p2.sqrt();
          k2_x0 = -w * (sigma2 * (wk * p5).sum() - 2 * (wtu2 * p5).sum()) / (x0 * x0 * x0);
          k2_l = k2 + 3 * w * sigma2 * (wu * p5).sum() / (x0 * x0);
        }
      }
      if (slopes != nullptr) {
        // dk1/dx0 = w x0/h^3, dk1/dln l = -w x0^2/h^3.
        const Real hu3 = hu * hu * hu;
        s_x0 += (w / (x0 * x0 * hu3) - k2_x0) * dq[j];
        s_l += (-w / (x0 * hu3) - k2_l) * dq[j];
      }
      s1 += k1 * dq[j];
      s2 += k2 * dq[j];
      if (wq != nullptr) (*wq)[j] = k1 - k2;
    }
    const Real d1 = nd.d1, d2 = nd.d2;
    const Real h1 = hypot(x0, d1), h2 = hypot(x0, d2);
    // log1p(x0^2/(2 d (h + d))) = ln((h + d)/(2 d)).
    const Real ends_l =
        -(log1p(x0 * x0 / (2 * d1 * (h1 + d1))) + log1p(x0 * x0 / (2 * d2 * (h2 + d2))));
    Real ends_2 = 0, ends_2_x0 = 0, ends_2_l = 0;
    for (std::size_t k = 0; k < nt; ++k) {
      const Real g1 = hypot(xk[k], d1), g2 = hypot(xk[k], d2);
      const Real a1 = 1 / (g1 * (g1 + d1)), a2 = 1 / (g2 * (g2 + d2));
      ends_2 += wk[k] * xk[k] * (a1 + a2);
      if (slopes != nullptr) {
        // phi = x A, A = 1/(g (g + d)), g = hypot(x, d): dphi/dx = A - x^2 (2 g + d) A^2 / g,
        // dphi/dln l = d dphi/dd = -x d / g^3.
        const Real x2 = xk[k] * xk[k];
        ends_2_x0 += wk[k] * (a1 - x2 * (2 * g1 + d1) * a1 * a1 / g1 + a2 -
                              x2 * (2 * g2 + d2) * a2 * a2 / g2);
        ends_2_l -= wk[k] * xk[k] * (d1 / (g1 * g1 * g1) + d2 / (g2 * g2 * g2));
      }
    }
    if (ends != nullptr) *ends = ends_l - ends_2;
    if (slopes != nullptr) {
      // d ln((h + d)/(2 d))/dx0 = x0/(h (h + d)); its derivative in ln l is -x0^2/(h (h + d)).
      const Real e1 = x0 / (h1 * (h1 + d1)), e2 = x0 / (h2 * (h2 + d2));
      slopes->x0 = s_x0 + q * (-(e1 + e2) - ends_2_x0);
      slopes->l = s_l + q * (x0 * (e1 + e2) - ends_2_l);
    }
    // (L6): (Lambda - I_x0)[Q] - V int e^-t dI/dx[Q, x0 + V t] dt
    return (s1 + q * ends_l) - (s2 + q * ends_2);
  }

  /// The right side of the paper's (44) in the form (L2), multiplied by e^{(a + b)/V} to the
  /// scaling of (42).
  Real paper_right(const LineShape<Real>& s, Real y, Real x0) const {
    using std::exp;
    LineOperators<Real, Quadrature> ops(s.l);
    const auto q = [&](Real yp) {
      return strip_functions(p_.c1, s.a(yp), s.b(yp), p_.vtau, p_.f).q;
    };
    return exp(x0 / p_.vtau) * ops.leading_edge_kernel(q, p_.vtau, y);
  }

  /// e^z K0(z), e^z K1(z) at z = a/V and the leading-edge row's scale C1 a (e^z K1 + r_i e^z K0),
  /// its slope in b at fixed a.
  struct EdgeTerms {
    Real k0, k1, slope;
  };

  /// (34) and the leading-edge row at one point from the finite-part differences df0_j and the
  /// right side of the leading-edge condition; returns the terms of the row's left side.
  EdgeTerms point_rows(Real d, Real y, const StripFunctions<Real>& here, const PointNodes& nd,
                       const std::vector<Real>& df0, Real right, Real& r34, Real& rle) const {
    using std::log;
    const Real c1 = p_.c1, v = p_.vtau, a = here.a, b = here.b;
    Real fp = 0;
    for (std::size_t j = 0; j < df0.size(); ++j) fp += nd.weight[j] * df0[j] / nd.dist[j];
    // (34), scaled by C1 a_ref^2.
    const Real lhs34 = fp + here.f0 * (log(4 * nd.d1 / a) + log(4 * nd.d2 / a));
    const Real rhs34 = -c1 * a * a / 4 - c1 * b * (b - 2 * v) / 2 - p_.c2 * y * y / 2 + d;
    r34 = (lhs34 - rhs34) / (c1 * p_.a_ref * p_.a_ref);
    // Leading-edge condition.
    const Real z = a / v;
    const Real k0 = special::bessel_k0_scaled(z), k1 = special::bessel_k1_scaled(z);
    const Real bessel = c1 * (a * b * k1 - here.g * k0);  // C1 e^z {a b K1 - G K0}, Eq. (42)
    const Real r_i = special::bessel_i1_over_i0_fast(Real((1 + p_.f) * a / v));
    const Real slope = c1 * a * (k1 + r_i * k0);  // d(bessel)/db at fixed a
    rle = (bessel - right) / (slope * p_.a_ref);
    return {k0, k1, slope};
  }

  /// G (36), F0 (33), Q (46) (as strip_functions) with their partial derivatives in a and b,
  /// and I1/I0 and its derivative; all zero for a <= 0 (beyond the ends).
  struct StripDerivatives {
    StripFunctions<Real> value;
    Real g_a, g_b, f0_a, f0_b, q_a, q_b, ri, ri_x;
  };
  StripDerivatives strip_derivatives(Real a, Real b) const {
    using std::sqrt;
    const Real c1 = p_.c1, v = p_.vtau, f = p_.f;
    if (!(a > 0)) return {{Real(0), b, Real(0), Real(0), Real(0)}, 0, 0, 0, 0, 0, 0, 0, 0};
    const Real alpha = (1 + f) * a / v;                      // Eq. (37)
    const Real ri = special::bessel_i1_over_i0_fast(alpha);  // I1/I0
    // DLMF 10.29.2: (I1/I0)' = 1 - (I1/I0)/x - (I1/I0)^2; 1/2 - 3x^2/16 + ... at 0.
    const Real ri_x = alpha < sqrt(std::numeric_limits<Real>::epsilon())
                          ? Real(0.5)
                          : Real(1 - ri / alpha - ri * ri);
    const StripFunctions<Real> value = strip_functions_from_ratio(c1, a, b, v, f, ri);
    const Real k = v * f / (1 + f) - b, g = value.g;
    const Real g_a = k * (ri + alpha * ri_x), g_b = -a * ri;
    return {value,
            g_a,
            g_b,
            c1 * (a / 2 + g_a / 2),
            c1 * g_b / 2,
            c1 * g_a * (v - b) / (2 * v),
            c1 * (g_b * (v - b) - g) / (2 * v),
            ri,
            ri_x};
  }

  /// d a(y)/d x and d b(y)/d x at y for fixed t = y/l (zero in ln l and d).
  void shape_gradient(const LineShape<Real>& s, Real y, Real a, Vector& da, Vector& db) const {
    da.setZero(unknowns());
    db.setZero(unknowns());
    const Real w = s.one_minus_t2(y);
    const Real u = LineShape<Real>::coordinate(basis_, scale_, w > 0 ? w : Real(0));
    Real tkm1 = 1, tk = u;  // T_0, T_1
    for (int k = 0; k <= n_; ++k) {
      const Real tval = k == 0 ? Real(1) : tk;
      if (k < n_) da[k] = a * tval;
      db[n_ + k] = p_.a_ref * tval;
      if (k >= 1) {
        const Real next = 2 * u * tk - tkm1;
        tkm1 = tk;
        tk = next;
      }
    }
  }

  /// The nodes and weights of the load integral (47) on [0, l]: a side's nodes from y = 0, with
  /// the other end at distance l and no kernel (its scale taken as l, so the first panel is l/4).
  void load_nodes(const LineShape<Real>& s, std::vector<Real>& nodes,
                  std::vector<Real>& weights) const {
    append_side_nodes(s, s.l, s.l, s.l, nodes, weights);
  }

  /// The distance of the nearest pole of G beyond y = +-l, where (1 + f) a(y) / V tau = +- i
  /// j_{0,1} (a^2 < 0 just past the end).
  Real pole_distance(const LineShape<Real>& s) const {
    const Real j01 = Real(2.404825557695772768621631879326454643124L);
    const Real a_end = s.a_ref * s.end_factor();
    const Real cc = j01 * p_.vtau / ((1 + p_.f) * a_end);
    return s.l * cc * cc / 2;  // 1 - t^2 = -cc^2 at t = 1 + cc^2/2
  }

  /// The last panel toward the end of a side of length len: a quarter of pole_distance.
  Real end_width(const LineShape<Real>& s, Real len) const {
    return std::max(Real(pole_distance(s) / 4), Real(len * std::numeric_limits<Real>::epsilon()));
  }

  LineProblem<Real> p_;
  int n_;
  int oversampling_;
  LeadingEdgeForm form_;
  LineBasis basis_;
  Real scale_;  ///< e of LineBasis::s_mapped, else 0
  std::vector<Real> t_;
  Real t_max_;
};

template <RealScalar Real, class Quadrature>
requires NodalQuadratureRule<Quadrature, Real>
auto LineResidual<Real, Quadrature>::operator()(const Vector& x, Vector& r) const -> bool {
  r.resize(equations());
  const LineShape<Real> s = shape(x);
  const Real d = penetration(x);
  const int m = points();
  for (int i = 0; i < m; ++i) {
    Real r34 = 0, rle = 0;
    if (!at_point(s, d, t_[i] * s.l, r34, rle)) return false;
    // (34) depends on b through C1 V b, the leading-edge condition through its slope C1 V (as
    // V tau >> a): adding V/a_ref times the latter (scaled to an error in b/a_ref) cancels the b
    // dependence of (34) to first order, so that (34) speaks for a, l and d at every speed. A row
    // operation: the solution is unchanged, the Jacobian's condition number no longer grows as V.
    r[i] = r34 + p_.vtau / p_.a_ref * rle;
    r[m + i] = rle;
  }
  r[2 * m] = load(s) / p_.load_target - 1;
  for (int i = 0; i < r.size(); ++i)
    if (!(boost::math::isfinite)(r[i])) return false;
  return true;
}

template <RealScalar Real, class Quadrature>
requires NodalQuadratureRule<Quadrature, Real>
auto LineResidual<Real, Quadrature>::jacobian(const Vector& x, Vector& r, Matrix& jac) const
    -> bool {
  using std::log;
  if (form_ != LeadingEdgeForm::exterior) return false;
  const int m = points(), nu = unknowns(), lam = 2 * n_ + 1, del = 2 * n_ + 2;
  r.resize(equations());
  jac.setZero(equations(), nu);
  const LineShape<Real> s = shape(x);
  const Real d = penetration(x), c1 = p_.c1, v = p_.vtau;
  const Real scale34 = c1 * p_.a_ref * p_.a_ref;
  Vector da_i(nu), db_i(nu), df0_i(nu), dq_i(nu), dright(nu), dlhs(nu), dnode(nu);
  for (int i = 0; i < m; ++i) {
    const Real t = t_[i], y = t * s.l;
    const auto dh = strip_derivatives(s.a(y), s.b(y));
    const auto& here = dh.value;
    const Real a = here.a, b = here.b, x0 = a + b;
    if (!(a > 0) || !(x0 > 0)) return false;
    shape_gradient(s, y, a, da_i, db_i);
    df0_i = dh.f0_a * da_i + dh.f0_b * db_i;
    dq_i = dh.q_a * da_i + dh.q_b * db_i;
    PointNodes nd;
    point_nodes(s, y, x0, nd);
    const std::size_t count = nd.yp.size();
    std::vector<Real> df0(count), dq(count), wq(count);
    dlhs.setZero();
    dright.setZero();
    Vector dan(nu), dbn(nu);
    std::vector<StripDerivatives> dn(count);
    for (std::size_t j = 0; j < count; ++j) {
      dn[j] = strip_derivatives(s.a(nd.yp[j]), s.b(nd.yp[j]));
      df0[j] = dn[j].value.f0 - here.f0;
      dq[j] = dn[j].value.q - here.q;
    }
    Real ends = 0;
    KernelSlopes slopes;
    const Real right = exterior_right(nd, dq, here.q, x0, &wq, &ends, &slopes);
    Real r34 = 0, rle = 0;
    const auto edge = point_rows(d, y, here, nd, df0, right, r34, rle);
    r[i] = r34 + v / p_.a_ref * rle;
    r[m + i] = rle;
    // Node values: d F(y'_j) at fixed t'_j; the differences' second terms via the weight sums.
    Real w0sum = 0, wqsum = 0;
    for (std::size_t j = 0; j < count; ++j) {
      const Real w0 = nd.weight[j] / nd.dist[j];
      w0sum += w0;
      wqsum += wq[j];
      const auto& dj = dn[j];
      if (!(dj.value.a > 0)) continue;  // at an end: F0 = Q = 0 there for every coefficient
      shape_gradient(s, nd.yp[j], dj.value.a, dan, dbn);
      dnode = dj.f0_a * dan + dj.f0_b * dbn;
      dlhs += w0 * dnode;
      dnode = dj.q_a * dan + dj.q_b * dbn;
      dright += wq[j] * dnode;
    }
    dlhs -= w0sum * df0_i;
    dright += (ends - wqsum) * dq_i;
    // The kernels' dependence on x0 and on l (nodes fixed in t).
    dright += slopes.x0 * (da_i + db_i);
    dright[lam] += slopes.l;
    // (34): lhs = FP + F0 ln[16 (l^2 - y^2)/a^2],
    //       rhs = -C1 a^2/4 - C1 b (b - 2V)/2 - C2 y^2/2 + d.
    const Real lnfac = log(4 * (s.l - y) / a) + log(4 * (s.l + y) / a);
    dlhs += lnfac * df0_i - (2 * here.f0 / a) * da_i;
    dlhs[lam] += 2 * here.f0;
    Vector drhs = -(c1 * a / 2) * da_i - c1 * (b - v) * db_i;
    drhs[lam] -= p_.c2 * y * y;
    drhs[del] += scale34;
    const Vector dr34 = (dlhs - drhs) / scale34;
    // Leading edge: rle = (bessel - right) / (slope a_ref).
    const Real z = a / v, e0 = edge.k0, e1 = edge.k1, slope = edge.slope, ri = dh.ri;
    const Real e0z = e0 - e1, e1z = e1 - e0 - e1 / z;
    const Real bessel_a = c1 * (b * e1 + a * b * e1z / v - dh.g_a * e0 - here.g * e0z / v);
    const Real bessel_b = c1 * (a * e1 - dh.g_b * e0);
    const Real slope_a =
        c1 * (e1 + ri * e0) + c1 * a * (e1z / v + dh.ri_x * (1 + p_.f) / v * e0 + ri * e0z / v);
    const Vector dbessel = bessel_a * da_i + bessel_b * db_i;
    const Vector drle = (dbessel - dright) / (slope * p_.a_ref) - (rle * slope_a / slope) * da_i;
    jac.row(i) = (dr34 + (v / p_.a_ref) * drle).transpose();
    jac.row(m + i) = drle.transpose();
  }
  // Load (47), nodes fixed in y/l: d/d ln l of the integral is the integral itself.
  std::vector<Real> nodes, weights;
  load_nodes(s, nodes, weights);
  Real sum = 0;
  Vector dsum = Vector::Zero(nu), dan(nu), dbn(nu);
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    const auto dj = strip_derivatives(s.a(nodes[j]), s.b(nodes[j]));
    const auto& sf = dj.value;
    sum += weights[j] * sf.f0;
    if (!(sf.a > 0)) continue;
    shape_gradient(s, nodes[j], sf.a, dan, dbn);
    dsum += weights[j] * (dj.f0_a * dan + dj.f0_b * dbn);
  }
  r[2 * m] = 2 * sum / p_.load_target - 1;
  jac.row(2 * m) = (2 * dsum / p_.load_target).transpose();
  jac(2 * m, lam) = 2 * sum / p_.load_target;
  for (int i = 0; i < r.size(); ++i)
    if (!(boost::math::isfinite)(r[i])) return false;
  return jac.allFinite();
}

// Compiled mode (docs/building.md): with VISCOROLL_COMPILED, which the CMake target
// viscoroll::compiled sets, the residuals of the line solvers' default rule (12-point
// Gauss-Legendre) are instantiated once in that library (src/) and not in the including
// translation unit; operator() and jacobian() are defined out of the class (not inline), so that
// g++ does not instantiate them here for inlining either.
#if defined(VISCOROLL_COMPILED)
extern template class LineResidual<float, GaussLegendre<float, 12>>;
extern template class LineResidual<double, GaussLegendre<double, 12>>;
extern template class LineResidual<long double, GaussLegendre<long double, 12>>;
#endif

}  // namespace viscoroll
