// line_vs_bem_spectrum: the line solver for a spectrum (docs/theory.md, section 14) against the
// BEM (N = 32 cells per semi-axis) on the paper's proportions (C2/C1 = (ln 20 - 1)/25, l0 = 5 a0),
// for a two-term and a twenty-term material, from the slow to the fast limit, with the line
// solver at N = 4 and 6 Chebyshev terms. Prints the table of docs/validation.md ("The line solver
// for a spectrum against the BEM") and the line solves' wall times.
//   line_vs_bem_spectrum [grid]   (default 32)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony.hpp>

int main(int argc, char** argv) {
  using viscoroll::PronyCreep;
  using viscoroll::PronyTerm;
  const int grid = argc > 1 ? std::atoi(argv[1]) : 32;
  std::vector<PronyTerm<double>> twenty;
  for (int k = 0; k < 20; ++k) twenty.push_back({0.45, std::pow(10.0, -3 + 6.0 * k / 19)});
  const std::vector<std::pair<const char*, PronyCreep<double>>> materials{
      {"two terms", PronyCreep<double>(1.0, 0.5, {{3.0, 0.05}, {6.0, 5.0}})},
      {"twenty terms", PronyCreep<double>(1.0, 0.5, twenty)}};
  const double c2 = (std::log(20.0) - 1) / 25;
  std::printf("| material | V | active (N) | a(0): BEM / line | b(0): BEM / line | l: BEM / line | d: BEM / line | chi: BEM / line | line s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& [name, m] : materials)
    for (const double speed : {0.01, 0.1, 1.0, 10.0, 100.0, 1e4}) {
      viscoroll::BemOptions options;
      options.grid = grid;
      const viscoroll::BemScene<double> bem_scene{.c1 = 1.0, .c2 = c2, .load = 1.0, .speed = speed};
      const auto e = viscoroll::BemSolver(m, options).solve(bem_scene);
      for (const int terms : {4, 6}) {
        const viscoroll::LineSolver<double, PronyCreep<double>> line(m, viscoroll::LineOptions{.terms = terms});
        const auto start = std::chrono::steady_clock::now();
        const auto s = line.solve({.c1 = 1.0, .c2 = c2, .load = 1.0, .speed = speed});
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("| %s | %g | %d (%d) | %.4f / %.4f | %.4f / %.4f | %.3f / %.3f | %.4f / %.4f | %.4f / %.4f | %.2f%s |\n",
                    name, speed, s.active_terms, terms, e.a0, s.a(0), e.b0, s.b(0), e.l, s.l(), e.d, s.d,
                    e.chi, s.chi, seconds, s.converged ? "" : (" (not converged: " + s.reason + ")").c_str());
        std::fflush(stdout);
      }
      if (!e.converged) std::printf("(BEM not converged: %s)\n", e.reason.c_str());
    }
}
