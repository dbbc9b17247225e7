// Inexact early solves do not change the result: with coarse_tolerance (the default
// 1e-3) the paper's scene gives d, chi, a(0), l and the peak pressure of the iteration with every
// active set solved to the tolerance, to 1e-10 relative. Both end with a final solve of the
// converged set to final_tolerance = 1e-13 (docs/bem.md, B11); without it the two differed by up
// to 7.6e-9 (the peak pressure, N = 16, V tau/a0 = 0.1), GMRES' 1e-10 times the system's condition.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <viscoroll/bem/bem_solver.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_bem_final_solve {

namespace {

using viscoroll::BemOptions;
using viscoroll::BemScene;
using viscoroll::BemSolution;
using viscoroll::BemSolverD;
using viscoroll::StandardLinearSolid;

double peak(const BemSolution<double>& s) {
  return *std::max_element(s.pressure.begin(), s.pressure.end());
}

/// The paper's scene (f = 9, 5:1, line-contact a0 = 1, tau = 1) at V tau/a0 = `speed` on grid N,
/// solved with coarse early solves and without.
void check_coarse_equals_tight(int n, double speed) {
  const double f = 9, c = 0.5 / (2 * std::acos(-1.0));
  const BemScene<double> scene{
      .c1 = 1.0, .c2 = (std::log(20.0) - 1) / 25, .load = 5.0 / (3 * (1 + f) * c), .speed = speed};
  const StandardLinearSolid<double> sls(1.0, 0.5, f, 1.0);
  BemOptions coarse;
  coarse.grid = n;
  BemOptions tight = coarse;
  tight.coarse_tolerance = 0;
  const auto a = BemSolverD(sls, coarse).solve(scene), b = BemSolverD(sls, tight).solve(scene);
  INFO("N = " << n << ", V tau/a0 = " << speed);
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  // The same final set, in fewer GMRES steps.
  CHECK(a.contact_cells == b.contact_cells);
  for (std::size_t q = 0; q < a.pressure.size(); ++q)
    if ((a.pressure[q] > 0) != (b.pressure[q] > 0)) FAIL("cell " << q << " in one contact only");
  CHECK(a.krylov_iterations < b.krylov_iterations);
  // Measured at most 2.6e-12 (the peak pressure, N = 16, V tau/a0 = 0.1).
  CHECK(a.d == Approx(b.d).epsilon(1e-10).margin(0));
  CHECK(a.chi == Approx(b.chi).epsilon(1e-10).margin(0));
  CHECK(a.a0 == Approx(b.a0).epsilon(1e-10).margin(0));
  CHECK(a.l == Approx(b.l).epsilon(1e-10).margin(0));
  CHECK(peak(a) == Approx(peak(b)).epsilon(1e-10).margin(0));
}

}  // namespace

TEST_CASE("bem: coarse early solves give the tight iteration's result to 1e-10, N = 16", "[bem]") {
  for (const double speed : {0.1, 1.0, 10.0}) check_coarse_equals_tight(16, speed);
}

TEST_CASE("bem: coarse early solves give the tight iteration's result to 1e-10, N = 32",
          "[bem][slow]") {
  for (const double speed : {0.1, 1.0, 10.0}) check_coarse_equals_tight(32, speed);
}

}  // namespace test_bem_final_solve
