// viscoroll: the errors the library reports instead of returning a plausible wrong number.
#pragma once

#include <stdexcept>
#include <string>

namespace viscoroll {

/// Thrown where a computation that has no result object to carry a flag (a quadrature rule, a
/// special function) cannot meet its accuracy; solvers report non-convergence in their Result.
class ConvergenceError : public std::runtime_error {
 public:
  /// The message `what`, prefixed with "viscoroll: ".
  explicit ConvergenceError(const std::string& what) : std::runtime_error("viscoroll: " + what) {}
};

}  // namespace viscoroll
