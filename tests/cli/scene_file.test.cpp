// The scene reader of viscoroll-solve (examples/cli/scene_file.hpp) as a unit: valid scenes give
// the right values, each error names its key with its path and the valid range, and the shipped
// scenes parse.
#include "cli/scene_file.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <variant>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_scene_file {

namespace {

using namespace viscoroll::cli;

/// The message parse_scene throws for `text`, or "" if it parses.
std::string error_of(const std::string& text) {
  try {
    (void)parse_scene(text, "s.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

const std::string sls =
    R"("material": {"model": "standard_linear_solid", "mu_d": 2e6, "nu": 0.5, "f": 9, "tau": 0.01})";
const std::string ellipsoid = R"("roller": {"profile": "ellipsoid", "c1": 20.0, "c2": 1.0})";

std::string scene_with(const std::string& material, const std::string& roller,
                       const std::string& rest = R"("load": 100, "speeds": [0.001, 0.01])") {
  return "{" + material + ", " + roller + ", " + rest + "}";
}

}  // namespace

TEST_CASE("cli scene file: a valid scene gives its values", "[cli][scene]") {
  const Scene s = parse_scene(
      "{\"description\": \"d\", " + sls + ", " + ellipsoid +
          R"(, "load": 100.0, "speeds": [0.001, 0.01, 0.1, 1.0], "method": "line", "grid": 6,)"
          R"( "setting": "fast"})",
      "s.json");
  CHECK(s.description == "d");
  const auto& m = std::get<StandardLinearSolidModel>(s.material);
  CHECK(m.mu_d == 2e6);
  CHECK(m.nu == 0.5);
  CHECK(m.f == 9);
  CHECK(m.tau == 0.01);
  const auto& r = std::get<EllipsoidProfile>(s.roller);
  CHECK(r.c1 == 20);
  CHECK(r.c2 == 1);
  CHECK(s.load == 100);
  CHECK(s.speeds == std::vector<double>{0.001, 0.01, 0.1, 1.0});
  REQUIRE(s.method);
  CHECK(*s.method == Method::line);
  REQUIRE(s.grid);
  CHECK(*s.grid == 6);
  CHECK(s.setting == LineSetting::fast);
}

TEST_CASE("cli scene file: elastic material, cylinder, optional keys absent", "[cli][scene]") {
  const Scene s =
      parse_scene(scene_with(R"("material": {"nu": 0.3, "model": "elastic", "mu": 8e10})",
                             R"("roller": {"profile": "cylinder", "radius": 0.05})",
                             R"("speeds": [0], "load": 5e4)"),
                  "s.json");
  CHECK(s.description.empty());
  CHECK(std::get<ElasticModel>(s.material).mu == 8e10);
  CHECK(std::get<ElasticModel>(s.material).nu == 0.3);
  CHECK(std::get<CylinderProfile>(s.roller).radius == 0.05);
  CHECK(s.speeds == std::vector<double>{0});
  CHECK(!s.method);
  CHECK(!s.grid);
  CHECK(!s.setting);
  CHECK_NOTHROW(check_scene_for_method(s, Method::plane, "s.json"));
  CHECK_THROWS_WITH(check_scene_for_method(s, Method::line, "s.json"),
                    Catch::Contains("roller.profile = \"cylinder\" suits the plane method only"));
}

TEST_CASE("cli scene file: each error names its key with its path and the range", "[cli][scene]") {
  const std::string rest = R"("load": 100, "speeds": [0.001, 0.01])";
  struct Case {
    std::string text, message;
  };
  const std::vector<Case> cases = {
      {"{", "s.json: not valid JSON: parse error at line 1, column 2"},
      {"{\n\"load\": 1,\n}", "parse error at line 3, column 1"},
      {"", "not valid JSON"},
      {"[1]", "s.json: the scene must be a JSON object, got array"},
      {scene_with(sls, ellipsoid, rest + R"(, "speed": 1)"), "unknown key speed"},
      {scene_with(
           R"("material": {"model": "standard_linear_solid", "mu_d": 1, "nu": 0.5, "f": 9, "tau": 1, "g": 2})",
           ellipsoid),
       "unknown key material.g"},
      {scene_with(sls, R"("roller": {"profile": "ellipsoid", "c1": 1, "c2": 0.1, "radius": 1})"),
       "unknown key roller.radius"},
      {scene_with(R"("material": {"model": "standard_linear_solid", "mu_d": 1, "nu": 0.5, "f": 9})",
                  ellipsoid),
       "missing key material.tau"},
      {"{" + sls + ", " + rest + "}", "missing key roller"},
      {scene_with(sls, ellipsoid, R"("speeds": [1])"), "missing key load"},
      {scene_with(sls, ellipsoid, R"("load": 1, "speeds": [1, "2"])"),
       "speeds[1] must be a number, got string"},
      {scene_with(sls, ellipsoid, R"("load": 1, "speeds": [1, 2, -3])"),
       "speeds[2] = -3 is outside the valid range speed >= 0"},
      {scene_with(sls, ellipsoid, R"("load": 1, "speeds": [])"), "speeds is empty"},
      {scene_with(sls, ellipsoid, R"("load": 1e999, "speeds": [1])"),
       "load = 1e999 is outside the valid range load > 0"},
      {scene_with(
           R"("material": {"model": "standard_linear_solid", "mu_d": 1, "nu": 0.7, "f": 9, "tau": 1})",
           ellipsoid),
       "material.nu = 0.7 is outside the valid range -1 < nu <= 0.5"},
      {scene_with(
           R"("material": {"model": "standard_linear_solid", "mu_d": 1, "nu": 0.5, "f": "9", "tau": 1})",
           ellipsoid),
       "material.f must be a number, got string"},
      {scene_with(R"("material": {"model": "maxwell"})", ellipsoid),
       "material.model = \"maxwell\" is not one of elastic, standard_linear_solid"},
      {scene_with(sls, R"("roller": {"profile": "cone"})"),
       "roller.profile = \"cone\" is not one of ellipsoid, cylinder"},
      {scene_with(sls, ellipsoid, rest + R"(, "grid": 2.5)"),
       "grid must be an integer, got number"},
      {scene_with(sls, ellipsoid, rest + R"(, "grid": 0)"), "grid = 0 is outside the valid range"},
      {scene_with(sls, ellipsoid, rest + R"(, "setting": "quick")"),
       "setting = \"quick\" is not one of default, fast"},
      {scene_with(sls, ellipsoid, rest + R"(, "setting": 1)"), "setting must be a string"},
      {scene_with(sls, ellipsoid, rest + R"(, "load": 2)"), "duplicate key load"},
      {scene_with(
           R"("material": {"model": "standard_linear_solid", "mu_d": 1, "nu": 0.5, "f": 9, "tau": 1, "f": 2})",
           ellipsoid),
       "duplicate key material.f"},
      {scene_with(sls, ellipsoid, R"("load": 1, "speeds": [[1], {"a": 2}, -1e999])"),
       "speeds[2] = -1e999 is outside the valid range speed >= 0"},
  };
  for (const auto& c : cases) {
    INFO(c.text);
    CHECK_THAT(error_of(c.text),
               Catch::Contains(c.message) && Catch::StartsWith("viscoroll-solve: s.json: "));
  }
}

TEST_CASE("cli scene file: the method's own ranges", "[cli][scene]") {
  Scene s = parse_scene(scene_with(sls, R"("roller": {"profile": "ellipsoid", "c1": 20, "c2": 8})"),
                        "s.json");
  CHECK_NOTHROW(check_scene_for_method(s, Method::bem, "s.json"));
  CHECK_NOTHROW(check_scene_for_method(s, Method::plane, "s.json"));
  CHECK_THROWS_WITH(check_scene_for_method(s, Method::line, "s.json"),
                    Catch::Contains("roller.c2 = 8 is outside the valid range 0 < c2 < 8 e^-3 c1"));
  s.grid = 65;
  CHECK_NOTHROW(check_scene_for_method(s, Method::bem, "s.json"));
  Scene slender = parse_scene(scene_with(sls, ellipsoid), "s.json");
  slender.grid = 65;
  CHECK_THROWS_WITH(check_scene_for_method(slender, Method::line, "s.json"),
                    Catch::Contains("grid = 65 is outside the valid range 1 <= grid <= 64"));
  slender.grid = 1;
  CHECK_THROWS_WITH(check_scene_for_method(slender, Method::bem, "s.json"),
                    Catch::Contains("grid = 1 is outside the valid range 2 <= grid <= 512"));
}

TEST_CASE("cli scene file: the shipped scenes parse", "[cli][scene]") {
  const std::filesystem::path dir = std::filesystem::path(VISCOROLL_SOURCE_DIR) / "examples/scenes";
  for (const char* name :
       {"paper.json", "polyamide_cylinder.json", "rubber_roller.json", "rubber_ball.json",
        "rubber_prony_bem.json", "rubber_dma_bem.json", "crowned_roller.json",
        "crowned_roller_line.json", "crowned_roller_prony_line.json"}) {
    INFO(name);
    const std::string path = (dir / name).string();
    const Scene s = parse_scene(read_scene_file(path), path);
    CHECK(!s.description.empty());
    CHECK(s.method);
    CHECK(!s.speeds.empty());
  }
  const std::string prony_path = (dir / "rubber_prony_bem.json").string();
  const Scene prony = parse_scene(read_scene_file(prony_path), prony_path);
  const auto* m = std::get_if<PronyModel>(&prony.material);
  REQUIRE(m);
  CHECK(m->terms.size() >= 10);
  CHECK(m->shift);
  CHECK(m->dma.empty());
  CHECK(prony.temperatures.size() >= 2);
  const std::string dma_path = (dir / "rubber_dma_bem.json").string();
  const Scene dma = parse_scene(read_scene_file(dma_path), dma_path);
  REQUIRE(std::holds_alternative<PronyModel>(dma.material));
  CHECK(std::get<PronyModel>(dma.material).dma == "../data/dma_known_spectrum.csv");
  CHECK(std::get<PronyModel>(dma.material).terms.empty());
  CHECK_NOTHROW(check_scene_for_method(prony, Method::line, "p.json"));
  CHECK_NOTHROW(check_scene_for_method(prony, Method::plane, "p.json"));
  CHECK_NOTHROW(check_scene_for_method(prony, Method::bem, "p.json"));
  CHECK_THROWS_WITH(read_scene_file(dir.string()), Catch::Contains("is a directory"));
  CHECK_THROWS_WITH(read_scene_file((dir / "none.json").string()), Catch::Contains("no such file"));
}

}  // namespace test_scene_file
