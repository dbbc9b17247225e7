// plane_rolling: the plane (Hunter) problem over speed, for f = 1 and f = 9, in units where the
// long-term Hertz half width a0 = 1, C1 = 1 and the load W = 1. Writes
//   <dir>/plane_sweep.csv     V tau/a0, f, a/a0, b/a0, chi/(C1 a0), pmax a0/W, pmax_x/a0
//   <dir>/plane_pressure.csv  f = 9: p(x) a0/W along the contact for several V tau/a0
// usage: plane_rolling [output-directory]   (default out/plane)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <viscoroll/plane/plane_solver.hpp>

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "out/plane";
  std::filesystem::create_directories(dir);
  const double pi = std::acos(-1.0);
  // mu_D chosen so that a0^2 = 4 c (1 + f) W / C1 = 1 with nu = 0.5, W = C1 = 1.
  auto solve = [&](double f, double vtau) {
    const double mu_d = 4 * (1 + f) * 0.5 / (2 * pi);
    const viscoroll::PlaneSolverD solver(
        viscoroll::StandardLinearSolid<double>(mu_d, 0.5, f, vtau));
    return solver.solve({.c1 = 1.0, .load = 1.0, .speed = 1.0});
  };
  std::ofstream sweep(dir / "plane_sweep.csv");
  sweep << "vtau_over_a0,f,a_over_a0,b_over_a0,chi_over_c1a0,pmax_a0_over_w,pmax_x_over_a0,"
           "converged\n";
  sweep.precision(12);
  bool ok = true;
  for (double f : {1.0, 9.0})
    for (int i = 0; i <= 80; ++i) {
      const double vtau = std::pow(10.0, -3 + 6.0 * i / 80);
      const auto s = solve(f, vtau);
      const auto peak = s.peak();
      ok = ok && s.converged;
      sweep << vtau << ',' << f << ',' << s.a << ',' << s.b << ',' << s.chi << ',' << peak.pressure
            << ',' << peak.x << ',' << s.converged << '\n';
    }
  std::ofstream profile(dir / "plane_pressure.csv");
  profile << "vtau_over_a0,x_over_a0,p_a0_over_w\n";
  profile.precision(12);
  for (double vtau : {0.01, 0.1, 1.0, 10.0, 100.0}) {
    const auto s = solve(9.0, vtau);
    for (int i = 0; i <= 400; ++i) {
      const double x = s.b - s.a * std::cos(pi * i / 400);
      profile << vtau << ',' << x << ',' << s.pressure(x) << '\n';
    }
  }
  std::cout << "plane_rolling: wrote " << (dir / "plane_sweep.csv").string() << " and "
            << (dir / "plane_pressure.csv").string()
            << (ok ? "" : " (some solutions did not converge)") << "\n";
  return ok ? 0 : 1;
}
