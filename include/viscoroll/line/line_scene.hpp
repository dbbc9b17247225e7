// viscoroll: the scene of the paper's 3-D solver (line_solver.hpp): an ellipsoidal roller, its
// curvatures, load and speed (Panek & Kalker (1980), Eq. 27), and the range of curvatures in which
// the line theory has a contact (static_line_contact.hpp).
#pragma once

#include <cmath>
#include <string>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/required_field.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll {

/// Largest curvature ratio C2/C1 for which the static line-contact equations have a solution:
/// max over rho of (ln 4 rho - 1)/rho^2, at rho = e^(3/2)/4, equal to 8 e^-3.
template <RealScalar Real>
Real max_line_contact_curvature_ratio() {
  using std::exp;
  return 8 * exp(Real(-3));
}

/// An ellipsoidal (doubly parabolic, Eq. 27) roller of curvatures c1 (across) and c2 (along the
/// axis) under total load `load`, rolling towards +x at `speed`.
template <RealScalar Real>
struct LineScene {
  /// C1, the curvature across the roller (1/R), > 0.
  Real c1 = detail::required_field<Real>();
  /// C2, the curvature along its axis: 0 < C2 < 8 e^-3 C1.
  Real c2 = detail::required_field<Real>();
  /// P, the total load, > 0.
  Real load = detail::required_field<Real>();
  /// V, the rolling speed, >= 0 (0: the static contact).
  Real speed = detail::required_field<Real>();

  /// Throws std::invalid_argument naming the parameter unless c1 > 0, 0 < c2 < 8 e^-3 c1 (the
  /// contact is longer in y than in x), load > 0, speed >= 0, all finite.
  void validate() const {
    detail::require_positive("c1", c1);
    detail::require_positive("c2", c2);
    detail::require_positive("load", load);
    detail::require_non_negative("speed", speed);
    detail::require(c2 < max_line_contact_curvature_ratio<Real>() * c1, "c2", c2,
                    "0 < c2 < 8 e^-3 c1 = 0.398 c1 (a contact longer in y than in x)");
  }
  /// "c1 = ..., c2 = ..., load = ..., speed = ...": the scene in an error's message.
  std::string describe() const {
    return "c1 = " + detail::format_value(c1) + ", c2 = " + detail::format_value(c2) +
           ", load = " + detail::format_value(load) + ", speed = " + detail::format_value(speed);
  }
};

}  // namespace viscoroll
