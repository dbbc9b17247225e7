// viscoroll: composite quadrature on [0, L], graded toward its singular ends.
//
// Internals of viscoroll/line/line_operators.hpp, line_residual.hpp, line_solver.hpp and
// paper_leading_edge.hpp (docs/line-operators.md, docs/theory.md section 7), as an integral or as
// a node set.
//
// Geometric grading (graded_integral, append_scaled_nodes, append_graded_nodes): an integrand
// with a (nearly) singular point at s = 0 of scale h (a pole at s = +-i h, a logarithm, s ln s)
// is integrated on the panels
//   [0, h 2^-K], [h 2^-K, h 2^-K+1], ..., [h/2, h], [h, 2h], [2h, 4h], ...,
// and, once a doubling would end closer to L than the panel's width, on panels halving toward L,
//   [s, (s + L)/2], ..., [L - L 2^-E, L],
// each by the fixed rule of the quadrature policy. The grading toward L is for integrands
// F(y +- s) whose F has a complex singularity near the end y' = +-l of the contact (G of Eq. (36)
// has poles where I0((1 + f) a(y) / V tau) = 0, close to y = +-l when a0 / V tau is large): a
// singularity at distance delta from the end is resolved once L 2^-E <= delta. On a panel [s, 2s]
// a singularity at 0 or at +-i h with h <= s lies at least three half-widths from the panel's
// centre, so an N-point Gauss-Legendre rule converges like (3 + sqrt 8)^(-2N) (Bernstein ellipse
// rho ~ 5.8) there.
//
// Mapped panels (append_log_mapped_nodes, append_logit_mapped_nodes): equal panels in a variable
// in which every singular point lies at a known distance from the real axis, as wide as the rule's
// order and the scalar's epsilon allow (strip_panel_width): the line residual's integrals.
#pragma once

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>
#include <vector>

namespace viscoroll::detail {

/// Appends the nodes and weights of the Quadrature's rule on the panel [lo, hi].
template <class Quadrature, class Real>
void append_panel(std::vector<Real>& s, std::vector<Real>& w, Real lo, Real hi) {
  const auto& x = Quadrature::nodes();
  const auto& wt = Quadrature::weights();
  const Real half = (hi - lo) / 2, mid = (lo + hi) / 2;
  for (int j = 0; j < Quadrature::points; ++j) {
    s.push_back(mid + half * Real(x[j]));
    w.push_back(half * Real(wt[j]));
  }
}

/// Calls node(v, weight) for the Quadrature's nodes v on equal panels of [lo, hi], as few as keep
/// each panel no wider than `width`; weight includes dv.
template <class Quadrature, class Real, class Node>
void for_each_equal_panel_node(Real lo, Real hi, Real width, const Node& node) {
  using std::ceil;
  const auto& x = Quadrature::nodes();
  const auto& wt = Quadrature::weights();
  const int panels = std::max(1, int(ceil((hi - lo) / width)));
  const Real half = (hi - lo) / (2 * panels);
  for (int k = 0; k < panels; ++k) {
    const Real mid = lo + (2 * k + 1) * half;
    for (int j = 0; j < Quadrature::points; ++j) node(mid + half * Real(x[j]), half * Real(wt[j]));
  }
}

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

/// Calls panel(lo, hi) for the panels of [0, length] doubling from `levels` halvings below
/// top = min(scale, length), then halving toward length down to width length / 2^end_levels.
/// levels = 0 puts one panel on [0, top].
template <class Real, class Panel>
void for_each_scaled_panel(Real length, Real scale, int levels, int end_levels,
                           const Panel& panel) {
  if (!(length > 0)) return;
  const Real top = std::min(scale, length);
  Real lo = top;
  for (int k = 0; k < levels; ++k) lo /= 2;
  Real finest_end = length;  // end_levels = 0: no halving toward the end
  for (int k = 0; k < end_levels; ++k) finest_end /= 2;
  for_each_graded_panel(length, lo, finest_end, panel);
}

/// Integral of g over [0, length] on the panels of for_each_scaled_panel.
template <class Quadrature, class Real, class G>
Real graded_integral(const G& g, Real length, Real scale, int levels, int end_levels = 0) {
  Real sum = 0;
  for_each_scaled_panel(length, scale, levels, end_levels,
                        [&](Real a, Real b) { sum += Quadrature::integrate(g, a, b); });
  return sum;
}

/// The nodes and weights of the Quadrature's rule on the panels of for_each_scaled_panel;
/// appends (node, weight) pairs. Quadrature: a NodalQuadratureRule.
template <class Quadrature, class Real>
void append_scaled_nodes(std::vector<Real>& s, std::vector<Real>& w, Real length, Real scale,
                         int levels, int end_levels) {
  for_each_scaled_panel(length, scale, levels, end_levels,
                        [&](Real lo, Real hi) { append_panel<Quadrature>(s, w, lo, hi); });
}

/// The nodes and weights of the composite rule on [0, length] with panels from `first` and
/// halving toward `length` down to width `finest` (the end grading starts with the first panel);
/// appends (node, weight) pairs. Quadrature: a NodalQuadratureRule.
template <class Quadrature, class Real>
void append_graded_nodes(std::vector<Real>& s, std::vector<Real>& w, Real length, Real first,
                         Real finest) {
  if (!(length > 0)) return;
  Real h = std::min(first, length);
  if (length > finest) h = std::min(h, Real(length / 2));
  for_each_graded_panel(length, h, finest,
                        [&](Real lo, Real hi) { append_panel<Quadrature>(s, w, lo, hi); });
}

/// The relative accuracy a node set is built for: `tolerance`, or the scalar's epsilon where
/// tolerance is 0 (the default of every rule below) or below it.
template <class Real>
Real quadrature_tolerance(Real tolerance) {
  return std::max(tolerance, std::numeric_limits<Real>::epsilon());
}

/// The widest panel, in a variable w in which the integrand is analytic in the strip
/// |Im w| < strip, on which the Quadrature's n-point rule (exact to degree 2n - 1, Gauss-Legendre)
/// has the error bound rho^(-2n) <= tol/4096 of the Bernstein ellipse through the worst-placed
/// singularity (at distance `strip` above the panel's centre): with half-width h,
/// rho = d/h + sqrt(1 + (d/h)^2) = exp(asinh(d/h)), so 2 n asinh(strip/h) >= ln(4096/tol) (Davis &
/// Rabinowitz, Methods of Numerical Integration, 4.6; the factor 4096 covers the constant of the
/// bound for a pole on the ellipse, docs/theory.md section 7). tol =
/// quadrature_tolerance(tolerance): the scalar's epsilon by default.
template <class Quadrature, class Real>
Real strip_panel_width(Real strip, Real tolerance = Real(0)) {
  using std::log;
  using std::sinh;
  const Real digits = log(Real(4096) / quadrature_tolerance(tolerance));
  return 2 * strip / sinh(digits / (2 * Quadrature::points));
}

/// The nodes and weights of int_0^length g(t) dt in the variable w = ln(1 + t/c) (t = c (e^w - 1),
/// dt = c e^w dw) on equal panels no wider than strip_panel_width(strip): for an integrand analytic
/// in w in |Im w| < strip, as g(t) = e^-t k(x0 + V t) with k singular only where x0 + V t is
/// imaginary and c = x0/V (strip = pi/2), to the relative accuracy of strip_panel_width's
/// `tolerance`. Appends (node, weight) pairs.
template <class Quadrature, class Real>
void append_log_mapped_nodes(std::vector<Real>& t, std::vector<Real>& w, Real length, Real c,
                             Real strip, Real tolerance = Real(0)) {
  using std::exp;
  using std::expm1;
  using std::log1p;
  if (!(length > 0)) return;
  for_each_equal_panel_node<Quadrature>(Real(0), Real(log1p(length / c)),
                                        strip_panel_width<Quadrature>(strip, tolerance),
                                        [&](Real v, Real weight) {
                                          const Real em1 = expm1(v);  // e^v = 1 + em1
                                          t.push_back(c * em1);
                                          w.push_back(weight * c * (1 + em1));
                                        });
}

/// The nodes and weights of int_0^length g(s) ds for g with singular points near both ends of
/// the interval (on the scale `first` at 0, `last` at length): the panel [0, first] as it is, the
/// panel [length - last, length] in the variable tau = sqrt((length - s)/last), and between them
/// equal panels in the variable w = ln(s / (length - s)) (s = length / (1 + e^-w),
/// ds = s (length - s) / length dw), no wider than max_width. The map puts a singularity at
/// s = +-i h (h > 0) at Re w < 0, pi/2 < |Im w| < pi, and one at s < 0 or s > length at
/// |Im w| = pi; so the panels are strip_panel_width(pi/2) wide for w < 2 and
/// strip_panel_width(pi) beyond, where the points s = +-i h, for every h, keep the rho the width
/// asks for (computed for n = 2 to 64 and epsilon from 1e-4 to 2^-167: at least 1.06 times it;
/// docs/theory.md section 7), to the relative accuracy of strip_panel_width's `tolerance`.
/// Requires 0 < first, 0 < last and first + last < length; appends (node, weight) pairs.
template <class Quadrature, class Real>
void append_logit_mapped_nodes(std::vector<Real>& s, std::vector<Real>& w, Real length, Real first,
                               Real last, Real max_width, Real tolerance = Real(0)) {
  using std::exp;
  using std::log;
  const auto mapped = [&](Real lo, Real hi, Real width) {
    if (!(hi > lo)) return;
    for_each_equal_panel_node<Quadrature>(
        lo, hi, std::min(width, max_width), [&](Real v, Real weight) {
          const Real e = exp(-v);
          const Real node = length / (1 + e);
          s.push_back(node);
          w.push_back(weight * node * e / (1 + e));  // ds/dw = s (length - s) / length
        });
  };
  append_panel<Quadrature>(s, w, Real(0), first);
  const Real lo = log(first / (length - first)), hi = log((length - last) / last);
  const Real pi = boost::math::constants::pi<Real>();
  const Real split = std::min(std::max(lo, Real(2)), hi);
  mapped(lo, split, strip_panel_width<Quadrature>(pi / 2, tolerance));
  mapped(split, hi, strip_panel_width<Quadrature>(pi, tolerance));
  // The last panel in s = length - last tau^2, tau in [0, 1] (ds = 2 last tau dtau): an integrand
  // with a branch point (length - s)^(k/2) at the end (a(y) in the variable sqrt(1 - t^2),
  // line_shape.hpp) is analytic in tau.
  const auto& x = Quadrature::nodes();
  const auto& wt = Quadrature::weights();
  for (int j = 0; j < Quadrature::points; ++j) {
    const Real tau = (1 + Real(x[j])) / 2;
    s.push_back(length - last * tau * tau);
    w.push_back(Real(wt[j]) * last * tau);
  }
}

}  // namespace viscoroll::detail
