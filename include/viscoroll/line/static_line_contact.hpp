// viscoroll: Kalker's static line-contact solution of an ellipsoidal indenter (V tau = 0).
//
// Panek & Kalker (1980), Eqs. (33), (34), (47), (48) at V tau = 0 (docs/paper.md, "Checked by
// derivation"): with G = 0 (Eq. 36 at V tau = 0 and b = 0) and F0 = C1 a^2 / 4, Eq. (34) is met
// exactly by
//   a(y) = a0 sqrt(1 - y^2/l^2),  C2/C1 = (a0/l)^2 (ln(4 l/a0) - 1),  d = (1/2) C1 a0^2 ln(4 l/a0),
// and the load (47) is int F0 dy = C1 a0^2 l / 3 = compliance * load. Given C1, C2 and the
// compliance times the load, the aspect rho = l/a0 is the root of (ln 4 rho - 1)/rho^2 = C2/C1 on
// rho > e^(3/2)/4, where the left side decreases from its maximum 8 e^-3 = 0.398; then
// a0^3 rho = 3 compliance load / C1. Used for the static scene, the elastic material and both
// speed limits (with the long-term and the instantaneous compliance), with no Bessel work.
//
// Scaling (docs/theory.md, "Scaling"): rho depends on C2/C1 alone, and a0 is formed in a unit of
// length 2^k near it (static_line_contact_in_units), so that 3 compliance load / C1 may lie beyond
// the range of Real where a0, l and d do not; static_line_contact checks that they are normal
// finite numbers in the caller's units and names the inputs where one is not.
#pragma once

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/line_scene.hpp>

namespace viscoroll {

/// The static line contact: a(y) = a0 sqrt(1 - y^2/l^2), b = 0, penetration d.
template <RealScalar Real>
struct StaticLineContact {
  Real a0;  ///< half width at y = 0
  Real l;   ///< half length
  Real d;   ///< penetration, (1/2) C1 a0^2 ln(4 l / a0)
};

namespace line {

/// The static line contact in units of powers of two: a0 and l in 2^length, d in
/// 2^(curvature + 2 length), for c1 and c2 given in a unit of curvature 2^curvature.
template <RealScalar Real>
struct StaticLineContactInUnits {
  StaticLineContact<Real> contact;  ///< a0, l, d in the units
  int length;                       ///< binary exponent of the unit of length
};

}  // namespace line

namespace detail {

/// rho = l/a0, the root of (ln 4 rho - 1)/rho^2 = ratio on rho > e^(3/2)/4 (Eq. 48 with (34)).
template <RealScalar Real>
Real static_line_aspect(Real ratio) {
  using std::exp;
  using std::log;
  // rho = l/a0 on the decreasing branch: h(rho) = (ln 4 rho - 1) - ratio rho^2, h(rho_min) > 0.
  const Real rho_min = exp(Real(1.5)) / 4;
  const auto h = [ratio](Real rho) { return (log(4 * rho) - 1) - ratio * rho * rho; };
  Real hi = 2 * rho_min;
  while (h(hi) > 0) hi *= 2;
  std::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(
      h, rho_min, hi,
      boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 1), iterations);
  return (bracket.first + bracket.second) / 2;
}

}  // namespace detail

namespace line {

/// Kalker's static line contact for curvatures c1 > 0, 0 < c2 < 8 e^-3 c1 (normal numbers, in a
/// unit of curvature 2^curvature) and compliance_load = (1 - nu)/(2 pi mu) * P = m 2^e in the
/// units of curvature times length cubed (Eq. 47: C1 a0^2 l / 3 = compliance load), unit of
/// length 1. The unit of length of the result is 2^k with a0 2^-k of order one: a0^3 rho =
/// 3 compliance load / C1 is formed as m 2^e, its cube root in the caller's units where m 2^e is a
/// normal number (so that the bits are those of static_line_contact) and with the exponent made
/// a multiple of 3 where it is not. Throws std::invalid_argument naming the parameter.
template <RealScalar Real>
StaticLineContactInUnits<Real> static_line_contact_in_units(Real c1, Real c2,
                                                            detail::Binary<Real> compliance_load,
                                                            int curvature = 0) {
  using std::cbrt;
  using std::log;
  detail::require_positive("c1", c1);
  detail::require_positive("compliance * load", compliance_load.m);
  const Real ratio = c2 / c1;
  detail::require(ratio >= (std::numeric_limits<Real>::min)() &&
                      ratio < max_line_contact_curvature_ratio<Real>(),
                  "c2/c1", ratio,
                  "0 < c2/c1 < 8 e^-3 = 0.398 (a contact longer in y than in x), c2/c1 a normal "
                  "number");
  const Real rho = detail::static_line_aspect(ratio);
  // Load (47): C1 a0^2 l / 3 = compliance load, l = rho a0.
  const Real x = 3 * compliance_load.m / (c1 * rho);
  const int e = compliance_load.e - curvature;
  const Real caller = detail::times_power_of_two(x, e);
  detail::Binary<Real> a0;
  using std::abs;
  if ((boost::math::isfinite)(caller) && abs(caller) >= (std::numeric_limits<Real>::min)()) {
    a0 = detail::binary(cbrt(caller));
  } else {
    const int third = (e >= 0 ? e : e - 2) / 3;  // floor(e / 3)
    a0 = detail::binary(cbrt(detail::times_power_of_two(x, e - 3 * third)));
    a0.e += third;
  }
  const Real a = a0.m;
  return {{a, rho * a, c1 * a * a * log(4 * rho) / 2}, a0.e};
}

}  // namespace line

/// Kalker's static line contact for curvatures c1 > 0, 0 < c2 < 8 e^-3 c1, and
/// compliance_load = (1 - nu)/(2 pi mu) * P > 0 (mu the modulus that acts: long-term for a slow
/// scene, instantaneous for a fast one). Throws std::invalid_argument naming the parameter, or
/// the inputs where a0, l or d is not a normal finite number (docs/errors.md).
template <RealScalar Real>
StaticLineContact<Real> static_line_contact(Real c1, Real c2, Real compliance_load) {
  detail::require_positive("c1", c1);
  detail::require_positive("c2", c2);
  detail::require_positive("compliance * load", compliance_load);
  const detail::Binary<Real> k1 = detail::binary(c1);
  const auto s = line::static_line_contact_in_units(k1.m, detail::times_power_of_two(c2, -k1.e),
                                                    detail::binary(compliance_load), k1.e);
  const auto inputs = [&] {
    return "c1 = " + detail::format_value(c1) + ", c2 = " + detail::format_value(c2) +
           ", compliance * load = " + detail::format_value(compliance_load);
  };
  return {detail::representable(s.contact.a0, s.length, "the static half width a0", inputs, false),
          detail::representable(s.contact.l, s.length, "the static half length l", inputs, false),
          detail::representable(s.contact.d, k1.e + 2 * s.length, "the static penetration d",
                                inputs, false)};
}

}  // namespace viscoroll
