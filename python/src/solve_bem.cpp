// viscoroll's Python module: the boundary-element solver behind solve_bem and sweep_bem, over the
// standard linear solid (BemSolverD) or a Prony series (BemSolver over PronyRelaxation). The fields
// are those of viscoroll-solve --method bem (examples/viscoroll_solve.cpp).
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <viscoroll/bem/bem_solver.hpp>

#include "bindings.hpp"

namespace viscoroll::python {
namespace {

using Solver = BemSolverD;
using SpectrumSolver = BemSolver<double, PronyRelaxation<double>>;
using Solution = BemSolution<double>;
static_assert(std::is_same_v<SpectrumSolver::Solution, Solution>);

class BemSolved final : public Solved {
 public:
  BemSolved(Solution s, const MaterialKeys& keys, double speed, int grid, double seconds)
      : Solved(Method::bem), s_(std::move(s)) {
    std::size_t peak = 0;
    for (std::size_t q = 0; q < s_.pressure.size(); ++q)
      if (s_.pressure[q] > s_.pressure[peak]) peak = q;
    const int peak_i = static_cast<int>(peak % static_cast<std::size_t>(s_.grid.nx));
    const double pmax = s_.pressure.empty() ? 0.0 : s_.pressure[peak];
    const auto along = s_.along_roller();
    record_ = joined(keys.head("bem", speed),
                     {{"a0", s_.a0},
                      {"b0", s_.b0},
                      {"l", s_.l},
                      {"y_minus", -s_.l},
                      {"y_plus", s_.l},
                      {"f0_max", along.f0_max},
                      {"f0_max_y", along.f0_max_y},
                      {"d", s_.d},
                      {"a_long_term", s_.long_term.a},
                      {"l0", s_.long_term.b},
                      {"d0", s_.long_term.d},
                      {"chi", s_.chi},
                      {"pmax", pmax},
                      {"pmax_x", s_.grid.x(peak_i)},
                      {"seconds", seconds},
                      {"converged", s_.converged},
                      {"iterations", static_cast<long long>(s_.iterations)},
                      {"gmres_iterations", static_cast<long long>(s_.krylov_iterations)},
                      {"residual", s_.residual},
                      {"grid", static_cast<long long>(grid)},
                      {"cells", static_cast<long long>(s_.grid.size())},
                      {"reason", s_.reason},
                      {"warnings", s_.warnings}});
  }

  const Solution& solution() const { return s_; }

  /// The pressure of the cell that holds (x, y); 0 off the grid.
  double pressure(double x, double y) const override {
    const auto& g = s_.grid;
    const double i = std::round(x / g.hx) + (g.nx - 1) / 2;
    const double j = std::round(y / g.hy) + (g.ny - 1) / 2;
    if (!(i >= 0 && i < g.nx && j >= 0 && j < g.ny)) return 0.0;
    return s_.p(static_cast<int>(i), static_cast<int>(j));
  }
  double a(double) const override { unavailable("a(y)"); }
  double b(double) const override { unavailable("b(y)"); }
  double f0(double) const override { unavailable("f0(y)"); }

 private:
  [[noreturn]] static void unavailable(const char* what) {
    throw std::invalid_argument(std::string("viscoroll: ") + what +
                                " is not available for the bem method (it gives a0, b0, l, the "
                                "cell pressures: Result.cell_pressures(), and pressure(x, y))");
  }

  Solution s_;
};

BemOptions options_for(int grid) {
  BemOptions options;
  options.grid = grid;
  return options;
}

Solver make_solver(const SceneSpec& scene, int grid) {
  const auto& m = scene.material;
  return Solver(StandardLinearSolid<double>(m.mu_d, m.nu, m.f, m.tau), options_for(grid));
}

SpectrumSolver make_spectrum_solver(const SceneSpec& scene, int grid) {
  return SpectrumSolver(prony_at(scene), options_for(grid));
}

BemScene<double> bem_scene(const SceneSpec& scene, double speed) {
  BemScene<double> s{
      .c1 = scene.roller.c1, .c2 = scene.roller.c2, .load = scene.load, .speed = speed};
  s.validate();
  return s;
}

}  // namespace

/// The cell centres and pressures of a bem result (for Result.cell_pressures()).
bool bem_cells(const Solved& solved, std::vector<double>& x, std::vector<double>& y,
               std::vector<double>& p) {
  const auto* bem = dynamic_cast<const BemSolved*>(&solved);
  if (!bem) return false;
  const auto& s = bem->solution();
  x.resize(static_cast<std::size_t>(s.grid.nx));
  y.resize(static_cast<std::size_t>(s.grid.ny));
  for (int i = 0; i < s.grid.nx; ++i) x[static_cast<std::size_t>(i)] = s.grid.x(i);
  for (int j = 0; j < s.grid.ny; ++j) y[static_cast<std::size_t>(j)] = s.grid.y(j);
  p = s.pressure;  // index i + nx j: row-major (ny, nx)
  return true;
}

SolvedPtr solve_bem(const SceneSpec& scene, double speed, int grid, const Solved* start) {
  const auto keys = MaterialKeys::of(scene);
  if (scene.material.prony)
    return solve_seeded<BemSolved>(make_spectrum_solver(scene, grid), bem_scene(scene, speed),
                                   Method::bem, start, keys, grid);
  return solve_seeded<BemSolved>(make_solver(scene, grid), bem_scene(scene, speed), Method::bem,
                                 start, keys, grid);
}

std::vector<SolvedPtr> sweep_bem(const SceneSpec& scene, std::span<const double> speeds, int grid,
                                 const SweepOptions& options) {
  for (const double v : speeds) bem_scene(scene, v);  // every speed checked before any work
  const auto keys = MaterialKeys::of(scene);
  if (scene.material.prony)
    return sweep_seeded<BemSolved>(make_spectrum_solver(scene, grid), bem_scene(scene, 0.0), speeds,
                                   keys, grid, options);
  return sweep_seeded<BemSolved>(make_solver(scene, grid), bem_scene(scene, 0.0), speeds, keys,
                                 grid, options);
}

}  // namespace viscoroll::python
