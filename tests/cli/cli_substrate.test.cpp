// viscoroll-solve on a layer or a spring bed: the scene key "substrate" (docs/cli.md), the bem
// method's body, the auto method's choice of it, the plane and line methods' refusal, and the
// key's errors named.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_substrate {

namespace {

using namespace viscoroll::cli_test;

/// A steel idler of radius 63.5 mm on a rubber of one relaxation time, with `substrate` (JSON,
/// or empty for none) and `method` (empty: the scene gives none).
fs::path idler(const fs::path& dir, const std::string& name, const std::string& substrate,
               const std::string& method) {
  const fs::path path = dir / name;
  std::ofstream out(path);
  out << R"({"material": {"model": "standard_linear_solid", "mu_d": 3e6, "nu": 0.5, "f": 4,
             "tau": 0.002},
            "roller": {"profile": "ellipsoid", "c1": 15.748, "c2": 0.5},
            "load": 500, "speeds": [2.0], "grid": 12)";
  if (!method.empty()) out << R"(, "method": ")" << method << '"';
  if (!substrate.empty()) out << R"(, "substrate": )" << substrate;
  out << "}\n";
  return path;
}

}  // namespace

TEST_CASE("cli: a bonded cover is stiffer than the half space, and the bed softer than it",
          "[cli][substrate]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_substrate");
  const Run half = run({"--scene", idler(dir.path(), "h.json", "", "bem").string()});
  const Run layer = run(
      {"--scene",
       idler(dir.path(), "l.json", R"({"model": "layer", "thickness": 0.004})", "bem").string()});
  const Run bed = run({"--scene", idler(dir.path(), "b.json",
                                        R"({"model": "spring_bed", "thickness": 0.004})", "bem")
                                      .string()});
  REQUIRE(half.status == 0);
  REQUIRE(layer.status == 0);
  REQUIRE(bed.status == 0);
  const auto h = json_lines(half.out).front(), l = json_lines(layer.out).front(),
             b = json_lines(bed.out).front();
  CHECK(l.at("converged").get<bool>());
  CHECK(b.at("converged").get<bool>());
  // The same load on a cover 4 mm thick (the half space's contact is about 9 mm wide): less
  // penetration and a narrower contact; the incompressible layer is stiffer than the bed, which
  // lets the rubber under the contact sink without bulging.
  CHECK(l.at("d").get<double>() < h.at("d").get<double>());
  CHECK(l.at("a0").get<double>() < h.at("a0").get<double>());
  CHECK(l.at("d").get<double>() < b.at("d").get<double>());
}

TEST_CASE("cli: the auto method answers a layer by the bem, and says why", "[cli][substrate]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_substrate_auto");
  const auto scene = idler(dir.path(), "a.json",
                           R"({"model": "layer", "thickness": 0.004, "base": "frictionless"})", "");
  std::string text = slurp(scene);
  const std::string grid = R"(, "grid": 12)";
  text.replace(text.find(grid), grid.size(), "");  // auto takes no grid
  std::ofstream(scene) << text;
  const Run r = run({"--scene", scene.string()});
  REQUIRE(r.status == 0);
  const auto rec = json_lines(r.out).front();
  CHECK(rec.at("method").get<std::string>() == "bem");
  CHECK(rec.at("method_reason").get<std::string>() ==
        "auto: bem (the substrate is a layer (thickness 0.004 m, frictionless); the line theory "
        "is the half space's)");
}

TEST_CASE("cli: the substrate key's errors name it", "[cli][substrate]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_substrate_errors");
  struct Case {
    std::string substrate, method, message;
  };
  const std::vector<Case> cases = {
      {R"({"model": "layer", "thickness": 0.004})", "line",
       R"(substrate.model = "layer" is solved by the bem method only: the line method's theory is )"
       R"(the half space's)"},
      {R"({"model": "spring_bed", "thickness": 0.004})", "plane",
       R"(substrate.model = "spring_bed" is solved by the bem method only)"},
      {R"({"model": "slab", "thickness": 0.004})", "bem",
       R"(substrate.model = "slab" is not one of half_space, layer, spring_bed)"},
      {R"({"model": "layer"})", "bem", "missing key substrate.thickness"},
      {R"({"model": "layer", "thickness": -0.004})", "bem",
       "substrate.thickness = -0.004 is outside the valid range thickness > 0 (m, finite)"},
      {R"({"model": "layer", "thickness": 0.004, "base": "glued"})", "bem",
       R"(substrate.base = "glued" is not one of bonded, frictionless)"},
      {R"({"model": "spring_bed", "thickness": 0.004, "base": "bonded"})", "bem",
       "substrate.base is a layer's (bonded or frictionless), not a spring_bed's"},
      {R"({"model": "half_space", "thickness": 0.004})", "bem",
       R"(substrate.model = "half_space" takes no thickness or base)"},
      {R"({"model": "layer", "thickness": 0.004, "depth": 1})", "bem",
       R"(unknown key substrate.depth (substrate has the keys model, thickness, base))"},
  };
  int k = 0;
  for (const auto& c : cases) {
    CAPTURE(c.substrate, c.method);
    const auto scene = idler(dir.path(), std::to_string(k++) + ".json", c.substrate, c.method);
    if (c.method == "plane") {
      // The plane method's roller is the cylinder.
      std::string text = slurp(scene);
      const std::string ellipsoid = R"({"profile": "ellipsoid", "c1": 15.748, "c2": 0.5})",
                        grid = R"(, "grid": 12)";
      text.replace(text.find(ellipsoid), ellipsoid.size(),
                   R"({"profile": "cylinder", "radius": 0.0635})");
      text.replace(text.find(grid), grid.size(), "");
      std::ofstream(scene) << text;
    }
    check_refused({"--scene", scene.string()}, c.message);
  }
}

}  // namespace test_cli_substrate
