// viscoroll-solve on a layer or a spring bed: the scene key "substrate" (docs/cli.md), the bem
// method's body, the plane method's on a cylinder (PlaneSubstrateSolver, to the scene's or
// --tolerance, else 1e-4), the auto method's choice of them, the line method's refusal, and the
// key's and the tolerance's errors named.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_substrate_solver.hpp>
#include <viscoroll/substrate/substrate.hpp>

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

/// The idler as the plane method's cylinder (radius 63.5 mm) on the same rubber, 1000 N per metre,
/// on `substrate` (JSON), at `speeds` (JSON), with the further top-level keys `extra` (JSON
/// members after a comma, or empty).
fs::path cylinder(const fs::path& dir, const std::string& name, const std::string& substrate,
                  const std::string& speeds, const std::string& extra) {
  const fs::path path = dir / name;
  std::ofstream out(path);
  out << R"({"material": {"model": "standard_linear_solid", "mu_d": 3e6, "nu": 0.5, "f": 4,
             "tau": 0.002},
            "roller": {"profile": "cylinder", "radius": 0.0635},
            "load": 1000, "substrate": )"
      << substrate << R"(, "speeds": )" << speeds << extra << "}\n";
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
       R"(substrate.model = "layer" is solved by the bem method, and on a "cylinder" roller by )"
       R"(the plane method, not by line: the line method's theory is the half space's (give )"
       R"("method": "bem" or "auto"))"},
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
    check_refused({"--scene", scene.string()}, c.message);
  }
}

TEST_CASE("cli: the plane method on a bonded layer is PlaneSubstrateSolver's, to its tolerance",
          "[cli][substrate]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_substrate_plane");
  const std::string layer = R"({"model": "layer", "thickness": 0.004, "base": "bonded"})";
  const Run r =
      run({"--scene",
           cylinder(dir.path(), "p.json", layer, "[2.0]", R"(, "method": "plane")").string()});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  const auto rec = json_lines(r.out).at(0);
  CHECK(rec.at("method").get<std::string>() == "plane");
  CHECK(rec.at("substrate").get<std::string>() == "layer (thickness 0.004 m, bonded)");
  CHECK(rec.at("converged").get<bool>());
  CHECK(rec.at("code").get<std::string>() == "converged");
  CHECK(rec.at("reason").get<std::string>().empty());  // words only when not converged
  CHECK_FALSE(rec.contains("a_long_term"));  // the solver computes no static long-term contact
  // The default tolerance, 1e-4, solved here by the library: the same a, d (from the base) and
  // chi to that tolerance, on the same Chebyshev terms.
  constexpr double tolerance = 1e-4;
  CHECK(rec.at("tolerance").get<double>() == tolerance);
  viscoroll::PlaneSubstrateOptions options;
  options.tolerance = tolerance;
  const viscoroll::PlaneSubstrateSolver solver(
      viscoroll::StandardLinearSolid<double>(3e6, 0.5, 4, 0.002),
      viscoroll::Layer<double>(0.004, viscoroll::LayerBase::bonded), options);
  const auto s =
      solver.solve(viscoroll::PlaneScene<double>{.c1 = 1 / 0.0635, .load = 1000, .speed = 2.0});
  REQUIRE(s.converged);
  REQUIRE(s.d_absolute);
  const double a0 = rec.at("a0").get<double>(), d = rec.at("d").get<double>(),
               chi = rec.at("chi").get<double>();
  CHECK(std::abs(a0 - s.a) <= tolerance * s.a);
  CHECK(std::abs(d - s.d) <= tolerance * s.d);
  CHECK(std::abs(chi - s.chi) <= tolerance * s.chi);
  CHECK(rec.at("terms").get<long>() == s.terms);
  // The record's own estimates (Q13) within the tolerance it reports.
  CHECK(rec.at("error_a0").get<double>() <= tolerance * a0);
  CHECK(rec.at("error_d").get<double>() <= tolerance * d);
  CHECK(rec.at("error_chi").get<double>() <= tolerance * chi);
  CHECK(rec.at("residual").get<double>() <= tolerance);
  CHECK(rec.at("rolling_resistance").get<double>() == chi * 1000);
  // The scene's tolerance is asked instead, and --tolerance replaces it.
  const auto coarse =
      cylinder(dir.path(), "q.json", layer, "[2.0]", R"(, "method": "plane", "tolerance": 1e-3)");
  const Run by_file = run({"--scene", coarse.string()});
  const Run by_option = run({"--scene", coarse.string(), "--tolerance", "1e-8"});
  REQUIRE(by_file.status == 0);
  REQUIRE(by_option.status == 0);
  CHECK(json_lines(by_file.out).at(0).at("tolerance").get<double>() == 1e-3);
  CHECK(json_lines(by_option.out).at(0).at("tolerance").get<double>() == 1e-8);
}

TEST_CASE(
    "cli: the auto method answers a cylinder on a spring bed by the plane method, and says why",
    "[cli][substrate]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_substrate_auto_plane");
  const Run r =
      run({"--scene", cylinder(dir.path(), "a.json",
                               R"({"model": "spring_bed", "thickness": 0.004})", "[0.2, 2.0]", "")
                          .string()});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  const auto recs = json_lines(r.out);
  REQUIRE(recs.size() == 2);
  for (const auto& rec : recs) {
    CHECK(rec.at("method").get<std::string>() == "plane");
    CHECK(rec.at("method_reason").get<std::string>() ==
          "auto: plane (a cylinder on a spring_bed (thickness 0.004 m): the plane problem on the "
          "substrate, to the tolerance 1e-04 in a, d and chi)");
    CHECK(rec.at("converged").get<bool>());
    CHECK(rec.at("terms").get<long>() == 0);  // the bed's closed form (Q11)
    CHECK(rec.at("d").get<double>() > 0);
  }
  // Faster rolling leaves the bed less time to sink: a shallower contact.
  CHECK(recs[1].at("d").get<double>() < recs[0].at("d").get<double>());
}

TEST_CASE("cli: a tolerance outside its method's range is named", "[cli][substrate]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_substrate_tolerance");
  const std::string layer = R"({"model": "layer", "thickness": 0.004})";
  const std::string plane_range =
      "is outside the valid range 64 eps = 1.4e-14 <= tolerance <= 0.1 for the plane method on a "
      "layer or a spring bed";
  // The bem's "one grid" is no tolerance of the plane method.
  check_refused({"--scene", cylinder(dir.path(), "zero.json", layer, "[2.0]",
                                     R"(, "method": "plane", "tolerance": 0)")
                                .string()},
                "tolerance = 0 " + plane_range);
  const auto plain = cylinder(dir.path(), "plain.json", layer, "[2.0]", "");
  check_refused({"--scene", plain.string(), "--tolerance", "0.2"},
                "--tolerance = 0.2 is outside the valid range 64 eps = 1.4e-14 <= --tolerance <= "
                "0.1 for the plane method");
  // The plane method's 1e-6 is finer than the bem's range.
  check_refused(
      {"--scene", idler(dir.path(), "bem.json", layer, "bem").string(), "--tolerance", "1e-6"},
      "--tolerance = 1e-06 is outside the valid range 0 (one grid) or 1e-4 <= "
      "--tolerance <= 0.5 for the bem method");
  // The line method on a cylinder on a layer: the plane method answers it.
  check_refused(
      {"--scene",
       cylinder(dir.path(), "line.json", layer, "[2.0]", R"(, "method": "line")").string()},
      R"(not by line: the line method's theory is the half space's (give "method": )"
      R"("plane" or "auto"))");
}

}  // namespace test_cli_substrate
