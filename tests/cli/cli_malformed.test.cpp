// Malformed scene files, generated from a table into a temporary directory: each makes the built
// viscoroll-solve exit 2 with a message naming the key (with its path) or the file's fault, and
// print nothing on stdout. Bad JSON, wrong types, unknown and missing keys, out-of-range and
// non-finite values (1e999 reads as inf), a 10 MB file, an empty file, a directory, a missing file.
#include <catch2/catch.hpp>
#include <functional>
#include <string>
#include <vector>

#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_malformed {

namespace {

using namespace viscoroll::cli_test;
using nlohmann::json;

json valid_scene() {
  return json::parse(R"({
    "description": "a valid scene, changed by each case",
    "material": {"model": "standard_linear_solid", "mu_d": 2.0e6, "nu": 0.5, "f": 9, "tau": 0.01},
    "roller": {"profile": "ellipsoid", "c1": 20.0, "c2": 1.0},
    "load": 100.0,
    "speeds": [0.001, 0.01, 0.1],
    "method": "line",
    "grid": 4
  })");
}

/// A case: the file's text (from the valid scene changed by `change`, or `raw` if not empty),
/// extra options, and what the message must contain.
struct Case {
  std::string name;
  std::function<void(json&)> change;
  std::string raw;
  std::string message;
  std::vector<std::string> options = {};
};

/// The valid scene's text with `change` applied; the number 123456789 becomes `literal`.
std::string text_with(const std::function<void(json&)>& change, const std::string& literal = "") {
  json s = valid_scene();
  if (change) change(s);
  std::string text = s.dump(2);
  if (!literal.empty()) text.replace(text.find("123456789"), 9, literal);
  return text;
}

}  // namespace

TEST_CASE("cli: malformed scene files exit 2 naming the key, nothing on stdout", "[cli][scene]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_malformed");
  const std::vector<Case> cases = {
      // Bad JSON: the parser's line and column.
      {"truncated", {}, "{\"load\": 1,", "not valid JSON: parse error at line 1, column 12"},
      {"trailing_comma", {}, "{\n  \"load\": 1,\n}\n", "parse error at line 3, column 1"},
      {"not_an_object", {}, "[1, 2]", "the scene must be a JSON object, got array"},
      {"duplicate_key", {}, text_with({}).replace(1, 0, "\"load\": 5,"), "duplicate key load"},
      // Wrong types.
      {"f_string", set_at("/material/f", "9"), "", "material.f must be a number, got string"},
      {"load_bool", set_at("/load", true), "", "load must be a number, got boolean"},
      {"mu_d_null", set_at("/material/mu_d", nullptr), "",
       "material.mu_d must be a number, got null"},
      {"speeds_number", set_at("/speeds", 1.0), "",
       "speeds must be an array of numbers, got number"},
      {"speed_string", set_at("/speeds/1", "fast"), "", "speeds[1] must be a number, got string"},
      {"material_array", set_at("/material", json::array({1, 2})), "",
       "material must be a JSON object, got array"},
      {"description_number", set_at("/description", 3), "", "description must be a string"},
      {"grid_fraction", set_at("/grid", 4.5), "", "grid must be an integer, got number"},
      {"method_number", set_at("/method", 2), "", "method must be a string, got integer"},
      // Unknown keys and values.
      {"unknown_top", set_at("/velocity", 1), "", "unknown key velocity"},
      {"unknown_material", set_at("/material/E", 1), "", "unknown key material.E"},
      {"unknown_roller", set_at("/roller/radius", 1), "", "unknown key roller.radius"},
      {"unknown_model", set_at("/material/model", "maxwell"), "",
       "material.model = \"maxwell\" is not one of elastic, standard_linear_solid"},
      {"unknown_profile", set_at("/roller/profile", "cone"), "",
       "roller.profile = \"cone\" is not one of ellipsoid, cylinder"},
      {"unknown_method", set_at("/method", "fem"), "",
       "method = \"fem\" is not one of plane, line, bem, auto"},
      // Missing keys.
      {"no_material", drop_at("/material"), "", "missing key material"},
      {"no_tau", drop_at("/material/tau"), "", "missing key material.tau"},
      {"no_model", drop_at("/material/model"), "", "missing key material.model"},
      {"no_c2", drop_at("/roller/c2"), "", "missing key roller.c2"},
      {"no_load", drop_at("/load"), "", "missing key load"},
      {"no_speeds", drop_at("/speeds"), "", "missing key speeds"},
      // No method: the auto method, which takes no grid.
      {"no_method", drop_at("/method"), "", "grid = 4 needs a method"},
      // Out of range.
      {"mu_d_zero", set_at("/material/mu_d", 0), "",
       "material.mu_d = 0 is outside the valid range mu_d > 0"},
      {"nu_high", set_at("/material/nu", 0.7), "",
       "material.nu = 0.7 is outside the valid range -1 < nu <= 0.5"},
      {"f_negative", set_at("/material/f", -1), "",
       "material.f = -1 is outside the valid range f >= 0"},
      {"tau_negative", set_at("/material/tau", -0.01), "",
       "material.tau = -0.01 is outside the valid range tau >= 0"},
      {"c1_zero", set_at("/roller/c1", 0), "", "roller.c1 = 0 is outside the valid range c1 > 0"},
      {"c2_round", set_at("/roller/c2", 20.0), "",
       "roller.c2 = 20 is outside the valid range 0 < c2 < 8 e^-3 c1 = 7.96"},
      {"load_negative", set_at("/load", -5), "", "load = -5 is outside the valid range load > 0"},
      {"speed_negative", set_at("/speeds/2", -1), "",
       "speeds[2] = -1 is outside the valid range speed >= 0"},
      {"speeds_empty", set_at("/speeds", json::array()), "", "speeds is empty"},
      {"grid_line", set_at("/grid", 100), "",
       "grid = 100 is outside the valid range 1 <= grid <= 64"},
      {"cylinder_line", set_at("/roller", json{{"profile", "cylinder"}, {"radius", 0.05}}), "",
       "roller.profile = \"cylinder\" suits the plane method only"},
      // Non-finite: JSON has no inf or nan; 1e999 reads as inf.
      {"f_inf",
       {},
       text_with(set_at("/material/f", 123456789), "1e999"),
       "material.f = 1e999 is outside the valid range f >= 0"},
      {"load_minus_inf",
       {},
       text_with(set_at("/load", 123456789), "-1e999"),
       "load = -1e999 is outside the valid range load > 0"},
      {"speed_inf",
       {},
       text_with(set_at("/speeds/0", 123456789), "1e999"),
       "speeds[0] = 1e999 is outside the valid range speed >= 0"},
      {"nu_nan_word", {}, text_with(set_at("/material/nu", 123456789), "NaN"), "not valid JSON"},
      // The file itself.
      {"empty", {}, "", "is empty"},
      {"blank", {}, " \n\t\n", "is empty"},
  };
  std::vector<std::pair<std::string, Case>> files;
  for (const auto& c : cases) {
    const fs::path path = dir.path() / (c.name + ".json");
    std::ofstream(path) << (c.change ? text_with(c.change) : c.raw);
    files.emplace_back(path.string(), c);
  }
  // A 10 MB file (a valid scene padded with spaces), a directory, a missing file, a conflict.
  const fs::path big = dir.path() / "big.json";
  std::ofstream(big) << text_with({}) << std::string(10 << 20, ' ');
  files.push_back({big.string(), {"big", {}, "", "over the limit of 1 MiB"}});
  files.push_back({dir.path().string(), {"directory", {}, "", "is a directory"}});
  files.push_back({(dir.path() / "missing.json").string(), {"missing", {}, "", "no such file"}});
  files.push_back({(scenes_dir() / "paper.json").string(),
                   {"conflict", {}, "", "--scene excludes --c1", {"--c1", "2"}}});
  CHECK(files.size() >= 30);
  for (const auto& [path, c] : files) {
    std::vector<std::string> args = {"--scene", path};
    args.insert(args.end(), c.options.begin(), c.options.end());
    const Run r = run(args);
    INFO(c.name << ": " << path << "\nstdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK(r.err.starts_with("viscoroll-solve: "));
  }
}

}  // namespace test_cli_malformed
