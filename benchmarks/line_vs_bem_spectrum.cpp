// line_vs_bem_spectrum: the line solver for a spectrum (docs/theory.md, section 14) against the
// BEM (N = 32 cells per semi-axis) on the paper's proportions (C2/C1 = (ln 20 - 1)/25, l0 = 5 a0),
// for a two-term and a twenty-term material, from the slow to the fast limit, with the line
// solver at N = 4 and 6 Chebyshev terms. Prints the table of docs/validation.md ("The line solver
// for a spectrum against the BEM") and the line solves' wall times, then each material's largest
// errors of the N = 4 solves against the BEM: relative in a(0), l, d, chi and b(0), and b(0)'s
// absolute error over the BEM's a(0) (the shift of the contact's centre against its half-width).
//   line_vs_bem_spectrum [grid]   (default 32)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
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
  std::printf(
      "| material | V | active (N) | a(0): BEM / line | b(0): BEM / line | l: BEM / line | d: BEM "
      "/ line | chi: BEM / line | line s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  // Largest errors of the N = 4 solves, per material: a(0), l, d, chi, b(0), |b - b_BEM|/a_BEM.
  std::map<std::string, std::vector<double>> worst;
  for (const auto& [name, m] : materials)
    for (const double speed : {0.01, 0.1, 1.0, 10.0, 100.0, 1e4}) {
      viscoroll::BemOptions options;
      options.grid = grid;
      const viscoroll::BemScene<double> bem_scene{.c1 = 1.0, .c2 = c2, .load = 1.0, .speed = speed};
      const auto e = viscoroll::BemSolver(m, options).solve(bem_scene);
      for (const int terms : {4, 6}) {
        const viscoroll::LineSolver<double, PronyCreep<double>> line(
            m, viscoroll::LineOptions{.terms = terms});
        const auto start = std::chrono::steady_clock::now();
        const auto s = line.solve({.c1 = 1.0, .c2 = c2, .load = 1.0, .speed = speed});
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf(
            "| %s | %g | %d (%d) | %.4f / %.4f | %.4f / %.4f | %.3f / %.3f | %.4f / %.4f | %.4f / "
            "%.4f | %.2f%s |\n",
            name, speed, s.active_terms, terms, e.a0, s.a(0), e.b0, s.b(0), e.l, s.l(), e.d, s.d,
            e.chi, s.chi, seconds,
            s.converged ? "" : (" (not converged: " + s.reason + ")").c_str());
        std::fflush(stdout);
        if (terms == 4 && s.converged) {
          auto& w = worst.try_emplace(name, 6, 0.0).first->second;
          const double errors[] = {std::abs(s.a(0) / e.a0 - 1), std::abs(s.l() / e.l - 1),
                                   std::abs(s.d / e.d - 1),     std::abs(s.chi / e.chi - 1),
                                   std::abs(s.b(0) / e.b0 - 1), std::abs(s.b(0) - e.b0) / e.a0};
          for (int i = 0; i < 6; ++i) w[i] = std::max(w[i], errors[i]);
        }
      }
      if (!e.converged) std::printf("(BEM not converged: %s)\n", e.reason.c_str());
    }
  std::printf(
      "\nlargest errors at N = 4 against the BEM\n\n| material | a(0) | l | d | chi | b(0) | "
      "Δb(0)/a(0) |\n|---|---|---|---|---|---|---|\n");
  for (const auto& [name, w] : worst)
    std::printf("| %s | %.2f%% | %.2f%% | %.2f%% | %.2f%% | %.1f%% | %.2f%% |\n", name.c_str(),
                100 * w[0], 100 * w[1], 100 * w[2], 100 * w[3], 100 * w[4], 100 * w[5]);
}
