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
  // Grading depth towards the kinks s = +-hx/2 (B4): the row Y = 0 carries a u ln|u| kink; a row
  // |Y| > hy/2 is analytic within |Y| - hy/2 of the kink, which matters only when that is < hx.
  int depth = 0;
  if (abs(y) < hy / 2) {
    depth = std::numeric_limits<Real>::digits;
  } else {
    const Real gap = abs(y) - hy / 2;
    if (gap < hx)
      depth = static_cast<int>(std::ceil(static_cast<double>(log(hx / gap) / log(Real(2))))) + 2;
  }
  const auto& gx = Quadrature::nodes();
  const auto& gw = Quadrature::weights();
  const auto panel = [&](Real a, Real b, Real origin) {
    const Real half = (b - a) / 2, mid = (a + b) / 2;
    Real s = 0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(Quadrature::points); ++k) {
      const Real x = mid + half * Real(gx[k]);
      s += Real(gw[k]) * exp(-(x - origin) / L) * ke(x);
    }
    return s * half / L;
  };
  std::vector<Real> points;
  // (1/L) int_{x0}^{x0 + hx} e^(-(s - x0)/L) K_e(s, y) ds on graded panels.
  const auto step_integral = [&](Real x0) {
    points.clear();
    const Real x1 = x0 + hx;
    const Real end = std::min(x1, x0 + L * u_max);
    points.push_back(x0);
    points.push_back(end);
    points.push_back(std::min(x0 + hx / 2, end));
    for (const Real e : {-hx / 2, hx / 2}) {
      if (!(e > x0 && e < x1)) continue;
      for (int k = 1; k <= depth; ++k) {
        const Real off = (hx / 2) * std::ldexp(Real(1), -k);
        for (const Real p : {e - off, e + off})
          if (p > x0 && p < end) points.push_back(p);
      }
    }
    // The exponential weight on panels at most 8 L wide.
    for (Real u = 8; u < u_max && x0 + L * u < end; u += 8) points.push_back(x0 + L * u);
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
      tail += panel(x_max + L * t0, x_max + L * t, x_max);
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

}  // namespace bem
}  // namespace viscoroll
