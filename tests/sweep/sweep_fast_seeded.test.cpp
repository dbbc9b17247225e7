// Seeded solves of LineOptions::fast() against cold solves, on the paper's scene: a sweep's
// continuation from 0.1 a0 up gives the cold start's roots (the continuation stages start from
// the seed at two terms: docs/line-solver.md, "Continuation in speed", which also says where a
// seed decides the root: far seeds in the slow regime, and V tau/a0 = 0.0093).
//
// Tolerance: Levenberg-Marquardt stops after a Newton step below eps^0.6 (1 + max |x|) <= 1e-9
// of the unknowns (max |x| <= 1.5 on this scene: log widths, b/a0, ln(l/l0), d/(C1 a0^2)); the
// error after it is of the order of its square plus the residual's rounding floor over the
// Jacobian's smallest singular value (1e-14 / 8e-4 at worst here), so 2e-9 relative bounds the
// difference of two solves of one root with room (measured: under 2e-13;
// benchmarks/line_seeded_sweep.cpp). Speeds from 0.1 a0 up: between 1.7e-3 and 0.07 a0 the
// square system has least-squares minima (1.7e-3 ... 3.5e-3), a fold (0.066) and two roots close
// together (0.0093, where the seeded and the cold solve differ by 17% in b(0);
// docs/line-solver.md).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>
#include <viscoroll/sweep.hpp>

#include "support/paper_scene.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_sweep_fast_seeded {

namespace {

void require_same_root(const viscoroll::LineSolverD::Solution& x,
                       const viscoroll::LineSolverD::Solution& y) {
  constexpr double tolerance = 2e-9;
  REQUIRE(x.converged);
  REQUIRE(x.root);
  REQUIRE(y.converged);
  REQUIRE(y.root);
  CHECK(std::abs(x.a(0.0) - y.a(0.0)) <= tolerance * y.a(0.0));
  CHECK(std::abs(x.b(0.0) - y.b(0.0)) <= tolerance * y.a(0.0));
  CHECK(std::abs(x.l() - y.l()) <= tolerance * y.l());
  CHECK(std::abs(x.d - y.d) <= tolerance * y.d);
  CHECK(std::abs(x.chi - y.chi) <= tolerance * std::abs(y.chi));
}

}  // namespace

TEST_CASE("sweep: fast() continuation gives the cold solves' roots", "[sweep]") {
  const viscoroll::testing::PaperScene paper;
  const viscoroll::LineSolverD solver(paper.material, viscoroll::LineOptions::fast());
  std::vector<double> speeds;  // tau = 1: V tau/a0 = speed, 0.1 ... 1000
  for (int k = 0; k < 9; ++k) speeds.push_back(std::pow(10.0, -1 + 4.0 * k / 8));
  viscoroll::SweepOptions options;
  options.chunk = speeds.size();  // one chunk: every speed but the first seeded
  options.threads = 1;
  const auto swept = viscoroll::sweep(solver, paper.scene(0), speeds, options);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    INFO("V tau/a0 = " << speeds[i]);
    require_same_root(swept[i], solver.solve(paper.scene(speeds[i])));
  }
}

}  // namespace test_sweep_fast_seeded
