// viscoroll-solve's engineering outputs (docs/cli.md, "Output"): every record carries after chi
// the rolling resistance F = chi W, the power loss chi W V and the energy per revolution
// chi W 2 pi R (examples/cli/engineering.hpp), the table F and P with their units; and
// a_long_term, l0, d0 are the static long-term contact in every method.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli/engineering.hpp"
#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_engineering {

namespace {

using namespace viscoroll::cli_test;

/// A scene file's load and rolling radius (its roller's radius, else 1/c1: docs/cli.md).
struct SceneDuty {
  double load, radius;
};

SceneDuty duty_of(const fs::path& scene) {
  const auto j = nlohmann::json::parse(slurp(scene));
  const auto& roller = j.at("roller");
  const double radius = roller.contains("radius") ? roller.at("radius").get<double>()
                                                  : 1 / roller.at("c1").get<double>();
  return {j.at("load").get<double>(), radius};
}

/// `x` is the product `expected` computed from the same doubles (the JSON's %.17g reads back to
/// the program's doubles): equal but for the order of rounding. Each of at most four products
/// rounds by at most eps/2 relatively, so two orders of evaluation differ by less than 2 eps;
/// 4 eps allows that and nothing a wrong formula gives.
void check_product(double x, double expected) {
  CHECK(std::abs(x - expected) <= 4 * std::numeric_limits<double>::epsilon() * std::abs(expected));
}

}  // namespace

TEST_CASE("engineering_fields: F = chi W, P = chi W V, E = chi W 2 pi R", "[cli]") {
  struct Field {
    std::string key;
    double value;
  };
  const auto fields =
      viscoroll::cli::engineering_fields<std::vector<Field>>(0.01, {200.0, 4.0, 0.0635});
  REQUIRE(fields.size() == 3);
  CHECK(fields[0].key == "rolling_resistance");
  CHECK(fields[1].key == "power_loss");
  CHECK(fields[2].key == "energy_per_revolution");
  check_product(fields[0].value, 2.0);
  check_product(fields[1].value, 8.0);
  check_product(fields[2].value, 2.0 * 2 * std::numbers::pi * 0.0635);
}

TEST_CASE("cli: every method's record carries F, P and the energy per revolution after chi",
          "[cli][scene]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  struct Case {
    std::string scene, method;
  };
  // The ellipsoid (R = 1/c1) by line and bem, a crowned roller (its radius) by line and bem, the
  // cylinder (per unit length) by plane, a Prony material by line.
  const std::vector<Case> cases = {{"paper.json", "line"},
                                   {"rubber_ball.json", "bem"},
                                   {"crowned_roller_line.json", "line"},
                                   {"crowned_roller_line.json", "bem"},
                                   {"polyamide_cylinder.json", "plane"},
                                   {"crowned_roller_prony_line.json", "line"}};
  for (const auto& c : cases) {
    const fs::path scene = scenes_dir() / c.scene;
    const SceneDuty duty = duty_of(scene);
    const Run r = run({"--scene", scene.string(), "--method", c.method});
    INFO(c.scene << " " << c.method << "\n" << r.err);
    CHECK(r.status == 0);
    const auto lines = json_lines(r.out);
    REQUIRE(!lines.empty());
    for (const auto& line : lines) {
      std::vector<std::string> keys;
      for (const auto& [key, value] : line.items()) keys.push_back(key);
      const auto chi_at = std::find(keys.begin(), keys.end(), "chi");
      REQUIRE(keys.end() - chi_at > 3);
      CHECK(chi_at[1] == "rolling_resistance");
      CHECK(chi_at[2] == "power_loss");
      CHECK(chi_at[3] == "energy_per_revolution");
      REQUIRE(line["converged"].get<bool>());
      const double chi = line["chi"].get<double>(), speed = line["speed"].get<double>();
      CHECK(chi > 0);
      check_product(line["rolling_resistance"].get<double>(), chi * duty.load);
      check_product(line["power_loss"].get<double>(), chi * duty.load * speed);
      check_product(line["energy_per_revolution"].get<double>(),
                    chi * duty.load * 2 * std::numbers::pi * duty.radius);
    }
  }
}

TEST_CASE("cli: the table's F and P columns are the records' rolling_resistance and power_loss",
          "[cli][scene]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const std::string scene = (scenes_dir() / "crowned_roller_line.json").string();
  for (const char* method : {"line", "bem"}) {
    const auto values = json_lines(run({"--scene", scene, "--method", method}).out);
    const Run table = run({"--scene", scene, "--method", method, "--format", "table"});
    INFO(method << "\n" << table.out);
    std::istringstream lines(table.out);
    std::string header;
    std::getline(lines, header);
    std::istringstream words(header);
    std::vector<std::string> columns;
    for (std::string word; words >> word;) columns.push_back(word);
    REQUIRE(columns.size() == 11);
    CHECK(columns[7] == "chi");
    CHECK(columns[8] == "F_N");
    CHECK(columns[9] == "P_W");
    for (const auto& value : values) {
      std::string row;
      REQUIRE(std::getline(lines, row));
      std::istringstream cells(row);
      std::vector<double> numbers;
      for (std::string word; cells >> word;) numbers.push_back(std::strtod(word.c_str(), nullptr));
      REQUIRE(numbers.size() == 11);
      // Printed with 7 significant digits: within half a unit of the 7th, 5e-7 relatively.
      CHECK(numbers[8] == Approx(value["rolling_resistance"].get<double>()).epsilon(5e-7));
      CHECK(numbers[9] == Approx(value["power_loss"].get<double>()).epsilon(5e-7));
    }
  }
}

TEST_CASE("cli: a result that did not converge has no F, P or energy in the table and the CSV",
          "[cli]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_engineering_not_converged");
  const std::string csv = (dir.path() / "sweep.csv").string();
  const Run r = run({"--scene", (scenes_dir() / "paper.json").string(), "--speed", "0.5",
                     "--max-iterations", "1", "--csv", csv});
  CHECK(r.status == 1);
  const auto values = json_lines(r.out);
  REQUIRE(values.size() == 1);
  CHECK(values[0]["rolling_resistance"].is_number());  // JSON keeps its fields
  std::istringstream file(slurp(csv));
  std::string header, row;
  std::getline(file, header);
  std::getline(file, row);
  int found = 0;
  std::istringstream keys(header), cells(row + ",");
  for (std::string key, cell; std::getline(keys, key, ',') && std::getline(cells, cell, ',');)
    if (key == "rolling_resistance" || key == "power_loss" || key == "energy_per_revolution") {
      INFO(key << " = '" << cell << "'");
      CHECK(cell.empty());
      ++found;
    }
  CHECK(found == 3);
}

TEST_CASE("cli: a_long_term, l0, d0 are the static long-term contact in line and bem",
          "[cli][scene]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // A roller of finite length: both methods report the line theory's static contact
  // (static_profile_contact with the same compliance times load), so the same doubles.
  const std::string crowned = (scenes_dir() / "crowned_roller_line.json").string();
  const auto line = json_lines(run({"--scene", crowned, "--speed", "1"}).out);
  const auto bem = json_lines(run({"--scene", crowned, "--speed", "1", "--method", "bem"}).out);
  REQUIRE(line.size() == 1);
  REQUIRE(bem.size() == 1);
  for (const char* key : {"a_long_term", "l0", "d0"}) {
    INFO(key);
    CHECK(bem[0][key].get<double>() == line[0][key].get<double>());
  }
  // The ellipsoid by bem: Hertz's contact, here a circle (c1 = c2 = 1/R): a^3 = 3 W R (1 - nu) /
  // (8 mu_lt), mu_lt = mu_d/(1 + f), d = a^2/R. The closed form's few roundings against the
  // Hertz solver's: 16 eps (1.7 ulp measured).
  const auto ball = json_lines(
      run({"--scene", (scenes_dir() / "rubber_ball.json").string(), "--speed", "1"}).out);
  REQUIRE(ball.size() == 1);
  const double radius = 1 / 40.0, mu = 2.0e6 / 5, a = std::cbrt(3 * 5.0 * radius * 0.5 / (8 * mu));
  const double tolerance = 16 * std::numeric_limits<double>::epsilon();
  CHECK(ball[0]["a_long_term"].get<double>() == Approx(a).epsilon(tolerance));
  CHECK(ball[0]["l0"].get<double>() == Approx(a).epsilon(tolerance));
  CHECK(ball[0]["d0"].get<double>() == Approx(a * a / radius).epsilon(tolerance));
}

}  // namespace test_cli_engineering
