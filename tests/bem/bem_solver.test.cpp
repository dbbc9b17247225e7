// Tests of the boundary-element solver (docs/bem.md): exact Hertz contact at V tau = 0 (long-term
// compliance) and V tau -> inf (instantaneous compliance) with the error falling under refinement,
// the plane solver for a very long roller, the line solver for the paper's scene, the Prony
// material, the scalar types, diagnostics and validation.
//
// Discretisation error (docs/bem.md, B13): with N cells per semi-axis the contact edge is located
// to a fraction of a cell, |a0 - a_H| <= hx/4, and the penetration converges as (h/a)^2,
// |d - d_H| / d_H <= (h/a)^2 / 5, h/a the cell size over the semi-axis actually in contact.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/generalized_maxwell.hpp>
#include <viscoroll/plane/plane_solver.hpp>

#include "support/centre_row.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_bem_solver {

namespace {

using viscoroll::BemOptions;
using viscoroll::BemScene;
using viscoroll::BemSolver;
using viscoroll::BemSolverD;
using viscoroll::StandardLinearSolid;
using viscoroll::bem::hertz_contact;

constexpr double f = 9, nu = 0.5, mu = 1;
const double pi = std::acos(-1.0);
const double c = (1 - nu) / (2 * pi * mu);
/// The paper's scene (examples/panek_kalker.cpp): line-contact a0 = 1, l0 = 5.
const double c2_paper = (std::log(20.0) - 1) / 25;
const double load_paper = 5.0 / (3 * (1 + f) * c);

BemSolverD solver(int n, double tau = 1.0) {
  BemOptions o;
  o.grid = n;
  return BemSolverD(StandardLinearSolid<double>(mu, nu, f, tau), o);
}

struct Errors {
  double a, l, d;
};

Errors hertz_errors(const viscoroll::BemSolution<double>& s,
                    const viscoroll::bem::HertzContact<double>& h) {
  return {std::abs(s.a0 - h.a), std::abs(s.l - h.b), std::abs(s.d - h.d) / h.d};
}

}  // namespace

TEST_CASE("bem: V tau = 0 against Hertz with the long-term compliance", "[bem]") {
  for (const double c2 : {1.0, c2_paper}) {
    const BemScene<double> scene{1.0, c2, 1.0, 0.0};
    const auto h = hertz_contact(1.0, c2, (1 + f) * c, 1.0);
    Errors previous{1e300, 1e300, 1e300};
    for (int n : {4, 8, 16}) {
      const auto s = solver(n).solve(scene);
      INFO("c2 = " << c2 << ", N = " << n);
      REQUIRE(s.converged);
      const auto e = hertz_errors(s, h);
      const double ha = s.grid.hx / h.a;
      CHECK(e.a <= s.grid.hx / 4);
      CHECK(e.l <= s.grid.hy / 4);
      CHECK(e.d <= ha * ha / 5);
      CHECK(s.b0 == Approx(0).margin(1e-12));
      CHECK(std::abs(s.chi) <= 1e-12);
      CHECK(s.load == Approx(1.0).epsilon(1e-9));
      // Refinement trend: the edges are O(h); d falls (for the circle, monotonically).
      CHECK(e.a < previous.a);
      CHECK(e.l < previous.l);
      if (c2 == 1.0) CHECK(e.d < previous.d);
      previous = e;
    }
  }
}

TEST_CASE("bem: V tau -> inf against Hertz with the instantaneous compliance", "[bem]") {
  const BemScene<double> scene{1.0, 1.0, 1.0, 1e12};
  const auto h = hertz_contact(1.0, 1.0, c, 1.0);
  double previous = 1e300;
  for (int n : {8, 16}) {
    const auto s = solver(n).solve(scene);
    INFO("N = " << n);
    REQUIRE(s.converged);
    const auto e = hertz_errors(s, h);
    const double ha = s.grid.hx / h.a;  // the glassy contact has (1+f)^(-1/3) N cells per semi-axis
    CHECK(e.a <= s.grid.hx / 4);
    CHECK(e.d <= ha * ha / 5);
    CHECK(e.d < previous);
    previous = e.d;
  }
}

TEST_CASE("bem: an elastic half space is Hertz", "[bem]") {
  BemOptions o;
  o.grid = 8;
  const BemSolver<double, viscoroll::Elastic<double>> s(viscoroll::Elastic<double>(1.0, 0.3), o);
  const auto sol = s.solve(BemScene<double>{1.0, 0.5, 2.0, 3.0});
  const auto h = hertz_contact(
      1.0, 0.5, viscoroll::Elastic<double>(1.0, 0.3).instantaneous_compliance(), 2.0);
  REQUIRE(sol.converged);
  const double ha = sol.grid.hx / h.a;
  CHECK(std::abs(sol.d - h.d) / h.d <= ha * ha / 5);
  CHECK(std::abs(sol.chi) <= 1e-12);
}

TEST_CASE("bem: a very long roller at y = 0 is the plane problem at the local load", "[bem]") {
  // C2/C1 = 1e-4: l/a ~ 240 static, so the 3-D corrections at y = 0 are O((a/l)^2 ln) ~ 1e-4,
  // below the discretisation error (edges to hx/4, the row's first moment to 1%).
  const BemScene<double> base{1.0, 1e-4, 1.0, 0.0};
  for (const double speed : {0.0, 1.0}) {
    BemScene<double> scene = base;
    scene.speed = speed;
    const auto s = solver(8, 0.3).solve(scene);
    REQUIRE(s.converged);
    const auto [w, moment] = viscoroll::testing::centre_row(s);
    const viscoroll::PlaneSolverD plane(StandardLinearSolid<double>(mu, nu, f, 0.3));
    const auto p = plane.solve(viscoroll::PlaneScene<double>{1.0, w, speed});
    INFO("V tau = " << 0.3 * speed);
    CHECK(std::abs(s.a0 - p.a) <= s.grid.hx / 4);
    CHECK(std::abs(s.b0 - p.b) <= s.grid.hx / 4);
    CHECK(moment / w == Approx(p.chi).epsilon(0.01).margin(1e-12));
  }
}

TEST_CASE("bem: rolling contact of the paper's scene (V tau / a0 = 1)", "[bem]") {
  const auto s = solver(8).solve(BemScene<double>{1.0, c2_paper, load_paper, 1.0});
  REQUIRE(s.converged);
  const auto slow = hertz_contact(1.0, c2_paper, (1 + f) * c, load_paper);
  const auto fast = hertz_contact(1.0, c2_paper, c, load_paper);
  // Between the glassy and the long-term contact; shifted forward; positive rolling friction.
  CHECK(s.d < slow.d);
  CHECK(s.d > fast.d);
  CHECK(s.a0 < slow.a);
  CHECK(s.a0 > fast.a);
  CHECK(s.b0 > 0);
  CHECK(s.chi > 0);
  CHECK(s.load == Approx(load_paper).epsilon(1e-9));
  CHECK(s.residual <= 1e-8);
  for (std::size_t q = 0; q < s.pressure.size(); ++q) {
    CHECK(s.pressure[q] >= 0);
    CHECK(s.gap[q] >= -1e-8 * slow.d);
  }
}

TEST_CASE("bem: agreement with the line solver within the line theory's error", "[bem][slow]") {
  // Line-contact theory is asymptotic in a/l; for the 5:1 scene its static error is a few %
  // (Hertz: l/a = 5.18, d differs by 0.2%); the BEM at N = 16 is converged to < 1% in a0, b0, l
  // and to 0.1% in d and chi (docs/bem.md, table).
  const viscoroll::LineSolverD line(StandardLinearSolid<double>(mu, nu, f, 1.0));
  const auto ls = line.solve(viscoroll::LineScene<double>{1.0, c2_paper, load_paper, 1.0});
  REQUIRE(ls.converged);
  const auto s = solver(16).solve(BemScene<double>{1.0, c2_paper, load_paper, 1.0});
  REQUIRE(s.converged);
  CHECK(s.a0 == Approx(ls.a(0.0)).epsilon(0.05));
  CHECK(s.b0 == Approx(ls.b(0.0)).epsilon(0.05));
  CHECK(s.l == Approx(ls.l()).epsilon(0.05));
  CHECK(s.d == Approx(ls.d).epsilon(0.02));
  CHECK(s.chi == Approx(ls.chi).epsilon(0.03));
}

TEST_CASE("bem: the Prony-series material", "[bem]") {
  BemOptions o;
  o.grid = 6;
  const BemScene<double> scene{1.0, c2_paper, load_paper, 1.0};
  const auto sls = BemSolverD(StandardLinearSolid<double>(mu, nu, f, 1.0), o).solve(scene);
  using GM = viscoroll::GeneralizedMaxwell<double>;
  const auto one = BemSolver<double, GM>(GM(mu, nu, {{f, 1.0}}), o).solve(scene);
  REQUIRE(one.converged);
  CHECK(one.d == sls.d);
  CHECK(one.chi == sls.chi);
  // Two retardation times: the long-term Hertz contact is that of 1 + f1 + f2; the rolling one
  // lies between the rolling contacts of each time alone.
  const auto two = BemSolver<double, GM>(GM(mu, nu, {{4.5, 0.2}, {4.5, 5.0}}), o).solve(scene);
  const auto short_time = BemSolverD(StandardLinearSolid<double>(mu, nu, f, 0.2), o).solve(scene);
  const auto long_time = BemSolverD(StandardLinearSolid<double>(mu, nu, f, 5.0), o).solve(scene);
  REQUIRE(two.converged);
  CHECK(two.d < short_time.d);
  CHECK(two.d > long_time.d);
}

TEMPLATE_TEST_CASE("bem: float, double and long double agree", "[bem]", float, long double) {
  using Real = TestType;
  BemOptions o;
  o.grid = 4;
  const auto ref = solver(4).solve(BemScene<double>{1.0, c2_paper, load_paper, 1.0});
  const BemSolver<Real, StandardLinearSolid<Real>> s(
      StandardLinearSolid<Real>(Real(mu), Real(nu), Real(f), Real(1)), o);
  const auto sol = s.solve(BemScene<Real>{Real(1), Real(c2_paper), Real(load_paper), Real(1)});
  REQUIRE(sol.converged);
  REQUIRE(sol.contact_cells == ref.contact_cells);
  // Rounding of the coefficients and of GMRES (tolerance 32 eps) amplified by the condition
  // number of the active-set system (~1e2 on this grid).
  const double tol =
      std::max(1e-9, 1e4 * static_cast<double>(std::numeric_limits<Real>::epsilon()));
  CHECK(static_cast<double>(sol.d) == Approx(ref.d).epsilon(tol));
  CHECK(static_cast<double>(sol.chi) == Approx(ref.chi).epsilon(tol));
}

TEST_CASE("bem: non-convergence is reported, inputs are validated", "[bem]") {
  BemOptions o;
  o.grid = 8;
  o.max_active_set_iterations = 1;
  const auto s = BemSolverD(StandardLinearSolid<double>(mu, nu, f, 1.0), o)
                     .solve(BemScene<double>{1.0, c2_paper, load_paper, 1.0});
  CHECK_FALSE(s.converged);
  CHECK(s.code == viscoroll::StopCode::iteration_limit);
  BemOptions bad;
  bad.grid = 1;
  CHECK_THROWS_WITH(BemSolverD(StandardLinearSolid<double>(mu, nu, f, 1.0), bad),
                    Catch::Contains("grid = 1"));
  // The grid's memory is bounded: (2 ceil(1.6 x 640) + 1)^2 = 4198401 > 2^22 cells at N = 640,
  // 4190209 at N = 639.
  bad = BemOptions{};
  bad.grid = 640;
  CHECK_THROWS_WITH(BemSolverD(StandardLinearSolid<double>(mu, nu, f, 1.0), bad),
                    Catch::Contains("grid = 640") && Catch::Contains("4198401 cells"));
  bad.grid = 639;
  CHECK_NOTHROW(bad.validate());
  bad.grid = 320;
  bad.extent = 3.3;  // (2 x 1056 + 1)^2 = 4464769
  CHECK_THROWS_WITH(bad.validate(),
                    Catch::Contains("grid = 320") && Catch::Contains("4464769 cells"));
  bad = BemOptions{};
  bad.extent = 1.2;
  CHECK_THROWS_WITH(BemSolverD(StandardLinearSolid<double>(mu, nu, f, 1.0), bad),
                    Catch::Contains("extent = 1.2"));
  const auto ok = solver(4);
  CHECK_THROWS_WITH(ok.solve(BemScene<double>{1.0, 0.0, 1.0, 1.0}), Catch::Contains("c2 = 0"));
  CHECK_THROWS_WITH(ok.solve(BemScene<double>{1.0, 1.0, 1.0, -1.0}), Catch::Contains("speed = -1"));
  CHECK_THROWS_WITH(ok.solve(BemScene<double>{1.0, 1.0, -2.0, 1.0}), Catch::Contains("load = -2"));
}

TEST_CASE("bem: a user profile replaces the doubly parabolic one", "[bem]") {
  // The same parabola given as a callable, shifted by a constant (absorbed into d).
  BemScene<double> scene{1.0, 0.5, 1.0, 0.5};
  const auto plain = solver(6).solve(scene);
  scene.profile = [](double x, double y) { return x * x / 2 + 0.25 * y * y + 0.125; };
  const auto shifted = solver(6).solve(scene);
  REQUIRE(shifted.converged);
  CHECK(shifted.d == Approx(plain.d + 0.125).epsilon(1e-9));
  CHECK(shifted.chi == Approx(plain.chi).epsilon(1e-9));
}

TEST_CASE("bem: converges at every V tau from 0 to 1e12, d falling with speed", "[bem]") {
  // The memory coefficient (B4)-(B5) covers L from 0 to any finite length; the active-set
  // iteration must converge throughout, and d must fall monotonically from the long-term to
  // the instantaneous Hertz value (the compliance that acts only decreases with speed).
  const auto s = solver(6);
  const BemScene<double> scene{1.0, c2_paper, load_paper, 0.0};
  const auto slow = hertz_contact(1.0, c2_paper, (1 + f) * c, load_paper);
  const auto fast = hertz_contact(1.0, c2_paper, c, load_paper);
  double previous = 2 * slow.d;
  for (const double speed : {0.0, 1e-9, 1e-3, 0.1, 1.0, 10.0, 1e3, 1e6, 1e12, 1e30}) {
    BemScene<double> at = scene;
    at.speed = speed;
    const auto sol = s.solve(at);
    INFO("V tau = " << speed);
    REQUIRE(sol.converged);
    CHECK(sol.d <= previous * (1 + 1e-8));  // the solve's tolerance is 1e-10 of d
    previous = sol.d;
  }
  // The discretised limits are within the N = 6 discretisation error of Hertz ((h/a)^2 / 5 with
  // the glassy contact's 0.46 N cells per semi-axis).
  const double ha = 1.0 / (6 * std::cbrt(1 + f));
  CHECK(std::abs(previous - fast.d) / fast.d <= ha * ha / 5);
}

TEST_CASE("bem: a glassy memory term is dropped, also when V tau overflows to +inf", "[bem]") {
  // BemSolver::effective_terms: f (R/L)(ln(L/R) + 1) <= eps drops the term (R the grid's
  // diagonal, L = V tau). V tau = 1e300 x 1e300 = +inf once hung the memory recurrence; it and
  // V tau = 1e30 (dropped as well) must give the same operator on the same grid (sized by the
  // long-term contact), hence the same solution, bit for bit.
  const BemScene<double> scene{1.0, c2_paper, load_paper, 1e30};
  BemScene<double> inf_scene = scene;
  inf_scene.speed = 1e300;
  const auto finite = solver(6).solve(scene);
  const auto infinite = solver(6, 1e300).solve(inf_scene);
  REQUIRE(std::isinf(inf_scene.speed * 1e300));
  REQUIRE(finite.converged);
  REQUIRE(infinite.converged);
  CHECK(infinite.d == finite.d);
  CHECK(infinite.a0 == finite.a0);
  CHECK(infinite.chi == finite.chi);
  // Both are the glassy contact: chi = 0 to the solve's tolerance, d = Hertz with the
  // instantaneous compliance within the N = 6 discretisation error (previous test).
  const auto fast = hertz_contact(1.0, c2_paper, c, load_paper);
  const double ha = 1.0 / (6 * std::cbrt(1 + f));
  CHECK(std::abs(infinite.d - fast.d) / fast.d <= ha * ha / 5);
  CHECK(std::abs(infinite.chi) <= 1e-9);
}

}  // namespace test_bem_solver
