// Rollers of finite length from the command line (docs/cli.md, docs/rollers.md): the
// shipped crowned roller runs with the bem method, --profile-out writes the load along the roller
// (its rows sum to the load), a tilt and its opposite mirror, and the plane method, a misplaced
// --profile-out and invalid profiles are errors naming the key (the line method on such rollers:
// cli_line_profile.test.cpp).
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/scene_file.hpp"
#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_rollers {

namespace {

using namespace viscoroll::cli_test;

/// A crowned roller scene file with tilt `tilt` in `dir`.
std::string crowned_scene(const fs::path& dir, const std::string& name, const std::string& tilt) {
  const fs::path path = dir / name;
  std::ofstream(path) << R"({"material": {"model": "standard_linear_solid", "mu_d": 2e6, "nu": 0.5,
      "f": 4, "tau": 0.005},
    "roller": {"profile": "crowned", "radius": 0.05, "flat_length": 0.03, "crown_radius": 0.1,
      "tilt": )" << tilt
                      << R"(},
    "load": 50, "speeds": [0.5], "method": "bem", "grid": 6})";
  return path.string();
}

}  // namespace

TEST_CASE("cli rollers: the crowned roller runs, --profile-out carries the load along it",
          "[cli][rollers]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_rollers");
  const fs::path csv = dir.path() / "along.csv";
  const Run r = run(
      {"--scene", (scenes_dir() / "crowned_roller.json").string(), "--profile-out", csv.string()});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  const auto lines = json_lines(r.out);
  REQUIRE(lines.size() == 4);
  const auto rows = profile_rows(csv);
  for (const auto& line : lines) {
    REQUIRE(line["converged"].get<bool>());
    const double speed = line["speed"].get<double>();
    double sum = 0, peak = 0, first = 0, last = 0, hy = 0, previous = std::nan("");
    bool any = false;
    for (const auto& row : rows) {
      if (row[2] != speed) continue;
      if (!std::isnan(previous)) hy = row[3] - previous;
      previous = row[3];
      if (!any) first = row[3];
      last = row[3];
      any = true;
      sum += row[4];
      peak = std::max(peak, row[4]);
      CHECK(row[5] > 0);
      CHECK(row[7] > 0);
    }
    REQUIRE(any);
    // The rows' loads times the row spacing are the load (100 N) to the solver's tolerance.
    CHECK(sum * hy == Approx(100.0).epsilon(1e-9));
    CHECK(line["f0_max"].get<double>() == peak);
    // The crown's edge peak: F0 is largest near the flat part's ends (|y| = 25 mm), not at y = 0.
    CHECK(std::abs(line["f0_max_y"].get<double>()) > 0.02);
    CHECK(line["y_minus"].get<double>() <= first);
    CHECK(line["y_plus"].get<double>() >= last);
    CHECK(line["y_plus"].get<double>() <= last + hy);
  }
}

TEST_CASE("cli rollers: a tilt and its opposite mirror", "[cli][rollers]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_rollers_tilt");
  const Run p = run({"--scene", crowned_scene(dir.path(), "p.json", "0.004")});
  const Run m = run({"--scene", crowned_scene(dir.path(), "m.json", "-0.004")});
  INFO(p.out << p.err << m.out << m.err);
  REQUIRE(p.status == 0);
  REQUIRE(m.status == 0);
  const auto a = json_lines(p.out).at(0), b = json_lines(m.out).at(0);
  CHECK(a["y_minus"].get<double>() == Approx(-b["y_plus"].get<double>()).epsilon(1e-9));
  CHECK(a["f0_max_y"].get<double>() == Approx(-b["f0_max_y"].get<double>()).epsilon(1e-9));
  CHECK(a["chi"].get<double>() == Approx(b["chi"].get<double>()).epsilon(1e-9));
  // tilt > 0 lowers the gap on y < 0: the contact reaches further there.
  CHECK(-a["y_minus"].get<double>() > a["y_plus"].get<double>());
}

TEST_CASE("cli rollers: plane, a misplaced --profile-out and bad profiles are errors",
          "[cli][rollers]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const std::string crowned = (scenes_dir() / "crowned_roller.json").string();
  const TempDir dir("viscoroll_cli_rollers_errors");
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::string bad = (dir.path() / "bad.json").string();
  std::ofstream(bad) << R"({"material": {"model": "elastic", "mu": 1e6, "nu": 0.5},
    "roller": {"profile": "crowned", "radius": 0.05, "flat_length": 0.03, "crown_radius": 0.1,
      "length": 0.02}, "load": 50, "speeds": [0.5], "method": "bem"})";
  const std::string table = (dir.path() / "table.json").string();
  std::ofstream(table) << R"({"material": {"model": "elastic", "mu": 1e6, "nu": 0.5},
    "roller": {"profile": "table", "radius": 0.05, "y": [-1, 0, 0, 1], "h": [1, 0, 0, 1]},
    "load": 50, "speeds": [0.5], "method": "bem"})";
  const std::string tilt = crowned_scene(dir.path(), "tilt.json", "0.2");
  const std::vector<Case> cases = {
      {{"--scene", crowned, "--method", "plane"},
       "roller.profile = \"crowned\" suits the line and bem methods, not plane"},
      {{"--scene", (scenes_dir() / "polyamide_cylinder.json").string(), "--profile-out",
        (dir.path() / "x.csv").string()},
       "--profile-out is valid only with --method line or bem"},
      {{"--scene", bad}, "roller.length = 0.02 is outside the valid range length > flat_length"},
      {{"--scene", table}, "roller.y[2] = 0 is outside the valid range y[k] > y[k-1]"},
      {{"--scene", tilt}, "roller.tilt = 0.2 is outside the valid range |tilt| < 0.1"},
  };
  for (const auto& c : cases) check_refused(c.args, c.message);
}

}  // namespace test_cli_rollers
