// Twenty plausible unit mistakes in a scene file (moduli in MPa, GPa or kPa, loads in kN or mN,
// lengths in mm, times in ms, speeds in mm/s), each solved by the front door (the auto method, no
// method named): every one ends in an error (exit 2, a key named), in a validity warning
// (docs/cli.md, "Validity checks"), or in a result that is physically valid (a0/R <= 0.2, the
// contact inside the roller) — never silently in a contact larger than the roller. With --strict
// a breach is an error (exit 2, nothing on stdout).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_unit_mistakes {

namespace {

using namespace viscoroll::cli_test;
using nlohmann::json;

/// A rubber-covered idler of radius 50 mm: a standard linear solid (3 MPa glassy, f = 9, 10 ms),
/// on the ellipsoid (c1 = 20/m, c2 = 1/m) or a crowned roller 160 mm long, 100 N, 1 m/s.
json base(bool crowned) {
  json scene = {{"material",
                 {{"model", "standard_linear_solid"},
                  {"mu_d", 3.0e6},
                  {"nu", 0.5},
                  {"f", 9.0},
                  {"tau", 0.01}}},
                {"load", 100.0},
                {"speeds", json::array({1.0})}};
  scene["roller"] = crowned ? json{{"profile", "crowned"},
                                   {"radius", 0.05},
                                   {"flat_length", 0.05},
                                   {"crown_radius", 1.0},
                                   {"length", 0.16}}
                            : json{{"profile", "ellipsoid"}, {"c1", 20.0}, {"c2", 1.0}};
  return scene;
}

struct Mistake {
  const char* what;
  bool crowned;
  const char* pointer;  ///< JSON pointer of the key given in the wrong unit
  json value;
};

/// The radius and the body's half length of the scene's roller (the ellipsoid's body: none).
double radius_of(const json& scene) {
  const auto& r = scene.at("roller");
  return r.contains("radius") ? r.at("radius").get<double>() : 1 / r.at("c1").get<double>();
}

}  // namespace

TEST_CASE("cli: twenty unit mistakes end in an error, a validity warning or a valid result",
          "[cli][validity]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const std::vector<Mistake> mistakes = {
      {"mu_d in MPa", false, "/material/mu_d", 3.0},
      {"mu_d in MPa (crowned)", true, "/material/mu_d", 3.0},
      {"mu_d in GPa", false, "/material/mu_d", 0.003},
      {"mu_d in GPa (crowned)", true, "/material/mu_d", 0.003},
      {"mu_d in kPa", false, "/material/mu_d", 3000.0},
      {"mu_d in kPa (crowned)", true, "/material/mu_d", 3000.0},
      {"load in kN", false, "/load", 0.1},
      {"load in kN (crowned)", true, "/load", 0.1},
      {"load in mN", false, "/load", 1.0e5},
      {"load in mN (crowned)", true, "/load", 1.0e5},
      {"radius in mm (crowned)", true, "/roller/radius", 50.0},
      {"c1 in 1/mm", false, "/roller/c1", 0.02},
      {"c2 in 1/mm", false, "/roller/c2", 0.001},
      {"crown radius in mm", true, "/roller/crown_radius", 1000.0},
      {"length in mm", true, "/roller/length", 160.0},
      {"flat length in mm", true, "/roller/flat_length", 50.0},
      {"tau in ms", false, "/material/tau", 10.0},
      {"tau in ms (crowned)", true, "/material/tau", 10.0},
      {"speed in mm/s", false, "/speeds/0", 1000.0},
      {"speed in mm/s (crowned)", true, "/speeds/0", 1000.0},
  };
  REQUIRE(mistakes.size() == 20);
  TempDir dir("viscoroll_unit_mistakes");
  int errors = 0, warned = 0, valid = 0;
  for (const auto& m : mistakes) {
    json scene = base(m.crowned);
    scene[json::json_pointer(m.pointer)] = m.value;
    const auto path = dir.path() / "scene.json";
    std::ofstream(path) << scene.dump();
    const auto r = run({"--scene", path.string()});
    INFO(m.what << "\nstdout: " << r.out << "\nstderr: " << r.err);
    if (r.status == 2) {
      // An error names the key (or the quantity) and prints nothing on stdout.
      CHECK(r.out.empty());
      CHECK(r.err.find("viscoroll") != std::string::npos);
      ++errors;
      continue;
    }
    const double radius = radius_of(scene);
    bool any_warning = false;
    std::istringstream lines(r.out);
    std::string line;
    while (std::getline(lines, line)) {
      const auto record = json::parse(line);
      bool breach_warned = false;
      REQUIRE(record.at("warning_codes").size() == record.at("warnings").size());
      for (const auto& w : record.at("warning_codes"))
        if (w == "small_slope" || w == "roller_length" || w == "slenderness" || w == "quasi_static")
          breach_warned = true;
      any_warning = any_warning || breach_warned;
      // A result that did not converge claims no contact; the scene's own breach (its long-term
      // static contact) is still among its warnings.
      if (!record.at("converged").get<bool>()) continue;
      const double a0 = record.at("a0").get<double>();
      bool inside = true;
      if (scene.at("roller").contains("length")) {
        const double half = scene.at("roller").at("length").get<double>() / 2;
        inside = record.at("y_plus").get<double>() <= half &&
                 record.at("y_minus").get<double>() >= -half;
      }
      // Valid, or said to be invalid: never silently a contact larger than the roller.
      CHECK((breach_warned || (a0 <= 0.2 * radius && inside)));
      CHECK(a0 <= radius * 1e6);  // (the output is a number, not an overflow)
    }
    if (any_warning) {
      CHECK(r.err.find("warning") != std::string::npos);
      ++warned;
      // --strict: the same scene is an error naming the breach.
      const auto strict = run({"--scene", path.string(), "--strict"});
      CHECK(strict.status == 2);
      CHECK(strict.out.empty());
      CHECK(strict.err.find("--strict") != std::string::npos);
    } else {
      ++valid;
    }
  }
  INFO(errors << " errors, " << warned << " warned, " << valid << " valid");
  CHECK(errors + warned + valid == 20);
  // The moduli in MPa or kPa and the loads in mN make contacts larger than the roller: warned.
  CHECK(warned >= 6);
}

}  // namespace test_cli_unit_mistakes
