// viscoroll: the rolling line contact of any roller profile, the pieces LineSolver uses.
//
// Panek & Kalker (1980), (34) with the roller's drop h(y) in place of C2 y^2/2 (docs/theory.md
// section 16, (RP1)): the memory of the solid acts along x only, so the strip equations, the
// leading-edge condition (L6) and the load (47) do not see h; (34) takes h(y), and its Jacobian
// in ln l takes h'(y) (y - c) (nodes fixed in t = (y - c)/l). A symmetric profile keeps the line
// solver's even representation (line_shape.hpp) on [-l, l]; an asymmetric one (a tilt) adds the odd
// parts and the centre c ((RP6), (RP7)). The cold start is (RP8): the static contact of the
// profile (static_profile_contact.hpp) at the compliance load (1 + f) c P (a/a0)^2 of the plane
// solution at the same V tau/a0, whose lengths scale as (a/a0)^(2/3) as (48)'s do.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/required_field.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/line_shape.hpp>
#include <viscoroll/line/static_profile_contact.hpp>
#include <viscoroll/roller/profile.hpp>

namespace viscoroll {

/// A roller of any profile (roller/profile.hpp) under a load, rolling at a speed: the scene of
/// LineSolver::solve for a profile.
template <RollerProfile Profile>
struct LineProfileScene {
  /// The profile's scalar.
  using Real = typename Profile::real_type;
  /// The roller's profile.
  Profile roller;
  /// P, the total load, > 0.
  Real load = detail::required_field<Real>();
  /// V, the rolling speed, >= 0.
  Real speed = detail::required_field<Real>();

  /// Throws std::invalid_argument naming the parameter unless load > 0 and speed >= 0 (finite).
  void validate() const {
    detail::require_positive("load", load);
    detail::require_non_negative("speed", speed);
  }
  /// "c1 = ... (a roller profile), load = ..., speed = ...": the scene in an error's message.
  std::string describe() const {
    return "c1 = " + detail::format_value(roller.c1()) +
           " (a roller profile), load = " + detail::format_value(load) +
           ", speed = " + detail::format_value(speed);
  }
};

namespace line {

/// The RollerDrop of a profile in the line solver's units: lengths in 2^length, curvatures in
/// 2^curvature, so that h_u(y) = h(2^length y) 2^-(curvature + 2 length) and h_u'(y) =
/// h'(2^length y) 2^-(curvature + length), exact (powers of two).
template <RollerProfile Profile>
class ProfileDrop {
 public:
  /// The profile's scalar.
  using Real = typename Profile::real_type;
  /// The profile, with the solver's units 2^length (lengths) and 2^curvature (curvatures).
  ProfileDrop(Profile profile, int length, int curvature)
      : profile_(std::move(profile)), length_(length), curvature_(curvature) {}
  /// h_u(y) = h(2^length y) 2^-(curvature + 2 length).
  template <class Problem>
  Real drop(const Problem&, Real y) const {
    return detail::times_power_of_two(profile_.drop(detail::times_power_of_two(y, length_)),
                                      -(curvature_ + 2 * length_));
  }
  /// h_u'(y) = h'(2^length y) 2^-(curvature + length).
  template <class Problem>
  Real drop_slope(const Problem&, Real y) const {
    return detail::times_power_of_two(profile_.drop_slope(detail::times_power_of_two(y, length_)),
                                      -(curvature_ + length_));
  }

 private:
  Profile profile_;
  int length_, curvature_;
};

/// A static profile contact (G3) as the line solver's shape (line_shape.hpp, t_squared) with
/// unit a_ref, n coefficients of ln a and b = b_over a_ref: ln(a/(a_ref sqrt(1 - t^2))) =
/// ln(a_ref_s/a_ref) + ln(omega_e(t)/(1 - t^2))/2 + sum alpha_k T_k(t) interpolated in u =
/// 2t^2 - 1 at the zeros of T_n: its even part, and for `asymmetric` also its odd part
/// (series(t) - series(-t))/(2t) (omega_e is even) and the centre c. In the contact's own units
/// (a_ref and s's lengths alike).
template <RealScalar Real>
LineShape<Real> profile_line_shape(const StaticProfileContact<Real>& s, Real a_ref, int n,
                                   Real b_over, bool asymmetric = false) {
  using std::log;
  using std::sqrt;
  const Real ratio = log(s.a_ref / a_ref);
  const auto g = [&](Real w) {
    const Real t = sqrt(1 - w);
    const Real series = asymmetric ? (s.series(t) + s.series(-t)) / 2 : s.series(t);
    return ratio + log(s.weight(t) / w) / 2 + series;
  };
  LineShape<Real> shape{a_ref,
                        s.half_length(),
                        LineShape<Real>::interpolate(LineBasis::t_squared, Real(0), n, g),
                        {b_over}};
  if (asymmetric) {
    const auto odd = [&](Real w) {
      const Real t = sqrt(1 - w);
      return (s.series(t) - s.series(-t)) / (2 * t);
    };
    shape.alpha_odd = LineShape<Real>::interpolate(LineBasis::t_squared, Real(0), n, odd);
    shape.beta_odd = {Real(0)};
    shape.centre = s.centre();
  }
  return shape;
}

}  // namespace line

}  // namespace viscoroll
