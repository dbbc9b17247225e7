// The plane solver on a layer (PlaneSubstrateSolver, docs/plane-substrate.md) against the exact
// 3-D boundary-element solver on the same layer (docs/bem.md B15-B19) under a very long roller,
// whose row y = 0 is the plane problem at the row's load: two independent discretisations of the
// layer's kernel (a wavenumber integral against a Hankel transform and its cell integrals).
#include <catch2/catch.hpp>
#include <cmath>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/plane/plane_substrate_solver.hpp>

#include "support/centre_row.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_substrate_bem {

namespace {

/// C2/C1 = 1e-4 (l/a about 240): the 3-D corrections at y = 0 are far below the BEM's
/// discretisation error at N = 16, which bounds the comparison as for the half space
/// (plane_spectrum_bem.test.cpp): the edges to 0.3 hx where the pressure ends as a square root
/// (B12's sub-cell model), `edge` hx otherwise, the row's chi to 1.5%; d, the row's approach from
/// the base, to 1e-3 (the BEM's d converges as the cell squared: docs/bem.md B13; measured
/// 2e-5 ... 3.4e-4).
template <class Body>
void check_long_roller(const Body& body, double speed, double edge) {
  const viscoroll::StandardLinearSolid<double> m(1.0, 0.45, 3.0, 1.0);
  viscoroll::BemOptions options;
  options.grid = 16;
  const viscoroll::BemSolver<double, viscoroll::StandardLinearSolid<double>> bem(m, options, body);
  const auto s =
      bem.solve(viscoroll::BemScene<double>{.c1 = 1.0, .c2 = 1e-4, .load = 1.0, .speed = speed});
  REQUIRE(s.converged);
  const auto [w, moment] = viscoroll::testing::centre_row(s);
  viscoroll::PlaneSubstrateOptions po;
  po.tolerance = 1e-6;
  const auto p = viscoroll::PlaneSubstrateSolver(m, body, po)
                     .solve(viscoroll::PlaneScene<double>{.c1 = 1.0, .load = w, .speed = speed});
  INFO("speed = " << speed << ", a = " << p.a << ", hx = " << s.grid.hx << ", d = " << p.d << " / "
                  << s.d << ", chi = " << p.chi << " / " << moment / w);
  REQUIRE(p.converged);
  CHECK(std::abs(s.a0 - p.a) <= edge * s.grid.hx);
  CHECK(std::abs(s.b0 - p.b) <= edge * s.grid.hx);
  CHECK(moment / w == Approx(p.chi).epsilon(0.015).margin(1e-12));
  CHECK(std::abs(s.d / p.d - 1) <= 1e-3);
}

}  // namespace

TEST_CASE("plane substrate: a very long BEM roller on a bonded layer at y = 0", "[plane][bem]") {
  for (const double speed : {0.1, 1.0, 10.0})
    check_long_roller(viscoroll::Layer<double>(0.5), speed, 0.3);
}

TEST_CASE("plane substrate: a very long BEM roller on the spring bed at y = 0", "[plane][bem]") {
  // The bed's pressure ends linearly (p is the local gap over the bed's compliance), not as the
  // square root B12 locates to a fraction of a cell: its edges are located within half a cell
  // (measured 0.31 and 0.40 hx).
  for (const double speed : {0.1, 1.0, 10.0})
    check_long_roller(viscoroll::SpringBed<double>(0.5), speed, 0.5);
}

}  // namespace test_plane_substrate_bem
