// The fields of a line solution in the command line's JSON order (docs/cli.md, "Output"), shared
// by viscoroll-solve and the Python bindings so that both print the same record.
#pragma once

#include <string>

namespace viscoroll::cli {

/// The fields of a line solution `s` (LineSolution or LineSpectrumSolution) after the record's
/// head (method, the material's keys, speed): the contact's shape up to chi, then `middle` (the
/// peak pressure pmax, pmax_x; a spectrum's active_terms), then the iteration's fields. `Record`
/// is a sequence of (key, value) fields built from braces.
template <class Record, class Solution>
Record line_fields(const Solution& s, const Record& middle, int terms, double seconds) {
  Record out = {{"a0", s.a(0.0)},
                {"b0", s.b(0.0)},
                {"l", s.l()},
                {"y_minus", -s.l()},
                {"y_plus", s.l()},
                {"d", s.d},
                {"a_long_term", s.a_long_term},
                {"l0", s.l_long_term},
                {"d0", s.d_long_term},
                {"chi", s.chi}};
  out.insert(out.end(), middle.begin(), middle.end());
  const Record tail = {{"seconds", seconds},
                       {"converged", s.converged},
                       {"root", s.root},
                       {"iterations", static_cast<long long>(s.iterations)},
                       {"residual", s.residual},
                       {"terms", static_cast<long long>(terms)},
                       {"reason", s.reason},
                       {"warnings", s.warnings}};
  out.insert(out.end(), tail.begin(), tail.end());
  return out;
}

}  // namespace viscoroll::cli
