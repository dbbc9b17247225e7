// The fields of a plane solution, on the half space or on a layer or a spring bed, in the command
// line's JSON order (docs/cli.md, "Output"), shared by viscoroll-solve and the Python bindings so
// that both print the same record.
#pragma once

#include <string>
#include <vector>

#include "engineering.hpp"
#include "outcome_fields.hpp"

namespace viscoroll::cli {

/// The fields of a plane solution `s` (with its active_terms and spectrum_error where `spectrum`,
/// a Prony material's record) after the record's head (method, the material's keys, speed):
/// a0, b0, the static long-term half width, chi with its engineering_fields for `duty` (per unit
/// length), the peak pressure, then the iteration's fields. `Record` is a sequence of (key, value)
/// fields built from braces.
template <class Record, class Solution>
Record plane_fields(const Solution& s, const Duty& duty, double seconds, bool spectrum) {
  const auto peak = s.peak();
  Record out = {{"a0", s.a}, {"b0", s.b}, {"a_long_term", s.a_long_term}, {"chi", s.chi}};
  const Record cost = engineering_fields<Record>(s.chi, duty);
  out.insert(out.end(), cost.begin(), cost.end());
  out.push_back({"pmax", peak.pressure});
  out.push_back({"pmax_x", peak.x});
  if (spectrum) {
    out.push_back({"active_terms", static_cast<long long>(s.active_terms)});
    out.push_back({"spectrum_error", s.spectrum_error});
  }
  const Record tail = {{"seconds", seconds},
                       {"converged", s.converged},
                       {"iterations", static_cast<long long>(s.iterations)},
                       {"residual", s.residual}};
  out.insert(out.end(), tail.begin(), tail.end());
  const Record outcome = outcome_fields<Record>(s);
  out.insert(out.end(), outcome.begin(), outcome.end());
  return out;
}

/// The fields of a plane solution `s` on a layer or a spring bed (PlaneSubstrateSolution,
/// docs/plane-substrate.md) after the record's head: a0, b0, d (the approach measured from the
/// rigid base, where the surface far from the contact stays: PlaneSubstrateSolution::d with
/// d_absolute, as on every layer and bed), chi with its engineering_fields for `duty` (per unit
/// length), the peak pressure, then the iteration's fields: residual |int p dx / W - 1|, terms
/// (the Chebyshev terms N of (Q5); 0 on a spring bed, solved in closed form), the `tolerance`
/// asked of a, d and chi, the estimated absolute errors of (Q13) (error_a0, error_d, error_chi;
/// error_pmax, reported, not held to the tolerance), the `substrate` (SubstrateSpec::describe())
/// and, when not converged, the solver's `reason`. No a_long_term: the solver computes no static
/// long-term contact.
template <class Record, class Solution>
Record plane_substrate_fields(const Solution& s, const std::string& substrate, double tolerance,
                              const Duty& duty, double seconds) {
  const auto peak = s.peak();
  Record out = {{"a0", s.a}, {"b0", s.b}};
  if (s.d_absolute) out.push_back({"d", s.d});
  out.push_back({"chi", s.chi});
  const Record cost = engineering_fields<Record>(s.chi, duty);
  out.insert(out.end(), cost.begin(), cost.end());
  const Record tail = {{"pmax", peak.pressure},
                       {"pmax_x", peak.x},
                       {"seconds", seconds},
                       {"converged", s.converged},
                       {"iterations", static_cast<long long>(s.iterations)},
                       {"residual", s.load_residual},
                       {"terms", static_cast<long long>(s.terms)},
                       {"tolerance", tolerance},
                       {"error_a0", s.error_a},
                       {"error_d", s.error_d},
                       {"error_chi", s.error_chi},
                       {"error_pmax", s.error_peak},
                       {"substrate", substrate}};
  out.insert(out.end(), tail.begin(), tail.end());
  const Record outcome = outcome_fields<Record>(s);
  out.insert(out.end(), outcome.begin(), outcome.end());
  return out;
}

}  // namespace viscoroll::cli
