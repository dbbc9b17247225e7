// The serial continuation that viscoroll::sweep and sweep_scenes promise, written out for the
// tests to compare with: the scenes in chunks of `chunk`, the first of a chunk cold, each later one
// seeded with the previous solution where that converged from an iteration and, for a solution
// that says so, is a root.
#pragma once

#include <cstddef>
#include <vector>

namespace viscoroll::testing {

/// Whether a solution is a root: its `root` flag where it has one, else true.
template <class Solution>
bool is_root(const Solution& s) {
  if constexpr (requires { s.root; })
    return s.root;
  else
    return true;
}

template <class Solver, class Scene>
std::vector<typename Solver::Solution> serial_continuation(const Solver& solver,
                                                           const std::vector<Scene>& scenes,
                                                           std::size_t chunk) {
  std::vector<typename Solver::Solution> out;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const typename Solver::Solution* seed = nullptr;
    if (i % chunk != 0 && out.back().converged && out.back().iterations > 0 && is_root(out.back()))
      seed = &out.back();
    out.push_back(solver.solve(scenes[i], seed));
  }
  return out;
}

}  // namespace viscoroll::testing
