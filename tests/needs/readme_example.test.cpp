// The README's code, as printed there: the one-scene example and the solver family's three
// declarations, each compiled and run. If the README changes, this file changes with it, so
// clang-format leaves it as printed.
// clang-format off
#include <catch2/catch.hpp>

#include <cstdio>
#include <type_traits>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/material/generalized_maxwell.hpp>
#include <viscoroll/viscoroll.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_readme_example {

TEST_CASE("readme: the example solves its scene", "[needs][line]") {
  // mu_D = 1 MPa, nu = 0.5, f = 9, tau = 10 ms; C1 = 1/R = 100/m, C2/C1 of a 5:1 contact; 10 N at 0.5 m/s
  const viscoroll::LineSolverD solver(viscoroll::StandardLinearSolid<double>(1e6, 0.5, 9.0, 0.01));
  const double load = 10.0, speed = 0.5;
  const auto s = solver.solve({.c1 = 100.0, .c2 = 7.98, .load = load, .speed = speed});
  std::printf("chi = %.4g, F = chi W = %.4g N, P = F V = %.4g W\n", s.chi, s.chi * load,
              s.chi * load * speed);  // chi = 0.1525, F = chi W = 1.525 N, P = F V = 0.7624 W
  CHECK(s.converged);
  CHECK(s.root);
  CHECK(s.l() > s.a(0.0));
  // The printed numbers, to their 4 digits (half a unit of the 4th: 5e-4 relatively).
  CHECK(s.chi == Approx(0.1525).epsilon(5e-4));
  CHECK(s.chi * load == Approx(1.525).epsilon(5e-4));
  CHECK(s.chi * load * speed == Approx(0.7624).epsilon(5e-4));
}

TEST_CASE("readme: the solver family's declarations", "[needs][bem]") {
  viscoroll::LineSolver<long double, viscoroll::Elastic<long double>, viscoroll::GaussLegendre<long double, 16>> fine(
      viscoroll::Elastic<long double>(1e6L, 0.3L));
  viscoroll::PlaneSolver plane(viscoroll::StandardLinearSolid<float>(1e6f, 0.5f, 9.0f, 0.01f));  // <float, ...>
  viscoroll::BemSolver rubber(viscoroll::GeneralizedMaxwell<double>(1e6, 0.5, {{4.0, 1e-3}, {5.0, 1e-1}}));

  STATIC_REQUIRE(std::is_same_v<decltype(plane),
                                viscoroll::PlaneSolver<float, viscoroll::StandardLinearSolid<float>>>);
  STATIC_REQUIRE(std::is_same_v<decltype(rubber),
                                viscoroll::BemSolver<double, viscoroll::GeneralizedMaxwell<double>>>);
  // Each solves a scene of its kind: an elastic line contact is Kalker's closed form; the float
  // plane rolls at V tau = a0 (load chosen so that a0 = 1 mm at C1 = 100/m); the Prony BEM on a
  // coarse grid.
  const auto e = fine.solve({.c1 = 100.0L, .c2 = 7.98L, .load = 10.0L, .speed = 1.0L});
  CHECK(e.converged);
  CHECK(e.l() > e.a(0.0L));
  const float c = plane.material().instantaneous_compliance();
  const auto p = plane.solve({.c1 = 100.0f, .load = 100.0f * 1e-6f / (4 * c * 10.0f), .speed = 0.1f});
  CHECK(p.converged);
  CHECK(p.chi > 0);
  const auto b = viscoroll::BemSolver(rubber.material(), viscoroll::BemOptions{.grid = 8})
                     .solve({.c1 = 100.0, .c2 = 7.98, .load = 10.0, .speed = 1.0});
  CHECK(b.converged);
  CHECK(b.chi > 0);
}

}  // namespace test_readme_example
// clang-format on
