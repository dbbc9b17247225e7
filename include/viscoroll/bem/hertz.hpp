// viscoroll: exact Hertz contact of a doubly parabolic indenter on an elastic half space, the
// reference of the boundary-element solver at V tau = 0 (long-term compliance) and V tau -> inf
// (instantaneous compliance). docs/bem.md, section B8.
//
// A gap h = C1 x^2/2 + C2 y^2/2 pressed by total load P on a half space of compliance c (the
// factor of Eq. 3) touches on the ellipse x^2/a^2 + y^2/b^2 <= 1 with
//   p = p0 sqrt(1 - x^2/a^2 - y^2/b^2),  P = (2/3) pi a b p0,
// and, with w the ellipsoidal coordinate of Ferrers' potential,
//   c int int p/r = (c pi p0 a b / 2) int_0^inf (1 - x^2/(a^2+w) - y^2/(b^2+w)) dw / Delta(w),
//   Delta(w) = sqrt(w (a^2+w) (b^2+w)).                                                 (B8a)
// For a <= b, e^2 = 1 - a^2/b^2 and the complete elliptic integrals K(e), E(e):
//   I0 = int dw/Delta = 2 K / b,  Ia = int dw/((a^2+w) Delta) = 2 (E - k'^2 K) / (a^2 b e^2),
//   Ib = int dw/((b^2+w) Delta) = 2 (K - E) / (b^3 e^2),  k'^2 = 1 - e^2 = a^2/b^2,       (B8b)
// and matching S = d - h inside the ellipse gives C1 = c pi p0 a b Ia, C2 = c pi p0 a b Ib,
// d = c pi p0 a b I0 / 2. So C2/C1 = k'^2 (K - E)/(E - k'^2 K) fixes e, then
//   a^3 = 3 c P k' (E - k'^2 K) / (C1 e^2),  d = 3 c P K / (2 b).                         (B8c)
#pragma once

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll::bem {

/// Hertz's elliptical contact: semi-axes along x and y, penetration and peak pressure.
template <RealScalar Real>
struct HertzContact {
  Real a;   ///< semi-axis along x
  Real b;   ///< semi-axis along y
  Real d;   ///< penetration (approach)
  Real p0;  ///< central pressure, 3 P / (2 pi a b)

  /// p(x, y) = p0 sqrt(1 - x^2/a^2 - y^2/b^2) inside the ellipse, 0 outside.
  Real pressure(Real x, Real y) const {
    using std::sqrt;
    const Real s = 1 - (x / a) * (x / a) - (y / b) * (y / b);
    return s > 0 ? p0 * sqrt(s) : Real(0);
  }
};

/// (B8c): C2/C1 as a function of the eccentricity e of the contact (semi-axis along the larger
/// curvature's direction the shorter), decreasing from 1 at e = 0 to 0 as e -> 1.
template <RealScalar Real>
Real hertz_curvature_ratio(Real e) {
  using boost::math::ellint_1;
  using boost::math::ellint_2;
  if (e == 0) return Real(1);
  const Real k = ellint_1(e), E = ellint_2(e);
  const Real kp2 = 1 - e * e;  // (a/b)^2
  return kp2 * (k - E) / (E - kp2 * k);
}

/// Exact Hertz contact for curvatures c1, c2 > 0 (gap c1 x^2/2 + c2 y^2/2) under load P > 0 on a
/// half space of compliance c = (1 - nu)/(2 pi mu) > 0 (the factor of Eq. 3). Throws
/// std::invalid_argument naming the parameter; supports 1e-10 <= c2/c1 <= 1e10.
template <RealScalar Real>
HertzContact<Real> hertz_contact(Real c1, Real c2, Real compliance, Real load) {
  using boost::math::ellint_1;
  using boost::math::ellint_2;
  using std::cbrt;
  using std::sqrt;
  detail::require_positive("c1", c1);
  detail::require_positive("c2", c2);
  detail::require_positive("compliance", compliance);
  detail::require_positive("load", load);
  if constexpr (std::numeric_limits<Real>::digits < std::numeric_limits<double>::digits) {
    // float: near the bracket's end k' = 1e-6, e = sqrt((1 - k')(1 + k')) rounds to 1 and K(e)
    // overflows (boost::math::overflow_error, measured for l/a >= 200); solve in double, round
    // once.
    const auto h = hertz_contact<double>(double(c1), double(c2), double(compliance), double(load));
    return {Real(h.a), Real(h.b), Real(h.d), Real(h.p0)};
  }
  const Real compliance_load = compliance * load;
  const bool swap = c2 > c1;  // the short semi-axis lies along the larger curvature
  const Real big = swap ? c2 : c1, ratio = swap ? c1 / c2 : c2 / c1;
  detail::require(ratio >= Real(1e-10), "c2/c1", c2 / c1, "1e-10 <= c2/c1 <= 1e10");
  const Real pi = boost::math::constants::pi<Real>();
  Real a, b, d;
  if (ratio == 1) {
    // Circle: a^3 = 3 pi c P / (4 C1), d = pi^2 c p0 a / 2 with p0 = 3 P/(2 pi a^2).
    a = cbrt(3 * pi * compliance_load / (4 * big));
    b = a;
    d = 3 * pi * compliance_load / (4 * a);
  } else {
    // Root of hertz_curvature_ratio(e) = ratio in the variable k' = a/b = sqrt(1 - e^2), bracketed
    // on log scale (ratio ~ k'^2 ln(4/k') as k' -> 0).
    const auto g = [&](Real kp) {
      const Real e = sqrt((1 - kp) * (1 + kp));
      return hertz_curvature_ratio(e) - ratio;
    };
    Real lo = Real(1e-6), hi = Real(1) - 16 * std::numeric_limits<Real>::epsilon();
    std::uintmax_t iterations = 300;
    const auto bracket = boost::math::tools::toms748_solve(
        g, lo, hi, boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 3),
        iterations);
    const Real kp = (bracket.first + bracket.second) / 2;
    const Real e2 = (1 - kp) * (1 + kp), e = sqrt(e2);
    const Real k = ellint_1(e), E = ellint_2(e);
    a = cbrt(3 * compliance_load * kp * (E - kp * kp * k) / (big * e2));
    b = a / kp;
    d = 3 * compliance_load * k / (2 * b);
  }
  HertzContact<Real> h{a, b, d, 3 * load / (2 * pi * a * b)};
  if (swap) std::swap(h.a, h.b);
  return h;
}

}  // namespace viscoroll::bem
