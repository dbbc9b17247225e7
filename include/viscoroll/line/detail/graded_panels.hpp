// viscoroll: composite quadrature on [0, L] graded geometrically toward 0.
//
// Internals of viscoroll/line/line_operators.hpp and line_residual.hpp (docs/line-operators.md),
// as an integral or as a node set. An integrand with a
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
#include <vector>

namespace viscoroll::detail {

/// Calls panel(lo, hi) for the panels [0, first], then doubling, but never ending a panel closer
/// to `length` than the panel is wide while more than `finest` remains (a singularity just beyond
/// the end would otherwise sit within a fraction of a half-width of the panel): the halving toward
/// `length` stops at width `finest`. Requires 0 < first <= length.
template <class Real, class Panel>
void for_each_graded_panel(Real length, Real first, Real finest, const Panel& panel) {
  Real h = first;
  panel(Real(0), h);  // smallest panels first
  while (h < length) {
    Real next = std::min(Real(2 * h), length);
    if (length - h > finest) next = std::min(next, Real(h + (length - h) / 2));
    panel(h, next);
    h = next;
  }
}

/// Integral of g over [0, length] on panels doubling from `levels` halvings below
/// top = min(scale, length), then halving toward length down to width length / 2^end_levels.
/// levels = 0 puts one panel on [0, top].
template <class Quadrature, class Real, class G>
Real graded_integral(const G& g, Real length, Real scale, int levels, int end_levels = 0) {
  if (!(length > 0)) return Real(0);
  const Real top = std::min(scale, length);
  Real lo = top;
  for (int k = 0; k < levels; ++k) lo /= 2;
  Real finest_end = length;  // end_levels = 0: no halving toward the end
  for (int k = 0; k < end_levels; ++k) finest_end /= 2;
  Real sum = 0;
  for_each_graded_panel(length, lo, finest_end,
                        [&](Real a, Real b) { sum += Quadrature::integrate(g, a, b); });
  return sum;
}

/// The nodes and weights of the composite rule on [0, length] with panels from `first` and
/// halving toward `length` down to width `finest` (the end grading starts with the first panel);
/// appends (node, weight) pairs. Quadrature: a NodalQuadratureRule.
template <class Quadrature, class Real>
void append_graded_nodes(std::vector<Real>& s, std::vector<Real>& w, Real length, Real first,
                         Real finest) {
  if (!(length > 0)) return;
  const auto& x = Quadrature::nodes();
  const auto& wt = Quadrature::weights();
  Real h = std::min(first, length);
  if (length > finest) h = std::min(h, Real(length / 2));
  for_each_graded_panel(length, h, finest, [&](Real lo, Real hi) {
    const Real half = (hi - lo) / 2, mid = (lo + hi) / 2;
    for (int j = 0; j < Quadrature::points; ++j) {
      s.push_back(mid + half * Real(x[j]));
      w.push_back(half * Real(wt[j]));
    }
  });
}

}  // namespace viscoroll::detail
