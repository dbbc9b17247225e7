// The fields of a bem solution in the command line's JSON order (docs/cli.md, "Output"), shared
// by viscoroll-solve and the Python bindings so that both print the same record.
#pragma once

#include <cstddef>
#include <limits>
#include <viscoroll/bem/bem_scene.hpp>
#include <viscoroll/line/static_profile_contact.hpp>

#include "engineering.hpp"
#include "outcome_fields.hpp"

namespace viscoroll::cli {

/// The static long-term contact (V = 0, the rubber relaxed to its long-term compliance) that a
/// record reports as a_long_term, l0 and d0: the half width at the contact's centre, the half
/// length and the penetration.
struct LongTermContact {
  double a = 0, l = 0, d = 0;
};

/// The static long-term contact of a roller of finite length (tilted or not) by the line theory,
/// static_profile_contact (docs/theory.md (G1)-(G3)) under the long-term compliance times the load
/// with its default 12 coefficients, as the line solver computes its own a_long_term, l0, d0.
/// NaN (null in the record) where it has no answer (the contact reaches the roller's ends).
template <class Profile, class Material>
LongTermContact profile_long_term(const Profile& roller, const Material& material, double load) {
  const auto s = static_profile_contact(
      roller, (1 + material.creep_ratio()) * material.instantaneous_compliance() * load);
  if (!s.converged) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan};
  }
  return {s.a(s.centre()), s.half_length(), s.d};
}

/// The static long-term contact of the ellipsoid: Hertz's ellipse of the long-term compliance
/// (BemSolution::long_term; exact in the half-space theory the bem discretises).
template <class Solution>
LongTermContact hertz_long_term(const Solution& s) {
  return {s.long_term.a, s.long_term.b, s.long_term.d};
}

/// The fields of a bem solution `s` after the record's head (method, the material's keys, speed):
/// the contact (its ends from `along`, s.along_roller(), for a roller of finite length, `axial`;
/// -l, l of (B12) for the ellipsoid), d, the static `long_term` contact, chi with its
/// engineering_fields for `duty`, the peak pressure, then the iteration's fields: the grid that
/// answered (s.elements), the `tolerance` asked (BemOptions::tolerance, 0: one grid), whether it
/// was met (false on one grid) and, with a tolerance, the error estimates (BemErrorEstimate;
/// null where a grid resolved the contact alone). `Record` is a sequence of (key, value) fields
/// built from braces.
template <class Record, class Solution>
Record bem_fields(const Solution& s, const AlongRoller<double>& along,
                  const LongTermContact& long_term, bool axial, const Duty& duty, double tolerance,
                  double seconds) {
  std::size_t peak = 0;
  for (std::size_t q = 0; q < s.pressure.size(); ++q)
    if (s.pressure[q] > s.pressure[peak]) peak = q;
  const int peak_i = static_cast<int>(peak % static_cast<std::size_t>(s.grid.nx));
  Record out = {{"a0", s.a0},
                {"b0", s.b0},
                {"l", s.l},
                {"y_minus", axial ? along.y_minus : -s.l},
                {"y_plus", axial ? along.y_plus : s.l},
                {"f0_max", along.f0_max},
                {"f0_max_y", along.f0_max_y},
                {"d", s.d},
                {"a_long_term", long_term.a},
                {"l0", long_term.l},
                {"d0", long_term.d},
                {"chi", s.chi}};
  const Record cost = engineering_fields<Record>(s.chi, duty);
  out.insert(out.end(), cost.begin(), cost.end());
  const Record tail = {{"pmax", s.pressure.empty() ? 0.0 : s.pressure[peak]},
                       {"pmax_x", s.grid.x(peak_i)},
                       {"seconds", seconds},
                       {"converged", s.converged},
                       {"iterations", static_cast<long long>(s.iterations)},
                       {"gmres_iterations", static_cast<long long>(s.krylov_iterations)},
                       {"residual", s.residual},
                       {"grid", static_cast<long long>(s.elements)},
                       {"cells", static_cast<long long>(s.grid.size())},
                       {"tolerance", tolerance},
                       {"tolerance_met", s.tolerance_met}};
  out.insert(out.end(), tail.begin(), tail.end());
  if (tolerance > 0) {
    const Record estimates = {{"error_d", s.error.d},   {"error_chi", s.error.chi},
                              {"error_a0", s.error.a0}, {"error_b0", s.error.b0},
                              {"error_l", s.error.l},   {"error_pmax", s.error.p_max}};
    out.insert(out.end(), estimates.begin(), estimates.end());
  }
  const Record outcome = outcome_fields<Record>(s);
  out.insert(out.end(), outcome.begin(), outcome.end());
  return out;
}

}  // namespace viscoroll::cli
