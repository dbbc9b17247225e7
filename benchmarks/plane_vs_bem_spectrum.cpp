// plane_vs_bem_spectrum: the plane solver for a spectrum (docs/theory.md, section 12) against the
// BEM on a very long roller (C2/C1 = 1e-4, l/a ~ 240) at y = 0, for a two-term and a twenty-term
// material, N = 8, 16, 32 cells per semi-axis, from the slow to the fast limit. Prints the table
// of docs/validation.md ("The plane solver for a spectrum against the BEM").
//   plane_vs_bem_spectrum [max-grid]   (default 32)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/plane/plane_solver.hpp>

int main(int argc, char** argv) {
  using viscoroll::PronyCreep;
  using viscoroll::PronyTerm;
  const int max_grid = argc > 1 ? std::atoi(argv[1]) : 32;
  std::vector<PronyTerm<double>> twenty;
  for (int k = 0; k < 20; ++k) twenty.push_back({0.5, std::pow(10.0, -3 + 6.0 * k / 19)});
  const std::vector<std::pair<const char*, PronyCreep<double>>> materials{
      {"two terms (f, tau) = (3, 0.05), (6, 5)",
       PronyCreep<double>(1.0, 0.5, {{3.0, 0.05}, {6.0, 5.0}})},
      {"twenty terms f = 0.5, tau = 1e-3 ... 1e3", PronyCreep<double>(1.0, 0.5, twenty)}};
  std::printf(
      "| material | V | N | a: BEM / plane | b: BEM / plane | (a, b errors)/hx | row chi: BEM / "
      "plane | chi error |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const auto& [name, m] : materials)
    for (double speed : {0.0, 0.03, 0.3, 3.0, 30.0, 1e6})
      for (int n = 8; n <= max_grid; n *= 2) {
        viscoroll::BemOptions options;
        options.grid = n;
        const auto s = viscoroll::BemSolver(m, options)
                           .solve(viscoroll::BemScene<double>{
                               .c1 = 1.0, .c2 = 1e-4, .load = 1.0, .speed = speed});
        const int j0 = (s.grid.ny - 1) / 2;
        double w = 0, moment = 0;
        for (int i = 0; i < s.grid.nx; ++i) {
          w += s.p(i, j0) * s.grid.hx;
          moment += s.grid.x(i) * s.p(i, j0) * s.grid.hx;
        }
        const auto p = viscoroll::PlaneSolver(m).solve({.c1 = 1.0, .load = w, .speed = speed});
        const double chi = moment / w;
        std::printf(
            "| %s | %g | %d | %.5f / %.5f | %.5f / %.5f | %.2f, %.2f | %.5f / %.5f | %s |\n", name,
            speed, n, s.a0, p.a, s.b0, p.b, (s.a0 - p.a) / s.grid.hx, (s.b0 - p.b) / s.grid.hx, chi,
            p.chi, p.chi > 0 ? (std::to_string(100 * (chi - p.chi) / p.chi) + " %").c_str() : "-");
        if (!s.converged || !p.converged)
          std::printf("(not converged: bem %d, plane %d)\n", s.converged, p.converged);
      }
}
