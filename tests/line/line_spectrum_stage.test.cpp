// LineOptions::stage_tolerance and stage_damping in the spectrum's line solver
// (docs/line-solver.md, "Continuation in N"): intermediate stages stopped at max |r| <= 1e-2 and
// later stages started at the damping 1e-9 end, at N = 4, on the root of the full end game (every
// stage to a root from the damping 1e-3), for the two-term spectrum of the validation and a
// twenty-term one (f = 0.45 each, tau = 10^-3 ... 10^3), at speeds from where the slowest term is
// in its slow regime to the glassy side. Bound: both are roots whose a posteriori error is at most
// sqrt(eps) in the scaled unknowns, so a(0), l, d and chi (relative) and b(0) (relative to a(0))
// agree within 8 sqrt(eps), as for one term (line_stage_tolerance.test.cpp).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony.hpp>

#include "support/same_line_solution.hpp"
#include "support/spectrum_scene.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_spectrum_stage {

namespace {

viscoroll::PronyCreep<double> twenty_terms() {
  std::vector<viscoroll::PronyTerm<double>> terms;
  for (int k = 0; k < 20; ++k) terms.push_back({0.45, std::pow(10.0, -3 + 6.0 * k / 19)});
  return viscoroll::PronyCreep<double>(1.0, 0.5, terms);
}

}  // namespace

TEST_CASE("line spectrum: the stage settings land on the full end game's root", "[line]") {
  const bool two = GENERATE(true, false);
  const auto material = two ? viscoroll::testing::two_term_creep() : twenty_terms();
  viscoroll::LineOptions full{.terms = 4};
  viscoroll::LineOptions staged = full;
  staged.stage_tolerance = 1e-2;
  staged.stage_damping = 1e-9;
  using Solver = viscoroll::LineSolver<double, viscoroll::PronyCreep<double>>;
  const Solver a_solver(material, staged), b_solver(material, full);
  const double bound = 8 * std::sqrt(std::numeric_limits<double>::epsilon());
  for (const double speed : {0.1, 1.0, 10.0, 100.0}) {
    const auto a = a_solver.solve(viscoroll::testing::spectrum_scene(speed));
    const auto b = b_solver.solve(viscoroll::testing::spectrum_scene(speed));
    INFO((two ? "two" : "twenty") << " terms, V = " << speed << ": " << a.reason << " / "
                                  << b.reason << ", iterations " << a.iterations << " / "
                                  << b.iterations);
    REQUIRE(b.converged);
    REQUIRE(a.converged);
    viscoroll::testing::check_same_root(a, b, bound);
    CHECK(a.iterations <= b.iterations);
  }
}

}  // namespace test_line_spectrum_stage
