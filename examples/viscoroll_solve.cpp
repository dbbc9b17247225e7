// viscoroll-solve: solve one scene for one or more relaxation times and print one JSON object
// per line (see README.md). Exit status: 0 all converged, 1 a solution did not converge,
// 2 bad input (message on stderr, nothing on stdout).
// --method plane: Hunter's plane problem (--load per unit length, --c2 ignored).
// --method line: the line-contact solver (--c2 required, --load the total load, --grid N the
// Chebyshev terms, default 6); the taus are solved in the given order with continuation, and each
// line also carries l, d, l0, d0 (the static long-term l and d), terms, reason and warnings.
// --method bem: the 3-D boundary-element solver (--c2 required, --load the total load, --grid N
// elements per semi-axis of the static long-term Hertz ellipse, default 16); each line carries
// a0 = a(0), b0 = b(0), l, d, chi, the Hertz a_long_term, l0, d0, grid, cells, reason,
// iterations (active set), gmres_iterations, residual and warnings. docs/bem.md. Warnings of
// either method also go to stderr, one per line; they do not change the exit status.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/plane/plane_solver.hpp>

#include "cli/solve_options.hpp"

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
  for (double tau : o.tau)
    solvers.emplace_back(viscoroll::StandardLinearSolid<double>(o.mu_d, o.nu, o.f, tau));
  bool all_converged = true;
  for (std::size_t i = 0; i < solvers.size(); ++i) {
    const auto start = std::chrono::steady_clock::now();
    const auto s = solvers[i].solve(scene);
    const auto peak = s.peak();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    all_converged = all_converged && s.converged;
    std::cout << "{\"method\":\"plane\",\"tau\":" << number(o.tau[i])
              << ",\"vtau\":" << number(o.speed * o.tau[i]) << ",\"a0\":" << number(s.a)
              << ",\"b0\":" << number(s.b) << ",\"a_long_term\":" << number(s.a_long_term)
              << ",\"chi\":" << number(s.chi) << ",\"pmax\":" << number(peak.pressure)
              << ",\"pmax_x\":" << number(peak.x) << ",\"seconds\":" << number(seconds)
              << ",\"converged\":" << (s.converged ? "true" : "false")
              << ",\"iterations\":" << s.iterations << ",\"residual\":" << number(s.residual)
              << "}\n";
  }
  return all_converged ? 0 : 1;
}

/// A JSON number, or null where the value is not finite (a failed iteration's residual).
std::string json_number(double x) { return std::isfinite(x) ? number(x) : std::string("null"); }

/// A JSON string literal.
std::string json_string(std::string_view text) {
  std::string out = "\"";
  for (const char ch : text) {
    const auto u = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (u < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(u));
      out += buffer;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

/// A JSON array of strings.
std::string json_strings(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (k) out += ',';
    out += json_string(items[k]);
  }
  return out + "]";
}

/// --grid for the line method: LineOptions::terms, default 6.
int line_terms(const SolveOptions& o) {
  constexpr long default_terms = 6, max_terms = 64;
  const long n = o.grid.value_or(default_terms);
  if (n < 1 || n > max_terms)
    throw std::invalid_argument(
        "viscoroll-solve: --grid (line: Chebyshev terms) expects 1 <= N <= " +
        std::to_string(max_terms) + ", got " + std::to_string(n));
  return static_cast<int>(n);
}

/// The line-contact (3-D) solver; the taus are solved in the given order, each seeded with the
/// previous converged iterated solution (continuation; a closed form carries no more than the
/// solver's own seed, so it is not passed on).
int run_line(const SolveOptions& o) {
  using Solver = viscoroll::LineSolverD;
  using Solution = Solver::Solution;
  if (!o.c2)
    throw std::invalid_argument("viscoroll-solve: --method line needs --c2; " +
                                viscoroll::cli::usage());
  viscoroll::LineOptions options;
  options.terms = line_terms(o);
  const viscoroll::LineScene<double> scene{o.c1, *o.c2, o.load, o.speed};
  scene.validate();
  std::vector<Solver> solvers;
  for (double tau : o.tau)
    solvers.emplace_back(viscoroll::StandardLinearSolid<double>(o.mu_d, o.nu, o.f, tau), options);
  bool all_converged = true;
  std::optional<Solution> previous;
  for (std::size_t i = 0; i < solvers.size(); ++i) {
    const auto start = std::chrono::steady_clock::now();
    const Solution* seed =
        previous && previous->converged && previous->iterations > 0 ? &*previous : nullptr;
    Solution s = solvers[i].solve(scene, seed);
    const auto peak = s.strip(0.0).peak();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    all_converged = all_converged && s.converged;
    const std::string warnings = json_strings(s.warnings);
    std::cout << "{\"method\":\"line\",\"tau\":" << number(o.tau[i])
              << ",\"vtau\":" << number(o.speed * o.tau[i]) << ",\"a0\":" << json_number(s.a(0.0))
              << ",\"b0\":" << json_number(s.b(0.0)) << ",\"l\":" << json_number(s.l())
              << ",\"d\":" << json_number(s.d) << ",\"a_long_term\":" << number(s.a_long_term)
              << ",\"l0\":" << number(s.l_long_term) << ",\"d0\":" << number(s.d_long_term)
              << ",\"chi\":" << json_number(s.chi) << ",\"pmax\":" << json_number(peak.pressure)
              << ",\"pmax_x\":" << json_number(peak.x) << ",\"seconds\":" << number(seconds)
              << ",\"converged\":" << (s.converged ? "true" : "false")
              << ",\"root\":" << (s.root ? "true" : "false") << ",\"iterations\":" << s.iterations
              << ",\"residual\":" << json_number(s.residual) << ",\"terms\":" << options.terms
              << ",\"reason\":" << json_string(s.reason) << ",\"warnings\":" << warnings << "}\n";
    for (const auto& w : s.warnings)
      std::cerr << "viscoroll-solve: warning: line solution for tau = " << number(o.tau[i]) << ": "
                << w << "\n";
    if (!s.converged)
      std::cerr << "viscoroll-solve: line solution for tau = " << number(o.tau[i])
                << " did not converge: " << s.reason << "\n";
    previous = std::move(s);
  }
  return all_converged ? 0 : 1;
}

/// --grid for the bem method: elements per semi-axis, default 16.
int bem_grid(const SolveOptions& o) {
  constexpr long default_grid = 16, max_grid = 512;
  const long n = o.grid.value_or(default_grid);
  if (n < 2 || n > max_grid)
    throw std::invalid_argument(
        "viscoroll-solve: --grid (bem: elements per semi-axis) expects 2 <= N <= " +
        std::to_string(max_grid) + ", got " + std::to_string(n));
  return static_cast<int>(n);
}

/// The boundary-element solver; the taus share one grid (it is sized by the static long-term
/// contact), and each solve starts from the previous converged contact.
int run_bem(const SolveOptions& o) {
  using Solver = viscoroll::BemSolverD;
  using Solution = viscoroll::BemSolution<double>;
  if (!o.c2)
    throw std::invalid_argument("viscoroll-solve: --method bem needs --c2; " +
                                viscoroll::cli::usage());
  viscoroll::BemOptions options;
  options.grid = bem_grid(o);
  const viscoroll::BemScene<double> scene{o.c1, *o.c2, o.load, o.speed};
  scene.validate();
  std::vector<Solver> solvers;
  for (double tau : o.tau)
    solvers.emplace_back(viscoroll::StandardLinearSolid<double>(o.mu_d, o.nu, o.f, tau), options);
  bool all_converged = true;
  std::optional<Solution> previous;
  for (std::size_t i = 0; i < solvers.size(); ++i) {
    const auto start = std::chrono::steady_clock::now();
    const Solution* seed = previous && previous->converged ? &*previous : nullptr;
    Solution s = solvers[i].solve(scene, seed);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    all_converged = all_converged && s.converged;
    std::size_t peak = 0;
    for (std::size_t q = 0; q < s.pressure.size(); ++q)
      if (s.pressure[q] > s.pressure[peak]) peak = q;
    const int peak_i = static_cast<int>(peak % static_cast<std::size_t>(s.grid.nx));
    std::cout << "{\"method\":\"bem\",\"tau\":" << number(o.tau[i])
              << ",\"vtau\":" << number(o.speed * o.tau[i]) << ",\"a0\":" << json_number(s.a0)
              << ",\"b0\":" << json_number(s.b0) << ",\"l\":" << json_number(s.l)
              << ",\"d\":" << json_number(s.d) << ",\"a_long_term\":" << number(s.long_term.a)
              << ",\"l0\":" << number(s.long_term.b) << ",\"d0\":" << number(s.long_term.d)
              << ",\"chi\":" << json_number(s.chi) << ",\"pmax\":" << json_number(s.pressure[peak])
              << ",\"pmax_x\":" << json_number(s.grid.x(peak_i))
              << ",\"seconds\":" << number(seconds)
              << ",\"converged\":" << (s.converged ? "true" : "false")
              << ",\"iterations\":" << s.iterations
              << ",\"gmres_iterations\":" << s.krylov_iterations
              << ",\"residual\":" << json_number(s.residual) << ",\"grid\":" << options.grid
              << ",\"cells\":" << s.grid.size() << ",\"reason\":" << json_string(s.reason)
              << ",\"warnings\":" << json_strings(s.warnings) << "}\n";
    for (const auto& w : s.warnings)
      std::cerr << "viscoroll-solve: warning: bem solution for tau = " << number(o.tau[i]) << ": "
                << w << "\n";
    if (!s.converged)
      std::cerr << "viscoroll-solve: bem solution for tau = " << number(o.tau[i])
                << " did not converge: " << s.reason << "\n";
    previous = std::move(s);
  }
  return all_converged ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::vector<std::string_view> args(argv + 1, argv + argc);
    const SolveOptions options = viscoroll::cli::parse_solve_options(args);
    switch (options.method) {
      case Method::plane:
        return run_plane(options);
      case Method::line:
        return run_line(options);
      case Method::bem:
        return run_bem(options);
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
