// The scene and material of the line solver's spectrum tests (docs/validation.md, "Line solver
// for a spectrum against the BEM"): the paper's proportions C1 = 1, C2/C1 = (ln 20 - 1)/25
// (l0 = 5 a0), load 1, the two-term creep spectrum (f, tau) = (3, 0.05), (6, 5) and the
// twenty-term one f_k = 0.45, tau_k = 10^-3 ... 10^3 evenly in log, with mu_D = 1, nu = 0.5.
#pragma once

#include <cmath>
#include <vector>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony.hpp>

namespace viscoroll::testing {

inline LineScene<double> spectrum_scene(double speed) {
  return {.c1 = 1.0, .c2 = (std::log(20.0) - 1) / 25, .load = 1.0, .speed = speed};
}

inline PronyCreep<double> two_term_creep() {
  return PronyCreep<double>(1.0, 0.5, {{3.0, 0.05}, {6.0, 5.0}});
}

inline PronyCreep<double> twenty_term_creep() {
  std::vector<PronyTerm<double>> terms;
  for (int k = 0; k < 20; ++k) terms.push_back({0.45, std::pow(10.0, -3 + 6.0 * k / 19)});
  return PronyCreep<double>(1.0, 0.5, terms);
}

}  // namespace viscoroll::testing
