// viscoroll: whether a result lies inside the assumptions of its model (docs/theory.md, section
// 18, (V1)-(V4), (V3s)). Every method rests on the linear half-space theory of small slopes; the
// line method also on a slender contact; all of them on quasi-static rolling and on a contact
// inside the roller's body. check_validity() reads a result's contact and its scene and returns
// each breach with the quantity, its value, the limit and the likely cause; the front doors print
// them as warnings, or refuse the result with --strict (strict=True in Python).
#pragma once

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll {

/// The kind of a validity check (docs/errors.md, "Validity checks").
enum class ValidityCheck {
  small_slope,    ///< (V1) contact half width against the roller's radius
  roller_length,  ///< (V2) the contact inside the roller's body
  slenderness,    ///< (V3) the line theory's long contact
  quasi_static,   ///< (V4) speed against the rubber's shear-wave speed
};

/// The warning code of a breach of `check` (core/outcome.hpp).
constexpr WarningCode warning_code(ValidityCheck check) {
  switch (check) {
    case ValidityCheck::small_slope:
      return WarningCode::small_slope;
    case ValidityCheck::roller_length:
      return WarningCode::roller_length;
    case ValidityCheck::slenderness:
      return WarningCode::slenderness;
    case ValidityCheck::quasi_static:
      break;
  }
  return WarningCode::quasi_static;
}

/// What check_validity reads: a result's contact and its scene, in any consistent units. NaN or
/// infinite values mean "not given" and skip the checks that need them.
template <RealScalar Real>
struct ValidityInputs {
  /// NaN: "not given".
  static constexpr Real none = std::numeric_limits<Real>::quiet_NaN();
  Real radius = none;  ///< the roller's radius across, 1/C1 (m)
  Real a0 = none;      ///< the contact's half width at y = 0 (m)
  Real l = none;       ///< the contact's half length (m): the line theory's slenderness
  ///@{
  Real y_minus = none, y_plus = none;  ///< the contact's ends along the roller (m)
  ///@}
  ///@{
  Real body_min = none, body_max = none;  ///< the roller body's ends along y (m)
  ///@}
  bool line_theory = false;  ///< the result is the line method's: (V3) applies
  /// The line method's active memory terms (LineSolution::active_terms): two or more
  /// solve by its spectrum path, whose chi needs the longer contact of (V3s).
  int memory_terms = 1;
  Real speed = none;  ///< rolling speed (m/s)
  /// sqrt(mu_glassy / density), the rubber's fastest shear-wave speed (m/s), where a density is
  /// given.
  Real shear_wave_speed = none;
};

/// One breach of a model assumption: which, the quantity's value and limit, and a message that
/// names them with the likely cause.
template <RealScalar Real>
struct ValidityBreach {
  /// The assumption breached.
  ValidityCheck check;
  Real value;  ///< the checked ratio (a0/R, l/a0, V/c_s, or how far the contact passes the end)
  /// The limit that the value passed (a ValidityLimits value).
  Real limit;
  /// The breach in words, with the likely cause.
  std::string message;
};

/// The limits of (V1)-(V4): each where the assumption's own error reaches 1%, the default
/// accuracy of the front doors.
template <RealScalar Real>
struct ValidityLimits {
  /// (V1): the parabolic gap's error in d and chi is below (a0/R)^2/4; 1% at a0/R = 0.2.
  static constexpr Real small_slope = Real(0.2);
  /// (V3): the line theory's static error in d is below 0.13 (a0/l)^2; 1% at l/a0 = 3.6.
  static constexpr Real slenderness = Real(3.6);
  /// (V3s): the line method's chi for two or more memory terms is off by up to 0.91 (a0/l)^2
  /// (measured); 0.63% at l/a0 = 12.
  static constexpr Real spectrum_slenderness = Real(12);
  /// (V4): inertia changes the stresses by about (V/c_s)^2; 1% at V/c_s = 0.1.
  static constexpr Real quasi_static = Real(0.1);
};

/// The breaches of (V1)-(V4) by the result `in` describes (empty: none).
template <RealScalar Real>
std::vector<ValidityBreach<Real>> check_validity(const ValidityInputs<Real>& in) {
  using std::isfinite;
  using L = ValidityLimits<Real>;
  const auto text = [](Real x) { return detail::format_value(x); };
  // Three significant digits for a ratio.
  const auto ratio = [](Real x) {
    std::ostringstream s;
    s.precision(3);
    s << x;
    return s.str();
  };
  std::vector<ValidityBreach<Real>> out;
  // (V1) Small slopes: a0/R.
  if (isfinite(in.radius) && in.radius > 0 && isfinite(in.a0) && in.a0 > 0) {
    const Real r = in.a0 / in.radius;
    if (r > L::small_slope) {
      std::string cause =
          r > 1 ? ": the contact is wider than the roller; is a modulus in MPa or GPa, a load in "
                  "kN, or the radius in mm? (all SI: Pa, N, m)"
                : ": the small-slope half-space theory is off by about (a0/R)^2/4 = " +
                      ratio(100 * r * r / 4) + "% in d and chi";
      out.push_back({ValidityCheck::small_slope, r, L::small_slope,
                     "a0 = " + text(in.a0) + " is " + ratio(r) + " times the roller radius " +
                         text(in.radius) + " (limit a0/R <= " + text(L::small_slope) + ")" +
                         cause});
    }
  }
  // (V2) The contact inside the body.
  if (isfinite(in.y_minus) && isfinite(in.y_plus)) {
    const bool low = isfinite(in.body_min) && in.y_minus < in.body_min;
    const bool high = isfinite(in.body_max) && in.y_plus > in.body_max;
    if (low || high) {
      const Real end = high ? in.body_max : in.body_min, reach = high ? in.y_plus : in.y_minus;
      out.push_back({ValidityCheck::roller_length, reach, end,
                     "the contact reaches y = " + text(reach) +
                         ", beyond the roller's end at y = " + text(end) +
                         ": the load or the compliance is too large for this roller, "
                         "or the body is shorter than meant"});
    }
  }
  // (V3) The line theory's slenderness: l/a0; (V3s) for the line method's spectrum path.
  if (in.line_theory && isfinite(in.l) && isfinite(in.a0) && in.a0 > 0) {
    const Real s = in.l / in.a0;
    if (in.memory_terms >= 2 && s < L::spectrum_slenderness)
      out.push_back({ValidityCheck::slenderness, s, L::spectrum_slenderness,
                     "l/a0 = " + ratio(s) + " is below " + text(L::spectrum_slenderness) +
                         " for a spectrum (" + std::to_string(in.memory_terms) +
                         " active terms): the line method is off by up to 0.91 (a0/l)^2 = " +
                         ratio(Real(91) / (s * s)) + "% in chi; use the bem method"});
    else if (s < L::slenderness)
      out.push_back({ValidityCheck::slenderness, s, L::slenderness,
                     "l/a0 = " + ratio(s) + " is below " + text(L::slenderness) +
                         ": the line theory is off by up to 0.13 (a0/l)^2 = " +
                         ratio(Real(13) / (s * s)) + "% in d; use the bem method"});
  }
  // (V4) Quasi-static rolling: V/c_s.
  if (isfinite(in.speed) && isfinite(in.shear_wave_speed) && in.shear_wave_speed > 0) {
    const Real m = in.speed / in.shear_wave_speed;
    if (m > L::quasi_static)
      out.push_back({ValidityCheck::quasi_static, m, L::quasi_static,
                     "the speed " + text(in.speed) + " is " + ratio(m) +
                         " times the rubber's shear-wave speed " + text(in.shear_wave_speed) +
                         " (limit " + text(L::quasi_static) +
                         "): inertia, which every method neglects, changes the stresses by "
                         "about (V/c_s)^2"});
  }
  return out;
}

}  // namespace viscoroll
