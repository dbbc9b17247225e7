// viscoroll-solve: solve one scene for one or more relaxation times and print one JSON object
// per line (see README.md). Exit status: 0 all converged, 1 a solution did not converge,
// 2 bad input (message on stderr, nothing on stdout).
#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "cli/solve_options.hpp"
#include <viscoroll/plane/plane_solver.hpp>

namespace {

using viscoroll::cli::Method;
using viscoroll::cli::SolveOptions;

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

int run_plane(const SolveOptions& o) {
  using Solver = viscoroll::PlaneSolverD;
  std::vector<Solver> solvers;
  const viscoroll::PlaneScene<double> scene{o.c1, o.load, o.speed};
  scene.validate();
  for (double tau : o.tau) solvers.emplace_back(viscoroll::StandardLinearSolid<double>(o.mu_d, o.nu, o.f, tau));
  bool all_converged = true;
  for (std::size_t i = 0; i < solvers.size(); ++i) {
    const auto start = std::chrono::steady_clock::now();
    const auto s = solvers[i].solve(scene);
    const auto peak = s.peak();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    all_converged = all_converged && s.converged;
    std::cout << "{\"method\":\"plane\",\"tau\":" << number(o.tau[i]) << ",\"vtau\":" << number(o.speed * o.tau[i])
              << ",\"a0\":" << number(s.a) << ",\"b0\":" << number(s.b) << ",\"a_long_term\":" << number(s.a_long_term)
              << ",\"chi\":" << number(s.chi) << ",\"pmax\":" << number(peak.pressure)
              << ",\"pmax_x\":" << number(peak.x) << ",\"seconds\":" << number(seconds)
              << ",\"converged\":" << (s.converged ? "true" : "false") << ",\"iterations\":" << s.iterations
              << ",\"residual\":" << number(s.residual) << "}\n";
  }
  return all_converged ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::vector<std::string_view> args(argv + 1, argv + argc);
    const SolveOptions options = viscoroll::cli::parse_solve_options(args);
    switch (options.method) {
      case Method::plane: return run_plane(options);
      case Method::line: std::cerr << "viscoroll-solve: --method line is not built yet\n"; return 2;
      case Method::bem: std::cerr << "viscoroll-solve: --method bem is not built yet\n"; return 2;
    }
  } catch (const std::invalid_argument& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "viscoroll-solve: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
