// viscoroll: composite quadrature on [0, L] graded geometrically toward 0.
//
// Internals of viscoroll/line/line_operators.hpp (docs/line-operators.md). An integrand with a
// (nearly) singular point at s = 0 of scale h (a pole at s = +-i h, a logarithm, s ln s) is
// integrated on the panels
//   [0, h 2^-K], [h 2^-K, h 2^-K+1], ..., [h/2, h], [h, 2h], [2h, 4h], ...,
// and, once a doubling would end closer to L than the panel's width, on panels halving toward L,
//   [s, (s + L)/2], ..., [L - L 2^-E, L],
// each by the fixed rule of the quadrature policy. The grading toward L is for integrands
// F(y +- s) whose F has a complex singularity near the end y' = +-l of the contact (G of Eq. (36)
// has poles where I0((1 + f) a(y) / V tau) = 0, close to y = +-l when a0 / V tau is large): a
// singularity at distance delta from the end is resolved once L 2^-E <= delta. On a panel [s, 2s] a singularity at 0 or at
// +-i h with h <= s lies at least three half-widths from the panel's centre, so an N-point
// Gauss-Legendre rule converges like (3 + sqrt 8)^(-2N) (Bernstein ellipse rho ~ 5.8) there.
#pragma once

#include <algorithm>

namespace viscoroll::detail {

/// Integral of g over [0, length] on panels doubling from `levels` halvings below
/// top = min(scale, length), then halving toward length down to width length / 2^end_levels.
/// levels = 0 puts one panel on [0, top].
template <class Quadrature, class Real, class G>
Real graded_integral(const G& g, Real length, Real scale, int levels, int end_levels = 0) {
  if (!(length > 0)) return Real(0);
  const Real top = std::min(scale, length);
  Real lo = top;
  for (int k = 0; k < levels; ++k) lo /= 2;
  Real finest_end = length;
  for (int k = 0; k < end_levels; ++k) finest_end /= 2;
  Real sum = Quadrature::integrate(g, Real(0), lo);  // smallest panels first
  Real h = lo;
  while (h < length) {
    // Double, but never end a panel closer to `length` than the panel is wide (a singularity
    // just beyond the end would then sit within a fraction of a half-width of the panel).
    Real next = std::min(Real(2 * h), length);
    if (end_levels > 0 && length - h > finest_end) next = std::min(next, Real(h + (length - h) / 2));
    sum += Quadrature::integrate(g, h, next);
    h = next;
  }
  return sum;
}

}  // namespace viscoroll::detail
