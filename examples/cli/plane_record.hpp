// The fields of a plane solution in the command line's JSON order (docs/cli.md, "Output"), shared
// by viscoroll-solve and the Python bindings so that both print the same record.
#pragma once

#include <string>
#include <vector>

#include "engineering.hpp"

namespace viscoroll::cli {

/// The fields of a plane solution `s` (PlaneSolution, or PlaneSpectrumSolution with its
/// active_terms and spectrum_error) after the record's head (method, the material's keys, speed):
/// a0, b0, the static long-term half width, chi with its engineering_fields for `duty` (per unit
/// length), the peak pressure, then the iteration's fields. `Record` is a sequence of (key, value)
/// fields built from braces.
template <class Record, class Solution>
Record plane_fields(const Solution& s, const Duty& duty, double seconds) {
  const auto peak = s.peak();
  Record out = {{"a0", s.a}, {"b0", s.b}, {"a_long_term", s.a_long_term}, {"chi", s.chi}};
  const Record cost = engineering_fields<Record>(s.chi, duty);
  out.insert(out.end(), cost.begin(), cost.end());
  out.push_back({"pmax", peak.pressure});
  out.push_back({"pmax_x", peak.x});
  if constexpr (requires { s.active_terms; }) {
    out.push_back({"active_terms", static_cast<long long>(s.active_terms)});
    out.push_back({"spectrum_error", s.spectrum_error});
  }
  const Record tail = {{"seconds", seconds},
                       {"converged", s.converged},
                       {"iterations", static_cast<long long>(s.iterations)},
                       {"residual", s.residual},
                       {"warnings", std::vector<std::string>{}}};
  out.insert(out.end(), tail.begin(), tail.end());
  return out;
}

}  // namespace viscoroll::cli
