// viscoroll-solve --setting fast: the line method's fast setting, LineOptions::fast() on 6-point
// panels (FastLineSolverD), the same numbers as the library's sweep with that solver; --grid and
// the other line options override it; other methods and other values exit 2 naming the option. A
// scene file's "setting" is the same, and --setting replaces it.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/sweep.hpp>

#include "cli_run.hpp"
#include "support/paper_scene.hpp"
#include "support/same_line_solution.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_setting {

namespace {

using namespace viscoroll::cli_test;
using viscoroll::testing::same_bits;

std::string digits17(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

}  // namespace

TEST_CASE("cli: --setting fast is the library's fast setting on 6-point panels", "[cli][line]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // The paper's scene (tests/support/paper_scene.hpp: mu_D = 1, nu = 0.5, f = 9, tau = 1) at
  // three speeds of the figures' range, one chunk of continuation.
  const viscoroll::testing::PaperScene paper;
  const auto at = paper.scene(0.0);
  const std::vector<double> speeds = {0.01, 1.0, 100.0};
  const std::vector<std::string> scene = {
      "--method", "line",      "--mu-d", "1", "--nu", "0.5",           "--f",    "9",
      "--tau",    "1",         "--c1",   "1", "--c2", digits17(at.c2), "--load", digits17(at.load),
      "--speed",  "0.01,1,100"};
  std::vector<std::string> args = scene;
  for (const char* extra : {"--setting", "fast"}) args.push_back(extra);
  const Run r = run(args);
  INFO("stderr: " << r.err);
  REQUIRE(r.status == 0);
  const auto lines = json_lines(r.out);
  REQUIRE(lines.size() == speeds.size());

  const viscoroll::FastLineSolverD solver(paper.material, viscoroll::LineOptions::fast());
  viscoroll::SweepOptions one_thread;
  one_thread.threads = 1;
  const auto expected = viscoroll::sweep(solver, at, speeds, one_thread);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    CAPTURE(i);
    CHECK(lines[i]["terms"] == viscoroll::LineOptions::fast().terms);
    CHECK(lines[i]["converged"] == true);
    CHECK(lines[i]["iterations"] == expected[i].iterations);
    CHECK(same_bits(lines[i]["a0"].get<double>(), expected[i].a(0.0)));
    CHECK(same_bits(lines[i]["b0"].get<double>(), expected[i].b(0.0)));
    CHECK(same_bits(lines[i]["l"].get<double>(), expected[i].l()));
    CHECK(same_bits(lines[i]["d"].get<double>(), expected[i].d));
    CHECK(same_bits(lines[i]["chi"].get<double>(), expected[i].chi));
  }

  // --grid overrides the setting's terms; --setting default is the default run.
  std::vector<std::string> four = args;
  for (const char* extra : {"--grid", "4"}) four.push_back(extra);
  const auto four_lines = json_lines(run(four).out);
  REQUIRE(four_lines.size() == speeds.size());
  CHECK(four_lines[0]["terms"] == 4);
  std::vector<std::string> named_default = scene;
  for (const char* extra : {"--setting", "default"}) named_default.push_back(extra);
  const Run d = run(named_default), plain = run(scene);
  CHECK(d.status == plain.status);
  const auto d_lines = json_lines(d.out), plain_lines = json_lines(plain.out);
  REQUIRE(d_lines.size() == speeds.size());
  REQUIRE(plain_lines.size() == speeds.size());
  CHECK(plain_lines[0]["terms"] == 6);
  for (std::size_t i = 0; i < speeds.size(); ++i)
    for (const auto& [key, value] : plain_lines[i].items())
      if (key != "seconds") {
        CAPTURE(i, key);
        CHECK(d_lines[i][key] == value);
      }

  // Another value, or another method: exit 2 naming the option, nothing on stdout.
  std::vector<std::string> bad = scene;
  for (const char* extra : {"--setting", "quick"}) bad.push_back(extra);
  const Run e = run(bad);
  CHECK(e.status == 2);
  CHECK(e.out.empty());
  CHECK(e.err.find("--setting expects default or fast") != std::string::npos);
  const Run plane = run({"--method", "plane", "--mu-d", "1", "--nu", "0.5", "--f", "9", "--tau",
                         "1", "--speed", "1", "--c1", "1", "--load", "1", "--setting", "fast"});
  CHECK(plane.status == 2);
  CHECK(plane.out.empty());
  CHECK(plane.err.find("--setting is valid only with --method line or auto") != std::string::npos);
}

TEST_CASE("cli: a scene file's setting is the line method's, --setting replaces it",
          "[cli][line]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // paper.json with "setting": "fast": the same lines as paper.json with --setting fast (the
  // file's grid 6 kept); --setting default over it: paper.json's own lines; the bem method
  // ignores it.
  nlohmann::ordered_json scene = nlohmann::ordered_json::parse(slurp(scenes_dir() / "paper.json"));
  scene["setting"] = "fast";
  const TempDir dir("viscoroll_cli_setting");
  const std::string fast_file = (dir.path() / "paper_fast.json").string();
  std::ofstream(fast_file) << scene.dump();
  const std::string paper = (scenes_dir() / "paper.json").string();
  const auto same_lines = [](const std::string& x, const std::string& y) {
    const auto a = json_lines(x), b = json_lines(y);
    REQUIRE(a.size() == b.size());
    REQUIRE_FALSE(a.empty());
    for (std::size_t i = 0; i < a.size(); ++i)
      for (const auto& [key, value] : b[i].items())
        if (key != "seconds") {
          CAPTURE(i, key);
          CHECK(a[i][key] == value);
        }
  };
  const Run from_file = run({"--scene", fast_file, "--speed", "0.1,1"});
  const Run from_option = run({"--scene", paper, "--speed", "0.1,1", "--setting", "fast"});
  INFO("stderr: " << from_file.err);
  REQUIRE(from_file.status == 0);
  REQUIRE(from_option.status == 0);
  same_lines(from_file.out, from_option.out);
  CHECK(json_lines(from_file.out)[0]["terms"] == 6);
  const Run replaced = run({"--scene", fast_file, "--speed", "0.1,1", "--setting", "default"});
  const Run plain = run({"--scene", paper, "--speed", "0.1,1"});
  REQUIRE(replaced.status == 0);
  same_lines(replaced.out, plain.out);
  CHECK(json_lines(plain.out)[0]["l"] != json_lines(from_file.out)[0]["l"]);
  const Run bem = run({"--scene", fast_file, "--speed", "1", "--method", "bem", "--grid", "6"});
  CHECK(bem.status == 0);
  CHECK(json_lines(bem.out).size() == 1);
}

}  // namespace test_cli_setting
