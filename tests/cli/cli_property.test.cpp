// Property test of viscoroll-solve at the ends of the floating-point range: random
// scenes whose inputs are each finite and log-uniform over 1e-300 ... 1e300 (nu uniform over its
// range), so that their products overflow and underflow, run through the command line with a
// time limit per case. Every case must end in one of
//   - exit 0: strict JSON lines (nlohmann's parser, which rejects inf and nan), each converged,
//     every number finite but vtau, f0_max, F, P and E (null where a product of the inputs
//     overflows, docs/cli.md), a0 > 0 and, for
//     line and bem, l > 0 and d > 0;
//   - exit 1: strict JSON lines whose converged ones pass the same checks, and a message on
//     stderr (a solve that did not converge);
//   - exit 2: nothing on stdout and a message on stderr (bad input, or an answer that the solver
//     says is not representable).
// A crash, a sanitizer report, a case over its time limit, a line that is not JSON, a converged
// result with a null, non-finite or non-positive size, or exit 0 with a result not converged
// fails the test; each failing case is printed as the exact command line that reproduces it.
//
// Parameters (environment): VISCOROLL_PROPERTY_CASES (cases per method; default 200 plane and
// line, 100 bem here; 2000 plane, 600 line and 400 bem in the [slow] tests; docs/errors.md gives
// the outcomes of 10000 plane, 2000 line and 2000 bem), VISCOROLL_PROPERTY_SEED
// (default 24), VISCOROLL_PROPERTY_TIMEOUT (seconds per case, default 120), VISCOROLL_PROPERTY_LOG
// (a file that receives one line per case: method, outcome, exit status, command, first stderr
// line). The bem cases use --grid 4 ... 8 (0.1 to 2 s a case in Release) and a line case takes
// about 30 ms, hence fewer of them.
// docs/errors.md.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_property {

namespace {

using namespace viscoroll::cli_test;

long env_long(const char* name, long fallback) {
  const char* text = std::getenv(name);
  return text != nullptr && *text != '\0' ? std::strtol(text, nullptr, 10) : fallback;
}

/// Uniform on [0, 1), from the top 53 bits (the same on every standard library).
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1p-53; }

/// 10^e with e uniform on [lo, hi].
double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::pow(10.0, lo + (hi - lo) * uniform(rng));
}

/// The arguments of case k of `method`: each input finite, log-uniform over 1e-300 ... 1e300,
/// within the method's valid ranges (line: c2 < 0.39 c1; bem: 1e-10 <= c2/c1 <= 1e10).
std::vector<std::string> random_case(const std::string& method, std::mt19937_64& rng) {
  const auto any = [&] { return log_uniform(rng, -300, 300); };
  const double mu_d = any(), f = any(), tau = any(), speed = any(), c1 = any(), load = any();
  const double nu = uniform(rng) < 0.1 ? 0.5 : -0.999 + 1.499 * uniform(rng);
  std::vector<std::string> args = {
      "--method", method,     "--mu-d",  exact(mu_d),  "--nu", exact(nu), "--f",    exact(f),
      "--tau",    exact(tau), "--speed", exact(speed), "--c1", exact(c1), "--load", exact(load)};
  const double e1 = std::log10(c1);
  if (method == "line") {
    const double top = e1 + std::log10(0.39);
    const double c2 = top > -300 ? log_uniform(rng, -300, top) : 0.39 * c1;
    args.insert(args.end(), {"--c2", exact(c2)});
  } else if (method == "bem") {
    const double lo = std::max(-10.0, -300 - e1), hi = std::min(10.0, 300 - e1);
    const double c2 = c1 * log_uniform(rng, lo, hi);
    const int grid = 4 + static_cast<int>(rng() % 5);
    args.insert(args.end(), {"--c2", exact(c2), "--grid", std::to_string(grid)});
  }
  return args;
}

/// The command line of a case, as a user would type it.
std::string command(const std::vector<std::string>& args) {
  std::string out = "viscoroll-solve";
  for (const auto& a : args) out += " " + a;
  return out;
}

/// Runs viscoroll-solve under coreutils' timeout: status 124 (or 137 after the KILL) when the
/// case ran over `seconds`.
Run run_limited(const std::vector<std::string>& args, long seconds) {
  std::vector<std::string> all = {"-k", "5", std::to_string(seconds), solve_program().string()};
  all.insert(all.end(), args.begin(), args.end());
  const fs::path dir = fs::temp_directory_path();
  const std::string stem = "viscoroll_cli_property_" + std::to_string(::getpid());
  const fs::path out = dir / (stem + ".out"), err = dir / (stem + ".err");
  std::string cmd = "timeout";
  for (const auto& a : all) cmd.append(" ").append(quote(a));
  cmd.append(" >").append(quote(out.string())).append(" 2>").append(quote(err.string()));
  const int raw = std::system(cmd.c_str());
  Run r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
  fs::remove(out);
  fs::remove(err);
  return r;
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

/// Why a converged line breaks the property, or empty.
std::string converged_defect(const nlohmann::json& line, const std::string& method) {
  // The parser has rejected inf and nan already (and a literal beyond a double): a number that
  // was not finite can only be null here.
  for (const auto& [key, value] : line.items()) {
    // null where speed * tau, resp. the load per unit length, resp. chi times the load (and the
    // speed or 2 pi R) overflows (docs/cli.md)
    if (key == "vtau" || key == "f0_max" || key == "f0_max_y" || key == "rolling_resistance" ||
        key == "power_loss" || key == "energy_per_revolution")
      continue;
    if (value.is_null()) return "converged with " + key + " null";
  }
  std::vector<const char*> sizes = {"a0"};
  if (method != "plane") sizes.insert(sizes.end(), {"l", "d"});
  for (const char* key : sizes) {
    if (!line.contains(key) || !line[key].is_number()) return std::string("no number ") + key;
    if (!(line[key].get<double>() > 0)) return std::string("converged with ") + key + " <= 0";
  }
  return {};
}

struct Outcome {
  std::string kind;  ///< "ok", "not converged", "error" (exit 2), or the defect
  bool defect = false;
};

Outcome classify(const Run& r, const std::string& method) {
  if (r.status == 124 || r.status == 137) return {"over the time limit", true};
  if (r.status < 0 || r.status > 2) return {"crashed, status " + std::to_string(r.status), true};
  if (r.err.find("Sanitizer") != std::string::npos ||
      r.err.find("runtime error:") != std::string::npos)
    return {"sanitizer report", true};
  std::vector<nlohmann::json> lines;
  try {
    for (const auto& line : json_lines(r.out)) lines.push_back(line);
  } catch (const nlohmann::json::exception&) {
    return {"stdout is not strict JSON", true};
  }
  if (r.status == 2) {
    if (!r.out.empty()) return {"exit 2 after output", true};
    if (first_line(r.err).rfind("viscoroll", 0) != 0) return {"exit 2 without a message", true};
    return {"error"};
  }
  if (lines.empty()) {
    if (r.status == 1 && !r.err.empty()) return {"error"};  // a runtime error before any output
    return {"no output", true};
  }
  bool all_converged = true;
  for (const auto& line : lines) {
    if (!line.contains("converged") || !line["converged"].is_boolean())
      return {"a line without converged", true};
    if (!line["converged"].get<bool>()) {
      all_converged = false;
      continue;
    }
    if (const std::string d = converged_defect(line, method); !d.empty()) return {d, true};
  }
  if (r.status == 0 && !all_converged) return {"exit 0 with a result not converged", true};
  if (r.status == 1 && all_converged) return {"exit 1 with every result converged", true};
  if (r.status == 1 && r.err.empty()) return {"exit 1 without a message", true};
  return {all_converged ? "ok" : "not converged"};
}

/// Runs `count` random cases of `method`; prints the tally and every failing command line.
void property(const std::string& method, long count) {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  count = env_long("VISCOROLL_PROPERTY_CASES", count);
  const long seconds = env_long("VISCOROLL_PROPERTY_TIMEOUT", 120);
  const auto seed = static_cast<std::uint64_t>(env_long("VISCOROLL_PROPERTY_SEED", 24));
  // One stream per method, so that the cases of a method do not depend on the others' counts.
  std::mt19937_64 rng(seed * 3 + (method == "plane" ? 0 : method == "line" ? 1 : 2));
  std::ofstream log;
  if (const char* path = std::getenv("VISCOROLL_PROPERTY_LOG")) log.open(path, std::ios::app);
  std::map<std::string, long> tally;
  std::vector<std::string> defects;
  for (long k = 0; k < count; ++k) {
    const auto args = random_case(method, rng);
    const Run r = run_limited(args, seconds);
    const Outcome o = classify(r, method);
    ++tally[o.kind];
    if (o.defect)
      defects.push_back(o.kind + ": " + command(args) + "  [" + first_line(r.err) + "]");
    if (log.is_open())
      log << method << '\t' << o.kind << '\t' << r.status << '\t' << command(args) << '\t'
          << first_line(r.err) << '\n';
  }
  std::string summary =
      method + ": " + std::to_string(count) + " random scenes (seed " + std::to_string(seed) + "):";
  for (const auto& [kind, n] : tally) summary += " " + kind + " " + std::to_string(n) + ";";
  WARN(summary);
  for (const auto& d : defects) UNSCOPED_INFO(d);
  CHECK(defects.empty());
}

}  // namespace

TEST_CASE("cli property: random extreme plane scenes end in finite JSON or a clear error",
          "[cli][property]") {
  property("plane", 200);
}

TEST_CASE("cli property: random extreme line scenes end in finite JSON or a clear error",
          "[cli][property]") {
  property("line", 200);
}

TEST_CASE("cli property: random extreme bem scenes end in finite JSON or a clear error",
          "[cli][property]") {
  property("bem", 100);
}

TEST_CASE("cli property: 2000 random extreme plane scenes", "[cli][property][slow]") {
  property("plane", 2000);
}

TEST_CASE("cli property: 600 random extreme line scenes", "[cli][property][slow]") {
  property("line", 600);
}

TEST_CASE("cli property: 400 random extreme bem scenes", "[cli][property][slow]") {
  property("bem", 400);
}

}  // namespace test_cli_property
