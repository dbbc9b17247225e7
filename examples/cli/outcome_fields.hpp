// The outcome of a solve in the command line's record (docs/cli.md, "Output"; docs/errors.md,
// "Outcome codes"), shared by viscoroll-solve and the Python bindings: `reason` and its stable
// `code`, `warnings` and, index for index, their `warning_codes`.
#pragma once

#include <string>
#include <vector>
#include <viscoroll/core/outcome.hpp>

namespace viscoroll::cli {

/// The stable names of `codes` (to_string), in order.
inline std::vector<std::string> code_names(const std::vector<WarningCode>& codes) {
  std::vector<std::string> out;
  out.reserve(codes.size());
  for (const WarningCode c : codes) out.emplace_back(to_string(c));
  return out;
}

/// reason, code, warnings, warning_codes of a solution `s` (any solver's: each has `reason`,
/// `code`; those without warnings give empty lists).
template <class Record, class Solution>
Record outcome_fields(const Solution& s) {
  Record out = {{"reason", s.reason}, {"code", std::string(to_string(s.code))}};
  if constexpr (requires { s.warnings; }) {
    out.push_back({"warnings", s.warnings});
    out.push_back({"warning_codes", code_names(s.warning_codes)});
  } else {
    out.push_back({"warnings", std::vector<std::string>{}});
    out.push_back({"warning_codes", std::vector<std::string>{}});
  }
  return out;
}

}  // namespace viscoroll::cli
