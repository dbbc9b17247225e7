// The plane solver for a spectrum (docs/theory.md, section 12) against the exact 3-D boundary
// element solver on a very long roller, whose row y = 0 is the plane problem at the local load
// (as `bem: a very long roller at y = 0 is the plane problem at the local load` for the standard
// linear solid): two terms and twenty terms, from the slow to the fast limit.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/plane/plane_solver.hpp>

#include "support/centre_row.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_spectrum_bem {

namespace {

using viscoroll::PronyCreep;
using viscoroll::PronyTerm;

/// C2/C1 = 1e-4: l/a ~ 240, so the 3-D corrections at y = 0 are O((a/l)^2 ln) ~ 1e-4, below the
/// BEM's discretisation error at N = 16, which bounds the comparison: the edges a fraction of a
/// cell (hx/4 for Hertz, docs/bem.md B13; measured up to 0.25 hx for these rolling contacts over
/// N = 8 ... 32, so 0.3 hx) and the row's chi to 1.5% (measured 0.1 ... 1.25% at N = 16, falling
/// to 0.04 ... 1.0% at N = 32: docs/validation.md, "Plane solver for a spectrum", `plane_vs_bem_spectrum`).
void check_long_roller(const PronyCreep<double>& m, double speed) {
  viscoroll::BemOptions options;
  options.grid = 16;
  const viscoroll::BemSolver bem(m, options);
  const auto s =
      bem.solve(viscoroll::BemScene<double>{.c1 = 1.0, .c2 = 1e-4, .load = 1.0, .speed = speed});
  REQUIRE(s.converged);
  const auto [w, moment] = viscoroll::testing::centre_row(s);
  const auto p = viscoroll::PlaneSolver(m).solve({.c1 = 1.0, .load = w, .speed = speed});
  INFO("terms = " << m.memory_terms().size() << ", speed = " << speed << ", a = " << p.a
                  << ", hx = " << s.grid.hx);
  REQUIRE(p.converged);
  CHECK(std::abs(s.a0 - p.a) <= 0.3 * s.grid.hx);
  CHECK(std::abs(s.b0 - p.b) <= 0.3 * s.grid.hx);
  CHECK(moment / w == Approx(p.chi).epsilon(0.015).margin(1e-12));
}

}  // namespace

TEST_CASE("plane spectrum: a very long BEM roller at y = 0, two terms", "[plane][spectrum][bem]") {
  const PronyCreep<double> m(1.0, 0.5, {{3.0, 0.05}, {6.0, 5.0}});
  for (double speed : {0.0, 0.3, 3.0, 30.0}) check_long_roller(m, speed);
}

TEST_CASE("plane spectrum: a very long BEM roller at y = 0, twenty terms",
          "[plane][spectrum][bem][slow]") {
  std::vector<PronyTerm<double>> terms;
  for (int k = 0; k < 20; ++k) terms.push_back({0.5, std::pow(10.0, -3 + 6.0 * k / 19)});
  const PronyCreep<double> m(1.0, 0.5, terms);
  for (double speed : {0.03, 3.0, 30.0}) check_long_roller(m, speed);
}

}  // namespace test_plane_spectrum_bem
