// viscoroll's Python module: the boundary-element solver behind solve_bem and sweep_bem, over the
// standard linear solid (BemSolverD) or a Prony series (BemSolver over PronyRelaxation), for the
// ellipsoid or a roller of finite length (tilted or not; its scene from bem_scene, as the command
// line's). The fields are those of viscoroll-solve --method bem (cli/bem_record.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <viscoroll/bem/bem_profile.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/roller/profile.hpp>

#include "bindings.hpp"
#include "cli/bem_record.hpp"
#include "cli/bem_substrate.hpp"
#include "cli/roller_profile.hpp"

namespace viscoroll::python {
namespace {

using Solver = BemSolverD;
using SpectrumSolver = BemSolver<double, PronyRelaxation<double>>;
using Solution = BemSolution<double>;
static_assert(std::is_same_v<SpectrumSolver::Solution, Solution>);

/// What a bem record takes besides its solution: the record's keys, and the static long-term
/// contact of a roller of finite length (none for the ellipsoid: Hertz's, from the solution).
struct BemKeys {
  RecordKeys record;
  std::optional<cli::LongTermContact> long_term;
  double tolerance = 0;  ///< BemOptions::tolerance of the solver
};

class BemSolved final : public Solved {
 public:
  /// `grid`: the solver's first grid; the record's grid is the one that answered (the
  /// solution's), and its tolerance the solver's (keys.tolerance).
  BemSolved(Solution s, const BemKeys& keys, double speed, [[maybe_unused]] int grid,
            double seconds)
      : Solved(Method::bem), s_(std::move(s)) {
    record_ =
        joined(keys.record.head("bem", speed),
               cli::bem_fields<Record>(
                   s_, s_.along_roller(), keys.long_term.value_or(cli::hertz_long_term(s_)),
                   keys.long_term.has_value(), keys.record.duty(speed), keys.tolerance, seconds));
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

/// The scene's standard linear solid (an elastic material: f = tau = 0).
StandardLinearSolid<double> material_of(const SceneSpec& scene) {
  const auto& m = scene.material;
  return {m.mu_d, m.nu, m.f, m.tau};
}

/// The options of a solve from `grid` at `tolerance`, as viscoroll-solve's run_bem: with a
/// tolerance the refinement may go up to at least the first grid.
BemOptions options_for(int grid, double tolerance) {
  BemOptions options;
  options.grid = grid;
  options.tolerance = tolerance;
  if (tolerance > 0) options.max_grid = std::max(options.max_grid, grid);
  return options;
}

Solver make_solver(const SceneSpec& scene, int grid, double tolerance) {
  return cli::bem_solver(material_of(scene), options_for(grid, tolerance), scene.substrate);
}

SpectrumSolver make_spectrum_solver(const SceneSpec& scene, int grid, double tolerance) {
  return cli::bem_solver(prony_at(scene), options_for(grid, tolerance), scene.substrate);
}

/// f(profile) with the library profile of the scene's roller of finite length in its tilt.
template <class F>
auto with_profile(const SceneSpec& scene, F f) {
  return cli::visit_axial_profile(*scene.roller.axial, [&](auto profile, double tilt) {
    return f(Tilted(std::move(profile), tilt));
  });
}

/// The scene at `speed`: the ellipsoid's, or a roller of finite length's by bem_scene (its grid
/// sized by the long-term compliance, which the temperature does not change: the command line's
/// scene, from the reference material).
BemScene<double> bem_scene_at(const SceneSpec& scene, double speed) {
  if (!scene.roller.axial) {
    BemScene<double> s{
        .c1 = scene.roller.c1, .c2 = scene.roller.c2, .load = scene.load, .speed = speed};
    s.validate();
    return s;
  }
  BemScene<double> s = with_profile(scene, [&](const auto& roller) {
    return scene.material.prony
               ? bem_scene(roller, scene.material.prony->reference, scene.load, speed)
               : bem_scene(roller, material_of(scene), scene.load, speed);
  });
  s.validate();
  return s;
}

/// The record's keys, with the line theory's static long-term contact of a roller of finite
/// length (cli::profile_long_term).
BemKeys keys_of(const SceneSpec& scene, double tolerance) {
  BemKeys keys{RecordKeys::of(scene), std::nullopt, tolerance};
  if (scene.roller.axial)
    keys.long_term = with_profile(scene, [&](const auto& roller) {
      return scene.material.prony
                 ? cli::profile_long_term(roller, scene.material.prony->reference, scene.load)
                 : cli::profile_long_term(roller, material_of(scene), scene.load);
    });
  return keys;
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

SolvedPtr solve_bem(const SceneSpec& scene, double speed, int grid, double tolerance,
                    const Solved* start) {
  const BemScene<double> at = bem_scene_at(scene, speed);
  const BemKeys keys = keys_of(scene, tolerance);
  if (scene.material.prony)
    return solve_seeded<BemSolved>(make_spectrum_solver(scene, grid, tolerance), at, Method::bem,
                                   start, keys, grid);
  return solve_seeded<BemSolved>(make_solver(scene, grid, tolerance), at, Method::bem, start, keys,
                                 grid);
}

std::vector<SolvedPtr> sweep_bem(const SceneSpec& scene, std::span<const double> speeds, int grid,
                                 double tolerance, const SweepOptions& options) {
  for (const double v : speeds) bem_scene_at(scene, v);  // every speed checked before any work
  const BemScene<double> at = bem_scene_at(scene, 0.0);
  const BemKeys keys = keys_of(scene, tolerance);
  if (scene.material.prony)
    return sweep_seeded<BemSolved>(make_spectrum_solver(scene, grid, tolerance), at, speeds, keys,
                                   grid, options);
  return sweep_seeded<BemSolved>(make_solver(scene, grid, tolerance), at, speeds, keys, grid,
                                 options);
}

std::pair<double, double> line_long_term(const SceneSpec& scene) {
  if (scene.roller.axial) {
    const auto lt = keys_of(scene, 0.0).long_term.value();
    return {lt.a, lt.l};
  }
  const double compliance = scene.material.prony
                                ? scene.material.prony->reference.long_term_compliance()
                                : material_of(scene).long_term_compliance();
  const auto h = bem::hertz_contact(scene.roller.c1, scene.roller.c2, compliance, scene.load);
  return {h.a, h.b};
}

std::pair<double, double> roller_body(const SceneSpec& scene) {
  if (!scene.roller.axial)
    return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  return with_profile(scene, [](const auto& roller) {
    return std::pair<double, double>(roller.y_min(), roller.y_max());
  });
}

}  // namespace viscoroll::python
