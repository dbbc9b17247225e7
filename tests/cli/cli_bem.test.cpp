// viscoroll-solve --method bem: bad input prints the library's message (parameter, value,
// range) or the driver's on stderr, exits 2 and prints nothing on stdout; good input prints one
// JSON line per tau and exits 0. The program is run as cli_run.hpp says.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_bem {

namespace {

/// Runs viscoroll-solve with `args`, words separated by spaces.
viscoroll::cli_test::Run run(const std::string& args) {
  std::vector<std::string> words;
  std::istringstream in(args);
  std::string word;
  while (in >> word) words.push_back(word);
  return viscoroll::cli_test::run(words);
}

/// The paper's scene (docs/bem.md) on a coarse grid, with options replaced ("--mu-d=0") or
/// removed ("--c2=") by `changes`.
std::string arguments(const std::vector<std::string>& changes = {}) {
  std::vector<std::pair<std::string, std::string>> options = {
      {"--method", "bem"}, {"--mu-d", "1"}, {"--nu", "0.5"},    {"--f", "9"},      {"--tau", "1"},
      {"--speed", "1"},    {"--c1", "1"},   {"--c2", "0.0798"}, {"--load", "5.3"}, {"--grid", "4"}};
  for (const auto& change : changes) {
    const auto eq = change.find('=');
    const std::string key = change.substr(0, eq), value = change.substr(eq + 1);
    bool found = false;
    for (auto& o : options)
      if (o.first == key) {
        o.second = value;
        found = true;
      }
    if (!found) options.emplace_back(key, value);
  }
  std::string out;
  for (const auto& [key, value] : options)
    if (!value.empty()) out += " " + key + " " + value;
  return out;
}

}  // namespace

TEST_CASE("cli: viscoroll-solve --method bem rejects bad input on stderr with exit 2",
          "[cli][bem]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  struct Case {
    std::string args, message;
  };
  const std::vector<Case> cases = {
      // The library's validation: parameter, value, range.
      {arguments({"--mu-d=0"}), "viscoroll: mu_d = 0 is outside the valid range mu_d > 0"},
      {arguments({"--mu-d=-2e-3"}), "viscoroll: mu_d = -0.002 is outside the valid range mu_d > 0"},
      {arguments({"--nu=0.7"}), "viscoroll: nu = 0.7 is outside the valid range -1 < nu <= 0.5"},
      {arguments({"--nu=-1"}), "viscoroll: nu = -1 is outside the valid range -1 < nu <= 0.5"},
      {arguments({"--f=-1"}), "viscoroll: f = -1 is outside the valid range f >= 0"},
      // Every tau is checked before anything is solved or printed.
      {arguments({"--tau=1,-2"}), "viscoroll: tau = -2 is outside the valid range tau >= 0"},
      {arguments({"--c1=-1"}), "viscoroll: c1 = -1 is outside the valid range c1 > 0"},
      {arguments({"--c2=0"}), "viscoroll: c2 = 0 is outside the valid range c2 > 0"},
      {arguments({"--c2=1e11"}),
       "viscoroll: c2/c1 = 100000000000 is outside the valid range 1e-10 <= c2/c1 <= 1e10"},
      {arguments({"--c2=1e-11"}),
       "viscoroll: c2/c1 = 1e-11 is outside the valid range 1e-10 <= c2/c1 <= 1e10"},
      {arguments({"--load=0"}), "viscoroll: load = 0 is outside the valid range load > 0"},
      {arguments({"--speed=-1"}), "viscoroll: speed = -1 is outside the valid range speed >= 0"},
      // The driver's own checks.
      {arguments({"--c2="}), "--method bem needs --c2"},
      {arguments({"--grid=1"}),
       "--grid (bem: elements per semi-axis) expects 2 <= N <= 512, got 1"},
      {arguments({"--grid=513"}),
       "--grid (bem: elements per semi-axis) expects 2 <= N <= 512, got 513"},
      {arguments({"--grid=4x"}), "--grid expects a positive integer, got '4x'"},
      {arguments({"--c2=nan"}), "--c2 expects a finite number, got 'nan'"},
      {arguments({"--load=1e999"}), "--load expects a finite number, got '1e999'"},
      {arguments({"--extent=2"}), "unknown option '--extent'"},
      {arguments() + " --grid 5", "--grid given twice"},
  };
  for (const auto& c : cases) {
    const auto r = run(c.args);
    INFO("viscoroll-solve " << c.args << "\nstdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(c.message) != std::string::npos);
  }
}

TEST_CASE("cli: viscoroll-solve --method bem prints one converged JSON line per tau",
          "[cli][bem]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const auto r = run(arguments({"--tau=0,1"}));
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  std::istringstream lines(r.out);
  std::string line;
  int n = 0;
  while (std::getline(lines, line)) {
    ++n;
    CHECK(line.starts_with("{\"method\":\"bem\""));
    CHECK(line.find("\"converged\":true") != std::string::npos);
    CHECK(line.find("null") == std::string::npos);
  }
  CHECK(n == 2);
}

TEST_CASE("cli: viscoroll-solve --method line prints the domain warning on stderr too",
          "[cli][line]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // C2/C1 = 0.3 makes a short contact (measured l/a(0) = 2.67 at V tau = C1 = 1): converged, exit
  // 0, the warning in the JSON and on stderr.
  const auto r = run(arguments({"--method=line", "--c2=0.3", "--grid=4"}));
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.status == 0);
  CHECK(r.out.find("\"converged\":true") != std::string::npos);
  CHECK(r.out.find("l/a(0) = ") != std::string::npos);
  CHECK(
      r.err.find("viscoroll-solve: warning: line solution for tau = 1: contact aspect l/a(0) = ") !=
      std::string::npos);
  // The paper's scene (l/a(0) = 4.6 at V tau = a0 = 1): no warning anywhere.
  const auto ok = run(arguments({"--method=line", "--grid=4"}));
  INFO("stdout: " << ok.out << "\nstderr: " << ok.err);
  CHECK(ok.status == 0);
  CHECK(ok.err.empty());
  CHECK(ok.out.find("\"warnings\":[]") != std::string::npos);
  CHECK(ok.out.find("\"warning_codes\":[]") != std::string::npos);
  CHECK(ok.out.find("\"code\":\"converged\"") != std::string::npos);
}

TEST_CASE(
    "cli: viscoroll-solve --method bem solves the floating-point extreme scenes or names them",
    "[cli][bem]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // Answers that are representable: converged, finite (no inf, nan or null), exit 0.
  for (const auto& changes : std::vector<std::vector<std::string>>{
           {"--speed=1e308", "--grid=8", "--load=1", "--c2=0.0798291"},
           {"--load=1e308", "--grid=8", "--c2=0.0798291"},
           {"--mu-d=1e-308", "--grid=8", "--load=1", "--c2=0.0798291"}}) {
    const auto r = run(arguments(changes));
    INFO("viscoroll-solve " << arguments(changes) << "\nstdout: " << r.out
                            << "\nstderr: " << r.err);
    CHECK(r.status == 0);
    CHECK(r.out.find("\"converged\":true") != std::string::npos);
    CHECK(r.out.find("nan") == std::string::npos);
    CHECK(r.out.find("inf") == std::string::npos);
    // No null but where a product of the inputs overflows a double: F = chi W, chi W V and
    // chi W 2 pi R (R = 1/c1 = 1 here), computed again in long double (docs/cli.md).
    long double load = 5.3L;
    for (const auto& change : changes)
      if (change.starts_with("--load=")) load = std::strtold(change.c_str() + 7, nullptr);
    for (const auto& line : nlohmann::json::parse("[" + r.out.substr(0, r.out.find('\n')) + "]")) {
      const long double force = line["chi"].get<double>() * load;
      const long double products[] = {force, force * line["speed"].get<double>(),
                                      force * 2 * std::numbers::pi_v<long double>};
      const char* keys[] = {"rolling_resistance", "power_loss", "energy_per_revolution"};
      for (const auto& [key, value] : line.items()) {
        INFO(key);
        if (!value.is_null()) continue;
        const auto at = std::find(std::begin(keys), std::end(keys), key) - std::begin(keys);
        REQUIRE(at < 3);
        CHECK(std::abs(products[at]) > std::numeric_limits<double>::max());
      }
    }
  }
  // mu_D = 1e308: the compliance underflows to 0 in the material: exit 2, the quantity and the
  // inputs named, nothing on stdout.
  const auto r = run(arguments({"--mu-d=1e308", "--grid=8", "--load=1"}));
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find("viscoroll: the instantaneous compliance c = 0 is below the smallest normal "
                   "number") != std::string::npos);
  CHECK(r.err.find("rescale the units") != std::string::npos);
}

TEST_CASE("cli: --threads builds the bem method's influence tables too, the same numbers",
          "[cli][bem]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // Two speeds, one chunk of the sweep: --threads 2 (and 0, every core) go to each solve's table
  // (BemOptions::threads), whose rows do not depend on the count: the lines of --threads 1 bit for
  // bit, but for their wall time.
  const auto one = run(arguments({"--grid=6", "--speed=1,2", "--threads=1"}));
  INFO("stdout: " << one.out << "\nstderr: " << one.err);
  REQUIRE(one.status == 0);
  auto a = viscoroll::cli_test::json_lines(one.out);
  REQUIRE(a.size() == 2);
  for (const char* threads : {"2", "0"}) {
    const auto r = run(arguments({"--grid=6", "--speed=1,2", std::string("--threads=") + threads}));
    INFO("--threads " << threads << "\nstdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    auto b = viscoroll::cli_test::json_lines(r.out);
    REQUIRE(b.size() == a.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      a[k].erase("seconds");
      b[k].erase("seconds");
      CHECK(b[k]["converged"] == true);
      CHECK(a[k].dump() == b[k].dump());
    }
  }
}

}  // namespace test_cli_bem
