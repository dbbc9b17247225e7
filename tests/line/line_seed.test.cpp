// LineSolver::solve with a seed: a seed that is not a converged, finite solution is set aside and
// the answer is the cold start's, bit for bit, with a warning; a seed from which the iteration
// stops short (the same scene at 1000 times the load) is followed by the cold start, with a
// warning; a good seed (a neighbouring speed) is used as before, without one.
#include <catch2/catch.hpp>
#include <limits>
#include <string>
#include <viscoroll/line/line_solver.hpp>

#include "support/paper_scene.hpp"
#include "support/same_line_solution.hpp"

namespace {

using viscoroll::testing::require_same_solution;

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
  for (const auto& w : warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("line solver: a seed that is not finite or not converged is set aside", "[line]") {
  const viscoroll::testing::PaperScene paper;
  viscoroll::LineOptions options;
  options.terms = 4;
  const viscoroll::LineSolverD solver(paper.material, options);
  const auto scene = paper.scene(1.0);
  const auto cold = solver.solve(scene);
  REQUIRE(cold.converged);
  REQUIRE_FALSE(mentions(cold.warnings, "seed"));

  auto nan_seed = cold;
  nan_seed.shape.alpha[1] = std::numeric_limits<double>::quiet_NaN();
  const auto from_nan = solver.solve(scene, &nan_seed);
  require_same_solution(from_nan, cold);
  REQUIRE(mentions(from_nan.warnings, "the seed was set aside"));

  auto failed_seed = cold;
  failed_seed.converged = false;
  const auto from_failed = solver.solve(scene, &failed_seed);
  require_same_solution(from_failed, cold);
  REQUIRE(mentions(from_failed.warnings, "the seed was set aside"));
}

TEST_CASE("line solver: an iteration from a seed that stops short is run again cold", "[line]") {
  const viscoroll::testing::PaperScene paper;
  viscoroll::LineOptions options;
  options.terms = 8;
  const viscoroll::LineSolverD solver(paper.material, options);
  auto heavy = paper.scene(1.0);
  heavy.load *= 1000;  // a0 ten times larger: at N = 8 the iteration from its shape breaks down
  const auto seed = solver.solve(heavy);
  REQUIRE(seed.converged);
  const auto scene = paper.scene(1.0);
  const auto cold = solver.solve(scene);
  const auto seeded = solver.solve(scene, &seed);
  REQUIRE(mentions(seeded.warnings, "solved again from the cold start"));
  require_same_solution(seeded, cold);
}

TEST_CASE("line solver: a good seed is used, without a warning", "[line]") {
  const viscoroll::testing::PaperScene paper;
  viscoroll::LineOptions options;
  options.terms = 4;
  const viscoroll::LineSolverD solver(paper.material, options);
  const auto near = solver.solve(paper.scene(1.1));
  REQUIRE(near.converged);
  const auto seeded = solver.solve(paper.scene(1.0), &near);
  REQUIRE(seeded.converged);
  REQUIRE_FALSE(mentions(seeded.warnings, "seed"));
  const auto cold = solver.solve(paper.scene(1.0));
  REQUIRE(seeded.iterations < cold.iterations);  // continuation saves work
}
