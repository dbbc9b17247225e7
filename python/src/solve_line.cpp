// viscoroll's Python module: the line-contact solver behind solve_line and sweep_line, over the
// standard linear solid (LineSolverD; FastLineSolverD in the fast setting) or a Prony series
// (LineSolver over PronyRelaxation, the line theory for a spectrum), for the ellipsoid (LineScene)
// or a scene file's roller of finite length (LineProfileScene, tilted or not; on a spectrum
// docs/theory.md (RP5)). The fields are those of viscoroll-solve --method line
// (examples/viscoroll_solve.cpp).
#include <concepts>
#include <stdexcept>
#include <utility>
#include <viscoroll/line/line_solver.hpp>

#include "bindings.hpp"
#include "cli/line_record.hpp"
#include "cli/roller_profile.hpp"

namespace viscoroll::python {
namespace {

using SpectrumSolver = LineSolver<double, PronyRelaxation<double>>;

/// A line solution by Solver (LineSolverD, or FastLineSolverD for the fast setting; SpectrumSolver
/// for a Prony material): the fields of viscoroll-solve --method line, with pmax for one
/// relaxation time and active_terms, spectrum_error for a spectrum, whose solution with two or
/// more active terms is the contact's shape and moments, no pressure field (docs/line-solver.md,
/// "Materials with a spectrum").
template <class Solver>
class LineSolved final : public Solved {
 public:
  using Solution = typename Solver::Solution;
  static constexpr bool spectrum = std::same_as<Solver, SpectrumSolver>;
  LineSolved(Solution s, const RecordKeys& keys, double speed, int terms, double seconds)
      : Solved(Method::line), s_(std::move(s)) {
    Record extra;
    if constexpr (spectrum) {
      extra = {{"active_terms", static_cast<long long>(s_.active_terms)},
               {"spectrum_error", s_.spectrum_error}};
    } else {
      const auto peak = s_.strip(0.0).peak();
      extra = {{"pmax", peak.pressure}, {"pmax_x", peak.x}};
    }
    record_ = joined(keys.head("line", speed),
                     cli::line_fields<Record>(s_, extra, keys.duty(speed), terms, seconds));
  }

  const Solution& solution() const { return s_; }
  double pressure(double x, double y) const override {
    if (!s_.has_pressure())
      throw std::invalid_argument(
          "viscoroll: pressure(x, y) is not available for the line method with a Prony material "
          "whose active_terms is " +
          std::to_string(s_.active_terms) +
          " >= 2 at this speed "
          "(its solution is the contact's shape and moments: a(y), b(y), f0(y); the bem method "
          "gives the pressure)");
    return s_.pressure(x, y);
  }
  double a(double y) const override { return s_.a(y); }
  double b(double y) const override { return s_.b(y); }
  double f0(double y) const override { return s_.f0(y); }

 private:
  Solution s_;
};

/// The line options at `terms`, over LineOptions::fast() for the fast setting; `roots_only`: no
/// least-squares minimisation (LineOptions::least_squares off).
LineOptions options_for(int terms, bool fast, bool roots_only) {
  LineOptions options = fast ? LineOptions::fast() : LineOptions{};
  options.terms = terms;
  options.least_squares = !roots_only;
  return options;
}

template <class Solver>
Solver make_solver(const SceneSpec& scene, int terms, bool fast, bool roots_only) {
  const auto& m = scene.material;
  return Solver(StandardLinearSolid<double>(m.mu_d, m.nu, m.f, m.tau),
                options_for(terms, fast, roots_only));
}

SpectrumSolver make_spectrum_solver(const SceneSpec& scene, int terms, bool fast, bool roots_only) {
  return SpectrumSolver(prony_at(scene), options_for(terms, fast, roots_only));
}

LineScene<double> line_scene(const SceneSpec& scene, double speed) {
  LineScene<double> s{
      .c1 = scene.roller.c1, .c2 = scene.roller.c2, .load = scene.load, .speed = speed};
  s.validate();
  return s;
}

/// The scene of a roller of finite length (`profile`, tilted or not) at `speed`.
template <class Profile>
LineProfileScene<Profile> profile_scene(Profile profile, const SceneSpec& scene, double speed) {
  LineProfileScene<Profile> s{.roller = std::move(profile), .load = scene.load, .speed = speed};
  s.validate();
  return s;
}

/// f(profile) with the library profile of the scene's roller of finite length in its tilt
/// (Tilted).
template <class F>
auto with_profile(const SceneSpec& scene, F f) {
  return cli::visit_axial_profile(*scene.roller.axial, [&](auto profile, double tilt) {
    return f(Tilted(std::move(profile), tilt));
  });
}

}  // namespace

SolvedPtr solve_line(const SceneSpec& scene, double speed, int terms, bool fast,
                     const Solved* start, bool roots_only) {
  const auto keys = RecordKeys::of(scene);
  // The scene `scene_at` builds at `speed`, by the material's solver (the setting's).
  const auto solve = [&](auto scene_at) {
    if (scene.material.prony)
      return solve_seeded<LineSolved<SpectrumSolver>>(
          make_spectrum_solver(scene, terms, fast, roots_only), scene_at(speed), Method::line,
          start, keys, terms);
    if (fast)
      return solve_seeded<LineSolved<FastLineSolverD>>(
          make_solver<FastLineSolverD>(scene, terms, fast, roots_only), scene_at(speed),
          Method::line, start, keys, terms);
    return solve_seeded<LineSolved<LineSolverD>>(
        make_solver<LineSolverD>(scene, terms, fast, roots_only), scene_at(speed), Method::line,
        start, keys, terms);
  };
  if (scene.roller.axial)
    return with_profile(scene, [&](auto profile) {
      return solve([&](double v) { return profile_scene(profile, scene, v); });
    });
  return solve([&](double v) { return line_scene(scene, v); });
}

std::vector<SolvedPtr> sweep_line(const SceneSpec& scene, std::span<const double> speeds, int terms,
                                  bool fast, const SweepOptions& options, bool roots_only) {
  const auto keys = RecordKeys::of(scene);
  // The scenes `scene_at` builds, every speed checked before any work, by the material's solver
  // (the setting's).
  const auto sweep = [&](auto scene_at) {
    for (const double v : speeds) scene_at(v);
    if (scene.material.prony)
      return sweep_seeded<LineSolved<SpectrumSolver>>(
          make_spectrum_solver(scene, terms, fast, roots_only), scene_at(0.0), speeds, keys, terms,
          options);
    if (fast)
      return sweep_seeded<LineSolved<FastLineSolverD>>(
          make_solver<FastLineSolverD>(scene, terms, fast, roots_only), scene_at(0.0), speeds, keys,
          terms, options);
    return sweep_seeded<LineSolved<LineSolverD>>(
        make_solver<LineSolverD>(scene, terms, fast, roots_only), scene_at(0.0), speeds, keys,
        terms, options);
  };
  if (scene.roller.axial)
    return with_profile(scene, [&](auto profile) {
      return sweep([&](double v) { return profile_scene(profile, scene, v); });
    });
  return sweep([&](double v) { return line_scene(scene, v); });
}

}  // namespace viscoroll::python
