// viscoroll's Python module: the plane method on a layer or a spring bed (PlaneSubstrateSolver,
// docs/plane-substrate.md), as viscoroll-solve's run_plane_substrate: the scene's material (a
// standard linear solid, an elastic one as f = tau = 0, or a Prony series at the scene's
// temperature) on its substrate, to a relative tolerance in a, d and chi; the record
// cli::plane_substrate_fields. Behind solve_plane_substrate() and sweep_plane_substrate()
// (bindings.hpp), so that pybind11 and the solver never meet in one translation unit.
#include <chrono>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_solver.hpp>

#include "bindings.hpp"
#include "cli/plane_record.hpp"
#include "cli/plane_substrate.hpp"

namespace viscoroll::python {

namespace {

/// A plane solution on a layer or a spring bed: its record, and its pressure, a and b (constant
/// along y). It has no F0 (Eq. 52 is the half space's closed form): f0() raises ValueError.
class PlaneSubstrateSolved final : public Solved {
 public:
  PlaneSubstrateSolved(PlaneSubstrateSolution<double> s, const RecordKeys& keys,
                       const std::string& substrate, double tolerance, double speed, double seconds)
      : Solved(Method::plane), s_(std::move(s)) {
    record_ = joined(
        keys.head("plane", speed),
        cli::plane_substrate_fields<Record>(s_, substrate, tolerance, keys.duty(speed), seconds));
  }
  double pressure(double x, double) const override { return s_.pressure(x); }
  double a(double) const override { return s_.a; }
  double b(double) const override { return s_.b; }
  double f0(double) const override {
    throw std::invalid_argument(
        "viscoroll: f0(y) is F0 of Eq. (52), the half space's plane solution's; the plane method "
        "on a layer or a spring bed gives none (its record has a0, b0, d, chi; pressure(x, y))");
  }

 private:
  PlaneSubstrateSolution<double> s_;
};

PlaneScene<double> plane_scene(const SceneSpec& scene, double speed) {
  PlaneScene<double> s{.c1 = scene.roller.c1, .load = scene.load, .speed = speed};
  s.validate();
  return s;
}

/// f(solver): PlaneSubstrateSolver of the scene's material on its substrate at `tolerance`.
template <class F>
auto with_solver(const SceneSpec& scene, double tolerance, F&& f) {
  const PlaneSubstrateOptions options = cli::plane_substrate_options(tolerance);
  return cli::visit_plane_body(scene.substrate, [&](const auto& body) {
    if (scene.material.prony) return f(PlaneSubstrateSolver(prony_at(scene), body, options));
    const auto& m = scene.material;
    return f(
        PlaneSubstrateSolver(StandardLinearSolid<double>(m.mu_d, m.nu, m.f, m.tau), body, options));
  });
}

}  // namespace

SolvedPtr solve_plane_substrate(const SceneSpec& scene, double speed, double tolerance) {
  const PlaneScene<double> at = plane_scene(scene, speed);
  const auto keys = RecordKeys::of(scene);
  const std::string substrate = scene.substrate.describe();
  return with_solver(scene, tolerance, [&](const auto& solver) -> SolvedPtr {
    const auto t0 = std::chrono::steady_clock::now();
    auto s = solver.solve(at);
    const double seconds = seconds_since(t0);
    return std::make_shared<PlaneSubstrateSolved>(std::move(s), keys, substrate, tolerance, speed,
                                                  seconds);
  });
}

std::vector<SolvedPtr> sweep_plane_substrate(const SceneSpec& scene, std::span<const double> speeds,
                                             double tolerance, const SweepOptions& options) {
  const PlaneScene<double> at = plane_scene(scene, 0.0);
  for (const double v : speeds) plane_scene(scene, v);
  const auto keys = RecordKeys::of(scene);
  const std::string substrate = scene.substrate.describe();
  return with_solver(scene, tolerance, [&](const auto& solver) {
    return sweep_timed(
        solver, at, speeds,
        [keys, substrate, tolerance](const PlaneSubstrateSolution<double>& s, double speed,
                                     double seconds) -> SolvedPtr {
          return std::make_shared<PlaneSubstrateSolved>(s, keys, substrate, tolerance, speed,
                                                        seconds);
        },
        options);
  });
}

}  // namespace viscoroll::python
