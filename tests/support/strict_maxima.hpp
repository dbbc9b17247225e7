// The strict local maxima of a sampled curve (chi against speed): how many, and the lowest of
// them. For the spectrum tests that count the peaks of rolling friction, one per retardation time
// far apart from the others.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

namespace viscoroll::testing {

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
