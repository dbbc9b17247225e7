// viscoroll: outcomes a program can read. Every solution of every solver carries, beside the
// words of `reason` and `warnings`, a StopCode `code` (why the solve stopped) and WarningCodes
// `warning_codes` (one per warning, in the same order), so that a caller branches on an enum and
// prints the text (docs/errors.md, "Outcome codes"). The names of to_string() are stable: the
// command line writes them as `code` and `warning_codes`, Python returns them as strings.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace viscoroll {

/// Why a solve stopped. `converged` is the only code of a converged solution; every other code
/// comes with converged == false and the values of the last iterate.
enum class StopCode : std::uint8_t {
  converged,                 ///< a closed form, or every claimed quantity met its tolerance
  iteration_limit,           ///< the iteration used the allowed steps without meeting its test
  no_descent,                ///< no step lowers the residual any more, above the tolerance
  outside_domain,            ///< the start or an iterate left the equations' domain
  singular_jacobian,         ///< Newton's step is not defined (a singular Jacobian)
  not_a_contact,             ///< a root of the equations that is not a contact (d, a, l or p < 0)
  precision_exhausted,       ///< the root's error estimate exceeds sqrt(eps) of a narrow scalar
  tolerance_not_met,         ///< the error estimates exceed the tolerance at the largest setting
  under_resolved,            ///< the contact is finer than the discretisation's largest setting
  root_finder_failed,        ///< a one-dimensional root finder did not converge
  contact_reaches_body_end,  ///< the contact runs past the roller's body (line theory)
  contact_reaches_grid_boundary,  ///< the contact reaches the BEM grid's edge
  linear_solver_failed,           ///< GMRES did not converge
  active_set_cycles,              ///< the active set returned to a set seen before
  empty_contact,                  ///< the active set lost every cell
  non_finite,                     ///< a value of the solution is NaN or infinite
  static_contact_failed,          ///< the long-term static contact behind the solve failed
  not_run,                        ///< no iteration ran (no stage)
};

/// What a warning is about. A warning qualifies a result (converged or not); the text says by
/// how much and what to do.
enum class WarningCode : std::uint8_t {
  line_aspect,             ///< l/a(0) < 3: outside the line theory's slender contact
  line_width,              ///< a(y) somewhere is not small against l
  rolling_bound,           ///< a(0) <= a0, l <= l0 or b(0) >= 0 broken by the discretisation
  chi_negative,            ///< a converged chi below zero: zero to the method's accuracy
  least_squares_minimum,   ///< no root: a certified least-squares minimum is returned
  near_fold,               ///< a root where the Jacobian is nearly singular
  seed_set_aside,          ///< the seed was not used: solved from the cold start
  solved_from_seed,        ///< the cold start stopped; the seed's iteration converged
  seed_failed,             ///< the cold start and the seed both stopped
  edge_layer_unresolved,   ///< the BEM's leading-edge layer is under a quarter cell: a0, b0
  contact_at_roller_end,   ///< the contact reaches the roller's end: resolved to the grid
  tolerance_not_verified,  ///< the BEM's error estimate needs a grid more than it had
  tolerance_not_met,       ///< the BEM's estimated errors exceed the tolerance
  collocation_spacing,     ///< the static profile's collocation points are too close
  short_contact,           ///< the static profile's contact is short against its width
  small_slope,             ///< (V1) a0/R above its limit
  roller_length,           ///< (V2) the contact beyond the roller's end
  slenderness,             ///< (V3), (V3s) l/a0 below the line theory's limit
  quasi_static,            ///< (V4) speed against the shear-wave speed
};

namespace detail {
inline constexpr std::array<std::string_view, 18> stop_code_names = {
    "converged",
    "iteration_limit",
    "no_descent",
    "outside_domain",
    "singular_jacobian",
    "not_a_contact",
    "precision_exhausted",
    "tolerance_not_met",
    "under_resolved",
    "root_finder_failed",
    "contact_reaches_body_end",
    "contact_reaches_grid_boundary",
    "linear_solver_failed",
    "active_set_cycles",
    "empty_contact",
    "non_finite",
    "static_contact_failed",
    "not_run"};
inline constexpr std::array<std::string_view, 19> warning_code_names = {
    "line_aspect",           "line_width",
    "rolling_bound",         "chi_negative",
    "least_squares_minimum", "near_fold",
    "seed_set_aside",        "solved_from_seed",
    "seed_failed",           "edge_layer_unresolved",
    "contact_at_roller_end", "tolerance_not_verified",
    "tolerance_not_met",     "collocation_spacing",
    "short_contact",         "small_slope",
    "roller_length",         "slenderness",
    "quasi_static"};
static_assert(stop_code_names.size() == std::size_t(StopCode::not_run) + 1,
              "a name for every StopCode");
static_assert(warning_code_names.size() == std::size_t(WarningCode::quasi_static) + 1,
              "a name for every WarningCode");
}  // namespace detail

/// The code's stable name, its enumerator's spelling ("converged", "iteration_limit", ...).
constexpr std::string_view to_string(StopCode c) { return detail::stop_code_names[std::size_t(c)]; }
/// The code's stable name, its enumerator's spelling ("line_aspect", "small_slope", ...).
constexpr std::string_view to_string(WarningCode c) {
  return detail::warning_code_names[std::size_t(c)];
}

/// One warning: its code and its words.
struct Warning {
  /// Which warning.
  WarningCode code;
  /// The warning in words.
  std::string text;
};

/// Adds a warning to a solution's `warnings` and `warning_codes` (kept index for index).
template <class Solution>
void add_warning(Solution& s, WarningCode code, std::string text) {
  s.warnings.push_back(std::move(text));
  s.warning_codes.push_back(code);
}
/// Whether a solution carries a warning with `code`.
template <class Solution>
bool has_warning(const Solution& s, WarningCode code) {
  for (const WarningCode c : s.warning_codes)
    if (c == code) return true;
  return false;
}

namespace detail {

/// Adds each of `list` to a solution (add_warning).
template <class Solution>
void append_warnings(Solution& s, std::vector<Warning> list) {
  for (auto& w : list) add_warning(s, w.code, std::move(w.text));
}
/// Appends the warnings of solution `from` to solution `to`.
template <class To, class From>
void copy_warnings(To& to, const From& from) {
  to.warnings.insert(to.warnings.end(), from.warnings.begin(), from.warnings.end());
  to.warning_codes.insert(to.warning_codes.end(), from.warning_codes.begin(),
                          from.warning_codes.end());
}
/// Sets a solution's stop: not converged, with `code` and `reason`.
template <class Solution>
void set_stop(Solution& s, StopCode code, std::string reason) {
  s.converged = code == StopCode::converged;
  s.code = code;
  s.reason = std::move(reason);
}

}  // namespace detail

}  // namespace viscoroll
