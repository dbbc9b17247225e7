// viscoroll's Python module: what its translation units share. module.cpp holds the
// bindings, the scene types and the plane solver of the half space; solve_line.cpp, solve_bem.cpp
// and solve_plane_substrate.cpp (the plane method on a layer or a spring bed) the heavy solvers,
// each behind solve_*() and sweep_*() so that pybind11 and the solvers never meet in one
// translation unit; study.cpp the solves of a study (solve_with() over viscoroll::sweep_scenes).
// python_support.hpp holds what the units that talk to Python share. Every solve is in double
// precision; an elastic material is the standard linear solid with f = tau = 0, as on the command
// line (docs/cli.md).
#pragma once

#include <chrono>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/material/temperature_shift.hpp>
#include <viscoroll/sweep.hpp>

#include "cli/engineering.hpp"
#include "cli/scene_file.hpp"
#include "cli/solve_options.hpp"

namespace viscoroll::python {

/// The command line's methods and their names (examples/cli/solve_options.hpp).
using cli::Method;
using cli::method_name;

/// A Prony series in relaxation form (docs/materials.md) at its reference temperature, and its
/// optional time-temperature shift.
struct PronySpec {
  PronyRelaxation<double> reference;
  std::optional<ShiftLaw<double>> shift;
};

/// A material: the standard linear solid of Eq. (1), elastic (mu = mu_d, f = tau = 0), or a
/// Prony series (`prony` set; mu_d its glassy modulus, nu its Poisson's ratio).
struct MaterialSpec {
  bool elastic = false;
  double mu_d = 0, nu = 0, f = 0, tau = 0;
  std::shared_ptr<const PronySpec> prony;
};

/// A roller: the paper's ellipsoid (c1, c2), a cylinder of `radius` (plane only, c1 = 1/radius),
/// or a roller of finite length (`axial`: crowned, logarithmic or table, tilted or not; c1 =
/// 1/radius), which the line and bem methods solve on any material
/// (LineSolver::solve(LineProfileScene), bem_scene; cli::check_scene_for_method).
struct RollerSpec {
  bool cylinder = false;
  double c1 = 0, c2 = 0, radius = 0;
  std::shared_ptr<const cli::RollerProfile> axial;
};

/// One scene: what a scene file holds (docs/cli.md), in any consistent units.
struct SceneSpec {
  MaterialSpec material;
  RollerSpec roller;
  double load = 0;
  std::vector<double> speeds;
  std::optional<Method> method;
  std::optional<long> grid;
  /// A scene file's "setting" (none where it has none): the line method's default setting in
  /// solve() and sweep().
  std::optional<cli::LineSetting> setting;
  std::string description;
  /// A scene file's "tolerance": the bem method's default relative accuracy in d and chi
  /// (BemOptions::tolerance) in solve() and sweep(), or on a layer or a spring bed the plane
  /// method's in a, d and chi (PlaneSubstrateOptions::tolerance).
  std::optional<double> tolerance;
  /// The rubber's density (a scene file's "density", Scene(density=...)): the quasi-static
  /// check (core/validity.hpp, (V4)); none: not checked.
  std::optional<double> density;
  /// A scene file's "strict": a validity breach is an error in solve() and sweep().
  bool strict = false;
  /// The body the roller presses (a scene file's "substrate", Scene(substrate=...)): the half
  /// space by default; a layer or a spring bed is the bem method's, and the plane method's
  /// (PlaneSubstrateSolver) for a cylinder.
  cli::SubstrateSpec substrate = {};
  std::string source = "Scene";  ///< starts the messages of method-dependent checks
  /// A Prony material's temperature (degrees Celsius): its shift law's t_ref by default; NaN
  /// without a shift law (the material is its reference).
  double temperature = std::numeric_limits<double>::quiet_NaN();
};

/// The Prony material of a scene at its temperature: every time times a_T (at_temperature).
inline PronyRelaxation<double> prony_at(const SceneSpec& scene) {
  const auto& p = *scene.material.prony;
  return p.shift ? at_temperature(p.reference, *p.shift, scene.temperature) : p.reference;
}

/// a_T of the scene's temperature (1 without a shift law).
inline double shift_factor_of(const SceneSpec& scene) {
  const auto& p = *scene.material.prony;
  return p.shift ? shift_factor(*p.shift, scene.temperature) : 1.0;
}

/// One output field: the command line's JSON value types.
using Value = std::variant<double, long long, bool, std::string, std::vector<std::string>>;
/// The command line's JSON fields of one solution, in its order (docs/cli.md, "Output").
using Record = std::vector<std::pair<std::string, Value>>;

/// The rolling radius of a roller: its `radius` (a cylinder, a roller of finite length), else
/// 1/c1 (the ellipsoid; cli::Duty).
inline double rolling_radius(const RollerSpec& roller) {
  return roller.radius > 0 ? roller.radius : 1 / roller.c1;
}

/// What a record says beyond its solution, as the command line: tau and V tau, or a Prony
/// material's temperature and a_T; the load and the rolling radius of its engineering fields.
struct RecordKeys {
  bool prony = false;
  double tau = 0, temperature = 0, a_t = 1;
  double load = 0, radius = 0;

  static RecordKeys of(const SceneSpec& scene) {
    const double load = scene.load, radius = rolling_radius(scene.roller);
    if (!scene.material.prony) return {false, scene.material.tau, 0, 1, load, radius};
    return {true, 0, scene.temperature, shift_factor_of(scene), load, radius};
  }
  /// The load, `speed` and radius of cli::engineering_fields.
  cli::Duty duty(double speed) const { return {load, speed, radius}; }
  /// The record's first fields: method, then tau, speed, vtau or temperature, a_T, speed.
  Record head(const char* method, double speed) const {
    if (prony)
      return {{"method", std::string(method)},
              {"temperature", temperature},
              {"a_T", a_t},
              {"speed", speed}};
    return {{"method", std::string(method)}, {"tau", tau}, {"speed", speed}, {"vtau", speed * tau}};
  }
};

/// `head` followed by `tail`.
inline Record joined(Record head, const Record& tail) {
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

/// One solution of any method: its fields and its functions of position.
class Solved {
 public:
  explicit Solved(Method method) : method_(method) {}
  Solved(const Solved&) = delete;
  Solved& operator=(const Solved&) = delete;
  virtual ~Solved() = default;

  Method method() const { return method_; }
  const Record& record() const { return record_; }
  const Value* find(const std::string& key) const {
    for (const auto& [name, value] : record_)
      if (name == key) return &value;
    return nullptr;
  }

  /// p(x, y); 0 outside the contact. Plane: p(x) for every y.
  virtual double pressure(double x, double y) const = 0;
  /// Half width, offset, F0 of the strip at y. Not available for the bem method (throws).
  virtual double a(double y) const = 0;
  virtual double b(double y) const = 0;
  virtual double f0(double y) const = 0;

  Record record_;

 private:
  Method method_;
};

using SolvedPtr = std::shared_ptr<const Solved>;

/// The solver's discretisation for `method` from the scene's or the caller's grid: line terms
/// (1..64, default 6; 4 for a Prony material, as the command line), bem elements per semi-axis
/// (2..512, default 16; 8, the refinement's first grid, with a `tolerance`); throws
/// std::invalid_argument naming `grid`.
int discretisation(Method method, std::optional<long> grid, bool prony, bool fast = false,
                   double tolerance = 0);

/// Seconds since `start`.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// One solve of a seeded method (line: SolvedT = LineSolved; bem: BemSolved), timed; `start`
/// must be a result of the same method and solution type. SolvedT is constructed from
/// (solution, keys, speed, grid, seconds); `keys` is its RecordKeys (or what it takes in their
/// place).
template <class SolvedT, class Solver, class Scene, class Keys>
SolvedPtr solve_seeded(const Solver& solver, const Scene& at, Method method, const Solved* start,
                       const Keys& keys, int grid) {
  const typename Solver::Solution* seed = nullptr;
  if (start) {
    const auto* same = dynamic_cast<const SolvedT*>(start);
    if (!same)
      throw std::invalid_argument(
          std::string("viscoroll: start must be a result of the ") + method_name(method) +
          " method for this kind of material and setting, got " + method_name(start->method()));
    seed = &same->solution();
  }
  const auto t0 = std::chrono::steady_clock::now();
  auto s = solver.solve(at, seed);
  const double seconds = seconds_since(t0);
  return std::make_shared<SolvedT>(std::move(s), keys, at.speed, grid, seconds);
}

/// viscoroll::sweep over `speeds` from the scene `at` (its speed replaced), timed by
/// viscoroll::TimedSolver; `make` builds each result's Solved from (solution, speed, seconds) on
/// the worker thread.
template <class Solver, class Scene, class Make>
std::vector<SolvedPtr> sweep_timed(const Solver& solver, const Scene& at,
                                   std::span<const double> speeds, Make make,
                                   const SweepOptions& options) {
  const viscoroll::TimedSolver<Solver, Make> timed{solver, std::move(make)};
  auto solutions = sweep(timed, at, speeds, options);
  std::vector<SolvedPtr> out;
  out.reserve(solutions.size());
  for (auto& s : solutions) out.push_back(std::move(s.extra));
  return out;
}

/// sweep_timed for a seeded method (line: SolvedT = LineSolved; bem: BemSolved).
template <class SolvedT, class Solver, class Scene, class Keys>
std::vector<SolvedPtr> sweep_seeded(const Solver& solver, const Scene& at,
                                    std::span<const double> speeds, const Keys& keys, int grid,
                                    const SweepOptions& options) {
  return sweep_timed(
      solver, at, speeds,
      [keys, grid](const typename Solver::Solution& s, double speed, double seconds) -> SolvedPtr {
        return std::make_shared<SolvedT>(s, keys, speed, grid, seconds);
      },
      options);
}

// The solvers (module.cpp: plane; solve_line.cpp; solve_bem.cpp; solve_plane_substrate.cpp).
// `scene` was checked for the method; `start` seeds the iteration (line, bem) when it is a
// solution of the same method.
/// tolerance: on a layer or a spring bed PlaneSubstrateOptions::tolerance (solve_plane_substrate);
/// the half space (Hunter's closed form) ignores it.
SolvedPtr solve_plane(const SceneSpec& scene, double speed, double tolerance);
/// The plane method on the scene's layer or spring bed: PlaneSubstrateSolver of its material at
/// `tolerance` (relative, in a, d and chi), the record cli::plane_substrate_fields.
SolvedPtr solve_plane_substrate(const SceneSpec& scene, double speed, double tolerance);
/// fast: the line method's fast setting (LineOptions::fast(); FastLineSolverD for a material of
/// one relaxation time). roots_only: LineOptions::least_squares off (the auto method, which takes
/// only a root: a result that is not one stops at Levenberg-Marquardt's stop).
SolvedPtr solve_line(const SceneSpec& scene, double speed, int terms, bool fast,
                     const Solved* start, bool roots_only = false);
/// tolerance: BemOptions::tolerance (0: the one grid `grid`; else refined from it).
SolvedPtr solve_bem(const SceneSpec& scene, double speed, int grid, double tolerance,
                    const Solved* start);
/// The cell centres x (nx), y (ny) and pressures (ny x nx, row-major) of a bem result; false for
/// another method.
bool bem_cells(const Solved& solved, std::vector<double>& x, std::vector<double>& y,
               std::vector<double>& p);

// viscoroll::sweep over `speeds`; called with the GIL released.
std::vector<SolvedPtr> sweep_plane(const SceneSpec& scene, std::span<const double> speeds,
                                   double tolerance, const SweepOptions& options);
std::vector<SolvedPtr> sweep_plane_substrate(const SceneSpec& scene, std::span<const double> speeds,
                                             double tolerance, const SweepOptions& options);
std::vector<SolvedPtr> sweep_line(const SceneSpec& scene, std::span<const double> speeds, int terms,
                                  bool fast, const SweepOptions& options, bool roots_only = false);
std::vector<SolvedPtr> sweep_bem(const SceneSpec& scene, std::span<const double> speeds, int grid,
                                 double tolerance, const SweepOptions& options);

/// What solve() decides before it solves a scene, as it decides it: the method (the caller's, else
/// the scene's, else auto), the grid asked, the line method's setting, the tolerance, strict. A
/// study (study.cpp) decides it once per scene and solves each of the scene's items with it.
struct SolveSetup {
  Method method = Method::automatic;
  std::optional<long> grid;
  bool fast = false;
  double tolerance = 0;
  bool strict = false;
};

/// solve()'s checks of `scene` against its arguments (std::invalid_argument naming the
/// parameter, solve()'s messages), and the setup they give (module.cpp).
SolveSetup solve_setup(const SceneSpec& scene, const std::optional<std::string>& method,
                       std::optional<long> grid, const std::optional<std::string>& setting,
                       std::optional<double> tolerance, std::optional<bool> strict);

/// solve(scene, speed=speed, start=start) with `setup`, without Python (module.cpp): the solve
/// and the model's validity checks, whose breaches join the result's warnings and are appended to
/// `breaches` as solve() words its Python warnings; with setup.strict the first breach throws
/// std::invalid_argument. `start` (or null) seeds the solve as solve()'s start does: a result of
/// the same material and setting (line, bem; the auto method takes the one of the method it
/// runs, the plane method none).
SolvedPtr solve_with(const SceneSpec& scene, const SolveSetup& setup, double speed,
                     const Solved* start, std::vector<std::string>& breaches);

/// The half width a0 and half length l0 of the line theory's static long-term contact of the
/// scene (solve_bem.cpp): Hertz's for the ellipsoid, static_profile_contact for a roller of
/// finite length (NaN where it has none), as viscoroll-solve's line_long_term; what
/// cli::line_precheck judges.
std::pair<double, double> line_long_term(const SceneSpec& scene);
/// Where the body of the scene's roller ends along y (+-inf: the ellipsoid, the cylinder).
std::pair<double, double> roller_body(const SceneSpec& scene);

}  // namespace viscoroll::python
