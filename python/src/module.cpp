// viscoroll's Python module `_viscoroll` (re-exported by the package `viscoroll`, docs/python.md):
// materials, rollers, Scene (and Scene.from_json, the command line's scene reader), solve(),
// sweep() and Result. The plane solver of the half space lives here; the line and bem solvers in
// solve_line.cpp and solve_bem.cpp, the plane solver on a layer or a spring bed in
// solve_plane_substrate.cpp. std::invalid_argument (the library's and the scene reader's messages,
// naming the parameter) becomes ValueError.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>
#include <viscoroll/bem/bem_scene.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/input_limits.hpp>
#include <viscoroll/line/line_options.hpp>
#include <viscoroll/material/dma_fit.hpp>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_solver.hpp>

#include "bindings.hpp"
#include "cli/auto_method.hpp"
#include "cli/plane_record.hpp"
#include "cli/roller_profile.hpp"
#include "cli/scene_file.hpp"
#include "cli/validity_record.hpp"
#include "python_support.hpp"

#ifndef VISCOROLL_PYTHON_VERSION
#define VISCOROLL_PYTHON_VERSION "0"
#endif

namespace py = pybind11;

namespace viscoroll::python {

int discretisation(Method method, std::optional<long> grid, bool prony, bool fast,
                   double tolerance) {
  if (method == Method::line) {
    const long n = grid.value_or(prony ? 4 : fast ? LineOptions::fast().terms : 6);
    if (n < 1 || n > 64)
      throw std::invalid_argument(
          "viscoroll: grid = " + std::to_string(n) +
          " is outside the valid range 1 <= grid <= 64 for the line method (Chebyshev terms)");
    return static_cast<int>(n);
  }
  if (method == Method::bem) {
    const long n = grid.value_or(tolerance > 0 ? 8 : 16);
    if (n < 2 || n > 512)
      throw std::invalid_argument(
          "viscoroll: grid = " + std::to_string(n) +
          " is outside the valid range 2 <= grid <= 512 for the bem method (elements per "
          "semi-axis)");
    return static_cast<int>(n);
  }
  return 0;  // plane: no discretisation
}

// ---------------------------------------------------------------------------------------------
// The plane solver.

namespace {

using PlaneSpectrumSolver = viscoroll::PlaneSolver<double, PronyRelaxation<double>>;
using PlaneSolver = PlaneSolverD;

/// A plane solution of either material (a PlaneSolution; a spectrum's record with active_terms
/// and spectrum_error).
template <class Solution>
class PlaneSolved final : public Solved {
 public:
  PlaneSolved(Solution s, const RecordKeys& keys, double speed, double seconds, bool spectrum)
      : Solved(Method::plane), s_(std::move(s)) {
    record_ = joined(keys.head("plane", speed),
                     cli::plane_fields<Record>(s_, keys.duty(speed), seconds, spectrum));
  }
  double pressure(double x, double) const override { return s_.pressure(x); }
  double a(double) const override { return s_.a; }
  double b(double) const override { return s_.b; }
  double f0(double) const override { return s_.f0; }

 private:
  Solution s_;
};

/// The solver's material has a spectrum (its record carries active_terms and spectrum_error).
template <class Solver>
constexpr bool spectrum_solver =
    !viscoroll::SingleTimeModel<std::remove_cvref_t<decltype(std::declval<Solver>().material())>>;

PlaneScene<double> plane_scene(const SceneSpec& scene, double speed) {
  PlaneScene<double> s{.c1 = scene.roller.c1, .load = scene.load, .speed = speed};
  s.validate();
  return s;
}

template <class Solver>
SolvedPtr solve_plane_with(const Solver& solver, const SceneSpec& scene, double speed) {
  const PlaneScene<double> at = plane_scene(scene, speed);
  const auto t0 = std::chrono::steady_clock::now();
  auto s = solver.solve(at);
  const double seconds = seconds_since(t0);
  return std::make_shared<PlaneSolved<typename Solver::Solution>>(
      std::move(s), RecordKeys::of(scene), speed, seconds, spectrum_solver<Solver>);
}

template <class Solver>
std::vector<SolvedPtr> sweep_plane_with(const Solver& solver, const SceneSpec& scene,
                                        std::span<const double> speeds,
                                        const SweepOptions& options) {
  const PlaneScene<double> at = plane_scene(scene, 0.0);
  for (const double v : speeds) plane_scene(scene, v);
  const auto keys = RecordKeys::of(scene);
  using Solution = typename Solver::Solution;
  return sweep_timed(
      solver, at, speeds,
      [keys](const Solution& s, double speed, double seconds) -> SolvedPtr {
        return std::make_shared<PlaneSolved<Solution>>(s, keys, speed, seconds,
                                                       spectrum_solver<Solver>);
      },
      options);
}

PlaneSolver make_plane_solver(const SceneSpec& scene) {
  const auto& m = scene.material;
  return PlaneSolver(StandardLinearSolid<double>(m.mu_d, m.nu, m.f, m.tau));
}

}  // namespace

SolvedPtr solve_plane(const SceneSpec& scene, double speed, double tolerance) {
  if (!scene.substrate.is_half_space()) return solve_plane_substrate(scene, speed, tolerance);
  if (scene.material.prony)
    return solve_plane_with(PlaneSpectrumSolver(prony_at(scene)), scene, speed);
  return solve_plane_with(make_plane_solver(scene), scene, speed);
}

std::vector<SolvedPtr> sweep_plane(const SceneSpec& scene, std::span<const double> speeds,
                                   double tolerance, const SweepOptions& options) {
  if (!scene.substrate.is_half_space())
    return sweep_plane_substrate(scene, speeds, tolerance, options);
  if (scene.material.prony)
    return sweep_plane_with(PlaneSpectrumSolver(prony_at(scene)), scene, speeds, options);
  return sweep_plane_with(make_plane_solver(scene), scene, speeds, options);
}

// ---------------------------------------------------------------------------------------------
// Python-facing types.

namespace {

struct Material {
  MaterialSpec spec;
};
struct StandardLinearSolidMaterial : Material {};
struct ElasticMaterial : Material {};
struct PronyMaterial : Material {};

/// A time-temperature shift law (WLF or Arrhenius).
struct Shift {
  ShiftLaw<double> law;
};
struct WlfShiftObject : Shift {};
struct ArrheniusShiftObject : Shift {};

struct Roller {
  RollerSpec spec;
};
struct EllipsoidRoller : Roller {};
struct CylinderRoller : Roller {};
struct CrownedRoller : Roller {};
struct LogarithmicRoller : Roller {};
struct TableRoller : Roller {};

/// The result of one solve, shared with Python.
struct Result {
  SolvedPtr solved;
};

std::string shortest(double x) { return cli::scene_detail::shortest(x); }

/// The message of a scene-reader error without the program's name (it names the file and key).
std::string reader_message(const std::string& what) {
  const std::string prefix = "viscoroll-solve: ";
  return what.starts_with(prefix) ? what.substr(prefix.size()) : what;
}

std::optional<Method> parse_method(const std::optional<std::string>& name) {
  if (!name) return std::nullopt;
  if (*name == "plane") return Method::plane;
  if (*name == "line") return Method::line;
  if (*name == "bem") return Method::bem;
  if (*name == "auto") return Method::automatic;
  throw std::invalid_argument("viscoroll: method = \"" + *name +
                              "\" is not one of \"plane\", \"line\", \"bem\", \"auto\"");
}

/// Each speed >= 0 and finite, and at most limits::speeds of them (as the command line).
void check_speeds(const std::vector<double>& speeds) {
  if (const std::string over = detail::count_over_limit("speeds", speeds.size(), limits::speeds);
      !over.empty())
    throw std::invalid_argument("viscoroll: " + over);
  for (const double v : speeds) detail::require_non_negative("speed", v);
}

/// The method to use: the caller's, else the scene's, else the auto method; the auto method on a
/// cylinder on the half space is the plane method, the only one it has (as viscoroll-solve's
/// from_scene; on a layer or a bed it stays auto, whose result says why it is the plane's).
Method method_for(const SceneSpec& scene, const std::optional<std::string>& method) {
  Method m = Method::automatic;
  if (auto given = parse_method(method))
    m = *given;
  else if (scene.method)
    m = *scene.method;
  return m == Method::automatic && scene.roller.cylinder && scene.substrate.is_half_space()
             ? Method::plane
             : m;
}

cli::Method to_cli(Method m) {
  switch (m) {
    case Method::plane:
      return cli::Method::plane;
    case Method::line:
      return cli::Method::line;
    case Method::bem:
      return cli::Method::bem;
    case Method::automatic:
      return cli::Method::automatic;
  }
  return cli::Method::plane;
}

/// The command line's checks of a scene against a method (the cylinder is the plane method's
/// roller; the line method's slender contact; the bem method's c2/c1; a layer or a bed not the
/// line method's; the scene's own grid; no grid for the auto method but on a cylinder, which the
/// plane method answers), and the discretisation at `tolerance` (the bem's): `grid` (the
/// caller's) wins over the scene's. The scene's tolerance is tolerance_for's.
int check_for_method(const SceneSpec& scene, Method method, std::optional<long> grid,
                     bool fast = false, double tolerance = 0) {
  if (grid && method == Method::automatic && !scene.roller.cylinder)
    throw std::invalid_argument("viscoroll: grid = " + std::to_string(*grid) +
                                " needs method 'line' or 'bem' (the auto method picks line or "
                                "bem per result, each at its own default)");
  cli::Scene s;
  if (scene.material.prony) s.material = cli::PronyModel{};
  if (scene.roller.axial)
    s.roller = *scene.roller.axial;
  else if (scene.roller.cylinder)
    s.roller = cli::CylinderProfile{scene.roller.radius};
  else
    s.roller = cli::EllipsoidProfile{scene.roller.c1, scene.roller.c2};
  if (!grid) s.grid = scene.grid;
  s.substrate = scene.substrate;
  try {
    cli::check_scene_for_method(s, to_cli(method), scene.source);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(reader_message(e.what()));
  }
  return discretisation(method, grid ? grid : scene.grid, bool(scene.material.prony), fast,
                        tolerance);
}

/// The tolerance of the method: on a layer or a spring bed with the plane method (or the auto
/// method on a cylinder, which answers by it), its relative tolerance in a, d and chi
/// (PlaneSubstrateOptions::tolerance, docs/plane-substrate.md (Q13)): the caller's `given`, else
/// the scene's, else cli::plane_substrate_tolerance (1e-4), as viscoroll-solve's plane_tolerance.
/// Otherwise the bem method's relative tolerance in d and chi (BemOptions::tolerance,
/// docs/theory.md section 17): `given`, else the scene's, else 0.01 unless a grid is given (the
/// caller's or the scene's), which fixes it; as viscoroll-solve's bem_tolerance. `given` must be
/// in the range of the method that takes it (the bem's: BemOptions' own check), with the bem or
/// auto method or the plane method on a layer or a bed; the scene's, in its method's range.
double tolerance_for(const SceneSpec& scene, std::optional<double> given, Method method,
                     std::optional<long> grid) {
  const bool plane_substrate =
      cli::solves_plane_substrate(scene.substrate.model, to_cli(method), scene.roller.cylinder);
  if (given) {
    if (plane_substrate) {
      if (!cli::tolerance_in_range(*given, true))
        throw std::invalid_argument("viscoroll: tolerance = " + shortest(*given) +
                                    " is outside the valid range " +
                                    cli::tolerance_range("tolerance", true));
    } else {
      BemOptions options;
      options.tolerance = *given;
      options.validate();  // the library's range and message
      if (method != Method::bem && method != Method::automatic)
        throw std::invalid_argument(
            std::string("viscoroll: tolerance is valid only with the bem or auto method, or the "
                        "plane method on a layer or a spring bed, got method '") +
            method_name(method) +
            "' (the plane method on the half space is exact to rounding; the line method's "
            "error is its theory's)");
    }
  } else if (scene.tolerance &&
             (plane_substrate || method == Method::bem || method == Method::automatic) &&
             !cli::tolerance_in_range(*scene.tolerance, plane_substrate)) {
    // A scene file's tolerance, read in either method's range (cli::parse_scene).
    throw std::invalid_argument(scene.source + ": tolerance = " + shortest(*scene.tolerance) +
                                " is outside the valid range " +
                                cli::tolerance_range("tolerance", plane_substrate));
  }
  const std::optional<double> tolerance = given ? given : scene.tolerance;
  if (plane_substrate) return tolerance.value_or(cli::plane_substrate_tolerance);
  return tolerance.value_or(grid || scene.grid ? 0.0 : 0.01);
}

std::optional<ShiftLaw<double>> shift_from_cli(const std::optional<cli::ShiftSpec>& shift) {
  if (!shift) return std::nullopt;
  if (shift->law == "wlf") return WlfShift<double>(shift->c1, shift->c2, shift->t_ref);
  return ArrheniusShift<double>(shift->activation_energy, shift->t_ref);
}

/// A material spec of a Prony series with its shift law (validated by the library).
MaterialSpec prony_spec(PronyRelaxation<double> reference, std::optional<ShiftLaw<double>> shift) {
  MaterialSpec out;
  out.mu_d = reference.glassy_modulus();
  out.nu = reference.nu();
  out.prony = std::make_shared<const PronySpec>(PronySpec{std::move(reference), std::move(shift)});
  return out;
}

/// A scene file's prony material: its terms, or the fit of its DMA file (relative to the scene
/// file's directory; a poor fit is a Python warning, as the command line's on stderr).
MaterialSpec prony_from_cli(const cli::PronyModel& m, const std::string& source) {
  const auto fail = [&](const std::string& message) {
    throw std::invalid_argument(source + ": " + message);
  };
  const auto shift = shift_from_cli(m.shift);
  if (m.dma.empty()) {
    std::vector<RelaxationTerm<double>> terms;
    for (const auto& t : m.terms) terms.push_back({t.g, t.tau});
    try {
      return prony_spec(PronyRelaxation<double>(m.g_inf, m.nu, std::move(terms)), shift);
    } catch (const std::invalid_argument& e) {
      fail(std::string("material: ") + e.what());
    }
  }
  std::filesystem::path path(m.dma);
  if (path.is_relative())
    path = (std::filesystem::path(source).parent_path() / path).lexically_normal();
  try {
    const auto data = read_dma_csv_file<double>(path);
    if (data.has_temperature && !shift)
      fail("material.dma = \"" + m.dma +
           "\" has a temperature_c column: give material.shift (wlf or arrhenius) to build the "
           "master curve");
    DmaFitOptions<double> options;
    options.nu = m.nu;
    options.shift = shift;
    auto fit = fit_prony(data, options);
    if (fit.report.poor)
      py::module_::import("warnings")
          .attr("warn")("viscoroll: material.dma = " + path.string() +
                        ": a poor fit of the DMA data (" + fit.report.summary +
                        "); the solutions are of the fitted spectrum");
    return prony_spec(std::move(fit.material), shift);
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    if (what.starts_with(source + ": ")) throw;
    fail("material.dma = \"" + m.dma + "\": " + what);
  }
  throw std::logic_error("unreachable");
}

/// Sets the scene's temperature: `given` (the caller's), else the law's t_ref; NaN without a
/// law. A temperature needs a Prony material with a shift law; it is checked against the law's
/// range (ValueError naming temperature).
void set_temperature(SceneSpec& s, std::optional<double> given) {
  const auto* prony = s.material.prony.get();
  if (given && !(prony && prony->shift))
    throw std::invalid_argument(
        "viscoroll: temperature is valid only with a Prony material with a shift law (WLF or "
        "Arrhenius)");
  if (!prony || !prony->shift) return;
  s.temperature = given ? *given : reference_temperature(*prony->shift);
  shift_factor(*prony->shift, s.temperature);  // validates
}

SceneSpec from_cli(const cli::Scene& in, const std::string& source) {
  SceneSpec out;
  std::visit(
      [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, cli::ElasticModel>) {
          out.material = {true, m.mu, m.nu, 0.0, 0.0, nullptr};
        } else if constexpr (std::is_same_v<M, cli::PronyModel>) {
          out.material = prony_from_cli(m, source);
        } else {
          static_assert(std::is_same_v<M, cli::StandardLinearSolidModel>);
          out.material = {false, m.mu_d, m.nu, m.f, m.tau, nullptr};
        }
      },
      in.material);
  std::visit(
      [&](const auto& r) {
        using R = std::decay_t<decltype(r)>;
        if constexpr (std::is_same_v<R, cli::EllipsoidProfile>) {
          out.roller = {false, r.c1, r.c2, 0.0, nullptr};
        } else if constexpr (std::is_same_v<R, cli::CylinderProfile>) {
          out.roller = {true, 1 / r.radius, 0.0, r.radius, nullptr};
        } else {
          // The library validates what the reader has not (a table's spline), as the command
          // line does.
          try {
            cli::visit_axial_profile(in.roller, [](const auto&, double) {});
          } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(source + ": roller: " + e.what());
          }
          out.roller = {false, 1 / r.radius, 0.0, r.radius,
                        std::make_shared<const cli::RollerProfile>(in.roller)};
        }
      },
      in.roller);
  out.load = in.load;
  out.speeds = in.speeds;
  if (in.method) out.method = parse_method(std::string(cli::method_name(*in.method)));
  out.grid = in.grid;
  out.setting = in.setting;
  out.tolerance = in.tolerance;
  out.density = in.density;
  out.strict = in.strict;
  out.substrate = in.substrate;
  out.description = in.description;
  out.source = source;
  return out;
}

/// A Python value as the scene reader's JSON: a bool, a number, a string, or a sequence of them
/// (a table's y, h); anything else as its repr (the reader then names the key and its type).
nlohmann::json to_json(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value) ||
      py::hasattr(value, "__float__"))
    return value.cast<double>();
  if (py::isinstance<py::sequence>(value) || py::isinstance<py::array>(value)) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto item : py::iter(value)) out.push_back(to_json(item));
    return out;
  }
  return py::repr(value).cast<std::string>();
}

/// A roller of finite length, `profile` ("crowned", "logarithmic", "table") with `keys` (a scene
/// Scene(substrate=...): a dict of the scene file's "substrate" keys (model, thickness, base; a
/// None value is a key left out), read by the scene file's reader, with its messages.
cli::SubstrateSpec substrate_from(const py::dict& keys) {
  namespace sd = cli::scene_detail;
  nlohmann::json object = nlohmann::json::object();
  for (const auto& [key, value] : keys)
    if (!value.is_none()) object[py::str(key).cast<std::string>()] = to_json(value);
  const nlohmann::json top = {{"substrate", object}};
  try {
    return sd::read_substrate(sd::ObjectReader("viscoroll", top, "", {}, "the scene"));
  } catch (const std::invalid_argument& e) {
    const std::string message = reader_message(e.what());
    throw std::invalid_argument(message.starts_with("viscoroll: ") ? message
                                                                   : "viscoroll: " + message);
  }
}

/// file's keys of that profile, docs/rollers.md; a None value is a key left out), read by the
/// scene file's reader and validated by the library as Scene.from_json's: the same ranges and
/// messages, naming the key ("viscoroll: radius = -1 is outside the valid range radius > 0").
RollerSpec axial_roller(const std::string& profile, const py::dict& keys) {
  namespace sd = cli::scene_detail;
  if (profile != "crowned" && profile != "logarithmic" && profile != "table")
    throw std::invalid_argument("viscoroll: profile = '" + profile +
                                "' is not one of 'crowned', 'logarithmic', 'table' (the "
                                "ellipsoid and the cylinder are Ellipsoid(c1, c2) and "
                                "Cylinder(radius))");
  nlohmann::json object = nlohmann::json::object();
  for (const auto& [key, value] : keys)
    if (!value.is_none()) object[py::str(key).cast<std::string>()] = to_json(value);
  const auto& readers = sd::roller_readers();
  const auto reader = std::find_if(readers.begin(), readers.end(),
                                   [&](const auto& r) { return r.profile == profile; });
  cli::RollerProfile roller;
  try {
    roller = reader->read(
        sd::ObjectReader("viscoroll", object, "", reader->keys, "profile '" + profile + "'"));
    cli::visit_axial_profile(roller, [](const auto&, double) {});
  } catch (const std::invalid_argument& e) {
    const std::string message = reader_message(e.what());
    throw std::invalid_argument(message.starts_with("viscoroll: ") ? message
                                                                   : "viscoroll: " + message);
  }
  const double radius = std::visit(
      [](const auto& r) -> double {
        if constexpr (requires { r.radius; })
          return r.radius;
        else
          return 0.0;
      },
      roller);
  return {false, 1 / radius, 0.0, radius,
          std::make_shared<const cli::RollerProfile>(std::move(roller))};
}

/// A 1-D float64 array as a vector (any sequence of numbers converts).
std::vector<double> as_vector(const py::object& values, const char* name) {
  // NumPy would read a string of digits as a number.
  if (py::isinstance<py::str>(values) || py::isinstance<py::bytes>(values))
    throw std::invalid_argument(std::string("viscoroll: ") + name + " = " +
                                py::repr(values).cast<std::string>() +
                                " is a string, not a number or a 1-D sequence of numbers");
  const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
  if (!array || array.ndim() > 1)
    throw std::invalid_argument(std::string("viscoroll: ") + name +
                                " must be a number or a 1-D sequence of numbers");
  const double* data = array.data();
  return std::vector<double>(data, data + array.size());
}

py::array_t<double> as_array(const std::vector<double>& values) {
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

/// The line method's setting: None or "default", or "fast" (LineOptions::fast(); the line and
/// auto methods only). None with the line or auto method: the scene file's "setting" (the other
/// methods ignore it).
bool fast_setting(const SceneSpec& scene, const std::optional<std::string>& setting,
                  Method method) {
  const bool line = method == Method::line || method == Method::automatic;
  if (!setting) return line && scene.setting == cli::LineSetting::fast;
  const auto named = cli::parse_line_setting(*setting);
  if (!named)
    throw std::invalid_argument("viscoroll: setting = '" + *setting +
                                "' is not a setting: expected None, 'default' or 'fast'");
  if (*named == cli::LineSetting::standard) return false;
  if (!line)
    throw std::invalid_argument(std::string("viscoroll: setting = 'fast' is valid only with the "
                                            "line or auto method, got method '") +
                                method_name(method) + "'");
  return true;
}

/// The record of a result not yet handed to Python, to amend (the auto method's reason, the
/// validity warnings).
Record& record_of(const SolvedPtr& solved) {
  return std::const_pointer_cast<Solved>(solved)->record_;
}

/// `solved` with the field method_reason (cli::with_method_reason).
SolvedPtr with_reason(SolvedPtr solved, const std::string& reason) {
  Record& record = record_of(solved);
  record = cli::with_method_reason(std::move(record), reason);
  return solved;
}

/// What the validity checks need of the scene (cli/validity_record.hpp), as viscoroll-solve's
/// validity_facts: the rolling radius, where the roller's body ends, the rubber's shear-wave
/// speed where the scene gives a density.
cli::ValidityFacts validity_facts(const SceneSpec& scene) {
  cli::ValidityFacts facts;
  facts.radius = rolling_radius(scene.roller);
  std::tie(facts.body_min, facts.body_max) = roller_body(scene);
  if (scene.density) {
    const auto& m = scene.material;
    const double c =
        m.prony ? m.prony->reference.instantaneous_compliance()
                : StandardLinearSolid<double>(m.mu_d, m.nu, m.f, m.tau).instantaneous_compliance();
    facts.shear_wave_speed = cli::shear_wave_speed(c, m.nu, *scene.density);
  }
  return facts;
}

/// Why the line method does not apply to the scene before any solve (cli/auto_method.hpp: the
/// ellipsoid's c2/c1, then line_precheck on the line theory's long-term contact and a roller's
/// axial_curvature_precheck), or empty.
std::string auto_precheck(const SceneSpec& scene) {
  if (!scene.substrate.is_half_space()) return cli::substrate_precheck(scene.substrate.describe());
  std::string why = scene.roller.axial ? std::string()
                                       : cli::ellipsoid_precheck(scene.roller.c1, scene.roller.c2);
  if (why.empty()) {
    const auto [a0, l0] = line_long_term(scene);
    why = cli::line_precheck(a0, l0, validity_facts(scene));
    if (why.empty() && scene.roller.axial)
      why = cli::visit_axial_profile(*scene.roller.axial, [&](const auto& profile, double) {
        return cli::axial_curvature_precheck(profile, a0, l0);
      });
  }
  return why;
}

/// The auto method's discretisations: the line method's default terms (its setting's), the bem's
/// first grid at `tolerance`.
int auto_terms(const SceneSpec& scene, bool fast) {
  return discretisation(Method::line, std::nullopt, bool(scene.material.prony), fast);
}
int auto_grid(const SceneSpec& scene, double tolerance) {
  return discretisation(Method::bem, std::nullopt, bool(scene.material.prony), false, tolerance);
}

/// The reason of the auto method's plane result for a cylinder: on the half space
/// cli::plane_cylinder(), on a layer or a spring bed cli::plane_substrate_cylinder at `tolerance`.
std::string plane_reason(const SceneSpec& scene, double tolerance) {
  return scene.substrate.is_half_space()
             ? cli::plane_cylinder()
             : cli::plane_substrate_cylinder(scene.substrate.describe(), tolerance);
}

/// The auto method at one speed, as viscoroll-solve's run_auto (cli/auto_method.hpp): the line
/// method where its theory applies and its result stands, else the bem method at `tolerance`;
/// the plane method for a cylinder (on a layer or a spring bed at `tolerance`, the plane
/// method's there: tolerance_for). `start` seeds the method it is a result of.
SolvedPtr solve_auto(const SceneSpec& scene, double speed, bool fast, double tolerance,
                     const Solved* start) {
  // The plane method takes no start, as solve(method="plane") ignores it.
  if (scene.roller.cylinder)
    return with_reason(solve_plane(scene, speed, tolerance), plane_reason(scene, tolerance));
  if (start && start->method() == Method::plane)
    throw std::invalid_argument(
        "viscoroll: start must be a result of the line or bem method for the auto method, got "
        "plane");
  const auto seed = [&](Method m) { return start && start->method() == m ? start : nullptr; };
  const auto bem = [&](const std::string& why) {
    return with_reason(
        solve_bem(scene, speed, auto_grid(scene, tolerance), tolerance, seed(Method::bem)),
        cli::bem_instead(why));
  };
  if (const std::string why = auto_precheck(scene); !why.empty()) return bem(why);
  SolvedPtr line =
      solve_line(scene, speed, auto_terms(scene, fast), fast, seed(Method::line), true);
  const std::string rejected = cli::line_rejection(line->record(), validity_facts(scene));
  if (rejected.empty()) return with_reason(std::move(line), cli::line_accepted());
  return bem(rejected);
}

/// The auto method over `speeds`, as viscoroll-solve's run_auto: the line sweep, and the bem
/// sweep of every speed when the line method cannot answer for one of them (or for none before
/// any solve); each speed's result is its line result where it stands, else its bem result.
std::vector<SolvedPtr> sweep_auto(const SceneSpec& scene, std::span<const double> speeds, bool fast,
                                  double tolerance, const SweepOptions& options) {
  const auto reasoned = [](std::vector<SolvedPtr> solved, const auto& reason_of) {
    for (std::size_t k = 0; k < solved.size(); ++k)
      solved[k] = with_reason(std::move(solved[k]), reason_of(k));
    return solved;
  };
  if (scene.roller.cylinder) {
    const std::string reason = plane_reason(scene, tolerance);
    return reasoned(sweep_plane(scene, speeds, tolerance, options),
                    [&](std::size_t) { return reason; });
  }
  const auto bems = [&] {
    return sweep_bem(scene, speeds, auto_grid(scene, tolerance), tolerance, options);
  };
  if (const std::string why = auto_precheck(scene); !why.empty())
    return reasoned(bems(), [&](std::size_t) { return cli::bem_instead(why); });
  std::vector<SolvedPtr> lines =
      sweep_line(scene, speeds, auto_terms(scene, fast), fast, options, true);
  if (options.stop && *options.stop) return lines;  // interrupted: dropped by the caller
  const auto facts = validity_facts(scene);
  std::vector<std::string> rejected;
  for (const auto& r : lines) rejected.push_back(cli::line_rejection(r->record(), facts));
  std::vector<SolvedPtr> others;
  if (std::any_of(rejected.begin(), rejected.end(), [](const auto& w) { return !w.empty(); }))
    others = bems();
  if (options.stop && *options.stop) return lines;
  for (std::size_t k = 0; k < lines.size(); ++k)
    lines[k] = rejected[k].empty()
                   ? with_reason(std::move(lines[k]), cli::line_accepted())
                   : with_reason(std::move(others[k]), cli::bem_instead(rejected[k]));
  return lines;
}

SolvedPtr solve_scene(const SceneSpec& scene, Method method, std::optional<long> grid, double speed,
                      bool fast, double tolerance, const Solved* seed) {
  const int n = check_for_method(scene, method, grid, fast, tolerance);
  switch (method) {
    case Method::plane:
      return solve_plane(scene, speed, tolerance);
    case Method::line:
      return solve_line(scene, speed, n, fast, seed);
    case Method::bem:
      return solve_bem(scene, speed, n, tolerance, seed);
    case Method::automatic:
      return solve_auto(scene, speed, fast, tolerance, seed);
  }
  throw std::logic_error("viscoroll: unknown method");
}

/// The model's validity checks (core/validity.hpp) on every result, as viscoroll-solve's: each
/// breach joins the result's warnings (cli::add_validity_warnings) and is returned as a message
/// naming the result, for Python's warnings; with `strict` the first breach is a ValueError.
std::vector<std::string> check_validity(const std::vector<SolvedPtr>& solved,
                                        const SceneSpec& scene, bool strict) {
  const cli::ValidityFacts facts = validity_facts(scene);
  std::vector<std::string> messages;
  // The scene's long-term static contact (cli::scene_breaches), on every result, once among the
  // messages; a line result that did not converge on an end-loaded roller says so
  // (cli::add_end_hint).
  const auto& m = scene.material;
  const double compliance =
      m.prony ? m.prony->reference.long_term_compliance()
              : StandardLinearSolid<double>(m.mu_d, m.nu, m.f, m.tau).long_term_compliance();
  const auto [a0, l0] =
      scene.roller.cylinder
          ? std::pair{std::sqrt(4 * compliance * scene.load / scene.roller.c1), std::nan("")}
          : line_long_term(scene);
  const auto scene_wide = cli::scene_breaches(facts, a0, scene.roller.axial ? l0 : std::nan(""),
                                              compliance, scene.load, scene.roller.c1);
  if (strict && !scene_wide.empty())
    throw std::invalid_argument("viscoroll: strict: the scene: " + scene_wide.front().text +
                                " (without strict this is a warning; docs/errors.md, \"Validity "
                                "checks\")");
  for (const auto& b : scene_wide) messages.push_back("viscoroll: the scene: " + b.text);
  for (const auto& r : solved) {
    Record& record = record_of(r);
    if (r->method() == Method::line) cli::add_end_hint(record, facts);
    cli::add_warnings(record, scene_wide, true);
  }
  for (const auto& r : solved)
    for (const auto& breach : cli::add_validity_warnings(record_of(r), facts)) {
      if (strict)
        throw std::invalid_argument("viscoroll: strict: " + cli::record_label(r->record()) + ": " +
                                    breach.text +
                                    " (without strict this is a warning; docs/errors.md, "
                                    "\"Validity checks\")");
      messages.push_back("viscoroll: " + cli::record_label(r->record()) + ": " + breach.text);
    }
  return messages;
}

/// Each message as a Python warning (UserWarning) at the caller of solve() or sweep().
void warn(const std::vector<std::string>& messages) {
  for (const auto& m : messages)
    if (PyErr_WarnEx(PyExc_UserWarning, m.c_str(), 2) != 0) throw py::error_already_set();
}

/// The sweep's fields as NumPy arrays (numbers float64, counts int64, flags bool) and lists
/// (reason, warnings), in the command line's order; `method` only with the auto method (else it
/// is the argument). A field some results lack (the auto method's line and bem results) is a
/// float64 array with nan where missing (a list: None).
py::dict to_columns(const std::vector<SolvedPtr>& solved, bool with_method) {
  py::dict out;
  if (solved.empty()) return out;
  const std::size_t n = solved.size();
  // Every result's keys, each after the key before it in the first result that has it.
  std::vector<std::string> keys;
  for (const auto& r : solved) {
    std::size_t at = 0;
    for (const auto& [key, value] : r->record()) {
      const auto it = std::find(keys.begin(), keys.end(), key);
      if (it != keys.end())
        at = static_cast<std::size_t>(it - keys.begin()) + 1;
      else
        keys.insert(keys.begin() + static_cast<std::ptrdiff_t>(at++), key);
    }
  }
  for (const auto& key : keys) {
    if (key == "method" && !with_method) continue;
    std::vector<const Value*> values(n);
    bool complete = true;
    const Value* first = nullptr;
    for (std::size_t i = 0; i < n; ++i) {
      values[i] = solved[i]->find(key);
      if (!first) first = values[i];
      complete = complete && values[i] && values[i]->index() == first->index();
    }
    const auto number = [](const Value* v) {
      if (const auto* x = std::get_if<double>(v)) return *x;
      if (const auto* c = std::get_if<long long>(v)) return static_cast<double>(*c);
      if (const auto* b = std::get_if<bool>(v)) return *b ? 1.0 : 0.0;
      return std::nan("");
    };
    if (std::holds_alternative<std::string>(*first) ||
        std::holds_alternative<std::vector<std::string>>(*first)) {
      py::list column;
      for (const Value* v : values) column.append(v ? to_python(*v) : py::none());
      out[py::str(key)] = column;
    } else if (complete && std::holds_alternative<long long>(*first)) {
      py::array_t<std::int64_t> column(static_cast<py::ssize_t>(n));
      auto* data = column.mutable_data();
      for (std::size_t i = 0; i < n; ++i)
        data[i] = static_cast<std::int64_t>(std::get<long long>(*values[i]));
      out[py::str(key)] = column;
    } else if (complete && std::holds_alternative<bool>(*first)) {
      py::array_t<bool> column(static_cast<py::ssize_t>(n));
      auto* data = column.mutable_data();
      for (std::size_t i = 0; i < n; ++i) data[i] = std::get<bool>(*values[i]);
      out[py::str(key)] = column;
    } else {
      py::array_t<double> column(static_cast<py::ssize_t>(n));
      auto* data = column.mutable_data();
      for (std::size_t i = 0; i < n; ++i) data[i] = values[i] ? number(values[i]) : std::nan("");
      out[py::str(key)] = column;
    }
  }
  return out;
}

/// The docstrings of the result's fields (the command line's JSON fields, docs/cli.md).
const std::vector<std::pair<const char*, const char*>>& field_docs() {
  static const std::vector<std::pair<const char*, const char*>> docs = {
      {"method", "'plane', 'line' or 'bem': the method that answered."},
      {"method_reason",
       "The auto method: why its method answered ('auto: line (...)', 'auto: bem (...)', "
       "'auto: plane (...)')."},
      {"tau", "Relaxation time (0 for an elastic material); not with a Prony material."},
      {"temperature", "Prony material: the temperature (degrees Celsius; nan without a shift)."},
      {"a_T", "Prony material: the shift factor a_T at that temperature (1 at t_ref)."},
      {"active_terms",
       "Prony material, plane and line: retardation terms neither relaxed nor glassy at V "
       "(after merging near-equal times)."},
      {"spectrum_error",
       "Prony material, plane and line: bound on the relative change of the complex compliance "
       "made by merging near-equal times, plus (line) the estimated share of the terms folded "
       "as relaxed or glassy; 0 if none (docs/materials.md)."},
      {"speed", "Rolling speed V."},
      {"vtau", "V tau, the memory length; not with a Prony material."},
      {"a0", "Half width of the contact at y = 0."},
      {"b0", "Offset of the contact's centre at y = 0 ahead of the roller's axis."},
      {"l", "Half length of the contact along the roller's axis (line, bem)."},
      {"y_minus", "Lower end of the contact along the axis, -l if symmetric (line, bem)."},
      {"y_plus", "Upper end of the contact along the axis, +l if symmetric (line, bem)."},
      {"f0_max", "Largest load per unit length along the roller, N/m (line, bem)."},
      {"f0_max_y", "Where the load per unit length is largest, m (as f0_max)."},
      {"d",
       "Penetration (line, bem; plane on a layer or a spring bed). On a layer or a bed it is "
       "measured from the rigid base (the surface far from the contact)."},
      {"a_long_term",
       "Half width at its centre of the static (V = 0) contact under the long-term modulus: "
       "plane, Hertz's strip; line, the line theory's; bem, Hertz's ellipse (an Ellipsoid) or "
       "the line theory's (a roller of finite length); nan where the line theory has none. Not "
       "given by the plane method on a layer or a spring bed."},
      {"l0", "Half length of that static long-term contact (line, bem)."},
      {"d0", "Penetration of that static long-term contact (line, bem)."},
      {"chi",
       "Rolling-friction coefficient chi = F/W (Eq. 51/54): the rolling-resistance force over "
       "the load."},
      {"rolling_resistance",
       "F = chi W, the rolling-resistance force (N with SI inputs; plane: per unit length, N/m)."},
      {"power_loss", "P = chi W V, the power the rolling resistance costs (W; plane: W/m)."},
      {"energy_per_revolution",
       "E = chi W 2 pi R, the energy lost per revolution of the roller (J; plane: J/m); R the "
       "roller's radius (an Ellipsoid: 1/c1)."},
      {"pmax", "Peak pressure on y = 0 (not line with a Prony material)."},
      {"pmax_x", "Where the peak pressure on y = 0 is (not line with a Prony material)."},
      {"seconds", "Run time of this solve (s)."},
      {"converged", "The iteration met its tolerance (nothing is claimed otherwise)."},
      {"root",
       "line: the line equations have a root here (False: a certified least-squares minimum)."},
      {"iterations", "Iterations (bem: active-set iterations)."},
      {"residual", "Final residual (nan where undefined)."},
      {"terms",
       "line: Chebyshev terms of ln a(y) (the grid argument); plane on a layer or a spring bed: "
       "the Chebyshev terms of the pressure that answered (0 on a spring bed, a closed form)."},
      {"gmres_iterations", "bem: Krylov iterations over all active-set iterations."},
      {"grid",
       "bem: elements per semi-axis of the static long-term Hertz ellipse, of the grid that "
       "answered."},
      {"cells", "bem: cells of the grid."},
      {"tolerance",
       "bem: the relative tolerance asked in d and chi (0: one grid, no estimate); plane on a "
       "layer or a spring bed: the relative tolerance asked in a0, d and chi."},
      {"tolerance_met", "bem: the error estimates of d and chi met the tolerance."},
      {"error_d",
       "bem with a tolerance, plane on a layer or a spring bed: the estimated discretisation "
       "error of d, in d's units (bem: nan where not estimated, a grid resolved the contact "
       "alone)."},
      {"error_chi",
       "bem with a tolerance, plane on a layer or a spring bed: the estimated error of chi "
       "(absolute)."},
      {"error_a0",
       "bem with a tolerance, plane on a layer or a spring bed: the estimated error of a0 "
       "(absolute)."},
      {"error_b0", "bem with a tolerance: the estimated error of b0 (absolute)."},
      {"error_l", "bem with a tolerance: the estimated error of l (absolute)."},
      {"error_pmax",
       "bem with a tolerance, plane on a layer or a spring bed: the estimated error of pmax "
       "(absolute; plane: reported, not held to the tolerance)."},
      {"substrate",
       "plane on a layer or a spring bed: the body, as 'layer (thickness 0.004 m, bonded)' or "
       "'spring_bed (thickness 0.004 m)'."},
      {"reason", "Why the solve stopped, in words (plane: empty when converged)."},
      {"code",
       "Why the solve stopped, a stable name from viscoroll.STOP_CODES: 'converged' for a "
       "converged result, else e.g. 'iteration_limit', 'not_a_contact', "
       "'contact_reaches_body_end'."},
      {"warnings",
       "The solver's warnings and the model's validity checks that the result breaches (a list "
       "of str)."},
      {"warning_codes",
       "The warnings' stable names from viscoroll.WARNING_CODES, index for index with warnings "
       "(a list of str), e.g. 'small_slope', 'least_squares_minimum'."},
  };
  return docs;
}

std::string shift_repr(const ShiftLaw<double>& law) {
  if (const auto* w = std::get_if<WlfShift<double>>(&law))
    return "WLF(c1=" + shortest(w->c1()) + ", c2=" + shortest(w->c2()) +
           ", t_ref=" + shortest(w->t_ref()) + ")";
  const auto& a = std::get<ArrheniusShift<double>>(law);
  return "Arrhenius(activation_energy=" + shortest(a.activation_energy()) +
         ", t_ref=" + shortest(a.t_ref()) + ")";
}

std::string material_repr(const MaterialSpec& m) {
  if (m.prony) {
    const auto& r = m.prony->reference;
    std::string out =
        "Prony(g_inf=" + shortest(r.g_inf()) + ", nu=" + shortest(r.nu()) + ", terms=[";
    for (std::size_t i = 0; i < r.terms().size(); ++i)
      out += (i ? ", (" : "(") + shortest(r.terms()[i].g) + ", " + shortest(r.terms()[i].rho) + ")";
    out += "]";
    if (m.prony->shift) out += ", shift=" + shift_repr(*m.prony->shift);
    return out + ")";
  }
  if (m.elastic) return "Elastic(mu=" + shortest(m.mu_d) + ", nu=" + shortest(m.nu) + ")";
  return "StandardLinearSolid(mu_d=" + shortest(m.mu_d) + ", nu=" + shortest(m.nu) +
         ", f=" + shortest(m.f) + ", tau=" + shortest(m.tau) + ")";
}

/// The Python class of a roller of finite length ("Crowned").
std::string axial_class(const cli::RollerProfile& roller) {
  std::string name = cli::roller_profile_name(roller);
  name[0] = static_cast<char>(name[0] - 'a' + 'A');
  return name;
}

/// A roller of finite length as its keys: Crowned(radius=..., flat_length=..., ...).
std::string axial_repr(const cli::RollerProfile& roller) {
  std::string out = axial_class(roller) + "(";
  const auto key = [&](const char* name, double x) {
    out += std::string(out.ends_with("(") ? "" : ", ") + name + "=" + shortest(x);
  };
  const auto list = [&](const char* name, const std::vector<double>& xs) {
    out += std::string(out.ends_with("(") ? "" : ", ") + name + "=[";
    for (std::size_t i = 0; i < xs.size(); ++i) out += (i ? ", " : "") + shortest(xs[i]);
    out += "]";
  };
  if (const auto* c = std::get_if<cli::CrownedProfile>(&roller)) {
    key("radius", c->radius);
    key("flat_length", c->flat_length);
    key("crown_radius", c->crown_radius);
    if (std::isfinite(c->length)) key("length", c->length);
  } else if (const auto* g = std::get_if<cli::LogarithmicProfile>(&roller)) {
    key("radius", g->radius);
    key("length", g->length);
    key("scale", g->scale);
    if (std::isfinite(g->end_drop)) key("end_drop", g->end_drop);
  } else {
    const auto& t = std::get<cli::TableProfile>(roller);
    key("radius", t.radius);
    list("y", t.y);
    list("h", t.h);
  }
  const double tilt = cli::roller_tilt(roller);
  if (tilt != 0) key("tilt", tilt);
  return out + ")";
}

std::string roller_repr(const RollerSpec& r) {
  if (r.axial) return axial_repr(*r.axial);
  if (r.cylinder) return "Cylinder(radius=" + shortest(r.radius) + ")";
  return "Ellipsoid(c1=" + shortest(r.c1) + ", c2=" + shortest(r.c2) + ")";
}

py::object material_object(const MaterialSpec& m) {
  if (m.prony) return py::cast(PronyMaterial{{m}});
  if (m.elastic) return py::cast(ElasticMaterial{{m}});
  return py::cast(StandardLinearSolidMaterial{{m}});
}

py::object shift_object(const ShiftLaw<double>& law) {
  if (std::holds_alternative<WlfShift<double>>(law)) return py::cast(WlfShiftObject{{law}});
  return py::cast(ArrheniusShiftObject{{law}});
}

/// The compliances of any material spec (the library's values).
double compliance(const MaterialSpec& m, bool long_term) {
  if (m.prony)
    return long_term ? m.prony->reference.long_term_compliance()
                     : m.prony->reference.instantaneous_compliance();
  const StandardLinearSolid<double> sls(m.mu_d, m.nu, m.f, m.tau);
  return long_term ? sls.long_term_compliance() : sls.instantaneous_compliance();
}

py::object roller_object(const RollerSpec& r) {
  if (r.axial) {
    if (std::holds_alternative<cli::CrownedProfile>(*r.axial)) return py::cast(CrownedRoller{{r}});
    if (std::holds_alternative<cli::LogarithmicProfile>(*r.axial))
      return py::cast(LogarithmicRoller{{r}});
    return py::cast(TableRoller{{r}});
  }
  if (r.cylinder) return py::cast(CylinderRoller{{r}});
  return py::cast(EllipsoidRoller{{r}});
}

// Pickling (copy, multiprocessing, Dask): a material, shift or roller is its class and its
// constructor's arguments (__reduce__), a scene the dict of its fields (py::pickle). Every number
// is the stored double, so an unpickled scene solves to the same bits.

/// A shift law's constructor arguments, in its constructor's order.
py::tuple shift_arguments(const ShiftLaw<double>& law) {
  if (const auto* w = std::get_if<WlfShift<double>>(&law))
    return py::make_tuple(w->c1(), w->c2(), w->t_ref());
  const auto& a = std::get<ArrheniusShift<double>>(law);
  return py::make_tuple(a.activation_energy(), a.t_ref());
}

/// A material's constructor arguments, in its constructor's order.
py::tuple material_arguments(const MaterialSpec& m) {
  if (m.prony) {
    const auto& r = m.prony->reference;
    py::list terms;
    for (const auto& t : r.terms()) terms.append(py::make_tuple(t.g, t.rho));
    return py::make_tuple(r.g_inf(), r.nu(), terms,
                          m.prony->shift ? shift_object(*m.prony->shift) : py::none());
  }
  if (m.elastic) return py::make_tuple(m.mu_d, m.nu);
  return py::make_tuple(m.mu_d, m.nu, m.f, m.tau);
}

/// A roller's constructor arguments by name, in its constructor's order, so that
/// type(roller)(**arguments) rebuilds it (a roller of finite length's optional length or end drop
/// None where it has none); a Roller(profile=...) is its profile's class's.
py::dict roller_arguments(const RollerSpec& r) {
  py::dict out;
  const auto optional = [](double x) -> py::object {
    return std::isfinite(x) ? py::object(py::float_(x)) : py::object(py::none());
  };
  if (!r.axial) {
    if (r.cylinder) {
      out["radius"] = r.radius;
    } else {
      out["c1"] = r.c1;
      out["c2"] = r.c2;
    }
  } else if (const auto* c = std::get_if<cli::CrownedProfile>(&*r.axial)) {
    out["radius"] = c->radius;
    out["flat_length"] = c->flat_length;
    out["crown_radius"] = c->crown_radius;
    out["length"] = optional(c->length);
    out["tilt"] = c->tilt;
  } else if (const auto* g = std::get_if<cli::LogarithmicProfile>(&*r.axial)) {
    out["radius"] = g->radius;
    out["length"] = g->length;
    out["scale"] = g->scale;
    out["end_drop"] = optional(g->end_drop);
    out["tilt"] = g->tilt;
  } else {
    const auto& t = std::get<cli::TableProfile>(*r.axial);
    out["radius"] = t.radius;
    out["y"] = py::cast(t.y);
    out["h"] = py::cast(t.h);
    out["tilt"] = t.tilt;
  }
  return out;
}

/// A scene's fields, its pickled state; the objects among them pickle themselves.
py::dict scene_state(const SceneSpec& s) {
  py::dict out;
  out["material"] = material_object(s.material);
  out["roller"] = roller_object(s.roller);
  out["load"] = s.load;
  out["speeds"] = py::cast(s.speeds);
  out["temperature"] = s.material.prony && !std::isnan(s.temperature)
                           ? py::object(py::float_(s.temperature))
                           : py::object(py::none());
  out["density"] = py::cast(s.density);
  py::dict substrate;
  substrate["model"] = s.substrate.model;
  if (!s.substrate.is_half_space()) substrate["thickness"] = s.substrate.thickness;
  if (s.substrate.model == "layer") substrate["base"] = s.substrate.base;
  out["substrate"] = substrate;
  out["method"] = s.method ? py::object(py::str(method_name(*s.method))) : py::object(py::none());
  out["grid"] = py::cast(s.grid);
  out["setting"] =
      s.setting ? py::object(py::str(cli::line_setting_name(*s.setting))) : py::object(py::none());
  out["tolerance"] = py::cast(s.tolerance);
  out["strict"] = s.strict;
  out["description"] = s.description;
  out["source"] = s.source;
  return out;
}

/// The scene of a state (scene_state's keys), checked as Scene() checks its arguments.
SceneSpec scene_from_state(const py::dict& state) {
  const auto optional = [&](const char* key) -> std::optional<py::object> {
    if (!state.contains(key) || state[key].is_none()) return std::nullopt;
    return py::reinterpret_borrow<py::object>(state[key]);
  };
  SceneSpec s;
  s.material = state["material"].cast<const Material&>().spec;
  s.roller = state["roller"].cast<const Roller&>().spec;
  if (const auto substrate = optional("substrate"))
    s.substrate = substrate_from(substrate->cast<py::dict>());
  s.load = state["load"].cast<double>();
  viscoroll::detail::require_positive("load", s.load);
  if (const auto speeds = optional("speeds")) s.speeds = as_vector(*speeds, "speeds");
  check_speeds(s.speeds);
  const auto temperature = optional("temperature");
  set_temperature(s, temperature ? std::optional(temperature->cast<double>()) : std::nullopt);
  if (const auto density = optional("density")) {
    s.density = density->cast<double>();
    viscoroll::detail::require_positive("density", *s.density);
  }
  if (const auto method = optional("method")) s.method = parse_method(method->cast<std::string>());
  if (const auto grid = optional("grid")) s.grid = grid->cast<long>();
  if (const auto setting = optional("setting")) {
    const auto text = setting->cast<std::string>();
    s.setting = cli::parse_line_setting(text);
    if (!s.setting)
      throw std::invalid_argument("viscoroll: setting = '" + text +
                                  "' is not a setting: expected None, 'default' or 'fast'");
  }
  if (const auto tolerance = optional("tolerance")) s.tolerance = tolerance->cast<double>();
  if (const auto strict = optional("strict")) s.strict = strict->cast<bool>();
  if (const auto description = optional("description"))
    s.description = description->cast<std::string>();
  if (const auto source = optional("source")) s.source = source->cast<std::string>();
  return s;
}

constexpr const char* solve_doc = R"doc(
solve(scene, method=None, grid=None, speed=None, start=None, setting=None, tolerance=None,
      strict=None) -> Result

Solve one scene at one speed.

Parameters
----------
scene : Scene
    Material, roller, load (line, bem: total load; plane: load per unit length) and speeds.
method : {"auto", "line", "plane", "bem"}, optional
    "line": the paper's 3-D line-contact theory (an Ellipsoid with c2 < 8 e^-3 c1, or a
    roller of finite length: Crowned, Logarithmic, Table);
    "plane": Hunter's plane problem of a cylinder (an Ellipsoid's c2 is ignored); on a
    layer or a spring bed (Scene's substrate) the plane problem on that body
    (PlaneSubstrateSolver), to `tolerance`;
    "bem": the exact 3-D boundary-element reference (an Ellipsoid or a roller of finite
    length, tilted or not), to `tolerance`;
    "auto": the line method where its theory applies (a slender long-term contact inside the
    roller) and its result stands (converged to a root, no warning, slender, inside the
    roller), else the bem method; the plane method for a Cylinder; on a layer or a spring
    bed the bem method, and the plane method for a Cylinder. Its result's method is the one
    that answered, and method_reason says why.
    Default: the scene's method (a scene file's "method"), else "auto".
grid : int, optional
    Discretisation, as viscoroll-solve --grid: line, Chebyshev terms of ln a(y), 1..64
    (default 6; 4 for a Prony material); bem, elements per semi-axis of the static long-term
    Hertz ellipse, 2..512 (default 16 on one grid; with a tolerance the first grid, default
    8); ignored by plane; not with "auto" (but for a Cylinder, which it answers by the plane
    method). Default: the scene's grid, else those defaults.
speed : float, optional
    Rolling speed >= 0. Default: the scene's only speed (a ValueError if it has none or
    several; use sweep() for several).
start : Result, optional
    A result of the same method, material and setting at a nearby speed to continue from
    (line, bem).
setting : {"default", "fast"}, optional
    line only: "fast" is viscoroll-solve --setting fast, LineOptions::fast() (5 terms unless
    grid is given, integrals to 1e-4, loose intermediate stages) on 6-point panels: within 1%
    of the converged solution in a(0), b(0), l, d and chi on the paper's scene at
    V tau/a0 = 1e-3 ... 1e3, about 1 ms a solve (docs/performance.md, "The fast setting").
    A Prony material keeps its 4 terms and 12-point panels. Also the auto method's line
    solves. Default (None): the scene file's "setting" with the line or auto method, else
    "default".
tolerance : float, optional
    bem and auto: the relative accuracy asked in d and chi, 0 (one grid, no estimate) or
    1e-4..0.5. The bem refines its grid (doubling it from `grid`, up to 128) until its error
    estimates of d and chi (error_d, error_chi) are within it; tolerance_met says whether
    they are. Default: the scene's tolerance, else 0.01 unless a grid is given (the call's
    or the scene's), which solves on that one grid.
    plane on a layer or a spring bed (and auto on a Cylinder there): the relative accuracy
    asked in a0, d and chi, 64 eps (1.4e-14)..0.1; the Chebyshev terms double from 16 until
    the error estimates (error_a0, error_d, error_chi) are within it, else converged is
    False with a reason. Default: the scene's tolerance, else 1e-4 (docs/cli.md).
strict : bool, optional
    True: a result that breaches its model's assumptions (small slopes a0/R <= 0.2, a contact
    inside the roller, the line theory's slenderness, quasi-static rolling where the scene
    gives a density; docs/errors.md, "Validity checks") raises ValueError. False: each breach
    is a warning (in the result's warnings, and a Python UserWarning). Default: the scene's
    strict, else False.

Returns
-------
Result
    The scalar outputs as attributes (a0, b0, l, d, chi, pmax, converged, reason, ...: the
    command line's JSON fields) and the functions pressure(x, y), a(y), b(y), f0(y).

Raises
------
ValueError
    Invalid input, with the library's message naming the parameter; with strict, a breach of
    the model's assumptions. A solve that does not converge raises nothing: its result has
    converged == False and a reason.

Example
-------
>>> import viscoroll as vr
>>> scene = vr.Scene(material=vr.StandardLinearSolid(mu_d=3.0e6, nu=0.5, f=9.0, tau=0.01),
...                  roller=vr.Ellipsoid(c1=20.0, c2=1.596582), load=20.0)
>>> r = vr.solve(scene, speed=1.0)
>>> r.method, r.method_reason, r.converged, r.a0, r.chi
)doc";

constexpr const char* sweep_doc = R"doc(
sweep(scene, speeds=None, method=None, grid=None, threads=None, chunk=16, with_results=False,
      setting=None, tolerance=None, strict=None) -> dict

Solve one scene over many speeds on several threads (viscoroll::sweep).

The speeds are cut, in the order given, into chunks of `chunk` speeds. Within a chunk each
speed continues from the previous converged solution (as the command line does); the first
speed of a chunk starts cold. Chunks run on `threads` threads with the GIL released; the
numbers are the same bit for bit for any thread count. chunk=len(speeds) continues through
every speed, serially, as viscoroll-solve and panek_kalker do.

Parameters
----------
scene : Scene
speeds : sequence of float, optional
    Speeds >= 0, solved in this order; default the scene's speeds.
method, grid, setting, tolerance, strict : as for solve(). The auto method sweeps the line
    method, and the bem method over every speed when a line result cannot answer for one.
threads : int, optional
    Worker threads, 0..4096; None or 0: every core (std::thread::hardware_concurrency()).
chunk : int, optional
    Speeds per chunk of continuation, 1..1048576 (default 16, viscoroll::SweepOptions's).
with_results : bool, optional
    Also return the Result of every speed (key "results").

Returns
-------
dict
    One entry per output field of solve() except "method", in the command line's order:
    numbers as float64 arrays, counts (iterations, terms, ...) as int64 arrays, converged
    (and, line, root) as bool arrays, reason (str) and warnings (list of str) as lists. The
    auto method adds "method" and "method_reason" (lists of str); a field that some of its
    results lack (line's root, bem's grid) is a float64 array with nan there (a list: None).
    Non-convergence is per speed: check converged. with_results=True adds "results", the
    list of Result objects (for pressure(x, y), a(y), ... at each speed, or as start= of
    solve()).

Raises
------
ValueError
    Invalid input (checked before any solve), with the library's message; with strict, a
    breach of the model's assumptions (after the solves).
)doc";

}  // namespace

SolveSetup solve_setup(const SceneSpec& scene, const std::optional<std::string>& method,
                       std::optional<long> grid, const std::optional<std::string>& setting,
                       std::optional<double> tolerance, std::optional<bool> strict) {
  SolveSetup out;
  out.method = method_for(scene, method);
  out.fast = fast_setting(scene, setting, out.method);
  out.tolerance = tolerance_for(scene, tolerance, out.method, grid);
  out.grid = grid;
  check_for_method(scene, out.method, grid, out.fast, out.tolerance);
  out.strict = strict.value_or(scene.strict);
  return out;
}

SolvedPtr solve_with(const SceneSpec& scene, const SolveSetup& setup, double speed,
                     const Solved* start, std::vector<std::string>& breaches) {
  viscoroll::detail::require_non_negative("speed", speed);
  SolvedPtr solved =
      solve_scene(scene, setup.method, setup.grid, speed, setup.fast, setup.tolerance, start);
  for (auto& m : check_validity({solved}, scene, setup.strict)) breaches.push_back(std::move(m));
  return solved;
}

}  // namespace viscoroll::python

PYBIND11_MODULE(_viscoroll, m) {
  // std::invalid_argument becomes ValueError with its message read as UTF-8, any byte that is not
  // shown as an escape (pybind11's own translation would lose such a message), never empty.
  py::register_local_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const std::invalid_argument& e) {
      std::string what = e.what();
      if (what.empty()) what = "viscoroll: invalid input (std::invalid_argument without a message)";
      const py::object text = py::reinterpret_steal<py::object>(PyUnicode_DecodeUTF8(
          what.data(), static_cast<py::ssize_t>(what.size()), "backslashreplace"));
      PyErr_SetObject(PyExc_ValueError, text.ptr());
    }
  });
  using namespace viscoroll::python;
  namespace vp = viscoroll::python;
  m.doc() =
      "viscoroll: steady rolling of a rigid roller on a viscoelastic half space (Panek & Kalker "
      "1980).\n\nThe compiled part of the package `viscoroll`; see help(viscoroll).";
  m.attr("__version__") = VISCOROLL_PYTHON_VERSION;
  m.attr("DEFAULT_CHUNK") = viscoroll::SweepOptions{}.chunk;  // sweep()'s default chunk
  // The stable names of a result's `code` and `warning_codes` (core/outcome.hpp), in the enums'
  // order.
  const auto names = [](const auto& list) {
    py::list out;
    for (const std::string_view n : list) out.append(py::str(n.data(), n.size()));
    return py::tuple(out);
  };
  m.attr("STOP_CODES") = names(viscoroll::detail::stop_code_names);
  m.attr("WARNING_CODES") = names(viscoroll::detail::warning_code_names);

  // Materials.
  py::class_<vp::Material>(m, "Material",
                           "Base class of the materials (StandardLinearSolid, Elastic).")
      .def_property_readonly(
          "nu", [](const vp::Material& s) { return s.spec.nu; }, "Poisson's ratio.")
      .def_property_readonly(
          "instantaneous_compliance",
          [](const vp::Material& s) { return compliance(s.spec, false); },
          "c = (1 - nu)/(2 pi mu_d), the factor of the Boussinesq equation (mu_d the glassy "
          "modulus; the library's value).")
      .def_property_readonly(
          "long_term_compliance", [](const vp::Material& s) { return compliance(s.spec, true); },
          "(1 + f) c (a Prony series: (1 + sum f_k) c), the compliance under a load held for "
          "long.")
      .def("__repr__", [](const vp::Material& s) { return material_repr(s.spec); })
      .def("__reduce__", [](const vp::Material& s) {
        return py::make_tuple(py::type::of(material_object(s.spec)), material_arguments(s.spec));
      });

  py::class_<StandardLinearSolidMaterial, vp::Material>(
      m, "StandardLinearSolid",
      "StandardLinearSolid(mu_d, nu, f, tau)\n\n"
      "The standard linear solid of the paper's Eq. (1): instantaneous (glassy) shear modulus\n"
      "mu_d > 0, Poisson's ratio -1 < nu <= 0.5, creep ratio f >= 0 (the long-term modulus is\n"
      "mu_d/(1 + f)), relaxation time tau >= 0. Raises ValueError naming a parameter out of "
      "range.")
      .def(py::init([](double mu_d, double nu, double f, double tau) {
             viscoroll::StandardLinearSolid<double>(mu_d, nu, f, tau);  // validates
             return StandardLinearSolidMaterial{{{false, mu_d, nu, f, tau, nullptr}}};
           }),
           py::arg("mu_d"), py::arg("nu"), py::arg("f"), py::arg("tau"))
      .def_property_readonly(
          "mu_d", [](const vp::Material& s) { return s.spec.mu_d; }, "Instantaneous shear modulus.")
      .def_property_readonly(
          "f", [](const vp::Material& s) { return s.spec.f; }, "Creep ratio of Eq. (1).")
      .def_property_readonly(
          "tau", [](const vp::Material& s) { return s.spec.tau; }, "Relaxation time.");

  py::class_<ElasticMaterial, vp::Material>(
      m, "Elastic",
      "Elastic(mu, nu)\n\nA linear elastic half space: shear modulus mu > 0, Poisson's ratio\n"
      "-1 < nu <= 0.5 (solved as the standard linear solid with f = tau = 0, as on the command\n"
      "line). Raises ValueError naming a parameter out of range.")
      .def(py::init([](double mu, double nu) {
             viscoroll::Elastic<double>(mu, nu);  // validates
             return ElasticMaterial{{{true, mu, nu, 0.0, 0.0, nullptr}}};
           }),
           py::arg("mu"), py::arg("nu"))
      .def_property_readonly(
          "mu", [](const vp::Material& s) { return s.spec.mu_d; }, "Shear modulus.");

  py::class_<vp::Shift>(m, "Shift", "Base class of the time-temperature shifts (WLF, Arrhenius).")
      .def(
          "factor",
          [](const vp::Shift& s, double temperature) {
            return viscoroll::shift_factor(s.law, temperature);
          },
          py::arg("temperature"),
          "factor(temperature) -> float\n\nThe shift factor a_T (1 at t_ref): every time of the "
          "spectrum\nis multiplied by it at that temperature (degrees Celsius).")
      .def_property_readonly(
          "t_ref", [](const vp::Shift& s) { return viscoroll::reference_temperature(s.law); },
          "Reference temperature (degrees Celsius).")
      .def("__repr__", [](const vp::Shift& s) { return shift_repr(s.law); })
      .def("__reduce__", [](const vp::Shift& s) {
        return py::make_tuple(py::type::of(shift_object(s.law)), shift_arguments(s.law));
      });
  py::class_<WlfShiftObject, vp::Shift>(
      m, "WLF",
      "WLF(c1, c2, t_ref)\n\nThe Williams-Landel-Ferry shift: log10 a_T = -c1 (T - t_ref)/(c2 + "
      "T - t_ref),\nc1 > 0, c2 > 0 (K), t_ref in degrees Celsius; valid for T > t_ref - c2.")
      .def(py::init([](double c1, double c2, double t_ref) {
             return WlfShiftObject{{viscoroll::WlfShift<double>(c1, c2, t_ref)}};
           }),
           py::arg("c1"), py::arg("c2"), py::arg("t_ref"));
  py::class_<ArrheniusShiftObject, vp::Shift>(
      m, "Arrhenius",
      "Arrhenius(activation_energy, t_ref)\n\nThe Arrhenius shift: ln a_T = (E_a/R)(1/T - "
      "1/T_ref) in kelvin,\nactivation_energy > 0 (J/mol), t_ref in degrees Celsius.")
      .def(py::init([](double activation_energy, double t_ref) {
             return ArrheniusShiftObject{
                 {viscoroll::ArrheniusShift<double>(activation_energy, t_ref)}};
           }),
           py::arg("activation_energy"), py::arg("t_ref"));

  py::class_<PronyMaterial, vp::Material>(
      m, "Prony",
      "Prony(g_inf, nu, terms, shift=None)\n\n"
      "A generalised Maxwell solid in relaxation form, G(t) = g_inf + sum g exp(-t/tau)\n"
      "(docs/materials.md): long-term shear modulus g_inf > 0, Poisson's ratio -1 < nu <= 0.5,\n"
      "terms a sequence of (g, tau) pairs (g >= 0, tau > 0), and optionally a shift (WLF or\n"
      "Arrhenius) for Scene(temperature=...). Every method solves it: plane and bem exactly,\n"
      "line by the line theory for a spectrum (slower; default grid 4). Raises ValueError\n"
      "naming a parameter out of range.")
      .def(py::init([](double g_inf, double nu, const std::vector<std::pair<double, double>>& terms,
                       const std::optional<vp::Shift>& shift) {
             // As a scene file's material.terms: a spectrum has at least one term.
             viscoroll::detail::require(!terms.empty(), "len(terms)", terms.size(),
                                        "len(terms) >= 1 (at least one (g, tau) pair)");
             std::vector<viscoroll::RelaxationTerm<double>> t;
             for (const auto& [g, tau] : terms) t.push_back({g, tau});
             return PronyMaterial{{prony_spec(viscoroll::PronyRelaxation<double>(g_inf, nu, t),
                                              shift ? std::optional(shift->law) : std::nullopt)}};
           }),
           py::arg("g_inf"), py::arg("nu"), py::arg("terms"), py::arg("shift") = py::none())
      .def_property_readonly(
          "g_inf", [](const vp::Material& s) { return s.spec.prony->reference.g_inf(); },
          "Long-term shear modulus.")
      .def_property_readonly(
          "terms",
          [](const vp::Material& s) {
            std::vector<std::pair<double, double>> out;
            for (const auto& t : s.spec.prony->reference.terms()) out.emplace_back(t.g, t.rho);
            return out;
          },
          "The relaxation terms (g, tau) as given.")
      .def_property_readonly(
          "glassy_modulus", [](const vp::Material& s) { return s.spec.mu_d; },
          "g_inf + sum g, the instantaneous shear modulus.")
      .def_property_readonly(
          "shift",
          [](const vp::Material& s) -> py::object {
            if (!s.spec.prony->shift) return py::none();
            return shift_object(*s.spec.prony->shift);
          },
          "The shift law, or None.");

  // Rollers.
  py::class_<vp::Roller>(
      m, "Roller",
      "Roller(profile, **keys)\n\n"
      "Base class of the roller profiles (Ellipsoid, Cylinder, Crowned, Logarithmic, Table).\n"
      "Roller(profile='crowned', radius=..., ...) builds a roller of finite length from a scene\n"
      "file's roller keys (docs/rollers.md), as Crowned(...), Logarithmic(...), Table(...) do.")
      .def(py::init([](const std::string& profile, const py::kwargs& keys) {
             return vp::Roller{axial_roller(profile, keys)};
           }),
           py::arg("profile"))
      .def("__repr__", [](const vp::Roller& r) { return roller_repr(r.spec); })
      .def("__reduce__",
           [](const vp::Roller& r) {
             const py::dict arguments = roller_arguments(r.spec);
             py::list values;
             for (const auto& [key, value] : arguments) values.append(value);
             return py::make_tuple(py::type::of(roller_object(r.spec)), py::tuple(values));
           })
      .def_property_readonly(
          "_arguments", [](const vp::Roller& r) { return roller_arguments(r.spec); },
          "The constructor's arguments by name: type(roller)(**roller._arguments) rebuilds it "
          "(viscoroll.study's roller axes).");
  py::class_<EllipsoidRoller, vp::Roller>(
      m, "Ellipsoid",
      "Ellipsoid(c1, c2)\n\nThe paper's doubly parabolic roller (Eq. 27), gap c1 x^2/2 + c2 "
      "y^2/2:\ncurvature c1 > 0 across the rolling direction, c2 > 0 along the axis (line: c2 < "
      "8 e^-3 c1;\nbem: 1e-10 <= c2/c1 <= 1e10; plane uses c1 only).")
      .def(py::init([](double c1, double c2) {
             viscoroll::detail::require_positive("c1", c1);
             viscoroll::detail::require_positive("c2", c2);
             return EllipsoidRoller{{{false, c1, c2, 0.0, nullptr}}};
           }),
           py::arg("c1"), py::arg("c2"))
      .def_property_readonly(
          "c1", [](const vp::Roller& r) { return r.spec.c1; }, "Curvature across (1/radius).")
      .def_property_readonly(
          "c2", [](const vp::Roller& r) { return r.spec.c2; }, "Curvature along the axis.");
  py::class_<CylinderRoller, vp::Roller>(
      m, "Cylinder",
      "Cylinder(radius)\n\nA cylinder of radius > 0: the plane method's roller (c1 = 1/radius).")
      .def(py::init([](double radius) {
             viscoroll::detail::require_positive("radius", radius);
             return CylinderRoller{{{true, 1 / radius, 0.0, radius, nullptr}}};
           }),
           py::arg("radius"))
      .def_property_readonly(
          "radius", [](const vp::Roller& r) { return r.spec.radius; }, "Radius.")
      .def_property_readonly(
          "c1", [](const vp::Roller& r) { return r.spec.c1; }, "1/radius.");

  // Rollers of finite length: a scene file's crowned, logarithmic and table rollers
  // (docs/rollers.md), read by its reader (axial_roller).
  const auto keys = [](std::initializer_list<std::pair<const char*, py::object>> items) {
    py::dict out;
    for (const auto& [key, value] : items) out[key] = value;
    return out;
  };
  const auto axial_properties = [](auto& cls) {
    cls.def_property_readonly(
           "radius", [](const vp::Roller& r) { return r.spec.radius; }, "Radius R (c1 = 1/R).")
        .def_property_readonly(
            "tilt", [](const vp::Roller& r) { return viscoroll::cli::roller_tilt(*r.spec.axial); },
            "Misalignment (rad), 0 when aligned.");
  };
  py::class_<CrownedRoller, vp::Roller> crowned(
      m, "Crowned",
      "Crowned(radius, flat_length, crown_radius, length=None, tilt=None)\n\n"
      "A cylinder of radius > 0 with a flat part of flat_length >= 0 and circular crowns of\n"
      "crown_radius > 0 beyond it, cut at length > flat_length (None: at the crown circle's\n"
      "end), misaligned by |tilt| < 0.1 rad: a scene file's \"crowned\" roller\n"
      "(docs/rollers.md; the line and bem methods). Lengths in the scene's units (m with SI).\n"
      "Raises ValueError naming a parameter out of range.");
  crowned.def(py::init([keys](const py::object& radius, const py::object& flat_length,
                              const py::object& crown_radius, const py::object& length,
                              const py::object& tilt) {
                return CrownedRoller{{axial_roller("crowned", keys({{"radius", radius},
                                                                    {"flat_length", flat_length},
                                                                    {"crown_radius", crown_radius},
                                                                    {"length", length},
                                                                    {"tilt", tilt}}))}};
              }),
              py::arg("radius"), py::arg("flat_length"), py::arg("crown_radius"),
              py::arg("length") = py::none(), py::arg("tilt") = py::none());
  axial_properties(crowned);
  py::class_<LogarithmicRoller, vp::Roller> logarithmic(
      m, "Logarithmic",
      "Logarithmic(radius, length, scale, end_drop=None, tilt=None)\n\n"
      "A logarithmic crown h = -A ln(1 - k (2y/L)^2) on a roller of radius > 0 and length L > 0,\n"
      "scale A > 0, end drop > 0 (None: Lundberg's profile), misaligned by |tilt| < 0.1 rad: a\n"
      "scene file's \"logarithmic\" roller (docs/rollers.md). Raises ValueError naming a\n"
      "parameter out of range.");
  logarithmic.def(
      py::init([keys](const py::object& radius, const py::object& length, const py::object& scale,
                      const py::object& end_drop, const py::object& tilt) {
        return LogarithmicRoller{{axial_roller("logarithmic", keys({{"radius", radius},
                                                                    {"length", length},
                                                                    {"scale", scale},
                                                                    {"end_drop", end_drop},
                                                                    {"tilt", tilt}}))}};
      }),
      py::arg("radius"), py::arg("length"), py::arg("scale"), py::arg("end_drop") = py::none(),
      py::arg("tilt") = py::none());
  axial_properties(logarithmic);
  py::class_<TableRoller, vp::Roller> table(
      m, "Table",
      "Table(radius, y, h, tilt=None)\n\n"
      "A roller of radius > 0 whose drop h(y) is tabulated at y (at least 4 points, strictly\n"
      "increasing, y = 0 strictly inside; one h per y) and interpolated by a modified Akima\n"
      "spline, misaligned by |tilt| < 0.1 rad: a scene file's \"table\" roller\n"
      "(docs/rollers.md). Raises ValueError naming a parameter out of range.");
  table.def(py::init([keys](const py::object& radius, const py::object& y, const py::object& h,
                            const py::object& tilt) {
              return TableRoller{{axial_roller(
                  "table", keys({{"radius", radius}, {"y", y}, {"h", h}, {"tilt", tilt}}))}};
            }),
            py::arg("radius"), py::arg("y"), py::arg("h"), py::arg("tilt") = py::none());
  axial_properties(table);

  // Scene.
  py::class_<SceneSpec>(
      m, "Scene",
      "Scene(material, roller, load, speeds=None, temperature=None, density=None, "
      "substrate=None)\n\n"
      "One problem: a material (StandardLinearSolid, Elastic or Prony), a roller (Ellipsoid,\n"
      "Cylinder, Crowned, Logarithmic or Table), the load (> 0; total for line and bem, per unit "
      "length for plane) and\n"
      "optionally the speeds (each >= 0) for sweep() and solve(). Any consistent units.\n"
      "temperature (degrees Celsius): a Prony material with a shift law is solved there (every\n"
      "time of its spectrum times a_T); default the law's t_ref.\n"
      "density (> 0; kg/m^3 with SI units): the rubber's, for the check that rolling is\n"
      "quasi-static (V at most 0.1 of the shear-wave speed); None: not checked.\n"
      "substrate: the body the roller presses, the scene file's keys as a dict: None or\n"
      "{'model': 'half_space'}; {'model': 'layer', 'thickness': h, 'base': 'bonded'} (or\n"
      "'frictionless'), a layer of the material on a rigid base; {'model': 'spring_bed',\n"
      "'thickness': h}, the conveyor model u = h p/E. A layer or a bed is the bem method's,\n"
      "and the plane method's for a Cylinder (the auto method picks them); d is then\n"
      "measured from the base.\n"
      "Scene.from_json(path) reads a scene file of the command line (docs/cli.md).")
      .def(py::init([](const vp::Material& material, const vp::Roller& roller, double load,
                       const std::optional<py::object>& speeds, std::optional<double> temperature,
                       std::optional<double> density, const std::optional<py::dict>& substrate) {
             SceneSpec s;
             if (substrate) s.substrate = substrate_from(*substrate);
             s.material = material.spec;
             s.roller = roller.spec;
             viscoroll::detail::require_positive("load", load);
             s.load = load;
             if (speeds && !speeds->is_none()) s.speeds = as_vector(*speeds, "speeds");
             check_speeds(s.speeds);
             set_temperature(s, temperature);
             if (density) viscoroll::detail::require_positive("density", *density);
             s.density = density;
             return s;
           }),
           py::arg("material"), py::arg("roller"), py::arg("load"), py::arg("speeds") = py::none(),
           py::arg("temperature") = py::none(), py::arg("density") = py::none(),
           py::arg("substrate") = py::none())
      .def_static(
          "from_json",
          [](const py::object& path, std::optional<double> temperature) {
            // The name's bytes, as the command line gets them (os.fsencode: a str, bytes or
            // path; a name that is not UTF-8 included).
            const std::string file =
                py::module_::import("os").attr("fsencode")(path).cast<std::string>();
            try {
              const auto scene =
                  viscoroll::cli::parse_scene(viscoroll::cli::read_scene_file(file), file);
              SceneSpec s = from_cli(scene, file);
              if (!temperature && scene.temperatures.size() > 1)
                throw std::invalid_argument(
                    file + ": temperature: the file gives " +
                    std::to_string(scene.temperatures.size()) +
                    " temperatures and a Scene holds one: read it once per temperature with "
                    "Scene.from_json(path, temperature=T)");
              if (!temperature && scene.temperatures.size() == 1)
                temperature = scene.temperatures.front();
              set_temperature(s, temperature);
              if (s.method) {
                check_for_method(s, *s.method, std::nullopt);
                tolerance_for(s, std::nullopt, method_for(s, std::nullopt), std::nullopt);
              }
              return s;
            } catch (const std::invalid_argument& e) {
              throw std::invalid_argument(reader_message(e.what()));
            }
          },
          py::arg("path"), py::arg("temperature") = py::none(),
          "Scene.from_json(path, temperature=None) -> Scene\n\n"
          "Read a scene file (JSON, SI units; docs/cli.md) with the command line's reader.\n"
          "Its method, grid, setting, tolerance and strict become the defaults of solve() and\n"
          "sweep(); its density is the scene's. A prony\n"
          "material (its terms, or the fit of its DMA file: a poor fit is a warning) is solved at\n"
          "`temperature` (degrees Celsius), else at the file's one temperature, else at its shift\n"
          "law's t_ref. Raises ValueError naming the file and the key with its path, e.g.\n"
          "'paper.json: material.f = -1 is outside the valid range f >= 0 (finite)'.")
      .def_property_readonly(
          "temperature",
          [](const SceneSpec& s) -> py::object {
            if (!s.material.prony || std::isnan(s.temperature)) return py::none();
            return py::float_(s.temperature);
          },
          "The temperature of a Prony material with a shift law (degrees Celsius), else None.")
      .def_property_readonly(
          "material", [](const SceneSpec& s) { return material_object(s.material); },
          "The material.")
      .def_property_readonly(
          "roller", [](const SceneSpec& s) { return roller_object(s.roller); }, "The roller.")
      .def_property_readonly(
          "substrate",
          [](const SceneSpec& s) {
            py::dict d;
            d["model"] = s.substrate.model;
            if (!s.substrate.is_half_space()) d["thickness"] = s.substrate.thickness;
            if (s.substrate.model == "layer") d["base"] = s.substrate.base;
            return d;
          },
          "The body the roller presses, as the scene file's \"substrate\": {'model': "
          "'half_space'}, {'model': 'layer', 'thickness': h, 'base': 'bonded' or "
          "'frictionless'} or {'model': 'spring_bed', 'thickness': h}.")
      .def_readonly("load", &SceneSpec::load, "The load.")
      .def_property_readonly(
          "speeds", [](const SceneSpec& s) { return as_array(s.speeds); },
          "The speeds (a float64 array; empty if none).")
      .def_property_readonly(
          "method",
          [](const SceneSpec& s) -> py::object {
            if (!s.method) return py::none();
            return py::str(method_name(*s.method));
          },
          "The scene file's method, or None.")
      .def_property_readonly(
          "grid",
          [](const SceneSpec& s) -> py::object {
            if (!s.grid) return py::none();
            return py::int_(*s.grid);
          },
          "The scene file's grid, or None.")
      .def_property_readonly(
          "setting",
          [](const SceneSpec& s) -> py::object {
            if (!s.setting) return py::none();
            return py::str(viscoroll::cli::line_setting_name(*s.setting));
          },
          "The scene file's setting (\"default\" or \"fast\", the line method's), or None.")
      .def_property_readonly(
          "tolerance",
          [](const SceneSpec& s) -> py::object {
            if (!s.tolerance) return py::none();
            return py::float_(*s.tolerance);
          },
          "The scene file's tolerance (the bem method's, relative in d and chi; on a layer or a "
          "spring bed the plane method's, in a0, d and chi), or None.")
      .def_property_readonly(
          "density",
          [](const SceneSpec& s) -> py::object {
            if (!s.density) return py::none();
            return py::float_(*s.density);
          },
          "The rubber's density (the quasi-static check), or None.")
      .def_readonly("strict", &SceneSpec::strict,
                    "The scene file's strict: a validity breach is an error in solve() and "
                    "sweep().")
      .def_readonly("description", &SceneSpec::description, "The scene file's description.")
      .def(py::pickle([](const SceneSpec& s) { return scene_state(s); },
                      [](const py::dict& state) { return scene_from_state(state); }))
      .def("__repr__", [](const SceneSpec& s) {
        std::string out = "Scene(material=" + material_repr(s.material) +
                          ", roller=" + roller_repr(s.roller) + ", load=" + shortest(s.load);
        out += ", speeds=[";
        for (std::size_t i = 0; i < s.speeds.size(); ++i)
          out += (i ? ", " : "") + shortest(s.speeds[i]);
        out += "]";
        if (s.method) out += std::string(", method='") + method_name(*s.method) + "'";
        if (s.grid) out += ", grid=" + std::to_string(*s.grid);
        if (s.tolerance) out += ", tolerance=" + shortest(*s.tolerance);
        if (s.density) out += ", density=" + shortest(*s.density);
        if (s.strict) out += ", strict=True";
        if (!s.substrate.is_half_space()) {
          out += ", substrate={'model': '" + s.substrate.model +
                 "', 'thickness': " + shortest(s.substrate.thickness);
          if (s.substrate.model == "layer") out += ", 'base': '" + s.substrate.base + "'";
          out += "}";
        }
        if (s.material.prony && !std::isnan(s.temperature))
          out += ", temperature=" + shortest(s.temperature);
        return out + ")";
      });

  // Result.
  auto result = py::class_<Result>(
      m, "Result",
      "The result of solve(): the command line's output fields as attributes (a field that\n"
      "its method does not give raises AttributeError), as_dict(), and the functions\n"
      "pressure(x, y), a(y), b(y), f0(y) of NumPy arrays (broadcast; scalars give scalars).\n"
      "Check converged (and reason) before using the numbers.");
  for (const auto& [name, doc] : field_docs()) {
    const std::string key = name;
    result.def_property_readonly(
        name,
        [key](const Result& r) -> py::object {
          const Value* v = r.solved->find(key);
          if (!v)
            throw py::attribute_error("viscoroll: the " +
                                      std::string(method_name(r.solved->method())) +
                                      " method gives no " + key);
          return to_python(*v);
        },
        doc);
  }
  result
      .def(
          "as_dict",
          [](const Result& r) {
            py::dict out;
            for (const auto& [key, value] : r.solved->record())
              out[py::str(key)] = to_python(value);
            return out;
          },
          "The output fields as a dict, in the command line's JSON order.")
      .def("pressure", py::vectorize([](const Result* r, double x, double y) {
             return r->solved->pressure(x, y);
           }),
           py::arg("x"), py::arg("y"),
           "pressure(x, y) -> ndarray\n\nThe contact pressure p(x, y) (Eq. 35), 0 outside the "
           "contact; x in the rolling\ndirection from the roller's axis (the frame moves with the "
           "roller, towards +x), y along\nthe axis. x and y broadcast (NumPy rules); float64 out; "
           "scalars give a float.\nplane: p(x) for any y. bem: the pressure of the cell holding "
           "(x, y).")
      .def("a", py::vectorize([](const Result* r, double y) { return r->solved->a(y); }),
           py::arg("y"),
           "a(y) -> ndarray\n\nHalf width of the contact strip at y (plane: a for every y). Not "
           "for bem (ValueError).")
      .def("b", py::vectorize([](const Result* r, double y) { return r->solved->b(y); }),
           py::arg("y"),
           "b(y) -> ndarray\n\nOffset of the strip's centre ahead of the axis at y (plane: b). "
           "Not for bem.")
      .def("f0", py::vectorize([](const Result* r, double y) { return r->solved->f0(y); }),
           py::arg("y"),
           "f0(y) -> ndarray\n\nF0(y) of Eq. (33), the strip's integral of the pseudo-pressure "
           "(plane: F0 of Eq. 52).\nNot for bem, nor for plane on a layer or a spring bed.")
      .def(
          "cell_pressures",
          [](const Result& r) {
            std::vector<double> x, y, p;
            if (!bem_cells(*r.solved, x, y, p))
              throw std::invalid_argument(
                  "viscoroll: cell_pressures() is for results of the bem method");
            py::array_t<double> grid(
                {static_cast<py::ssize_t>(y.size()), static_cast<py::ssize_t>(x.size())});
            std::copy(p.begin(), p.end(), grid.mutable_data());
            return py::make_tuple(as_array(x), as_array(y), grid);
          },
          "cell_pressures() -> (x, y, p)\n\nbem: the cell centres x (nx,), y (ny,) and the cell "
          "pressures p (ny, nx).")
      .def("__repr__", [](const Result& r) {
        const auto real = [&](const char* key) {
          const Value* v = r.solved->find(key);
          return v && std::holds_alternative<double>(*v) ? shortest(std::get<double>(*v))
                                                         : std::string("-");
        };
        const Value* c = r.solved->find("converged");
        std::string out = std::string("Result(method='") + method_name(r.solved->method()) +
                          "', speed=" + real("speed") + ", a0=" + real("a0") + ", b0=" + real("b0");
        if (r.solved->find("l")) out += ", l=" + real("l");
        if (r.solved->find("d")) out += ", d=" + real("d");
        out += ", chi=" + real("chi") +
               ", converged=" + (c && std::get<bool>(*c) ? "True" : "False") + ")";
        return out;
      });

  // solve() and sweep() are wrapped by the package's __init__.py (a Python signature for
  // help()); their docstrings here carry the signature line themselves.
  py::options options;
  options.disable_function_signatures();
  m.def(
      "solve",
      [](const SceneSpec& scene, const std::optional<std::string>& method, std::optional<long> grid,
         std::optional<double> speed, const Result* start,
         const std::optional<std::string>& setting, std::optional<double> tolerance,
         std::optional<bool> strict) {
        const Method which = method_for(scene, method);
        const bool fast = fast_setting(scene, setting, which);
        const double tol = tolerance_for(scene, tolerance, which, grid);
        double v = 0;
        if (speed) {
          v = *speed;
        } else if (scene.speeds.size() == 1) {
          v = scene.speeds.front();
        } else {
          throw std::invalid_argument("viscoroll: solve() needs one speed: the scene has " +
                                      std::to_string(scene.speeds.size()) +
                                      " speeds; give speed=V, or call sweep() for several");
        }
        viscoroll::detail::require_non_negative("speed", v);
        SolvedPtr solved;
        if (which == Method::bem || which == Method::automatic ||
            !scene.substrate.is_half_space()) {
          // A bem solve can take minutes, a plane solve on a layer or a bed seconds, and neither
          // can be stopped: Ctrl-C is answered at once and the solve ends in the background, on
          // copies of its inputs.
          solved = interruptible<SolvedPtr>(
              [scene, which, grid, v, fast, tol,
               seed = start ? std::optional(*start) : std::nullopt](const std::atomic<bool>&) {
                return solve_scene(scene, which, grid, v, fast, tol,
                                   seed ? seed->solved.get() : nullptr);
              },
              false);
        } else {
          // The plane method on the half space and the line method take milliseconds (a line
          // spectrum on a roller profile up to half a second): Python's handlers run when they
          // return.
          py::gil_scoped_release release;
          solved =
              solve_scene(scene, which, grid, v, fast, tol, start ? start->solved.get() : nullptr);
        }
        warn(check_validity({solved}, scene, strict.value_or(scene.strict)));
        return Result{std::move(solved)};
      },
      py::arg("scene"), py::arg("method") = py::none(), py::arg("grid") = py::none(),
      py::arg("speed") = py::none(), py::arg("start") = py::none(), py::arg("setting") = py::none(),
      py::arg("tolerance") = py::none(), py::arg("strict") = py::none(), solve_doc);

  m.def(
      "sweep",
      [](const SceneSpec& scene, const std::optional<py::object>& speeds,
         const std::optional<std::string>& method, std::optional<long> grid,
         std::optional<long> threads, long chunk, bool with_results,
         const std::optional<std::string>& setting, std::optional<double> tolerance,
         std::optional<bool> strict) {
        const Method which = method_for(scene, method);
        const bool fast = fast_setting(scene, setting, which);
        const double tol = tolerance_for(scene, tolerance, which, grid);
        std::vector<double> v =
            speeds && !speeds->is_none() ? as_vector(*speeds, "speeds") : scene.speeds;
        if (v.empty())
          throw std::invalid_argument(
              "viscoroll: sweep() needs at least one speed: give speeds= or a scene with speeds");
        check_speeds(v);
        const int n = check_for_method(scene, which, grid, fast, tol);
        viscoroll::SweepOptions options;
        const long t = threads.value_or(0);
        viscoroll::detail::require(t >= 0 && t <= 4096, "threads", t,
                                   "0 <= threads <= 4096 (0 or None: all cores)");
        viscoroll::detail::require(chunk >= 1 && chunk <= (1L << 20), "chunk", chunk,
                                   "1 <= chunk <= 1048576");
        options.threads = static_cast<unsigned>(t);
        options.chunk = static_cast<std::size_t>(chunk);
        // Ctrl-C stops every thread before its next solve (SweepOptions::stop).
        std::vector<SolvedPtr> solved = interruptible<std::vector<SolvedPtr>>(
            [&](const std::atomic<bool>& stop) {
              viscoroll::SweepOptions stoppable = options;
              stoppable.stop = &stop;
              switch (which) {
                case Method::plane:
                  return sweep_plane(scene, v, tol, stoppable);
                case Method::line:
                  return sweep_line(scene, v, n, fast, stoppable);
                case Method::bem:
                  return sweep_bem(scene, v, n, tol, stoppable);
                case Method::automatic:
                  return sweep_auto(scene, v, fast, tol, stoppable);
              }
              throw std::logic_error("viscoroll: unknown method");
            },
            true);
        // One Python warning for the sweep (a sweep may have thousands of results).
        std::vector<std::string> breaches =
            check_validity(solved, scene, strict.value_or(scene.strict));
        if (breaches.size() > 1)
          breaches = {breaches.front() + " (and " + std::to_string(breaches.size() - 1) +
                      " more breaches in this sweep: see its warnings)"};
        warn(breaches);
        py::dict out = to_columns(solved, which == Method::automatic);
        if (with_results) {
          py::list results;
          for (auto& r : solved) results.append(py::cast(Result{std::move(r)}));
          out["results"] = results;
        }
        return out;
      },
      py::arg("scene"), py::arg("speeds") = py::none(), py::arg("method") = py::none(),
      py::arg("grid") = py::none(), py::arg("threads") = py::none(),
      py::arg("chunk") = static_cast<long>(viscoroll::SweepOptions{}.chunk),
      py::arg("with_results") = false, py::arg("setting") = py::none(),
      py::arg("tolerance") = py::none(), py::arg("strict") = py::none(), sweep_doc);

  register_study(m);  // solve_items(), the solves of viscoroll.study (study.cpp)
}
