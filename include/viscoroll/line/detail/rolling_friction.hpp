// viscoroll: the rolling-friction coefficient of a line solution of one relaxation time (Eq. 54
// strip by strip in the form (P7); docs/theory.md section 4).
#pragma once

#include <cstddef>
#include <limits>
#include <vector>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/line/detail/graded_panels.hpp>
#include <viscoroll/line/line_solution.hpp>
#include <viscoroll/special/bessel_ratio.hpp>

namespace viscoroll::detail {

/// chi = C1 int V n(y) dy / int F0 dy, V n = V (F0 f/(1+f) - Q) = (C1/4) strip_first_moment, of a
/// LineSolution. Over [0, l] for a symmetric contact (the ratio of two integrals over half of
/// it), over both halves of an asymmetric one (nodes at distances from its centre), on graded
/// panels of the Rule (the solver's own, or the 12-point one for integrals exact to rounding).
/// I1/I0 and I2/I0 from the double interpolants (within 2.5 eps) at each node.
template <class Rule, class Real, class Quadrature>
Real line_rolling_friction(const LineSolution<Real, Quadrature>& sol) {
  std::vector<Real> nodes, weights;
  const Real l = sol.shape.l;
  append_graded_nodes<Rule>(nodes, weights, l, l / 2,
                            l * std::numeric_limits<Real>::epsilon() * 16);
  const bool both = sol.shape.asymmetric();
  const std::size_t half = nodes.size();
  Real num = 0, den = 0;
  for (std::size_t k = 0; k < (both ? 2 * half : half); ++k) {
    const std::size_t j = k % half;
    const Real y = both ? Real(sol.shape.centre + (k < half ? nodes[j] : -nodes[j])) : nodes[j];
    const auto s = sol.functions(y);
    if (!(s.a > 0)) continue;
    const Real alpha = plane::strip_alpha(s.a, sol.vtau, sol.f);
    const Real vn = sol.c1 / 4 *
                    plane::strip_first_moment(s.a, s.b, s.g, sol.vtau, sol.f,
                                              special::bessel_i1_over_i0_fast(alpha),
                                              special::bessel_i2_over_i0_fast(alpha));
    num += weights[j] * vn;
    den += weights[j] * s.f0;
  }
  return sol.c1 * num / den;
}

}  // namespace viscoroll::detail
