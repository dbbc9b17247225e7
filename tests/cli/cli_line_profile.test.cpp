// The line method on rollers of finite length from the command line (docs/cli.md, "Rollers of
// finite length"): the shipped crowned_roller_line.json (a standard linear solid) and
// crowned_roller_prony_line.json (a three-term prony spectrum) solve at their three speeds, their
// records carry the load's peak along the roller, --profile-out writes 65 stations whose F0
// integrates to the load, the sweep's continuation lands on the cold solves' solutions, a tilted
// roller solves and mirrors, and the plane method and a misplaced --profile-out are errors naming
// their key.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <variant>
#include <vector>
#include <viscoroll/line/line_solver.hpp>

#include "cli/line_record.hpp"
#include "cli/scene_file.hpp"
#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_line_profile {

namespace {

using namespace viscoroll::cli_test;
namespace cli = viscoroll::cli;

const std::string sls =
    R"("material": {"model": "standard_linear_solid", "mu_d": 2e6, "nu": 0.5, "f": 4, "tau": 0.005})";

/// A scene of `material` and `roller` (JSON members), 100 N at 1 m/s, by the line method.
std::string line_scene(const std::string& material, const std::string& roller) {
  return "{" + material + ", " + roller + R"(, "load": 100, "speeds": [1], "method": "line"})";
}

/// The --profile-out rows (tau, temperature, speed, y, f0, a, b, p_max) by speed.
std::map<double, std::vector<std::vector<double>>> rows_by_speed(const fs::path& file) {
  std::map<double, std::vector<std::vector<double>>> out;
  for (auto& row : profile_rows(file)) out[row[2]].push_back(std::move(row));
  return out;
}

}  // namespace

TEST_CASE("cli line profile: the line method's checks of a roller of finite length",
          "[cli][rollers][line]") {
  const auto scene = [](const std::string& material, const std::string& roller) {
    return cli::parse_scene(line_scene(material, roller), "s.json");
  };
  const std::string crowned =
      R"("roller": {"profile": "crowned", "radius": 0.05, "flat_length": 0.05, "crown_radius": 1)";
  const std::string prony =
      R"("material": {"model": "prony", "nu": 0.5, "g_inf": 4e5, "terms": [{"g": 1.6e6, "tau": 0.005}]})";
  const std::string table = R"("roller": {"profile": "table", "radius": 0.05,
      "y": [-0.08, -0.04, 0, 0.04, 0.08], "h": [3e-3, 4e-4, 0, 4e-4, )";
  CHECK_NOTHROW(
      cli::check_scene_for_method(scene(sls, crowned + "}"), cli::Method::line, "s.json"));
  CHECK_NOTHROW(
      cli::check_scene_for_method(scene(sls, table + "3e-3]}"), cli::Method::line, "s.json"));
  CHECK_NOTHROW(cli::check_scene_for_method(scene(sls, crowned + ", \"tilt\": 0.01}"),
                                            cli::Method::bem, "s.json"));
  CHECK_NOTHROW(
      cli::check_scene_for_method(scene(prony, crowned + "}"), cli::Method::bem, "s.json"));
  CHECK_NOTHROW(
      cli::check_scene_for_method(scene(prony, crowned + "}"), cli::Method::line, "s.json"));
  // A tilt or an asymmetric table: the asymmetric contact (docs/theory.md (RP7)), on any material.
  for (const std::string& material : {sls, prony}) {
    CHECK_NOTHROW(cli::check_scene_for_method(scene(material, crowned + ", \"tilt\": 0.01}"),
                                              cli::Method::line, "s.json"));
    CHECK_NOTHROW(cli::check_scene_for_method(scene(material, table + "2e-3]}"), cli::Method::line,
                                              "s.json"));
  }
  CHECK_THROWS_WITH(
      cli::check_scene_for_method(scene(sls, crowned + "}"), cli::Method::plane, "s.json"),
      Catch::Contains("roller.profile = \"crowned\" suits the line and bem methods, not plane"));
}

TEST_CASE("cli line profile: the crowned roller solves, F0 along it integrates to the load",
          "[cli][rollers][line]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_line_profile");
  // A standard linear solid, and a prony spectrum of three terms (all active: the spectrum's own
  // line theory, (RP5), whose strips have no pressure: p_max an empty cell).
  for (const char* file : {"crowned_roller_line.json", "crowned_roller_prony_line.json"}) {
    const fs::path csv = dir.path() / "along.csv";
    const std::string path = (scenes_dir() / file).string();
    const cli::Scene scene = cli::parse_scene(cli::read_scene_file(path), path);
    const bool spectrum = std::holds_alternative<cli::PronyModel>(scene.material);
    const Run r = run({"--scene", path, "--profile-out", csv.string()});
    INFO(file << "\n" << r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    const auto lines = json_lines(r.out);
    REQUIRE(lines.size() == scene.speeds.size());
    REQUIRE(lines.size() == 3);
    const auto rows = rows_by_speed(csv);
    REQUIRE(rows.size() == 3);
    for (const auto& line : lines) {
      INFO(line.dump());
      CHECK(line["method"] == "line");
      REQUIRE(line["converged"].get<bool>());
      if (spectrum) CHECK(line["active_terms"] == 3);
      const double l = line["l"].get<double>();
      CHECK(line["y_minus"].get<double>() == -l);
      CHECK(line["y_plus"].get<double>() == l);
      const auto& along = rows.at(line["speed"].get<double>());
      REQUIRE(along.size() == 65);
      // The stations y_k = l (2k/66 - 1), k = 1..65: evenly spaced, h = 2l/66, F0 = 0 at -l and
      // l, so that the sum of the rows times h is the trapezoid rule. Its error is O(h^2): 1.6e-4
      // relative measured on 129 stations (h = 2l/130; docs/rollers.md, bound 1e-3 in
      // tests/line/line_along_roller.test.cpp), hence (130/66)^2 = 3.9 times that on 65: bound
      // 3.9e-3 (measured up to 3.7e-4 here with the solid, 5.6e-4 with the spectrum).
      const double h = 2 * l / 66;
      double sum = 0, peak = 0, peak_y = 0;
      for (std::size_t k = 0; k < along.size(); ++k) {
        CHECK(along[k][3] ==
              Approx(l * (2.0 * double(k + 1) / 66 - 1)).epsilon(1e-14).margin(1e-17));
        sum += along[k][4];
        if (along[k][4] > peak) {
          peak = along[k][4];
          peak_y = along[k][3];
        }
        CHECK(along[k][5] > 0);
        if (spectrum)
          CHECK(std::isnan(along[k][7]));
        else
          CHECK(along[k][7] > 0);
      }
      const double centre = along[32][4];
      CHECK(along[32][3] == 0);
      CHECK(sum * h == Approx(scene.load).epsilon(3.9e-3));
      // The record's peak (cli::line_f0_peak) is the rows' (along_roller), exactly.
      CHECK(line["f0_max"].get<double>() == peak);
      CHECK(line["f0_max_y"].get<double>() == peak_y);
      // The crowns' edge peak: F0 largest just past the flat part's ends (|y| = 25 mm), about
      // 30-33 mm from the centre, above F0(0).
      const double at = std::abs(line["f0_max_y"].get<double>());
      CHECK(at > 0.025);
      CHECK(at < 0.04);
      CHECK(peak > centre);
    }
    fs::remove(csv);
  }
}

TEST_CASE("cli line profile: the sweep's continuation lands on the cold solves' solutions",
          "[cli][rollers][line]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  for (const char* file : {"crowned_roller_line.json", "crowned_roller_prony_line.json"}) {
    const std::string path = (scenes_dir() / file).string();
    const Run sweep = run({"--scene", path, "--speed", "0.1,1"});
    const Run cold = run({"--scene", path, "--speed", "1"});
    INFO(file << "\n" << sweep.out << sweep.err << cold.out << cold.err);
    REQUIRE(sweep.status == 0);
    REQUIRE(cold.status == 0);
    const auto seeded = json_lines(sweep.out).at(1), alone = json_lines(cold.out).at(0);
    // The root of the line equations, to the iteration's tolerance (residual <= 64 sqrt(eps)).
    for (const char* key : {"a0", "b0", "l", "d", "chi", "f0_max"})
      CHECK(seeded[key].get<double>() == Approx(alone[key].get<double>()).epsilon(1e-6));
    CHECK(seeded["root"].get<bool>());
  }
}

TEST_CASE("cli line profile: a tilted roller solves and its opposite tilt mirrors it",
          "[cli][rollers][line]") {
  // The crowned idler of crowned_roller_line.json's proportions misaligned by +-2 mrad: the
  // asymmetric contact (docs/theory.md (RP7)), whose ends and edge peak mirror to the iteration's
  // tolerance (its last step below eps^0.6 of the unknowns; 4 eps^0.6 as in
  // line_profile_tilt.test.cpp; the records carry 17 digits) and whose load moves to y < 0 for
  // tilt > 0.
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_line_profile_tilt");
  const std::string crowned =
      R"("roller": {"profile": "crowned", "radius": 0.05, "flat_length": 0.05, "crown_radius": 1)";
  std::map<std::string, nlohmann::ordered_json> record;
  for (const std::string tilt : {"0.002", "-0.002"}) {
    const fs::path path = dir.path() / ("tilt" + tilt + ".json");
    std::ofstream(path) << line_scene(sls, crowned + ", \"tilt\": " + tilt + "}");
    const Run r = run({"--scene", path.string()});
    INFO(tilt << "\n" << r.out << r.err);
    REQUIRE(r.status == 0);
    const auto lines = json_lines(r.out);
    REQUIRE(lines.size() == 1);
    REQUIRE(lines[0]["converged"].get<bool>());
    record[tilt] = lines[0];
  }
  const double tol = 4 * std::pow(std::numeric_limits<double>::epsilon(), 0.6);
  const auto& p = record["0.002"];
  const auto& q = record["-0.002"];
  const double l = p["l"].get<double>();
  CHECK(p["y_minus"].get<double>() + p["y_plus"].get<double>() < -0.01 * l);
  CHECK(p["y_minus"].get<double>() == Approx(-q["y_plus"].get<double>()).epsilon(tol));
  CHECK(p["y_plus"].get<double>() == Approx(-q["y_minus"].get<double>()).epsilon(tol));
  CHECK(p["d"].get<double>() == Approx(q["d"].get<double>()).epsilon(tol));
  CHECK(p["chi"].get<double>() == Approx(q["chi"].get<double>()).epsilon(tol));
  CHECK(p["f0_max_y"].get<double>() < 0);
  CHECK(q["f0_max_y"].get<double>() > 0);
}

TEST_CASE("cli line profile: a contact that does not reach y = 0 has a0 = b0 = 0 in its record",
          "[cli][rollers][line]") {
  // A tilted roller pressed off its centre: no strip at y = 0, so the record's a0 and b0 (the
  // strip at y = 0) are 0, not b's series extrapolated beyond the contact. The shape is set by
  // hand (a = a_ref sqrt(1 - t^2), b = 0.1 a_ref + 0.05 a_ref t on [c - l, c + l]); the record
  // type is viscoroll-solve's (key, value) sequence.
  using Value = std::variant<double, long long, bool, std::string, std::vector<std::string>>;
  struct Field {
    std::string key;
    Value value;
  };
  const auto a0_b0 = [](const viscoroll::LineSolverD::Solution& s) {
    std::map<std::string, double> numbers;
    for (const Field& f : cli::line_fields<std::vector<Field>>(s, {}, cli::Duty{}, 4, 0.0))
      if (const double* x = std::get_if<double>(&f.value)) numbers[f.key] = *x;
    return std::pair{numbers.at("a0"), numbers.at("b0")};
  };
  viscoroll::LineSolverD::Solution s;
  s.shape.a_ref = 1;
  s.shape.l = 2;
  s.shape.beta = {0.1};
  s.shape.alpha_odd = {0.0};
  s.shape.beta_odd = {0.05};
  s.shape.centre = 0.5;  // the contact [-1.5, 2.5] holds y = 0
  const auto [a_in, b_in] = a0_b0(s);
  CHECK(a_in > 0);
  CHECK(a_in == s.a(0.0));
  CHECK(b_in == s.b(0.0));
  s.shape.centre = 3;  // the contact [1, 5] does not
  const auto [a_out, b_out] = a0_b0(s);
  CHECK(s.a(0.0) == 0);
  CHECK(s.b(0.0) != 0);  // b's series extrapolated to y = 0, which the record does not report
  CHECK(a_out == 0);
  CHECK(b_out == 0);
}

TEST_CASE("cli line profile: plane and a misplaced --profile-out are errors naming their key",
          "[cli][rollers][line]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_line_profile_errors");
  const std::string line = (scenes_dir() / "crowned_roller_line.json").string();
  const std::string csv = (dir.path() / "x.csv").string();
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"--scene", line, "--method", "plane"},
       "roller.profile = \"crowned\" suits the line and bem"},
      {{"--scene", line, "--method", "plane", "--profile-out", csv},
       "--profile-out is valid only with --method line or bem"},
  };
  for (const auto& c : cases) {
    check_refused(c.args, c.message);
    CHECK(!fs::exists(csv));
  }
}

}  // namespace test_cli_line_profile
