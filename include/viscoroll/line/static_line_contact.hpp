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
#pragma once

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll {

/// The static line contact: a(y) = a0 sqrt(1 - y^2/l^2), b = 0, penetration d.
template <RealScalar Real>
struct StaticLineContact {
  Real a0;  ///< half width at y = 0
  Real l;   ///< half length
  Real d;   ///< penetration, (1/2) C1 a0^2 ln(4 l / a0)
};

/// Largest curvature ratio C2/C1 for which the static line-contact equations have a solution:
/// max over rho of (ln 4 rho - 1)/rho^2, at rho = e^(3/2)/4, equal to 8 e^-3.
template <RealScalar Real>
Real max_line_contact_curvature_ratio() {
  using std::exp;
  return 8 * exp(Real(-3));
}

/// Kalker's static line contact for curvatures c1 > 0, 0 < c2 < 8 e^-3 c1, and
/// compliance_load = (1 - nu)/(2 pi mu) * P > 0 (mu the modulus that acts: long-term for a slow
/// scene, instantaneous for a fast one). Throws std::invalid_argument naming the parameter.
template <RealScalar Real>
StaticLineContact<Real> static_line_contact(Real c1, Real c2, Real compliance_load) {
  using std::cbrt;
  using std::exp;
  using std::log;
  detail::require_positive("c1", c1);
  detail::require_positive("c2", c2);
  detail::require_positive("compliance * load", compliance_load);
  const Real ratio = c2 / c1;
  detail::require(ratio < max_line_contact_curvature_ratio<Real>(), "c2/c1", ratio,
                  "0 < c2/c1 < 8 e^-3 = 0.398 (a contact longer in y than in x)");
  // rho = l/a0 on the decreasing branch: h(rho) = (ln 4 rho - 1) - ratio rho^2, h(rho_min) > 0.
  const Real rho_min = exp(Real(1.5)) / 4;
  const auto h = [ratio](Real rho) { return (log(4 * rho) - 1) - ratio * rho * rho; };
  Real hi = 2 * rho_min;
  while (h(hi) > 0) hi *= 2;
  std::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(
      h, rho_min, hi, boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 1),
      iterations);
  const Real rho = (bracket.first + bracket.second) / 2;
  const Real a0 = cbrt(3 * compliance_load / (c1 * rho));  // load (47): C1 a0^2 l / 3
  const Real l = rho * a0;
  return {a0, l, c1 * a0 * a0 * log(4 * rho) / 2};
}

}  // namespace viscoroll
