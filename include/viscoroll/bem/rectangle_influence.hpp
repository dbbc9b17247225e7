// viscoroll: influence coefficients of a uniformly loaded rectangle on the surface of a half space,
// elastic (Love 1929) and with the standard-linear-solid memory of Hunter's Eq. (2) integrated
// once into the coefficient (docs/bem.md, sections B1-B3).
//
// The rectangle is [-hx/2, hx/2] x [-hy/2, hy/2]; the coefficients are per unit pressure and per
// unit compliance, i.e. without the factor c = (1 - nu)/(2 pi mu_D) of Eq. (3):
//   K_e(X, Y) = int int dx' dy' / sqrt((X - x')^2 + (Y - y')^2)                      (B1)
//             = F(X+hx/2, Y+hy/2) - F(X-hx/2, Y+hy/2) - F(X+hx/2, Y-hy/2) + F(X-hx/2, Y-hy/2),
//   F(u, v)   = u asinh(v/|u|) + v asinh(u/|v|)  (d^2 F / du dv = 1/sqrt(u^2 + v^2)),
// evaluated by (B1) near the rectangle and by tensor Gauss-Legendre far from it, where (B1)
// cancels (B2). The memory coefficient of one relaxation term with length L = V tau_k is
//   M_L(X, Y) = int_0^inf e^(-eta) K_e(X + L eta, Y) d eta                             (B3)
// and is computed for a whole row of offsets X_i = i hx by the backward recurrence (B4)
//   M_L(X_i) = e^(-hx/L) M_L(X_{i+1}) + (1/L) int_{X_i}^{X_i + hx} e^(-(s - X_i)/L) K_e(s, Y) ds,
// with panels graded towards the kinks of K_e at s = +-hx/2 and the tail beyond the last offset
// on panels graded in t = (s - X_max)/L (B5).
//
// Quadrature: each panel of (B4)-(B5) is integrated by a nodal rule (NodalQuadratureRule of
// core/concepts.hpp), by default MemoryPanelRule, 16-point Gauss-Legendre; the grading makes every
// panel's integrand analytic well beyond the panel, so that the default reaches about eps. The far
// field (B2) keeps its own family of Gauss-Legendre rules: its point count is chosen per offset
// from the distance to the singularity (gauss_points_needed), which no single fixed rule matches.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

namespace viscoroll {

namespace detail {

/// n-point Gauss-Legendre sum of g over [-1, 1] for the n the far field needs (B2).
template <class Real, int N, class G>
Real gauss_sum(G&& g) {
  const auto& x = GaussLegendre<Real, N>::nodes();
  const auto& w = GaussLegendre<Real, N>::weights();
  Real s = 0;
  for (int k = 0; k < N; ++k) s += w[k] * g(x[k]);
  return s;
}

template <class Real, class G>
Real gauss_sum_n(int n, G&& g) {
  if (n <= 3) return gauss_sum<Real, 3>(g);
  if (n <= 4) return gauss_sum<Real, 4>(g);
  if (n <= 5) return gauss_sum<Real, 5>(g);
  if (n <= 6) return gauss_sum<Real, 6>(g);
  if (n <= 8) return gauss_sum<Real, 8>(g);
  if (n <= 10) return gauss_sum<Real, 10>(g);
  if (n <= 13) return gauss_sum<Real, 13>(g);
  if (n <= 16) return gauss_sum<Real, 16>(g);
  return gauss_sum<Real, 24>(g);
}

/// Points of an n-point Gauss-Legendre rule needed for eps relative error on a panel of half
/// length h whose integrand is analytic out to distance `dist` from the panel's centre: the error
/// falls as rho^(-2n), rho = dist/h + sqrt((dist/h)^2 - 1) (Bernstein ellipse), plus one point:
/// n = ceil(D / (2 ln rho)) + 1, D = -ln eps.
template <class Real>
int gauss_points_needed(Real dist_over_half_length) {
  using std::log;
  using std::sqrt;
  const Real q = dist_over_half_length;
  const Real rho = q + sqrt(q * q - 1);
  const Real digits = -log(std::numeric_limits<Real>::epsilon());
  return static_cast<int>(std::ceil(static_cast<double>(digits / (2 * log(rho))))) + 1;
}

/// The rule of gauss_sum_n that gauss_points_needed(q) selects, without its logarithms (the
/// table's hot path): n points suffice when rho >= e^(D / (2 (n - 1))), i.e. when
/// q >= cosh(D / (2 (n - 1))); the thresholds of the rules 3 .. 16 are computed once.
template <class Real>
int gauss_rule_for(Real dist_over_half_length) {
  static const std::array<Real, 8> threshold = [] {
    using std::cosh;
    using std::log;
    const Real digits = -log(std::numeric_limits<Real>::epsilon());
    std::array<Real, 8> t{};
    const int rules[8] = {3, 4, 5, 6, 8, 10, 13, 16};
    for (std::size_t k = 0; k < t.size(); ++k) t[k] = cosh(digits / (2 * Real(rules[k] - 1)));
    return t;
  }();
  static constexpr int rules[8] = {3, 4, 5, 6, 8, 10, 13, 16};
  for (std::size_t k = 0; k < threshold.size(); ++k)
    if (dist_over_half_length >= threshold[k]) return rules[k];
  return 24;
}

}  // namespace detail

namespace bem {

/// The type the coefficients are computed in: at least double (the far-field and memory work
/// needs more than float's 24 bits), Real itself when it is wider.
template <class Real>
using coefficient_real_t =
    std::conditional_t<(std::numeric_limits<Real>::digits < std::numeric_limits<double>::digits),
                       double, Real>;

/// The default rule of the memory panels (B4)-(B5): 16-point Gauss-Legendre in the coefficient
/// type. Another NodalQuadratureRule takes its place through memory_row's, InfluenceTable's and
/// BemSolver's Quadrature parameter; its nodes and weights are used in the coefficient type. A
/// rule of more points measures the default's quadrature error: GaussLegendre<double, 24> and
/// GaussLegendre<long double, 32> agree with it to about 10 eps. Fewer points set the table up
/// faster but are not at rounding level: 8 points leave 1e-12 .. 2e-11 relative
/// (tests/bem/bem_quadrature.test.cpp).
template <class Real>
using MemoryPanelRule = GaussLegendre<coefficient_real_t<Real>, 16>;

/// (B1): the primitive F(u, v) = u asinh(v/|u|) + v asinh(u/|v|) of 1/sqrt(u^2 + v^2).
template <RealScalar Real>
Real love_primitive(Real u, Real v) {
  using std::abs;
  using std::asinh;
  Real s = 0;
  if (u != 0) s += u * asinh(v / abs(u));
  if (v != 0) s += v * asinh(u / abs(v));
  return s;
}

/// (B1) literally: the four-corner difference of F. Exact near the rectangle; loses about
/// log10((R^2/(hx hy)) ln R) digits at distance R.
template <RealScalar Real>
Real rectangle_influence_closed_form(Real x, Real y, Real hx, Real hy) {
  const Real x1 = x - hx / 2, x2 = x + hx / 2, y1 = y - hy / 2, y2 = y + hy / 2;
  return love_primitive(x2, y2) - love_primitive(x1, y2) - love_primitive(x2, y1) +
         love_primitive(x1, y1);
}

/// K_e(x, y) of (B1) to about 100 eps relative at every offset: the closed form within two cell
/// sizes of the rectangle, tensor Gauss-Legendre (B2) beyond, where the closed form cancels.
template <RealScalar Real>
Real rectangle_influence(Real x, Real y, Real hx, Real hy) {
  using std::abs;
  using std::sqrt;
  const Real hmax = std::max(hx, hy);
  // Distance from the field point to the rectangle's nearest point.
  const Real dx = std::max(abs(x) - hx / 2, Real(0)), dy = std::max(abs(y) - hy / 2, Real(0));
  const Real dmin = sqrt(dx * dx + dy * dy);
  if (dmin < 2 * hmax) return rectangle_influence_closed_form(x, y, hx, hy);
  // (B2): the integrand's singularities lie at distance >= dmin + h/2 from each panel's centre.
  const int nx = detail::gauss_rule_for<Real>((dmin + hx / 2) / (hx / 2));
  const int ny = detail::gauss_rule_for<Real>((dmin + hy / 2) / (hy / 2));
  return detail::gauss_sum_n<Real>(nx,
                                   [&](Real sx) {
                                     const Real u = x - sx * hx / 2;
                                     return detail::gauss_sum_n<Real>(ny, [&](Real sy) {
                                       const Real v = y - sy * hy / 2;
                                       return 1 / sqrt(u * u + v * v);
                                     });
                                   }) *
         (hx * hy / 4);
}

/// The grading depth of (B4) towards the kinks s = +-hx/2 of row Y: a row |Y| <= hy/2 carries a
/// u ln|u| kink (graded to the scalar's last bit); a row |Y| > hy/2 is analytic within
/// |Y| - hy/2 of the kink, which matters only when that gap is below hx: ceil(log2(hx/gap)) + 2
/// levels, at most the scalar's digits (a gap of a few ulps would ask for a thousand).
template <RealScalar Real>
int kink_grading_depth(Real y, Real hx, Real hy) {
  using std::abs;
  using std::log;
  constexpr int full = std::numeric_limits<Real>::digits;
  const Real gap = abs(y) - hy / 2;
  if (!(gap > 0)) return full;
  if (!(gap < hx)) return 0;
  const double levels = std::ceil(static_cast<double>(log(hx / gap) / log(Real(2)))) + 2;
  return levels < full ? static_cast<int>(levels) : full;
}

/// (B4), (B5): the memory coefficients M_L(X_i, Y) of (B3) for X_i = i hx, i = -m .. m, at one Y,
/// for L > 0, each panel integrated by the rule Quadrature. Returns 2m + 1 values, index i + m.
/// L = 0 gives K_e itself (the limit of (B3)).
template <RealScalar Real, class Quadrature = MemoryPanelRule<Real>>
requires NodalQuadratureRule<Quadrature, Real> std::vector<Real> memory_row(int m, Real y, Real hx,
                                                                            Real hy, Real length) {
  using std::abs;
  using std::exp;
  using std::log;
  using std::sqrt;
  std::vector<Real> out(static_cast<std::size_t>(2 * m + 1));
  const auto ke = [&](Real s) { return rectangle_influence(s, y, hx, hy); };
  if (!(length > 0)) {
    for (int i = -m; i <= m; ++i) out[static_cast<std::size_t>(i + m)] = ke(Real(i) * hx);
    return out;
  }
  const Real L = length;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real u_max = -log(eps) + 6;  // e^(-u_max) < eps / 400: the weight beyond is negligible
  const int depth = kink_grading_depth(y, hx, hy);
  const auto& gx = Quadrature::nodes();
  const auto& gw = Quadrature::weights();
  // The panel [origin + a, origin + b] in offsets from the weight's origin: the weight
  // e^(-t/L) takes t itself (s - origin formed from s ~ m hx would be off by m hx eps, the
  // weight's argument by m hx eps/L, far beyond rounding for L << hx); only K_e's argument
  // origin + t rounds, as K_e's own evaluation does (docs/bem.md, B4).
  const auto panel = [&](Real a, Real b, Real origin) {
    const Real half = (b - a) / 2, mid = (a + b) / 2;
    Real s = 0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(Quadrature::points); ++k) {
      const Real t = mid + half * Real(gx[k]);
      s += Real(gw[k]) * exp(-t / L) * ke(origin + t);
    }
    return s * half / L;
  };
  std::vector<Real> points;
  // (1/L) int_0^hx e^(-t/L) K_e(x0 + t, y) dt on graded panels (offsets t from x0).
  const auto step_integral = [&](Real x0) {
    points.clear();
    const Real end = std::min(hx, L * u_max);
    points.push_back(Real(0));
    points.push_back(end);
    points.push_back(std::min(hx / 2, end));
    for (const Real e : {-hx / 2, hx / 2}) {
      const Real te = e - x0;  // the kink's offset
      if (!(te > 0 && te < hx)) continue;
      for (int k = 1; k <= depth; ++k) {
        const Real off = (hx / 2) * std::ldexp(Real(1), -k);
        for (const Real p : {te - off, te + off})
          if (p > 0 && p < end) points.push_back(p);
      }
    }
    // The exponential weight on panels at most 8 L wide.
    for (Real u = 8; u < u_max && L * u < end; u += 8) points.push_back(L * u);
    std::sort(points.begin(), points.end());
    Real s = 0;
    for (std::size_t k = 1; k < points.size(); ++k)
      if (points[k] > points[k - 1]) s += panel(points[k - 1], points[k], x0);
    return s;
  };
  // (B5): int_0^inf e^(-t) K_e(x_max + L t, y) dt on t-panels doubling from t1 to 8, then 8 wide.
  const Real x_max = Real(m) * hx;
  const Real r0 = std::max(hx, sqrt(x_max * x_max + y * y));
  Real t1 = std::min(Real(1), r0 / L) / 2;
  Real tail = 0;
  {
    Real t0 = 0, t = t1;
    while (t0 < u_max) {
      tail += panel(L * t0, L * t, x_max);
      t0 = t;
      t = t < 8 ? 2 * t : t + 8;
      if (t > u_max) t = u_max;
      if (t0 >= u_max) break;
    }
  }
  const Real decay = exp(-hx / L);
  out[static_cast<std::size_t>(2 * m)] = tail;
  for (int i = m - 1; i >= -m; --i)
    out[static_cast<std::size_t>(i + m)] =
        decay * out[static_cast<std::size_t>(i + m + 1)] + step_integral(Real(i) * hx);
  return out;
}

/// (B4), (B5) for several memory lengths at once (docs/bem.md, "Many memory terms"): the lengths
/// share their panels' nodes, so that Love's coefficient K_e, nearly all the cost of a row, is
/// evaluated once per node for all of them; each length weights the node values by its own
/// e^(-(s - X_i)/L)/L. The shared panels are memory_row's refined for the shortest length L_min:
/// on a step [X_i, X_i + hx] the midpoint, the kinks' grading (B4) and the points 8 L_min 2^k
/// (k >= 0) under hx/2; on the tail (B5) the points s - X_m = delta 2^k from delta =
/// min(L_min, R0)/2, R0 = max(hx, X_m) <= R, up to L_max u_max. A panel [A, 2A] from the weight's
/// origin integrates e^(-s/L) by 16 points to below 1e-29 of the whole integral for every L:
/// A <= 8 L is memory_row's criterion (panels at most 8 L long), and beyond it the weight has
/// fallen by e^(-A/L) faster than the rule's error grows. Every panel is one of memory_row's or
/// inside one, so K_e is as well resolved; the step integrals run to X_i + hx for every length
/// (memory_row stops at L u_max, the weight beyond being under eps/400). The rows agree with
/// memory_row's to rounding (tests/bem/memory_rows.test.cpp).
///   - MemoryRows(m, hx, hy, lengths): the shared nodes and every length's weights, lengths > 0;
///   - operator()(y): the rows M_L(X_i, y), X_i = i hx, i = -m .. m (index i + m), one per length
///     in the order given.
template <RealScalar Real, class Quadrature = MemoryPanelRule<Real>>
requires NodalQuadratureRule<Quadrature, Real>
class MemoryRows {
 public:
  /// The shared nodes and every length's weights for offsets i hx, |i| <= m; lengths > 0.
  MemoryRows(int m, Real hx, Real hy, std::vector<Real> lengths)
      : m_(m), hx_(hx), hy_(hy), lengths_(std::move(lengths)) {
    using std::exp;
    using std::log;
    Real lmin = std::numeric_limits<Real>::infinity(), lmax = 0;
    for (const Real L : lengths_) {
      lmin = std::min(lmin, L);
      lmax = std::max(lmax, L);
      decay_.push_back(exp(-hx / L));
    }
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real u_max = -log(eps) + 6;  // as memory_row
    // (B4): the step's panels, relative to X_i.
    std::vector<Real> step{Real(0), hx / 2, hx};
    for (Real a = 8 * lmin; a < hx / 2; a *= 2) step.push_back(a);
    step_ = panels(std::move(step));
    // (B5): the tail's panels, relative to X_m; 2a stays finite.
    const Real r0 = std::max(hx, Real(m) * hx), big = std::numeric_limits<Real>::max() / 4;
    std::vector<Real> tail{Real(0)};
    for (Real a = std::min(lmin, r0) / 2;; a *= 2) {
      tail.push_back(a);
      if (!(a < u_max * lmax) || a > big) break;
    }
    tail_ = panels(std::move(tail));
    step_weight_ = weights(step_);
    tail_weight_ = weights(tail_);
    grading_ = 8 * lmin;
  }

  /// The rows M_L(X_i, y), i = -m .. m (index i + m), one per length in the order given.
  std::vector<std::vector<Real>> operator()(Real y) const {
    using std::abs;
    using std::ceil;
    using std::log;
    const std::size_t nt = lengths_.size(), width = static_cast<std::size_t>(2 * m_ + 1);
    std::vector<std::vector<Real>> out(nt, std::vector<Real>(width));
    const Real hx = hx_, hy = hy_;
    const auto ke = [&](Real s) { return rectangle_influence(s, y, hx, hy); };
    const int depth = kink_grading_depth(y, hx, hy);  // as memory_row
    std::vector<Real> values(std::max(step_.node.size(), tail_.node.size())), sums(nt);
    // sums[t] = sum over the nodes of weight[t][q] K_e(origin + node[q]).
    const auto combine = [&](const Panels& p, const std::vector<Real>& weight, Real origin) {
      const std::size_t nn = p.node.size();
      for (std::size_t q = 0; q < nn; ++q) values[q] = ke(origin + p.node[q]);
      for (std::size_t t = 0; t < nt; ++t) {
        const Real* w = weight.data() + t * nn;
        Real s = 0;
        for (std::size_t q = 0; q < nn; ++q) s += w[q] * values[q];
        sums[t] = s;
      }
    };
    const Real x_max = Real(m_) * hx;
    combine(tail_, tail_weight_, x_max);
    for (std::size_t t = 0; t < nt; ++t) out[t][width - 1] = sums[t];
    for (int i = m_ - 1; i >= -m_; --i) {
      const Real x0 = Real(i) * hx, x1 = x0 + hx;
      bool kinked = false;
      for (const Real e : {-hx / 2, hx / 2}) kinked = kinked || (depth > 0 && e > x0 && e < x1);
      if (kinked)
        kinked_step(x0, x1, depth, ke, sums);
      else
        combine(step_, step_weight_, x0);
      const std::size_t k = static_cast<std::size_t>(i + m_);
      for (std::size_t t = 0; t < nt; ++t) out[t][k] = decay_[t] * out[t][k + 1] + sums[t];
    }
    return out;
  }

 private:
  /// Gauss nodes (offsets from the panels' origin) and weights (the rule's times the half width).
  struct Panels {
    std::vector<Real> node, weight;
  };

  static Panels panels(std::vector<Real> points) {
    std::sort(points.begin(), points.end());
    const auto& gx = Quadrature::nodes();
    const auto& gw = Quadrature::weights();
    Panels p;
    for (std::size_t k = 1; k < points.size(); ++k) {
      if (!(points[k] > points[k - 1])) continue;
      const Real half = (points[k] - points[k - 1]) / 2, mid = (points[k] + points[k - 1]) / 2;
      for (std::size_t q = 0; q < static_cast<std::size_t>(Quadrature::points); ++q) {
        p.node.push_back(mid + half * Real(gx[q]));
        p.weight.push_back(Real(gw[q]) * half);
      }
    }
    return p;
  }

  /// Every length's weights of the nodes, length-major: w_q e^(-s_q/L)/L (0 where it underflows).
  std::vector<Real> weights(const Panels& p) const {
    using std::exp;
    std::vector<Real> w;
    w.reserve(lengths_.size() * p.node.size());
    for (const Real L : lengths_)
      for (std::size_t q = 0; q < p.node.size(); ++q)
        w.push_back(p.weight[q] * (exp(-p.node[q] / L) / L));
    return w;
  }

  /// A step containing a kink e = +-hx/2 (B4): memory_row's breakpoints there (e +- (hx/2)
  /// 2^(-k), k = 1 .. depth, in the caller's coordinates as memory_row places them) with the
  /// shared ones, every length's weight evaluated at the nodes.
  template <class Ke>
  void kinked_step(Real x0, Real x1, int depth, const Ke& ke, std::vector<Real>& sums) const {
    using std::exp;
    const Real hx = hx_;
    std::vector<Real> points{x0, x1, x0 + hx / 2};
    for (Real a = grading_; a < hx / 2; a *= 2) points.push_back(x0 + a);
    for (const Real e : {-hx / 2, hx / 2}) {
      if (!(e > x0 && e < x1)) continue;
      for (int k = 1; k <= depth; ++k) {
        const Real off = (hx / 2) * std::ldexp(Real(1), -k);
        for (const Real p : {e - off, e + off})
          if (p > x0 && p < x1) points.push_back(p);
      }
    }
    std::sort(points.begin(), points.end());
    const auto& gx = Quadrature::nodes();
    const auto& gw = Quadrature::weights();
    std::fill(sums.begin(), sums.end(), Real(0));
    for (std::size_t k = 1; k < points.size(); ++k) {
      if (!(points[k] > points[k - 1])) continue;
      const Real half = (points[k] - points[k - 1]) / 2, mid = (points[k] + points[k - 1]) / 2;
      for (std::size_t q = 0; q < static_cast<std::size_t>(Quadrature::points); ++q) {
        const Real x = mid + half * Real(gx[q]);
        const Real v = Real(gw[q]) * half * ke(x);
        for (std::size_t t = 0; t < lengths_.size(); ++t) {
          const Real L = lengths_[t];
          sums[t] += v * (exp(-(x - x0) / L) / L);
        }
      }
    }
  }

  int m_;
  Real hx_, hy_;
  std::vector<Real> lengths_, decay_;
  Panels step_, tail_;
  std::vector<Real> step_weight_, tail_weight_;
  Real grading_ = 0;
};

}  // namespace bem
}  // namespace viscoroll
