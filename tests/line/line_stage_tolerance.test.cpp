// LineOptions::stage_tolerance and stage_damping (the continuation's intermediate stages stop at
// max |r| <= 1e-2 and later stages start at the damping 1e-9, as LineOptions::fast() sets them):
// the last stage iterates to a root as before. Over the 100 speeds V tau/a0 = 10^(-3 + 6i/99) of
// the paper's scene, fast() against the full end game (intermediate stages to a root, damping
// 1e-3):
// - outside the slow regime (V tau >= 0.1 a0, docs/theory.md section 10) on the same root. Bound:
//   both are roots whose a posteriori error max |J^+ r| is at most sqrt(eps) in the scaled unknowns
//   (alpha, beta / a_ref, ln l, d / (C1 a_ref^2); the solver warns of a larger one), so they differ
//   by at most 2 sqrt(eps) there; a(0), l, d relative, b(0) relative to a(0), chi through them:
//   8 sqrt(eps);
// - in the slow regime the square equations at N = 5 have several roots near the smooth branch
//   (docs/line-solver.md, "Continuation in speed"), and the looser seed may end on another one (5
//   of the 33 speeds below 0.1 a0, by up to 8e-4 in l): both within the fast setting's stated
//   discretisation error of 1% of the converged solution (line_fast_setting.test.cpp checks the
//   fast setting against it), so within 2% of each other.
// And the options' ranges.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <viscoroll/line/line_solver.hpp>

#include "support/paper_scene.hpp"
#include "support/same_line_solution.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_stage_tolerance {

TEST_CASE("line stage tolerance: fast() lands on the full end game's roots at 100 speeds",
          "[line]") {
  const viscoroll::testing::PaperScene paper;
  viscoroll::LineOptions full = viscoroll::LineOptions::fast();
  full.stage_tolerance = 0;
  full.stage_damping = 1e-3;
  const viscoroll::LineSolverD quick(paper.material, viscoroll::LineOptions::fast());
  const viscoroll::LineSolverD slow(paper.material, full);
  int fewer = 0;
  for (int i = 0; i < 100; ++i) {
    const double vtau = std::pow(10.0, -3 + 6.0 * i / 99);
    const double bound = vtau >= 0.1 ? 8 * std::sqrt(std::numeric_limits<double>::epsilon()) : 2e-2;
    const auto a = quick.solve(paper.scene(vtau));
    const auto b = slow.solve(paper.scene(vtau));
    INFO("V tau/a0 = " << vtau << ": " << a.reason << " / " << b.reason);
    REQUIRE(b.converged);
    REQUIRE(a.converged);
    // The stage tolerance stops intermediate stages only, never the last.
    CHECK(a.code == viscoroll::StopCode::converged);
    CHECK(b.code == viscoroll::StopCode::converged);
    viscoroll::testing::check_same_root(a, b, bound);
    if (a.iterations < b.iterations) ++fewer;
  }
  // What the stage options are for: fewer iterations (measured at every one of the 100 speeds).
  CHECK(fewer >= 90);
}

TEST_CASE("line stage tolerance: the options' ranges", "[line]") {
  const viscoroll::testing::PaperScene paper;
  const auto rejects = [&](double tolerance, double damping, const char* name) {
    viscoroll::LineOptions bad;
    bad.stage_tolerance = tolerance;
    bad.stage_damping = damping;
    CHECK_THROWS_WITH(viscoroll::LineSolverD(paper.material, bad), Catch::Contains(name));
  };
  rejects(-1e-3, 1e-3, "stage_tolerance");
  rejects(0.2, 1e-3, "stage_tolerance");
  rejects(std::nan(""), 1e-3, "stage_tolerance");
  rejects(0, 0, "stage_damping");
  rejects(0, 2, "stage_damping");
  rejects(0, std::nan(""), "stage_damping");
  viscoroll::LineOptions edge;
  edge.stage_tolerance = 0.1;
  edge.stage_damping = 1e-12;
  CHECK_NOTHROW(viscoroll::LineSolverD(paper.material, edge));
}

}  // namespace test_line_stage_tolerance
