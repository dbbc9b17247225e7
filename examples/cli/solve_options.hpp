// viscoroll-solve: command-line parsing, kept apart from main() so that tests and a fuzzer can
// drive it. Every error throws std::invalid_argument with a one-line message naming the option.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>
#include <viscoroll/input_limits.hpp>

namespace viscoroll::cli {

/// The methods; `automatic` ("auto") picks line or bem per result (docs/cli.md, "The auto
/// method"), plane for the cylinder.
enum class Method { plane, line, bem, automatic };

/// The line method's setting (--setting, a scene file's "setting", Python's setting=): the
/// defaults, or LineOptions::fast() on 6-point panels (FastLineSolverD) for a material of one
/// relaxation time.
enum class LineSetting { standard, fast };

/// The setting named `text` ("default" or "fast"), or nothing.
inline std::optional<LineSetting> parse_line_setting(std::string_view text) {
  if (text == "default") return LineSetting::standard;
  if (text == "fast") return LineSetting::fast;
  return std::nullopt;
}

inline const char* line_setting_name(LineSetting s) {
  return s == LineSetting::fast ? "fast" : "default";
}

/// How results go to stdout: one JSON object per line, or an aligned table.
enum class Format { json, table };

/// The method named `text`, or nothing.
inline std::optional<Method> parse_method(std::string_view text) {
  if (text == "plane") return Method::plane;
  if (text == "line") return Method::line;
  if (text == "bem") return Method::bem;
  if (text == "auto") return Method::automatic;
  return std::nullopt;
}

inline const char* method_name(Method m) {
  switch (m) {
    case Method::plane:
      return "plane";
    case Method::line:
      return "line";
    case Method::bem:
      return "bem";
    case Method::automatic:
      return "auto";
  }
  return "?";
}

/// The plane method on a layer or a spring bed (PlaneSubstrateSolver, docs/plane-substrate.md)
/// doubles its Chebyshev terms from 16 until its error estimates of a, d and chi ((Q13)) meet this
/// relative tolerance, where neither the scene nor the command line gives one. 1e-4 stops at
/// N = 32 to 128, 0.03 to 0.55 s a solve, with a and chi within 4e-8 of the answer at 1e-6 (the
/// estimate is about the coarser level's error; the answer is the finer level's). 1e-6 needs
/// N = 128 to 512, 0.4 to 9 s, in the slow regime (V tau/a ~ 0.005 to 0.2: a thin layer behind the
/// leading edge), and a many-term Prony spectrum minutes, or stops unconverged at N = 512, where
/// 1e-4 takes seconds: docs/cli.md, "The plane method on a layer or a spring bed", which has the
/// measurements.
inline constexpr double plane_substrate_tolerance = 1e-4;

/// Whether `method` solves a scene on `substrate_model` ("half_space", "layer", "spring_bed") by
/// the plane method on that body: the plane method, or the auto method on a cylinder, on a layer
/// or a spring bed. Its tolerance is PlaneSubstrateOptions::tolerance; the bem's (the bem and the
/// auto method otherwise) BemOptions::tolerance.
inline bool solves_plane_substrate(std::string_view substrate_model, Method method, bool cylinder) {
  return substrate_model != "half_space" &&
         (method == Method::plane || (method == Method::automatic && cylinder));
}

/// Whether `tolerance` is in the range of the method that takes it: the plane method on a layer
/// or a spring bed (`plane_substrate`), 64 eps <= T <= 0.1 (PlaneSubstrateOptions::validate and
/// the solver's 64 eps of the scalar); the bem, 0 (one grid) or 1e-4 <= T <= 0.5
/// (BemOptions::validate).
inline bool tolerance_in_range(double tolerance, bool plane_substrate) {
  if (plane_substrate)
    return tolerance >= 64 * std::numeric_limits<double>::epsilon() && tolerance <= 0.1;
  return tolerance == 0 || (tolerance >= 1e-4 && tolerance <= 0.5);
}

/// The valid range of a tolerance written `name` ("tolerance", "T"), as tolerance_in_range
/// decides it, for messages.
inline std::string tolerance_range(const std::string& name, bool plane_substrate) {
  if (plane_substrate)
    return "64 eps = 1.4e-14 <= " + name +
           " <= 0.1 for the plane method on a layer or a spring bed (relative, in a, d and chi)";
  return "0 (one grid) or 1e-4 <= " + name + " <= 0.5 for the bem method (relative, in d and chi)";
}

struct SolveOptions {
  std::optional<Method> method;  ///< required without --scene; with it, overrides the file's
  double mu_d = 0, nu = 0, f = 0, c1 = 0, load = 0;
  std::optional<double> c2;
  std::vector<double> tau;     ///< one solution per value (and per speed)
  std::vector<double> speeds;  ///< the sweep, in the given order; with --scene, may be empty
  std::optional<long> grid;    ///< discretisation size (line: terms; bem: elements per semi-axis)
  std::string scene;           ///< --scene FILE: the material, the roller, the load and speeds
  Format format = Format::json;
  std::string csv;   ///< --csv FILE: the sweep as CSV too (empty: none)
  std::string plot;  ///< --plot DIR: sweep.csv, sweep.gp and sweep.png there (empty: none)
  /// --profile-out FILE.csv: the contact along the roller of every line or bem solve (empty:
  /// none)
  std::string profile_out;
  unsigned threads = 0;  ///< --threads N: threads of the speed sweep (0: every core)
  /// --temperature T[,T...] (degrees Celsius): replaces the scene's "temperature"; valid only
  /// with a scene whose material is a prony series with a shift law.
  std::vector<double> temperatures;
  /// The line method's slow-regime settings (LineOptions; docs/line-solver.md, "Oversampling"):
  /// --oversampling K (1..8), --basis t2|s|mapped, --max-iterations N (1..100000).
  std::optional<long> oversampling;
  std::string basis;  ///< empty: the default, t2
  std::optional<long> max_iterations;
  /// --quadrature-tolerance TOL (0 <= TOL <= 1e-4; 0: every integral to rounding): the line
  /// method's LineOptions::quadrature_tolerance.
  std::optional<double> quadrature_tolerance;
  /// --setting default|fast (none: not given): the line method's setting; with fast,
  /// LineOptions::fast() (5 terms unless --grid, integrals to 1e-4, loose intermediate stages)
  /// on 6-point panels (FastLineSolverD) for a material of one relaxation time; the other line
  /// options given override it.
  std::optional<LineSetting> setting;
  /// --tolerance T: the bem method's BemOptions::tolerance (0, or 1e-4 <= T <= 0.5), the
  /// relative accuracy asked of d and chi, refining from --grid (default 8), none or 0: one grid;
  /// or, with the plane method on a scene file's layer or spring bed, PlaneSubstrateOptions'
  /// (64 eps <= T <= 0.1), in a, d and chi. Parsed here in either range; main() checks the
  /// method's (tolerance_in_range).
  std::optional<double> tolerance;
  /// --strict: a result outside its model's assumptions (core/validity.hpp) is an error, exit 2,
  /// not a warning.
  bool strict = false;
};

inline std::string usage() {
  return "usage: viscoroll-solve --method plane|line|bem|auto --mu-d M --nu N --f F --tau T[,T...] "
         "--speed V[,V...] --c1 C1 [--c2 C2] --load P [--grid N] [--format json|table] "
         "[--csv FILE] [--plot DIR] [--threads N] [--oversampling K] [--basis t2|s|mapped] "
         "[--max-iterations N] [--quadrature-tolerance TOL] [--setting default|fast] "
         "[--tolerance T] [--strict]\n"
         "   or: viscoroll-solve --scene FILE.json [--method plane|line|bem|auto] [--grid N] "
         "[--speed V[,V...]] [--temperature T[,T...]] [--format json|table] [--csv FILE] "
         "[--plot DIR] [--profile-out FILE.csv] [--threads N] [--oversampling K] "
         "[--basis t2|s|mapped] [--max-iterations N] [--quadrature-tolerance TOL] "
         "[--setting default|fast] [--tolerance T] [--strict]";
}

/// A finite number, the whole of `text`.
inline double parse_number(std::string_view option, std::string_view text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value))
    throw std::invalid_argument("viscoroll-solve: " + std::string(option) +
                                " expects a finite number, got '" + std::string(text) + "'");
  return value;
}

/// A comma-separated list of finite numbers ("1,2,3"), of at most `max_count`, checked before
/// any is parsed.
inline std::vector<double> parse_numbers(std::string_view option, std::string_view text,
                                         std::size_t max_count = std::size_t(-1)) {
  const auto count = static_cast<std::size_t>(std::count(text.begin(), text.end(), ',')) + 1;
  if (const std::string over = viscoroll::detail::count_over_limit(option, count, max_count);
      !over.empty())
    throw std::invalid_argument("viscoroll-solve: " + over);
  std::vector<double> values;
  while (true) {
    const auto comma = text.find(',');
    values.push_back(parse_number(option, text.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    text = text.substr(comma + 1);
  }
  return values;
}

/// Parses argv[1..]; throws std::invalid_argument on unknown, repeated, missing, conflicting or
/// malformed options. Physical ranges are checked later by the library (or the scene reader),
/// which names the parameter.
inline SolveOptions parse_solve_options(const std::vector<std::string_view>& args) {
  static const std::set<std::string_view> known = {"--method",
                                                   "--mu-d",
                                                   "--nu",
                                                   "--f",
                                                   "--tau",
                                                   "--speed",
                                                   "--c1",
                                                   "--c2",
                                                   "--load",
                                                   "--grid",
                                                   "--scene",
                                                   "--format",
                                                   "--csv",
                                                   "--plot",
                                                   "--threads",
                                                   "--temperature",
                                                   "--oversampling",
                                                   "--basis",
                                                   "--max-iterations",
                                                   "--profile-out",
                                                   "--quadrature-tolerance",
                                                   "--setting",
                                                   "--tolerance"};
  // Given by a scene file; with --scene they are a conflict.
  static const std::vector<std::string_view> scene_keys = {"--mu-d", "--nu", "--f",   "--tau",
                                                           "--c1",   "--c2", "--load"};
  std::map<std::string_view, std::string_view> given;
  const auto unknown = [](std::string_view key) {
    return std::invalid_argument("viscoroll-solve: unknown option '" + std::string(key) + "'; " +
                                 usage());
  };
  SolveOptions o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string_view key = args[i], value;
    if (key == "--strict") {  // the one flag: no value
      if (o.strict) throw std::invalid_argument("viscoroll-solve: --strict given twice");
      o.strict = true;
      continue;
    }
    if (const auto eq = key.find('='); key.starts_with("--") && eq != std::string_view::npos) {
      value = key.substr(eq + 1);
      key = key.substr(0, eq);
    } else {
      if (!known.count(key)) throw unknown(key);
      if (i + 1 >= args.size())
        throw std::invalid_argument("viscoroll-solve: " + std::string(key) + " needs a value");
      value = args[++i];
    }
    if (!known.count(key)) throw unknown(key);
    if (!given.emplace(key, value).second)
      throw std::invalid_argument("viscoroll-solve: " + std::string(key) + " given twice");
  }
  auto required = [&](std::string_view key) {
    const auto it = given.find(key);
    if (it == given.end())
      throw std::invalid_argument("viscoroll-solve: missing " + std::string(key) + "; " + usage());
    return it->second;
  };
  if (given.count("--scene")) {
    o.scene = std::string(given["--scene"]);
    if (o.scene.empty())
      throw std::invalid_argument("viscoroll-solve: --scene expects a file name, got ''");
    for (const auto key : scene_keys)
      if (given.count(key))
        throw std::invalid_argument(
            "viscoroll-solve: --scene excludes " + std::string(key) +
            " (the scene file gives the material, the roller and the load; only --method, "
            "--grid, --speed, --temperature, --format, --csv, --plot, --profile-out, --threads, "
            "--oversampling, --basis, --max-iterations, --quadrature-tolerance, --setting, "
            "--tolerance and --strict may go with it)");
  }
  if (given.count("--method") || o.scene.empty()) {
    const std::string_view method = required("--method");
    o.method = parse_method(method);
    if (!o.method)
      throw std::invalid_argument(
          "viscoroll-solve: --method expects plane, line, bem or auto, got '" +
          std::string(method) + "'");
  }
  if (o.scene.empty()) {
    o.mu_d = parse_number("--mu-d", required("--mu-d"));
    o.nu = parse_number("--nu", required("--nu"));
    o.f = parse_number("--f", required("--f"));
    o.c1 = parse_number("--c1", required("--c1"));
    o.load = parse_number("--load", required("--load"));
    if (given.count("--c2")) o.c2 = parse_number("--c2", given["--c2"]);
    o.tau = parse_numbers("--tau", required("--tau"));
    o.speeds = parse_numbers("--speed", required("--speed"), viscoroll::limits::speeds);
  } else if (given.count("--speed")) {
    o.speeds = parse_numbers("--speed", given["--speed"], viscoroll::limits::speeds);
  }
  if (given.count("--temperature")) {
    if (o.scene.empty())
      throw std::invalid_argument(
          "viscoroll-solve: --temperature is valid only with --scene and a material of model "
          "prony with a shift law (the options describe a standard linear solid)");
    o.temperatures = parse_numbers("--temperature", given["--temperature"]);
  }
  if (given.count("--grid")) {
    const std::string_view text = given["--grid"];
    long n = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || n < 1)
      throw std::invalid_argument("viscoroll-solve: --grid expects a positive integer, got '" +
                                  std::string(text) + "'");
    o.grid = n;
  }
  // The line method's settings: integers in their ranges, the basis by name.
  const auto integer = [&](std::string_view key, long lo, long hi) {
    const std::string_view text = given[key];
    long n = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || n < lo || n > hi)
      throw std::invalid_argument("viscoroll-solve: " + std::string(key) + " expects an integer " +
                                  std::to_string(lo) + " <= N <= " + std::to_string(hi) +
                                  ", got '" + std::string(text) + "'");
    return n;
  };
  if (given.count("--oversampling")) o.oversampling = integer("--oversampling", 1, 8);
  if (given.count("--max-iterations")) o.max_iterations = integer("--max-iterations", 1, 100000);
  if (given.count("--quadrature-tolerance")) {
    const double tol = parse_number("--quadrature-tolerance", given["--quadrature-tolerance"]);
    if (!(tol >= 0 && tol <= 1e-4))
      throw std::invalid_argument(
          "viscoroll-solve: --quadrature-tolerance expects 0 <= TOL <= 1e-4 (0: every integral "
          "to rounding), got '" +
          std::string(given["--quadrature-tolerance"]) + "'");
    o.quadrature_tolerance = tol;
  }
  if (given.count("--tolerance")) {
    const double tol = parse_number("--tolerance", given["--tolerance"]);
    if (!(tolerance_in_range(tol, false) || tolerance_in_range(tol, true)))
      throw std::invalid_argument(
          "viscoroll-solve: --tolerance expects " + tolerance_range("T", false) + ", or " +
          tolerance_range("T", true) + ", got '" + std::string(given["--tolerance"]) + "'");
    o.tolerance = tol;
  }
  if (given.count("--basis")) {
    o.basis = std::string(given["--basis"]);
    if (o.basis != "t2" && o.basis != "s" && o.basis != "mapped")
      throw std::invalid_argument("viscoroll-solve: --basis expects t2, s or mapped, got '" +
                                  o.basis + "'");
  }
  if (given.count("--setting")) {
    o.setting = parse_line_setting(given["--setting"]);
    if (!o.setting)
      throw std::invalid_argument("viscoroll-solve: --setting expects default or fast, got '" +
                                  std::string(given["--setting"]) + "'");
  }
  if (given.count("--threads")) {
    const std::string_view text = given["--threads"];
    unsigned n = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || n > 4096)
      throw std::invalid_argument(
          "viscoroll-solve: --threads expects an integer 0 <= N <= 4096 (0: every core), got '" +
          std::string(text) + "'");
    o.threads = n;
  }
  if (given.count("--format")) {
    const std::string_view format = given["--format"];
    if (format == "json")
      o.format = Format::json;
    else if (format == "table")
      o.format = Format::table;
    else
      throw std::invalid_argument("viscoroll-solve: --format expects json or table, got '" +
                                  std::string(format) + "'");
  }
  if (given.count("--csv")) {
    o.csv = std::string(given["--csv"]);
    if (o.csv.empty())
      throw std::invalid_argument("viscoroll-solve: --csv expects a file name, got ''");
  }
  if (given.count("--plot")) {
    o.plot = std::string(given["--plot"]);
    if (o.plot.empty())
      throw std::invalid_argument("viscoroll-solve: --plot expects a directory, got ''");
  }
  if (given.count("--profile-out")) {
    o.profile_out = std::string(given["--profile-out"]);
    if (o.profile_out.empty())
      throw std::invalid_argument("viscoroll-solve: --profile-out expects a file name, got ''");
    if (o.method && *o.method == Method::plane)
      throw std::invalid_argument(
          "viscoroll-solve: --profile-out is valid only with --method line or bem (the contact "
          "along the roller: docs/cli.md)");
  }
  return o;
}

}  // namespace viscoroll::cli
