// Rolling friction against speed for the spectrum tests that count its peaks, one per retardation
// time far apart from the others: chi over log-spaced speeds (every solve required converged), and
// the strict local maxima of a sampled curve (how many, and the lowest of them).
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace viscoroll::testing {

/// chi of solve(V) at V = 10^(first + step k), k = 0 .. count - 1; each solve must converge.
template <class Solve>
std::vector<double> chi_over_speeds(const Solve& solve, double first, double step, int count) {
  std::vector<double> chi;
  for (int k = 0; k < count; ++k) {
    const double speed = std::pow(10.0, first + step * k);
    const auto s = solve(speed);
    CAPTURE(speed, s.reason);
    REQUIRE(s.converged);
    chi.push_back(s.chi);
  }
  return chi;
}

struct StrictMaxima {
  int count = 0;
  double lowest = std::numeric_limits<double>::infinity();  ///< infinity where there is none
};

/// The samples v[k], 0 < k < n - 1, greater than both neighbours.
inline StrictMaxima strict_maxima(const std::vector<double>& v) {
  StrictMaxima out;
  for (std::size_t k = 1; k + 1 < v.size(); ++k)
    if (v[k] > v[k - 1] && v[k] > v[k + 1]) {
      ++out.count;
      if (v[k] < out.lowest) out.lowest = v[k];
    }
  return out;
}

}  // namespace viscoroll::testing
