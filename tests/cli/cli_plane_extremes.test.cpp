// viscoroll-solve at the ends of the floating-point range: a plane scene ends in strict
// JSON lines with finite numbers (exit 0) or in one message on stderr and nothing on stdout (exit
// 2), also when one speed of a sweep is the bad one; V tau overflowing a double is null in every
// method, the rest of the line finite (docs/cli.md, docs/errors.md).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_plane_extremes {

namespace {

using namespace viscoroll::cli_test;

std::vector<std::string> plane(std::vector<std::string> rest) {
  std::vector<std::string> args = {"--method", "plane", "--mu-d", "1", "--nu", "0.5", "--f", "9"};
  args.insert(args.end(), rest.begin(), rest.end());
  return args;
}

/// Exit 0 with `lines` JSON lines (nlohmann's parser rejects inf and nan), every value of them
/// non-null and every number finite, a0 and a_long_term positive.
void check_clean_result(const Run& r, std::size_t lines) {
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto json = json_lines(r.out);
  REQUIRE(json.size() == lines);
  for (const auto& line : json) {
    for (const auto& [key, value] : line.items()) {
      INFO(key);
      CHECK(!value.is_null());
      if (value.is_number()) CHECK(std::isfinite(value.get<double>()));
    }
    CHECK(line["converged"] == true);
    CHECK(line["a0"].get<double>() > 0);
    CHECK(line["a_long_term"].get<double>() > 0);
  }
}

}  // namespace

TEST_CASE("cli: plane scenes at the ends of the range end in strict JSON or a clean error",
          "[cli][plane][extremes]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // V tau = 1e308: the glassy closed form; with tau = 1e-300 too, V tau = 1e8 rolls.
  check_clean_result(run(plane({"--tau", "1", "--speed", "1e308", "--c1", "1", "--load", "0.01"})),
                     1);
  check_clean_result(
      run(plane({"--tau", "1e-300,1", "--speed", "1e308", "--c1", "1", "--load", "0.01"})), 2);
  // 4 c (1 + f) W / C1 overflows, a0 = 1.8e154 does not.
  check_clean_result(run(plane({"--tau", "1", "--speed", "1", "--c1", "1e-308", "--load", "1"})),
                     1);
  // F0 = c W = 3.9e-325 is not representable: exit 2, nothing on stdout.
  const Run tiny = run(plane({"--tau", "1", "--speed", "1", "--c1", "1", "--load", "4.9e-324"}));
  CHECK(tiny.status == 2);
  CHECK(tiny.out.empty());
  CHECK_THAT(tiny.err, Catch::Contains("F0 of Eq. (33)") && Catch::Contains("rescale the units"));
  // A sweep whose second speed gives b = 8e-311: the whole run is rejected before any output.
  const Run sweep =
      run(plane({"--tau", "1e-10", "--speed", "1,1.78e-300", "--c1", "1e300", "--load", "1e-300"}));
  CHECK(sweep.status == 2);
  CHECK(sweep.out.empty());
  CHECK_THAT(sweep.err, Catch::Contains("the offset b of the contact"));
}

TEST_CASE("cli: V tau beyond a double is null and the rest of the line finite, every method",
          "[cli][extremes]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // speed * tau = 1e400 overflows; each solver scales V tau and returns the glassy contact.
  for (const char* method : {"plane", "line", "bem"}) {
    INFO(method);
    const Run r = run({"--method", method,      "--mu-d", "1",         "--nu",   "0.5",  "--f",
                       "9",        "--tau",     "1e200",  "--speed",   "1e200",  "--c1", "1",
                       "--c2",     "0.0798291", "--load", "2.0943951", "--grid", "6"});
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto json = json_lines(r.out);  // strict: throws on inf or nan
    REQUIRE(json.size() == 1);
    const auto& line = json.front();
    CHECK(line["vtau"].is_null());
    CHECK(line["converged"] == true);
    // json_lines has rejected inf and nan: a number that was not finite is null here.
    for (const auto& [key, value] : line.items()) {
      INFO(key);
      if (key != "vtau") CHECK(!value.is_null());
    }
    CHECK(line["a0"].get<double>() > 0);
  }
}

}  // namespace test_cli_plane_extremes
