// The outcome codes of viscoroll-solve's records (docs/errors.md, "Outcome codes"): every record
// of every method carries `code` beside `reason` and `warning_codes` beside `warnings`, index for
// index, each a name of core/outcome.hpp; `code` is "converged" exactly when the record is; a
// stopped iteration and a breach of the model's assumptions have their codes.
#include <algorithm>
#include <catch2/catch.hpp>
#include <string>
#include <vector>
#include <viscoroll/core/outcome.hpp>

#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_outcome_codes {

namespace {

using namespace viscoroll::cli_test;

template <class Names>
bool named(const Names& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

/// The record's outcome fields hold the invariants above.
void check_outcome(const nlohmann::ordered_json& r) {
  INFO(r.dump());
  const std::string code = r.at("code").get<std::string>();
  CHECK(named(viscoroll::detail::stop_code_names, code));
  CHECK((code == "converged") == r.at("converged").get<bool>());
  REQUIRE(r.at("warning_codes").size() == r.at("warnings").size());
  for (const auto& w : r.at("warning_codes"))
    CHECK(named(viscoroll::detail::warning_code_names, w.get<std::string>()));
}

std::vector<std::string> codes_of(const nlohmann::ordered_json& r) {
  std::vector<std::string> out;
  for (const auto& w : r.at("warning_codes")) out.push_back(w.get<std::string>());
  return out;
}

}  // namespace

TEST_CASE("cli outcome codes: every method's records carry code and warning_codes", "[cli]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const std::string paper = (scenes_dir() / "paper.json").string();
  for (const char* method : {"plane", "line", "bem"}) {
    INFO(method);
    const Run r = run({"--scene", paper, "--method", method, "--speed", "0.5419"});
    REQUIRE(r.status == 0);
    const auto records = json_lines(r.out);
    REQUIRE(records.size() == 1);
    check_outcome(records[0]);
    CHECK(records[0].at("code") == "converged");
  }
  // The line method over the paper's 25 speeds, some of them least-squares minima with their
  // warning (docs/line-solver.md): each warning has its code.
  const Run sweep = run({"--scene", paper});
  for (const auto& r : json_lines(sweep.out)) {
    check_outcome(r);
    if (!r.at("root").get<bool>()) CHECK(named(codes_of(r), "least_squares_minimum"));
  }
}

TEST_CASE("cli outcome codes: a stopped iteration and a unit mistake have their codes", "[cli]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // One iteration allowed: not converged, stopped by the iteration limit.
  const Run stopped = run({"--scene", (scenes_dir() / "paper.json").string(), "--speed", "0.5",
                           "--max-iterations", "1"});
  CHECK(stopped.status == 1);
  const auto s = json_lines(stopped.out);
  REQUIRE(s.size() == 1);
  check_outcome(s[0]);
  CHECK(s[0].at("code") == "iteration_limit");
  // The modulus in MPa (3.0 for 3.0e6 Pa): a contact wider than the roller, warned as (V1).
  const TempDir dir("viscoroll_cli_outcome_codes");
  const auto scene = dir.path() / "mpa.json";
  std::ofstream(scene) << R"({"material": {"model": "standard_linear_solid", "mu_d": 3.0,
    "nu": 0.5, "f": 9.0, "tau": 0.01},
    "roller": {"profile": "crowned", "radius": 0.05, "flat_length": 0.05, "crown_radius": 1},
    "load": 20.0, "speeds": [1.0]})";
  const Run mistake = run({"--scene", scene.string()});
  const auto m = json_lines(mistake.out);
  REQUIRE(m.size() == 1);
  check_outcome(m[0]);
  CHECK(named(codes_of(m[0]), "small_slope"));
}

}  // namespace test_cli_outcome_codes
