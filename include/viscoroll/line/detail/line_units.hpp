// viscoroll: the units in which the line solver works (docs/theory.md, "Scaling"), and the
// conversion of a solution back to the caller's.
//
// c1 and c2 are held in a unit of curvature 2^curvature in which c1 lies in [1, 2), lengths in a
// unit 2^length near the long-term a0, d in 2^(curvature + 2 length). Powers of two: every product
// and quotient rounds as in the caller's units wherever those neither overflow nor underflow.
#pragma once

#include <string_view>
#include <utility>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/line_shape.hpp>

namespace viscoroll::detail {

/// The line solver's units: curvatures c1, c2 in 2^curvature, lengths in 2^length.
template <RealScalar Real>
struct LineUnits {
  Real c1, c2;
  int curvature, length;

  /// A profile's units: c1's power of two, a length a power of two near the long-term a(0)
  /// (a0_caller, in the caller's units).
  static LineUnits profile(Real c1_caller, Real a0_caller) {
    const auto k1 = detail::binary<Real>(c1_caller);
    return LineUnits{k1.m, Real(0), k1.e, detail::binary<Real>(a0_caller).e};
  }

  /// A shape's lengths (a_ref, l and the centre) from the caller's units into these.
  LineShape<Real> shape_in_units(LineShape<Real> shape) const {
    return scaled(std::move(shape), -length);
  }
  /// A shape's lengths from these units into the caller's (for the messages of the warnings).
  LineShape<Real> shape_in_caller_units(LineShape<Real> shape) const {
    return scaled(std::move(shape), length);
  }
  /// A penetration from the caller's units into these.
  Real penetration_in_units(Real d) const {
    return detail::times_power_of_two(d, -(curvature + 2 * length));
  }

 private:
  static LineShape<Real> scaled(LineShape<Real> shape, int exponent) {
    shape.a_ref = detail::times_power_of_two(shape.a_ref, exponent);
    shape.l = detail::times_power_of_two(shape.l, exponent);
    shape.centre = detail::times_power_of_two(shape.centre, exponent);
    return shape;
  }
};

/// A line solution (LineSolution, any material) from the units u into the caller's,
/// with c1 the caller's: a converged one's numbers each normal and finite (b, the centre and chi
/// may be zero), else an error naming the inputs (detail::representable, docs/errors.md); a
/// non-converged one scaled back as it is.
template <RealScalar Real, class Solution, class Inputs>
Solution in_caller_units(Solution sol, const LineUnits<Real>& u, Real c1, const Inputs& inputs) {
  const int length = u.length, curvature = u.curvature;
  const auto in = [&](Real x, int exponent, std::string_view what, bool zero_allowed) {
    if (!sol.converged) return detail::times_power_of_two(x, exponent);
    return representable(x, exponent, what, inputs, zero_allowed);
  };
  const Real centre = sol.shape.centre;  // 0 for a symmetric contact
  const Real a_origin = sol.shape.a(centre), b_origin = sol.shape.b(centre);
  in(a_origin, length, "the half width a(0)", false);
  in(b_origin, length, "the offset b(0)", true);
  sol.shape.a_ref = in(sol.shape.a_ref, length, "the unit a_ref of a(y), b(y)", false);
  sol.shape.l = in(sol.shape.l, length, "the half length l", false);
  sol.shape.centre = in(centre, length, "the contact's centre c", true);
  sol.d = in(sol.d, curvature + 2 * length, "the penetration d", false);
  sol.a_long_term = in(sol.a_long_term, length, "the long-term static half width a0", false);
  sol.l_long_term = in(sol.l_long_term, length, "the long-term static half length l0", false);
  sol.d_long_term = in(sol.d_long_term, curvature + 2 * length, "the long-term static d0", false);
  sol.chi = in(sol.chi, curvature + length, "the rolling-friction coefficient chi", true);
  sol.vtau = in(sol.vtau, length, "V tau", true);
  sol.c1 = c1;
  return sol;
}

}  // namespace viscoroll::detail
