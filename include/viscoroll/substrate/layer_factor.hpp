// viscoroll: the surface response of an elastic layer on a rigid base, relative to the half
// space's (docs/theory.md section 19, (H1)-(H5)).
//
// A layer of thickness h, shear modulus mu and Poisson's ratio nu, its surface loaded by a
// pressure p cos(q x), deflects by
//   w = (1 - nu)/(mu |q|) T(|q| h) p,                                                     (H1)
// the half space's response times a factor T of the geometry alone: with nu constant in time the
// viscoelastic memory of Eq. (2) and the layer separate. Bonded to the base (H2),
//   T(x) = [(3 - 4 nu) sinh 2x - 2x] / [(3 - 4 nu) cosh 2x + 2x^2 + 5 - 12 nu + 8 nu^2];
// lying on it without friction (H3), whatever nu,
//   T(x) = (cosh 2x - 1) / (sinh 2x + 2x).
// T rises from 0 at x = 0 to 1 as x -> inf (1 - T = O(x e^-2x)). A thin layer (x -> 0), (H4):
// bonded and compressible T ~ (1 - 2 nu) x / (2 (1 - nu)^2) (the constrained modulus,
// w = h p/(lambda + 2 mu)); bonded and incompressible T ~ (2/3) x^3 (w = q^2 h^3 p/(3 mu));
// frictionless T ~ x/2 (w = (1 - nu^2) h p / E, a spring bed).
#pragma once

#include <cmath>
#include <limits>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll {

/// How a layer meets its rigid base.
enum class LayerBase {
  bonded,        ///< no displacement at the base (H2)
  frictionless,  ///< no normal displacement and no shear stress at the base (H3)
};

/// T(x) of (H1): the layer's surface compliance over the half space's at x = |q| h >= 0 (+inf:
/// 1), for Poisson's ratio -1 < nu <= 0.5 (used by the bonded base only). Evaluated without
/// cancellation or overflow at every x: sinh 2x - 2x by its series below x = 1, and above it
/// numerator and denominator times 2 e^-2x ((H5), docs/theory.md). Throws std::invalid_argument
/// naming x or nu outside their ranges.
template <RealScalar Real>
Real layer_factor(Real x, Real nu, LayerBase base) {
  using std::cosh;
  using std::exp;
  using std::expm1;
  using std::isinf;
  using std::sinh;
  detail::require(!(x < 0) && !std::isnan(static_cast<double>(x)), "x", x, "x = |q| h >= 0");
  detail::require_poisson_ratio(nu);
  if (isinf(x)) return Real(1);
  if (x == 0) return Real(0);  // no layer
  if (base == LayerBase::frictionless) {
    // (H3) times 2 e^-2x: (1 - e^-2x)^2 / (1 - e^-4x + 4x e^-2x), every term positive.
    const Real a = -expm1(-2 * x), e2 = exp(-2 * x);
    return a * a / (-expm1(-4 * x) + 4 * x * e2);
  }
  const Real k = 3 - 4 * nu;                 // >= 1
  const Real c = 5 - 12 * nu + 8 * nu * nu;  // >= 1 on (-1, 0.5]
  if (x < 1) {
    // N = (4 - 8 nu) x + k (sinh 2x - 2x): both terms >= 0, the second by its series
    // sum_{j>=1} (2x)^(2j+1)/(2j+1)!, to the scalar's epsilon.
    const Real y = 2 * x, y2 = y * y;
    Real term = y * y2 / 6, series = 0;
    for (int j = 1; j < 64 && term > std::numeric_limits<Real>::epsilon() * series; ++j) {
      series += term;
      term *= y2 / Real((2 * j + 2) * (2 * j + 3));
    }
    return ((4 - 8 * nu) * x + k * series) / (k * cosh(y) + 2 * x * x + c);
  }
  // (H2) times 2 e^-2x: [k (1 - e^-4x) - 4x e^-2x] / [k (1 + e^-4x) + (4x^2 + 2c) e^-2x]; at
  // x >= 1 the numerator's first term is at least 0.98 k and its second at most 0.55.
  const Real e2 = exp(-2 * x), e4 = e2 * e2;
  return (k * -expm1(-4 * x) - 4 * x * e2) / (k * (1 + e4) + (4 * x * x + 2 * c) * e2);
}

}  // namespace viscoroll
