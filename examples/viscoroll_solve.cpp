// viscoroll-solve: solve one scene for one or more relaxation times and speeds and print one JSON
// object per line (or a table; docs/cli.md). Exit status: 0 all converged, 1 a solution did not
// converge (or the plot failed), 2 bad input (message on stderr, nothing on stdout).
// The scene comes from options (--mu-d --nu --f --tau --c1 --c2 --load --speed) or from a scene
// file in SI units (--scene FILE.json, examples/cli/scene_file.hpp). For each tau, each speed is
// solved by viscoroll::sweep on --threads threads: in chunks of 16 in the given order, line and
// bem continuing from the previous converged solution of the chunk (any thread count, same result).
// --method plane: Hunter's plane problem (load per unit length, c2 ignored); a scene file's layer
// or spring bed ("substrate") by PlaneSubstrateSolver to --tolerance (or the file's "tolerance"),
// default 1e-4 in a, d and chi, each line carrying d (from the base), terms, tolerance, the error
// estimates, substrate and, when not converged, reason.
// --method line: the line-contact solver (--grid N the Chebyshev terms, default 6; --setting fast
// the fast setting, LineOptions::fast() on FastLineSolverD, 5 terms) for the
// ellipsoid or a roller of finite length (crowned, logarithmic, table; tilted or not) on any
// material; each line also carries l, y_minus, y_plus, f0_max, f0_max_y
// (the peak of the load along the roller), d, l0, d0 (the static long-term l and d), terms,
// reason and warnings. --profile-out writes the contact along the roller of each line or bem
// solve.
// --method bem: the 3-D boundary-element solver (--grid N elements per semi-axis of the static
// long-term Hertz ellipse, default 16); each line carries a0 = a(0), b0 = b(0), l, y_minus,
// y_plus, d, chi, a_long_term, l0, d0 (the static long-term contact: Hertz's for the ellipsoid, the
// line theory's for a roller of finite length), grid, cells, reason, iterations (active set),
// gmres_iterations, residual and warnings. docs/bem.md. --threads N also builds each solve's
// influence table on threads (BemOptions::threads): the N threads are shared by the sweep's
// chunks running at once (bem_table_threads). Warnings of either method also go to stderr, one
// per line; they do not change the exit status.
// A scene's material of model "prony" (a Prony series in relaxation form, or fitted from a DMA
// file, with an optional WLF or Arrhenius shift) is solved by PlaneSolver (on a layer or a spring
// bed PlaneSubstrateSolver), LineSolver or BemSolver over PronyRelaxation<double> at each
// temperature (--temperature, else the scene's, else t_ref) and each speed, each line carrying
// temperature and a_T in place of tau and vtau (and the spectrum's active_terms in plane on the
// half space and in line).
// Every record carries after chi the rolling resistance F = chi W, the power loss F V and the
// energy per revolution F 2 pi R (cli/engineering.hpp; per unit length for the plane method).
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <thread>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>
#include <viscoroll/bem/bem_profile.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/dma_fit.hpp>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/material/temperature_shift.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/sweep.hpp>

#include "cli/auto_method.hpp"
#include "cli/bem_record.hpp"
#include "cli/bem_substrate.hpp"
#include "cli/engineering.hpp"
#include "cli/line_record.hpp"
#include "cli/plane_record.hpp"
#include "cli/plane_substrate.hpp"
#include "cli/roller_profile.hpp"
#include "cli/scene_file.hpp"
#include "cli/solve_options.hpp"
#include "cli/validity_record.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using viscoroll::cli::Format;
using viscoroll::cli::Method;
using viscoroll::cli::SolveOptions;

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
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

/// One result: its fields in output order. Numbers and booleans also go to the CSV.
using Value = std::variant<double, long long, bool, std::string, std::vector<std::string>>;
struct Field {
  std::string key;
  Value value;
};
using Record = std::vector<Field>;

const Value* find(const Record& r, std::string_view key) {
  for (const auto& field : r)
    if (field.key == key) return &field.value;
  return nullptr;
}

double real(const Record& r, std::string_view key) {
  const Value* v = find(r, key);
  return v && std::holds_alternative<double>(*v) ? std::get<double>(*v) : std::nan("");
}

std::string json_line(const Record& r) {
  std::string out = "{";
  for (const auto& [key, value] : r) {
    if (out.size() > 1) out += ',';
    out += json_string(key) + ':';
    if (const auto* x = std::get_if<double>(&value))
      out += json_number(*x);
    else if (const auto* n = std::get_if<long long>(&value))
      out += std::to_string(*n);
    else if (const auto* b = std::get_if<bool>(&value))
      out += *b ? "true" : "false";
    else if (const auto* s = std::get_if<std::string>(&value))
      out += json_string(*s);
    else
      out += json_strings(std::get<std::vector<std::string>>(value));
  }
  return out + "}";
}

bool in_csv(const Value& v) {
  return !std::holds_alternative<std::string>(v) &&
         !std::holds_alternative<std::vector<std::string>>(v);
}

std::string csv_header(const Record& r) {
  std::string out;
  for (const auto& [key, value] : r)
    if (in_csv(value)) {
      if (!out.empty()) out += ',';
      out += key;
    }
  return out;
}

/// The fields that are the solution (not the inputs, the long-term static contact or the
/// iteration's diagnostics): a result that did not converge shows none of them in the table and
/// the CSV (docs/cli.md, "Output").
bool solution_field(std::string_view key) {
  static constexpr std::string_view keys[] = {"a0",         "b0",
                                              "l",          "y_minus",
                                              "y_plus",     "f0_max",
                                              "f0_max_y",   "d",
                                              "chi",        "rolling_resistance",
                                              "power_loss", "energy_per_revolution",
                                              "pmax",       "pmax_x"};
  return std::find(std::begin(keys), std::end(keys), key) != std::end(keys);
}

/// Whether `r` converged (its field `converged`).
bool converged_record(const Record& r) {
  const Value* c = find(r, "converged");
  return c != nullptr && std::get<bool>(*c);
}

/// The numbers and booleans of `r`; a non-finite number, and a solution field of a result that
/// did not converge, is an empty cell.
std::string csv_row(const Record& r) {
  std::string out;
  bool first = true;
  const bool converged = converged_record(r);
  for (const auto& field : r) {
    if (!in_csv(field.value)) continue;
    if (!first) out += ',';
    first = false;
    if (!converged && solution_field(field.key)) continue;
    if (const auto* x = std::get_if<double>(&field.value))
      out += std::isfinite(*x) ? number(*x) : "";
    else if (const auto* n = std::get_if<long long>(&field.value))
      out += std::to_string(*n);
    else
      out += std::get<bool>(field.value) ? "true" : "false";
  }
  return out;
}

/// `name` on PATH, or empty.
fs::path on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string_view dirs = path ? path : "";
  while (!dirs.empty()) {
    const auto colon = dirs.find(':');
    const fs::path candidate = fs::path(std::string(dirs.substr(0, colon))) / name;
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return candidate;
    if (colon == std::string_view::npos) break;
    dirs = dirs.substr(colon + 1);
  }
  return {};
}

/// A gnuplot single-quoted string.
std::string gnuplot_string(const std::string& text) {
  std::string out = "'";
  for (const char ch : text) out += ch == '\'' ? std::string("''") : std::string(1, ch);
  return out + "'";
}

/// Where results go: stdout (JSON lines or a table), the CSV file, the plot's directory, and
/// progress on stderr when it is a terminal. open() comes after every input was validated, so
/// that bad input leaves no output at all.
class Output {
 public:
  Output(const SolveOptions& options, Method method, std::size_t total)
      : options_(options), method_(method), total_(total) {}

  /// Opens the CSV file and the plot directory; throws std::invalid_argument (exit 2) if they
  /// cannot be written or gnuplot is not on PATH.
  void open() {
    if (!options_.plot.empty()) {
      gnuplot_ = on_path("gnuplot");
      if (gnuplot_.empty())
        throw std::invalid_argument(
            "viscoroll-solve: --plot needs gnuplot on PATH (Debian: gnuplot-nox); not found");
      std::error_code ec;
      fs::create_directories(options_.plot, ec);
      if (!fs::is_directory(options_.plot))
        throw std::invalid_argument("viscoroll-solve: --plot " + options_.plot +
                                    ": cannot create the directory");
      plot_csv_.open(fs::path(options_.plot) / "sweep.csv");
      if (!plot_csv_)
        throw std::invalid_argument("viscoroll-solve: --plot " + options_.plot +
                                    ": cannot write sweep.csv there");
    }
    if (!options_.profile_out.empty()) {
      profile_csv_.open(options_.profile_out);
      if (!profile_csv_)
        throw std::invalid_argument("viscoroll-solve: --profile-out " + options_.profile_out +
                                    ": cannot be opened for writing");
      profile_csv_ << "tau,temperature,speed,y,f0,a,b,p_max\n";
    }
    if (!options_.csv.empty()) {
      csv_.open(options_.csv);
      if (!csv_)
        throw std::invalid_argument("viscoroll-solve: --csv " + options_.csv +
                                    ": cannot be opened for writing");
    }
    progress_ = ::isatty(2) != 0;
    start_ = std::chrono::steady_clock::now();
  }

  /// Keeps a result; nothing is printed until flush(), so that a run that fails (exit 2: a
  /// solve rejected its input) prints nothing on stdout, and every line printed stands. With
  /// check_validity(facts) set, a breach of the model's assumptions (core/validity.hpp) joins the
  /// result's warnings and stderr, or with `strict` makes the run an error (exit 2, nothing on
  /// stdout).
  void add(Record r) {
    // The scene's own breaches (scene_breaches): first, on every result, converged or not.
    viscoroll::cli::add_warnings(r, scene_breaches_, true);
    if (facts_) {
      const auto breaches = viscoroll::cli::add_validity_warnings(r, *facts_);
      for (const auto& b : breaches) {
        if (strict_)
          throw std::invalid_argument(
              "viscoroll-solve: --strict: " + viscoroll::cli::record_label(r) + ": " + b.text +
              " (without --strict this is a warning; docs/errors.md, \"Validity checks\")");
        note("viscoroll-solve: warning: " + viscoroll::cli::record_label(r) + ": " + b.text);
      }
    }
    pending_.push_back(std::move(r));
  }
  /// The warnings and the failure of a result chosen by the auto method, for stderr.
  void note_record(const Record& r) {
    if (const Value* w = find(r, "warnings"))
      for (const auto& text : std::get<std::vector<std::string>>(*w))
        note("viscoroll-solve: warning: " + viscoroll::cli::record_label(r) + ": " + text);
    if (!converged_record(r)) {
      const Value* reason = find(r, "reason");
      note("viscoroll-solve: " + viscoroll::cli::record_label(r) + " did not converge" +
           (reason ? ": " + std::get<std::string>(*reason) : std::string()));
    }
  }
  /// The results kept so far (not printed), taken: the auto method's choice among them.
  std::vector<Record> take() { return std::exchange(pending_, {}); }
  /// Checks every result added from now on against the model's assumptions; `strict`: a breach
  /// is an error.
  void check_validity(const viscoroll::cli::ValidityFacts& facts, bool strict) {
    facts_ = facts;
    strict_ = strict;
  }
  /// Breaches of the scene itself (its long-term static contact), added to every result's
  /// warnings and once to stderr.
  void scene_warnings(std::vector<viscoroll::Warning> breaches) {
    for (const auto& b : breaches) note("viscoroll-solve: warning: the scene: " + b.text);
    scene_breaches_ = std::move(breaches);
  }
  /// Keeps a message for stderr (a warning, a solve that did not converge), printed by flush().
  void note(std::string message) { notes_.push_back(std::move(message)); }

  /// --profile-out was given.
  bool wants_profile() const { return profile_csv_.is_open(); }

  /// Keeps the contact along the roller of a bem or line solve for --profile-out (one row per
  /// station: the bem's grid rows of the contact, the line solver's line_profile_stations; tau or
  /// the temperature empty when not the sweep's variable).
  void add_profile(double tau, double temperature, double speed,
                   const viscoroll::AlongRoller<double>& along) {
    if (!profile_csv_.is_open()) return;
    const auto number = [](double x) {
      return std::isnan(x) ? std::string() : viscoroll::cli::scene_detail::shortest(x);
    };
    for (std::size_t k = 0; k < along.y.size(); ++k)
      pending_profile_.push_back(number(tau) + "," + number(temperature) + "," + number(speed) +
                                 "," + number(along.y[k]) + "," + number(along.f0[k]) + "," +
                                 number(along.a[k]) + "," + number(along.b[k]) + "," +
                                 number(along.p_max[k]));
  }

  /// Prints the kept results (stdout, the CSV files) and then the messages (stderr).
  void flush() {
    for (const Record& r : pending_) emit(r);
    pending_.clear();
    for (const std::string& row : pending_profile_) profile_csv_ << row << "\n";
    if (profile_csv_.is_open()) profile_csv_.flush();
    pending_profile_.clear();
    for (const std::string& m : notes_) std::cerr << m << "\n";
    notes_.clear();
  }

 private:
  void emit(const Record& r) {
    ++count_;
    if (options_.format == Format::json) {
      std::cout << json_line(r) << "\n";
    } else {
      if (count_ == 1) table_header(r);
      table_row(r);
    }
    std::cout.flush();
    for (std::ofstream* csv : {&csv_, &plot_csv_}) {
      if (!csv->is_open()) continue;
      if (count_ == 1) *csv << csv_header(r) << "\n";
      *csv << csv_row(r) << "\n";
      csv->flush();
    }
    if (count_ == 1) header_ = csv_header(r);
  }

 public:
  /// Progress on stderr when it is a terminal: `done` solves of the whole run are finished.
  void progress(std::size_t done) const {
    if (!progress_) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr, "viscoroll-solve: speed %zu of %zu, elapsed %.1f s\n", done, total_,
                 elapsed);
  }

  /// Closes the files and draws the plot; false (with a message) if gnuplot failed.
  bool finish() {
    flush();
    if (csv_.is_open()) csv_.close();
    if (profile_csv_.is_open()) profile_csv_.close();
    if (!plot_csv_.is_open()) return true;
    plot_csv_.close();
    return plot();
  }

 private:
  bool three_d() const { return method_ != Method::plane; }

  /// A prony material's table has the temperature and a_T where the others have tau and
  /// V tau / a_lt.
  static bool prony_table(const Record& r) { return find(r, "temperature") != nullptr; }

  void table_header(const Record& first) {
    if (prony_table(first))
      std::printf("%-12s %-12s %-12s %-13s %-13s", "T_degC", "speed", "a_T", "a0", "b0");
    else
      std::printf("%-12s %-12s %-12s %-13s %-13s", "tau", "speed", "Vtau/a_lt", "a0", "b0");
    if (three_d()) std::printf(" %-13s %-13s", "l", "d");
    // The rolling resistance and the power loss in a scene file's SI units (per metre of roller
    // for the plane method); with options, in the options' consistent units.
    std::printf(" %-13s %-13s %-13s %s\n", "chi", three_d() ? "F_N" : "F_N/m",
                three_d() ? "P_W" : "P_W/m", "converged");
  }

  static std::string cell(double x, int precision) {
    if (!std::isfinite(x)) return "-";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, x);
    return buffer;
  }

  void table_row(const Record& r) {
    const bool prony = prony_table(r);
    const bool ok = converged_record(r);
    // A result that did not converge shows "-" for the solution, as for a non-finite number.
    const auto solved = [&](std::string_view key) {
      return cell(ok ? real(r, key) : std::numeric_limits<double>::quiet_NaN(), 7);
    };
    std::printf("%-12s %-12s %-12s %-13s %-13s",
                cell(real(r, prony ? "temperature" : "tau"), 6).c_str(),
                cell(real(r, "speed"), 6).c_str(),
                cell(prony ? real(r, "a_T") : real(r, "vtau") / real(r, "a_long_term"), 6).c_str(),
                solved("a0").c_str(), solved("b0").c_str());
    if (three_d()) std::printf(" %-13s %-13s", solved("l").c_str(), solved("d").c_str());
    // "min": converged to the certified least-squares minimum where the line equations have no
    // root (root false).
    const Value* root = find(r, "root");
    std::printf(" %-13s %-13s %-13s %s\n", solved("chi").c_str(),
                solved("rolling_resistance").c_str(), solved("power_loss").c_str(),
                !ok ? "no" : (root && !std::get<bool>(*root) ? "min" : "yes"));
  }

  /// 1-based column of `key` in the CSV, or 0.
  int column(std::string_view key) const {
    int k = 1;
    std::string_view rest = header_;
    while (true) {
      const auto comma = rest.find(',');
      if (rest.substr(0, comma) == key) return k;
      if (comma == std::string_view::npos) return 0;
      rest = rest.substr(comma + 1);
      ++k;
    }
  }

  bool plot() {
    const fs::path dir = fs::absolute(options_.plot);
    const std::string data = gnuplot_string((dir / "sweep.csv").string());
    const fs::path script_path = dir / "sweep.gp";
    std::ofstream script(script_path);
    const auto series = [&](std::string_view key, std::string_view title) {
      return "data skip 1 using " + std::to_string(column("speed")) + ":" +
             std::to_string(column(key)) + " with linespoints title '" + std::string(title) + "'";
    };
    script << "# Written by viscoroll-solve --plot: " << method_name(method_)
           << " sweep against speed.\n"
           << "data = " << data << "\n"
           << "set datafile separator ','\n"
           << "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
           << "  set terminal pngcairo size 900,900 font ',10'\n"
           << "} else {\n"
           << "  set terminal png size 900,900\n"
           << "}\n"
           << "set output " << gnuplot_string((dir / "sweep.png").string()) << "\n"
           << "set logscale x\nset grid\nset key outside right\n"
           << "set multiplot layout 2,1 title 'viscoroll-solve --method " << method_name(method_)
           << "'\n"
           << "set ylabel 'length (m with a scene file)'\n"
           << "plot " << series("a0", "a(0)") << ", \\\n  " << series("b0", "b(0)");
    if (three_d()) script << ", \\\n  " << series("l", "l") << ", \\\n  " << series("d", "d");
    script << "\nset xlabel 'speed (m/s with a scene file)'\nset ylabel 'chi'\n"
           << "plot " << series("chi", "chi") << "\nunset multiplot\n";
    script.close();
    if (!script) {
      std::cerr << "viscoroll-solve: --plot: cannot write " << script_path.string() << "\n";
      return false;
    }
    const std::string program = gnuplot_.string(), argument = script_path.string();
    std::vector<char*> argv = {const_cast<char*>(program.c_str()),
                               const_cast<char*>(argument.c_str()), nullptr};
    pid_t pid = 0;
    int status = 0;
    if (::posix_spawn(&pid, program.c_str(), nullptr, nullptr, argv.data(), environ) != 0 ||
        ::waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      std::cerr << "viscoroll-solve: --plot: gnuplot " << argument << " failed\n";
      return false;
    }
    return true;
  }

  const SolveOptions& options_;
  Method method_;
  std::size_t total_, count_ = 0;
  std::ofstream csv_, plot_csv_, profile_csv_;
  std::vector<std::string> pending_profile_;
  std::string header_;
  fs::path gnuplot_;
  bool progress_ = false;
  std::chrono::steady_clock::time_point start_;
  std::vector<Record> pending_;
  std::vector<std::string> notes_;
  std::optional<viscoroll::cli::ValidityFacts> facts_;
  bool strict_ = false;
  std::vector<viscoroll::Warning> scene_breaches_;
};

/// The scene as the solvers take it, from options or from a scene file.
struct Problem {
  Method method = Method::plane;
  double mu_d = 0, nu = 0, f = 0;
  std::vector<double> tau;
  double c1 = 0;
  std::optional<double> c2;
  double load = 0;
  std::vector<double> speeds;
  std::optional<long> grid;
  unsigned threads = 0;  ///< of the speed sweep (0: every core)
  /// A prony material at its reference temperature, its shift law, and the
  /// temperatures to solve at (degrees Celsius; one NaN without a shift law).
  std::optional<viscoroll::PronyRelaxation<double>> prony;
  std::optional<viscoroll::ShiftLaw<double>> shift;
  std::vector<double> temperatures;
  /// The line method's settings (--oversampling, --basis, --max-iterations,
  /// --quadrature-tolerance): LineOptions.
  viscoroll::LineOptions line;
  /// A roller of finite length from the scene file (docs/rollers.md), with its tilt (0 with the
  /// line method, which solves the profile itself).
  std::optional<std::variant<viscoroll::Tilted<viscoroll::CrownedCylinder<double>>,
                             viscoroll::Tilted<viscoroll::LogarithmicCrown<double>>,
                             viscoroll::Tilted<viscoroll::TabulatedProfile<double>>>>
      roller;
  /// --setting fast: the line method's fast setting, on 6-point panels (FastLineSolverD) for a
  /// material of one relaxation time.
  bool fast = false;
  /// The rolling radius of energy_per_revolution: the scene file's `radius`, else 1/c1.
  double radius = 0;
  /// --tolerance, else the scene file's "tolerance": BemOptions::tolerance, or on a layer or a
  /// spring bed the plane method's PlaneSubstrateOptions::tolerance.
  std::optional<double> tolerance = std::nullopt;
  /// The scene file's "density" (kg/m^3): the quasi-static check (core/validity.hpp, (V4)).
  std::optional<double> density = std::nullopt;
  /// --strict, or the scene file's "strict": a validity breach is an error.
  bool strict = false;
  /// The scene file's "substrate" (the half space by default): the bem and plane methods' body.
  viscoroll::cli::SubstrateSpec substrate = {};
};

/// --oversampling, --basis, --max-iterations and --quadrature-tolerance into LineOptions (their
/// defaults where not given), over LineOptions::fast() in the fast `setting` (--setting, else the
/// scene file's).
viscoroll::LineOptions line_options(const SolveOptions& o, viscoroll::cli::LineSetting setting) {
  viscoroll::LineOptions line = setting == viscoroll::cli::LineSetting::fast
                                    ? viscoroll::LineOptions::fast()
                                    : viscoroll::LineOptions{};
  if (o.oversampling) line.oversampling = static_cast<int>(*o.oversampling);
  if (o.max_iterations) line.max_iterations = static_cast<int>(*o.max_iterations);
  if (o.quadrature_tolerance) line.quadrature_tolerance = *o.quadrature_tolerance;
  if (o.basis == "s") line.basis = viscoroll::LineBasis::s;
  if (o.basis == "mapped") line.basis = viscoroll::LineBasis::s_mapped;
  return line;
}

Problem from_options(const SolveOptions& o) {
  const auto setting = o.setting.value_or(viscoroll::cli::LineSetting::standard);
  Problem p{*o.method, o.mu_d, o.nu,   o.f,      o.tau,
            o.c1,      o.c2,   o.load, o.speeds, o.grid,
            o.threads, {},     {},     {},       line_options(o, setting),
            {}};
  p.fast = setting == viscoroll::cli::LineSetting::fast;
  p.radius = 1 / p.c1;
  p.tolerance = o.tolerance;
  p.strict = o.strict;
  return p;
}

/// The prony material of a scene file: its terms, or the fit of its DMA file (the report on
/// stderr, a poor fit as a warning); its shift law; the temperatures to solve at (--temperature,
/// else the scene's, else the law's t_ref; one NaN without a law).
void set_prony(Problem& p, const viscoroll::cli::PronyModel& m,
               const std::vector<double>& scene_temperatures, const SolveOptions& o) {
  const auto fail = [&](const std::string& message) {
    throw std::invalid_argument("viscoroll-solve: " + o.scene + ": " + message);
  };
  if (m.shift) {
    if (m.shift->law == "wlf")
      p.shift = viscoroll::WlfShift<double>(m.shift->c1, m.shift->c2, m.shift->t_ref);
    else
      p.shift = viscoroll::ArrheniusShift<double>(m.shift->activation_energy, m.shift->t_ref);
  }
  if (m.dma.empty()) {
    std::vector<viscoroll::RelaxationTerm<double>> terms;
    for (const auto& t : m.terms) terms.push_back({t.g, t.tau});
    try {
      p.prony.emplace(m.g_inf, m.nu, std::move(terms));
    } catch (const std::invalid_argument& e) {
      fail(std::string("material: ") + e.what());
    }
  } else {
    fs::path path(m.dma);
    if (path.is_relative()) path = (fs::path(o.scene).parent_path() / path).lexically_normal();
    try {
      const auto data = viscoroll::read_dma_csv_file<double>(path);
      viscoroll::DmaFitOptions<double> options;
      options.nu = m.nu;
      options.shift = p.shift;
      if (data.has_temperature && !p.shift)
        fail("material.dma = \"" + m.dma +
             "\" has a temperature_c column: give material.shift (wlf or arrhenius) to build the "
             "master curve");
      auto fit = viscoroll::fit_prony(data, options);
      std::cerr << "viscoroll-solve: material.dma = " << path.string() << ": " << fit.report.summary
                << "\n";
      if (fit.report.poor)
        std::cerr << "viscoroll-solve: warning: material.dma = " << path.string()
                  << ": a poor fit of the DMA data (largest relative error above the threshold); "
                     "the solutions are of the fitted spectrum\n";
      p.prony.emplace(std::move(fit.material));
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      if (what.starts_with("viscoroll-solve: ")) throw;
      fail("material.dma = \"" + m.dma + "\": " + what);
    }
  }
  p.temperatures = o.temperatures.empty() ? scene_temperatures : o.temperatures;
  if (!o.temperatures.empty() && !p.shift)
    throw std::invalid_argument(
        "viscoroll-solve: --temperature is valid only with a material of model prony with a "
        "shift law (material.shift); " +
        o.scene + " has none");
  if (p.temperatures.empty())
    p.temperatures = {p.shift ? viscoroll::reference_temperature(*p.shift) : std::nan("")};
  if (p.shift)
    for (const double t : p.temperatures) try {
        (void)viscoroll::shift_factor(*p.shift, t);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("viscoroll-solve: ") +
                                    (o.temperatures.empty() ? o.scene + ": " : "--temperature: ") +
                                    e.what());
      }
}

Problem from_scene(const SolveOptions& o) {
  using namespace viscoroll::cli;
  Scene scene = parse_scene(read_scene_file(o.scene), o.scene);
  // No method given: the auto method; for the cylinder on the half space, the plane method it
  // has (a cylinder on a layer or a bed stays auto, whose result says why it is the plane's).
  std::optional<Method> method = o.method ? o.method : scene.method;
  if (!method) method = Method::automatic;
  const bool cylinder = std::holds_alternative<CylinderProfile>(scene.roller);
  if (*method == Method::automatic && cylinder && scene.substrate.is_half_space())
    method = Method::plane;
  if (o.grid) scene.grid.reset();
  if (o.tolerance) scene.tolerance.reset();  // checked in main() against the method's range
  if (o.grid && *method == Method::automatic && !cylinder)
    throw std::invalid_argument(
        "viscoroll-solve: --grid needs --method line or bem (the auto method picks line or bem "
        "per result, each at its own default)");
  check_scene_for_method(scene, *method, o.scene);
  Problem p;
  p.method = *method;
  p.substrate = scene.substrate;
  p.grid = o.grid ? o.grid : scene.grid;
  p.threads = o.threads;
  // --setting replaces the file's "setting".
  const auto setting =
      o.setting.value_or(scene.setting.value_or(viscoroll::cli::LineSetting::standard));
  p.line = line_options(o, setting);
  p.tolerance = o.tolerance ? o.tolerance : scene.tolerance;
  p.density = scene.density;
  p.strict = o.strict || scene.strict;
  p.fast = setting == viscoroll::cli::LineSetting::fast;
  p.load = scene.load;
  p.speeds = o.speeds.empty() ? scene.speeds : o.speeds;
  std::visit(
      [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, ElasticModel>) {
          p.mu_d = m.mu, p.nu = m.nu, p.f = 0, p.tau = {0.0};
        } else if constexpr (std::is_same_v<M, PronyModel>) {
          set_prony(p, m, scene.temperatures, o);
        } else {
          static_assert(std::is_same_v<M, StandardLinearSolidModel>);
          p.mu_d = m.mu_d, p.nu = m.nu, p.f = m.f, p.tau = {m.tau};
        }
      },
      scene.material);
  if (!p.prony && !o.temperatures.empty())
    throw std::invalid_argument(
        "viscoroll-solve: --temperature is valid only with a material of model prony with a "
        "shift law (material.shift); " +
        o.scene + " has a material without temperature");
  std::visit(
      [&](const auto& r) {
        using R = std::decay_t<decltype(r)>;
        using viscoroll::Tilted;
        if constexpr (std::is_same_v<R, EllipsoidProfile>) {
          p.c1 = r.c1, p.c2 = r.c2, p.radius = 1 / r.c1;
        } else if constexpr (std::is_same_v<R, CylinderProfile>) {
          p.c1 = 1 / r.radius, p.radius = r.radius;
        } else {
          p.c1 = 1 / r.radius, p.radius = r.radius;
          // The library validates what the reader has not (a table's spline); its message names
          // the parameter, here under the scene's key.
          try {
            viscoroll::cli::visit_axial_profile(scene.roller, [&](auto profile, double tilt) {
              p.roller = Tilted(std::move(profile), tilt);
            });
          } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("viscoroll-solve: " + o.scene + ": roller: " + e.what());
          }
        }
      },
      scene.roller);
  return p;
}

/// "tau = T" (and ", speed = V" in a sweep of several speeds), for messages.
std::string label(const Problem& p, double tau, double speed) {
  using viscoroll::cli::scene_detail::shortest;
  return "tau = " + shortest(tau) + (p.speeds.size() > 1 ? ", speed = " + shortest(speed) : "");
}

/// "temperature = T" (or "the prony material"), and ", speed = V" in a sweep of several speeds.
std::string temperature_label(const Problem& p, double temperature, double speed) {
  using viscoroll::cli::scene_detail::shortest;
  return (std::isnan(temperature) ? std::string("the prony material")
                                  : "temperature = " + shortest(temperature)) +
         (p.speeds.size() > 1 ? ", speed = " + shortest(speed) : "");
}

/// Solves `scene` at every speed of the problem with `solver` by viscoroll::sweep (chunks of
/// continuation on --threads threads; the result does not depend on the thread count), after
/// `done` solves of earlier taus (for the progress line).
template <class Solver, class Scene>
std::vector<typename viscoroll::TimedSolver<Solver>::Solution> sweep_speeds(const Solver& solver,
                                                                            const Scene& scene,
                                                                            const Problem& p,
                                                                            const Output& out,
                                                                            std::size_t done) {
  viscoroll::SweepOptions options;
  options.threads = p.threads;
  options.progress = [&out, done](std::size_t k, std::size_t) { out.progress(done + k); };
  return viscoroll::sweep(viscoroll::TimedSolver<Solver>{solver}, scene, p.speeds, options);
}

/// Runs every (key, speed) of the problem, the keys its taus (or a prony material's temperatures):
/// `scene_at(speed)` builds a scene and `solver_for(key)` a solver, all of them validated before
/// any output is opened; then each key's speeds are swept and `report(key, scene, solution,
/// seconds)` adds the record and any notes. Returns the exit
/// status (0 all converged, 1 not).
template <class SceneAt, class SolverFor, class Report>
int run_sweeps(const Problem& p, const std::vector<double>& keys, Output& out, SceneAt scene_at,
               SolverFor solver_for, Report report) {
  std::vector<std::invoke_result_t<SceneAt, double>> scenes;
  for (double speed : p.speeds) {
    scenes.push_back(scene_at(speed));
    scenes.back().validate();
  }
  std::vector<std::invoke_result_t<SolverFor, double>> solvers;
  for (double key : keys) solvers.push_back(solver_for(key));
  out.open();
  bool all_converged = true;
  for (std::size_t i = 0; i < solvers.size(); ++i) {
    const auto results = sweep_speeds(solvers[i], scenes.front(), p, out, i * scenes.size());
    for (std::size_t k = 0; k < scenes.size(); ++k) {
      all_converged = all_converged && results[k].solution.converged;
      report(keys[i], scenes[k], results[k].solution, results[k].seconds);
    }
  }
  return all_converged ? 0 : 1;
}

/// The material of the problem at relaxation time `tau`.
viscoroll::StandardLinearSolid<double> material(const Problem& p, double tau) {
  return {p.mu_d, p.nu, p.f, tau};
}

/// The warnings and the failure of one 3-D solution, for stderr; `reason`, when given, replaces
/// the solution's (a line record's, with add_end_hint's words).
template <class Solution>
void note_outcome(Output& out, const char* method, const std::string& which, const Solution& s,
                  const std::string* reason = nullptr) {
  for (const auto& w : s.warnings)
    out.note(std::string("viscoroll-solve: warning: ") + method + " solution for " + which + ": " +
             w);
  if (!s.converged)
    out.note(std::string("viscoroll-solve: ") + method + " solution for " + which +
             " did not converge: " + (reason ? *reason : s.reason));
}

/// --method needs --c2 (line, bem).
double required_c2(const Problem& p, const char* method) {
  if (!p.c2)
    throw std::invalid_argument(std::string("viscoroll-solve: --method ") + method +
                                " needs --c2; " + viscoroll::cli::usage());
  return *p.c2;
}

/// The prony material at `temperature` (the reference material when there is no shift law).
viscoroll::PronyRelaxation<double> prony_at(const Problem& p, double temperature);

/// The load, `speed` and rolling radius of the problem, for the record's engineering_fields.
viscoroll::cli::Duty duty(const Problem& p, double speed) { return {p.load, speed, p.radius}; }

/// `head` followed by `fields`.
Record with_fields(Record head, const Record& fields) {
  head.insert(head.end(), fields.begin(), fields.end());
  return head;
}

/// The plane method's relative tolerance in a, d and chi on a layer or a spring bed
/// (PlaneSubstrateOptions::tolerance, docs/plane-substrate.md (Q13)): --tolerance (or the
/// scene's), else cli::plane_substrate_tolerance, 1e-4.
double plane_tolerance(const Problem& p) {
  return p.tolerance.value_or(viscoroll::cli::plane_substrate_tolerance);
}

/// The plane method on the scene's layer or spring bed: PlaneSubstrateSolver of the material at
/// each tau (a prony material: each temperature) to plane_tolerance, its speeds swept as the
/// half space's (no seed: each solve starts from its own first Chebyshev level); the records'
/// fields cli::plane_substrate_fields.
int run_plane_substrate(const Problem& p, Output& out) {
  const double tolerance = plane_tolerance(p);
  const std::string substrate = p.substrate.describe();
  const viscoroll::PlaneSubstrateOptions options =
      viscoroll::cli::plane_substrate_options(tolerance);
  const auto scene_at = [&](double speed) {
    return viscoroll::PlaneScene<double>{.c1 = p.c1, .load = p.load, .speed = speed};
  };
  const auto fields = [&](const auto& s, double speed, double seconds) {
    return viscoroll::cli::plane_substrate_fields<Record>(s, substrate, tolerance, duty(p, speed),
                                                          seconds);
  };
  return viscoroll::cli::visit_plane_body(p.substrate, [&](const auto& body) {
    if (p.prony)
      return run_sweeps(
          p, p.temperatures, out, scene_at,
          [&](double temperature) {
            return viscoroll::PlaneSubstrateSolver(prony_at(p, temperature), body, options);
          },
          [&](double temperature, const auto& scene, const auto& s, double seconds) {
            const double a_t = p.shift ? viscoroll::shift_factor(*p.shift, temperature) : 1.0;
            out.add(with_fields({{"method", std::string("plane")},
                                 {"temperature", temperature},
                                 {"a_T", a_t},
                                 {"speed", scene.speed}},
                                fields(s, scene.speed, seconds)));
            if (!s.converged)
              out.note("viscoroll-solve: plane solution for " +
                       temperature_label(p, temperature, scene.speed) +
                       " did not converge: " + s.reason);
          });
    return run_sweeps(
        p, p.tau, out, scene_at,
        [&](double tau) {
          return viscoroll::PlaneSubstrateSolver(material(p, tau), body, options);
        },
        [&](double tau, const auto& scene, const auto& s, double seconds) {
          out.add(with_fields({{"method", std::string("plane")},
                               {"tau", tau},
                               {"speed", scene.speed},
                               {"vtau", scene.speed * tau}},
                              fields(s, scene.speed, seconds)));
          if (!s.converged)
            out.note("viscoroll-solve: plane solution for " + label(p, tau, scene.speed) +
                     " did not converge: " + s.reason);
        });
  });
}

/// The plane method: Hunter's closed form (PlaneSolver) on the half space, PlaneSubstrateSolver
/// on a scene file's layer or spring bed (run_plane_substrate).
int run_plane(const Problem& p, Output& out) {
  if (!p.substrate.is_half_space()) return run_plane_substrate(p, out);
  if (p.prony)
    return run_sweeps(
        p, p.temperatures, out,
        [&](double speed) {
          return viscoroll::PlaneScene<double>{.c1 = p.c1, .load = p.load, .speed = speed};
        },
        [&](double temperature) { return viscoroll::PlaneSolver(prony_at(p, temperature)); },
        [&](double temperature, const auto& scene, const auto& s, double seconds) {
          const double a_t = p.shift ? viscoroll::shift_factor(*p.shift, temperature) : 1.0;
          out.add(with_fields(
              {{"method", std::string("plane")},
               {"temperature", temperature},
               {"a_T", a_t},
               {"speed", scene.speed}},
              viscoroll::cli::plane_fields<Record>(s, duty(p, scene.speed), seconds, true)));
          if (!s.converged)
            out.note("viscoroll-solve: plane solution for " +
                     temperature_label(p, temperature, scene.speed) + " did not converge");
        });
  return run_sweeps(
      p, p.tau, out,
      [&](double speed) {
        return viscoroll::PlaneScene<double>{.c1 = p.c1, .load = p.load, .speed = speed};
      },
      [&](double tau) { return viscoroll::PlaneSolverD(material(p, tau)); },
      [&](double tau, const auto& scene, const auto& s, double seconds) {
        out.add(with_fields(
            {{"method", std::string("plane")},
             {"tau", tau},
             {"speed", scene.speed},
             {"vtau", scene.speed * tau}},
            viscoroll::cli::plane_fields<Record>(s, duty(p, scene.speed), seconds, false)));
        if (!s.converged)
          out.note("viscoroll-solve: plane solution for " + label(p, tau, scene.speed) +
                   " did not converge");
      });
}

/// --grid for the line method: LineOptions::terms, default 6 (the fast setting's 5 with --setting
/// fast); 4 for a prony material, where the spectrum's line theory converges at every speed of its
/// validation (docs/line-solver.md, "Materials with a spectrum"), in either setting.
int line_terms(const Problem& p) {
  constexpr long max_terms = 64;
  const long default_terms = p.prony ? 4 : p.fast ? viscoroll::LineOptions::fast().terms : 6;
  const long n = p.grid.value_or(default_terms);
  if (n < 1 || n > max_terms)
    throw std::invalid_argument(
        "viscoroll-solve: --grid (line: Chebyshev terms) expects 1 <= N <= " +
        std::to_string(max_terms) + ", got " + std::to_string(n));
  return static_cast<int>(n);
}

viscoroll::cli::ValidityFacts validity_facts(const Problem& p);
viscoroll::cli::LongTermContact line_long_term(const Problem& p);

/// The line-contact (3-D) solver; for each tau (a prony material: each temperature) the speeds
/// are swept by viscoroll::sweep: in chunks of 16 in the given order, each speed seeded with the
/// previous converged iterated solution of its chunk (continuation; a closed form carries no more
/// than the solver's own seed). A roller of finite length (tilted or not) is solved by
/// LineSolver::solve(LineProfileScene), on a spectrum by docs/theory.md (RP5); the ellipsoid by
/// LineSolver::solve(LineScene). --setting fast: LineOptions::fast() on FastLineSolverD (a
/// material of one relaxation time) or on the spectrum's solver.
int run_line(const Problem& p, Output& out) {
  viscoroll::LineOptions options = p.line;
  options.terms = line_terms(p);
  const auto facts = validity_facts(p);
  // A material of one relaxation time over the scene `scene_at(speed)` builds, by the solver
  // `tag` names (LineSolverD, or FastLineSolverD for the fast setting).
  const auto run_single_on = [&](auto scene_at, auto tag) {
    using Solver = typename decltype(tag)::type;
    return run_sweeps(
        p, p.tau, out, scene_at, [&](double tau) { return Solver(material(p, tau), options); },
        [&](double tau, const auto& scene, const auto& s, double seconds) {
          const auto peak = s.strip(0.0).peak();
          Record r = {{"method", std::string("line")},
                      {"tau", tau},
                      {"speed", scene.speed},
                      {"vtau", scene.speed * tau}};
          const Record middle = {{"pmax", peak.pressure}, {"pmax_x", peak.x}};
          const Record fields =
              viscoroll::cli::line_fields(s, middle, duty(p, scene.speed), options.terms, seconds);
          r.insert(r.end(), fields.begin(), fields.end());
          viscoroll::cli::add_end_hint(r, facts);
          const std::string reason = std::get<std::string>(*find(r, "reason"));
          out.add(std::move(r));
          if (out.wants_profile())
            out.add_profile(tau, std::nan(""), scene.speed,
                            s.along_roller(viscoroll::cli::line_profile_stations));
          note_outcome(out, "line", label(p, tau, scene.speed), s, &reason);
        });
  };
  // A prony material at each temperature over the scene `scene_at(speed)` builds.
  const auto run_spectrum = [&](auto scene_at) {
    return run_sweeps(
        p, p.temperatures, out, scene_at,
        [&](double temperature) {
          return viscoroll::LineSolver<double, viscoroll::PronyRelaxation<double>>(
              prony_at(p, temperature), options);
        },
        [&](double temperature, const auto& scene, const auto& s, double seconds) {
          const double a_t = p.shift ? viscoroll::shift_factor(*p.shift, temperature) : 1.0;
          // The spectrum's line solution carries the contact's shape and moments, not the
          // pressure at y = 0 (docs/line-solver.md): active_terms in place of pmax.
          Record r = {{"method", std::string("line")},
                      {"temperature", temperature},
                      {"a_T", a_t},
                      {"speed", scene.speed}};
          const Record middle = {{"active_terms", static_cast<long long>(s.active_terms)},
                                 {"spectrum_error", s.spectrum_error}};
          const Record fields =
              viscoroll::cli::line_fields(s, middle, duty(p, scene.speed), options.terms, seconds);
          r.insert(r.end(), fields.begin(), fields.end());
          viscoroll::cli::add_end_hint(r, facts);
          const std::string reason = std::get<std::string>(*find(r, "reason"));
          out.add(std::move(r));
          // p_max is NaN (an empty cell) unless one term is active (along_roller).
          if (out.wants_profile())
            out.add_profile(std::nan(""), temperature, scene.speed,
                            s.along_roller(viscoroll::cli::line_profile_stations));
          note_outcome(out, "line", temperature_label(p, temperature, scene.speed), s, &reason);
        });
  };
  const auto run = [&](auto scene_at) {
    if (p.prony) return run_spectrum(scene_at);
    return p.fast ? run_single_on(scene_at, std::type_identity<viscoroll::FastLineSolverD>{})
                  : run_single_on(scene_at, std::type_identity<viscoroll::LineSolverD>{});
  };
  if (p.roller)
    return std::visit(
        [&](const auto& tilted) {
          // Tilted (the asymmetric contact, docs/theory.md section 16) or not.
          using Profile = std::decay_t<decltype(tilted)>;
          return run([&](double speed) {
            return viscoroll::LineProfileScene<Profile>{
                .roller = tilted, .load = p.load, .speed = speed};
          });
        },
        *p.roller);
  const double c2 = required_c2(p, "line");
  return run([&](double speed) {
    return viscoroll::LineScene<double>{.c1 = p.c1, .c2 = c2, .load = p.load, .speed = speed};
  });
}

/// The bem method's relative tolerance in d and chi (BemOptions::tolerance, docs/theory.md
/// section 17): --tolerance (or the scene's), else 0.01 unless a grid is given, which fixes it.
double bem_tolerance(const Problem& p) { return p.tolerance.value_or(p.grid ? 0.0 : 0.01); }

/// --grid for the bem method: elements per semi-axis, default 16 (8, the refinement's first
/// grid, with a tolerance).
int bem_grid(const Problem& p) {
  constexpr long max_grid = 512;
  const long default_grid = bem_tolerance(p) > 0 ? 8 : 16;
  const long n = p.grid.value_or(default_grid);
  if (n < 2 || n > max_grid)
    throw std::invalid_argument(
        "viscoroll-solve: --grid (bem: elements per semi-axis) expects 2 <= N <= " +
        std::to_string(max_grid) + ", got " + std::to_string(n));
  return static_cast<int>(n);
}

/// The prony material at `temperature` (the reference material when there is no shift law).
viscoroll::PronyRelaxation<double> prony_at(const Problem& p, double temperature) {
  return p.shift ? viscoroll::at_temperature(*p.prony, *p.shift, temperature) : *p.prony;
}

/// BemOptions::threads for --threads N (0: every core): the N threads shared by the sweep's chunks
/// that run at once, each chunk's solves building their influence tables on N / (chunks at once)
/// of them, at least 1 and at most BemOptions' 1024. The table does not depend on the count.
int bem_table_threads(const Problem& p) {
  viscoroll::SweepOptions sweep;
  sweep.threads = p.threads;
  const std::size_t chunks = (p.speeds.size() + sweep.chunk - 1) / sweep.chunk;
  const unsigned all =
      p.threads != 0 ? p.threads : std::max(1u, std::thread::hardware_concurrency());
  return static_cast<int>(std::clamp(all / sweep.effective_threads(chunks), 1u, 1024u));
}

/// The boundary-element solver; every solve shares one grid (it is sized by the static
/// long-term contact), and the speeds are swept as the line method's are, each seeded with the
/// previous converged contact of its chunk. A prony material is solved at each temperature.
int run_bem(const Problem& p, Output& out) {
  viscoroll::BemOptions options;
  options.grid = bem_grid(p);
  options.tolerance = bem_tolerance(p);
  if (options.tolerance > 0) options.max_grid = std::max(options.max_grid, options.grid);
  options.threads = bem_table_threads(p);
  // A roller of finite length: its scene (gap, body, grid) from bem_scene, sized by the
  // long-term compliance, which neither tau nor the temperature changes; else the ellipsoid's.
  const viscoroll::BemScene<double> base =
      p.roller ? std::visit(
                     [&](const auto& roller) {
                       return p.prony ? viscoroll::bem_scene(roller, *p.prony, p.load, 0.0)
                                      : viscoroll::bem_scene(roller, material(p, p.tau.front()),
                                                             p.load, 0.0);
                     },
                     *p.roller)
               : viscoroll::BemScene<double>{
                     .c1 = p.c1, .c2 = required_c2(p, "bem"), .load = p.load, .speed = 0.0};
  const auto scene_at = [&](double speed) {
    auto scene = base;
    scene.speed = speed;
    return scene;
  };
  const bool axial = bool(p.roller);
  // The static long-term contact of a roller of finite length by the line theory, once (neither
  // tau nor the temperature changes the long-term compliance); the ellipsoid's is Hertz's, in
  // each solution.
  std::optional<viscoroll::cli::LongTermContact> roller_long_term;
  if (p.roller) roller_long_term = line_long_term(p);
  // The record after its head.
  const auto fields = [&](const auto& s, const viscoroll::AlongRoller<double>& along, double speed,
                          double seconds) {
    return viscoroll::cli::bem_fields<Record>(
        s, along, roller_long_term.value_or(viscoroll::cli::hertz_long_term(s)), axial,
        duty(p, speed), options.tolerance, seconds);
  };
  if (p.prony)
    return run_sweeps(
        p, p.temperatures, out, scene_at,
        [&](double temperature) {
          return viscoroll::cli::bem_solver(prony_at(p, temperature), options, p.substrate);
        },
        [&](double temperature, const auto& scene, const auto& s, double seconds) {
          const double a_t = p.shift ? viscoroll::shift_factor(*p.shift, temperature) : 1.0;
          const auto along = s.along_roller();
          out.add(with_fields({{"method", std::string("bem")},
                               {"temperature", temperature},
                               {"a_T", a_t},
                               {"speed", scene.speed}},
                              fields(s, along, scene.speed, seconds)));
          out.add_profile(std::nan(""), temperature, scene.speed, along);
          note_outcome(out, "bem", temperature_label(p, temperature, scene.speed), s);
        });
  return run_sweeps(
      p, p.tau, out, scene_at,
      [&](double tau) {
        return viscoroll::cli::bem_solver(material(p, tau), options, p.substrate);
      },
      [&](double tau, const auto& scene, const auto& s, double seconds) {
        const auto along = s.along_roller();
        out.add(with_fields({{"method", std::string("bem")},
                             {"tau", tau},
                             {"speed", scene.speed},
                             {"vtau", scene.speed * tau}},
                            fields(s, along, scene.speed, seconds)));
        out.add_profile(tau, std::nan(""), scene.speed, along);
        note_outcome(out, "bem", label(p, tau, scene.speed), s);
      });
}

/// What the validity checks need of the problem (cli/validity_record.hpp): the rolling radius,
/// the roller's body, the rubber's shear-wave speed sqrt(mu_glassy / density) where a density is
/// given (mu_glassy = (1 - nu)/(2 pi c), c the instantaneous compliance).
viscoroll::cli::ValidityFacts validity_facts(const Problem& p) {
  viscoroll::cli::ValidityFacts facts;
  facts.radius = p.radius;
  if (p.roller)
    std::visit(
        [&](const auto& r) {
          facts.body_min = r.y_min();
          facts.body_max = r.y_max();
        },
        *p.roller);
  if (p.density) {
    const double c = p.prony ? p.prony->instantaneous_compliance()
                             : material(p, p.tau.front()).instantaneous_compliance();
    const double nu = p.prony ? p.prony->nu() : p.nu;
    facts.shear_wave_speed = viscoroll::cli::shear_wave_speed(c, nu, *p.density);
  }
  return facts;
}

/// The line theory's long-term static contact of the problem (a0, l0; NaN where it has none):
/// Hertz's for the ellipsoid, static_profile_contact for a roller of finite length.
viscoroll::cli::LongTermContact line_long_term(const Problem& p) {
  const auto of = [&](const auto& m) {
    if (p.roller)
      return std::visit(
          [&](const auto& r) { return viscoroll::cli::profile_long_term(r, m, p.load); },
          *p.roller);
    const auto h = viscoroll::bem::hertz_contact(p.c1, *p.c2, m.long_term_compliance(), p.load);
    return viscoroll::cli::LongTermContact{h.a, h.b, h.d};
  };
  return p.prony ? of(*p.prony) : of(material(p, p.tau.front()));
}

/// The validity checks (V1), (V2) on the scene's long-term static contact, before any solve, in
/// words that name it: the ellipsoid's Hertz contact; a roller of finite length's line-theory
/// contact (static_profile_contact), or where that reaches the roller's ends, the width of a
/// contact along the whole roller, a = sqrt(4 (1 + f) c w / C1) at the load per length
/// w = W / length (Eq. 47 of a cylinder: the narrowest the contact can be); the cylinder's (plane)
/// the same at its load per length. A result that does not converge then still says why the
/// scene is suspect (a modulus in MPa: a contact wider than the roller).
std::vector<viscoroll::Warning> scene_breaches(const Problem& p) {
  const double compliance =
      p.prony ? p.prony->long_term_compliance() : material(p, p.tau.front()).long_term_compliance();
  const bool cylinder = !p.c2 && !p.roller;
  const auto lt = cylinder
                      ? viscoroll::cli::LongTermContact{std::sqrt(4 * compliance * p.load / p.c1),
                                                        std::nan(""), std::nan("")}
                      : line_long_term(p);
  return viscoroll::cli::scene_breaches(validity_facts(p), lt.a, p.roller ? lt.l : std::nan(""),
                                        compliance, p.load, p.c1);
}

/// The auto method (cli/auto_method.hpp): the plane method for a cylinder (on a layer or a spring
/// bed PlaneSubstrateSolver, at plane_tolerance); else the bem for a layer or a bed, and on the
/// half space the line method where its theory applies (line_precheck), each of its results
/// standing unless line_rejection finds a reason, the bem method (at its default tolerance) for
/// the others. Every result carries method_reason.
int run_auto(const Problem& p, Output& out, const SolveOptions& options) {
  namespace vc = viscoroll::cli;
  SolveOptions quiet = options;  // the methods' own results go nowhere until chosen
  quiet.csv.clear();
  quiet.plot.clear();
  quiet.profile_out.clear();
  const std::size_t total = (p.prony ? p.temperatures.size() : p.tau.size()) * p.speeds.size();
  const auto solve_by = [&](Method m) {
    Problem q = p;
    q.method = m;
    // A line result that is not a root does not answer (line_rejection): no least-squares
    // minimisation past Levenberg-Marquardt's stop.
    q.line.least_squares = false;
    Output scratch(quiet, m, total);
    const int status = m == Method::plane  ? run_plane(q, scratch)
                       : m == Method::line ? run_line(q, scratch)
                                           : run_bem(q, scratch);
    (void)status;  // the chosen records' own converged fields decide the exit status
    return scratch.take();
  };
  int status = 0;
  const auto keep = [&](Record r, const std::string& reason) {
    r = vc::with_method_reason(std::move(r), reason);
    if (!converged_record(r)) status = 1;
    out.note_record(r);
    out.add(std::move(r));
  };
  if (!p.c2 && !p.roller) {
    const std::string reason =
        p.substrate.is_half_space()
            ? vc::plane_cylinder()
            : vc::plane_substrate_cylinder(p.substrate.describe(), plane_tolerance(p));
    for (auto& r : solve_by(Method::plane)) keep(std::move(r), reason);
    return status;
  }
  if (!p.substrate.is_half_space()) {
    for (auto& r : solve_by(Method::bem))
      keep(std::move(r), vc::bem_instead(vc::substrate_precheck(p.substrate.describe())));
    return status;
  }
  const auto facts = validity_facts(p);
  std::string why = p.roller ? std::string() : vc::ellipsoid_precheck(p.c1, *p.c2);
  if (why.empty()) {
    const auto lt = line_long_term(p);
    why = vc::line_precheck(lt.a, lt.l, facts);
    if (why.empty() && p.roller)
      why = std::visit(
          [&](const auto& profile) { return vc::axial_curvature_precheck(profile, lt.a, lt.l); },
          *p.roller);
  }
  if (!why.empty()) {
    for (auto& r : solve_by(Method::bem)) keep(std::move(r), vc::bem_instead(why));
    return status;
  }
  std::vector<Record> lines = solve_by(Method::line), bems;
  std::vector<std::string> rejected;
  for (const auto& r : lines) rejected.push_back(vc::line_rejection(r, facts));
  if (std::any_of(rejected.begin(), rejected.end(), [](const auto& w) { return !w.empty(); }))
    bems = solve_by(Method::bem);
  for (std::size_t k = 0; k < lines.size(); ++k)
    if (rejected[k].empty())
      keep(std::move(lines[k]), vc::line_accepted());
    else
      keep(std::move(bems[k]), vc::bem_instead(rejected[k]));
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::vector<std::string_view> args(argv + 1, argv + argc);
    // --help (-h) and --version anywhere: print and exit 0, nothing solved.
    for (const std::string_view a : args) {
      if (a == "--help" || a == "-h") {
        std::cout << viscoroll::cli::usage()
                  << "\n\nOptions, scene files and output fields: docs/cli.md\n";
        return 0;
      }
      if (a == "--version") {
        std::cout << "viscoroll-solve " << VISCOROLL_VERSION_STRING << "\n";
        return 0;
      }
    }
    const SolveOptions options = viscoroll::cli::parse_solve_options(args);
    const Problem problem = options.scene.empty() ? from_options(options) : from_scene(options);
    if (problem.method != Method::line && problem.method != Method::automatic)
      for (const auto& [given, key] :
           {std::pair{bool(options.oversampling), "--oversampling"},
            std::pair{!options.basis.empty(), "--basis"},
            std::pair{bool(options.max_iterations), "--max-iterations"},
            std::pair{bool(options.quadrature_tolerance), "--quadrature-tolerance"},
            std::pair{options.setting.has_value(), "--setting"}})
        if (given)
          throw std::invalid_argument(std::string("viscoroll-solve: ") + key +
                                      " is valid only with --method line or auto");
    // The cylinder (no c2, no roller of finite length): the plane method's roller.
    const bool cylinder = !problem.c2 && !problem.roller;
    if (options.tolerance) {
      const bool plane_substrate =
          viscoroll::cli::solves_plane_substrate(problem.substrate.model, problem.method, cylinder);
      if (!plane_substrate && problem.method != Method::bem && problem.method != Method::automatic)
        throw std::invalid_argument(
            "viscoroll-solve: --tolerance is valid only with --method bem or auto, or plane on a "
            "scene file's layer or spring bed (the plane method on the half space is exact to "
            "rounding; the line method's error is its theory's: docs/cli.md)");
      if (!viscoroll::cli::tolerance_in_range(*options.tolerance, plane_substrate))
        throw std::invalid_argument(
            "viscoroll-solve: --tolerance = " +
            viscoroll::cli::scene_detail::shortest(*options.tolerance) +
            " is outside the valid range " +
            viscoroll::cli::tolerance_range("--tolerance", plane_substrate));
    }
    if (!options.profile_out.empty() && problem.method == Method::automatic)
      throw std::invalid_argument(
          "viscoroll-solve: --profile-out needs --method line or bem (the auto method picks one "
          "per result)");
    if (!options.profile_out.empty() && problem.method == Method::plane)
      throw std::invalid_argument(
          "viscoroll-solve: --profile-out is valid only with --method line or bem (the contact "
          "along the roller: docs/cli.md)");
    // The auto method on a cylinder answers by the plane method: its table.
    Output out(
        options, problem.method == Method::automatic && cylinder ? Method::plane : problem.method,
        (problem.prony ? problem.temperatures.size() : problem.tau.size()) * problem.speeds.size());
    // The validity checks read a scene file's physical roller (SI units). Options describe the
    // parabolic problem in any consistent units, often the paper's dimensionless form (C1 = 1,
    // lengths in a0), where a0/R is not a ratio of the roller: they are not checked.
    if (!options.scene.empty()) {
      out.check_validity(validity_facts(problem), problem.strict);
      auto breaches = scene_breaches(problem);
      if (problem.strict && !breaches.empty())
        throw std::invalid_argument("viscoroll-solve: --strict: " + options.scene + ": " +
                                    breaches.front().text +
                                    " (without --strict this is a warning; docs/errors.md, "
                                    "\"Validity checks\")");
      out.scene_warnings(std::move(breaches));
    }
    if (options.scene.empty() && options.strict)
      throw std::invalid_argument(
          "viscoroll-solve: --strict is valid only with --scene (the validity checks read a scene "
          "file's roller in SI units; docs/cli.md, \"Validity checks\")");
    int status = 0;
    switch (problem.method) {
      case Method::plane:
        status = run_plane(problem, out);
        break;
      case Method::line:
        status = run_line(problem, out);
        break;
      case Method::bem:
        status = run_bem(problem, out);
        break;
      case Method::automatic:
        status = run_auto(problem, out, options);
        break;
    }
    return out.finish() ? status : 1;
  } catch (const std::invalid_argument& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "viscoroll-solve: " << e.what() << "\n";
    return 1;
  }
}
