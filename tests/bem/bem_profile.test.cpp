// The BEM for any roller profile (bem_profile.hpp, docs/bem.md B14) and the contact
// along the roller (BemSolution::along_roller): the ellipsoid's scene is the ellipsoid's; Hertz's
// F0(y) and ends; a tilt mirrors and shifts the contact towards the side pressed harder; a barrel
// (L_f = 0) is the ellipsoid C2 = 1/R_c to O((l/R_c)^2); a long flat part carries the plane
// solution at its local load per length.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <viscoroll/bem/bem_profile.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/plane/plane_solver.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_bem_profile {

namespace {

using viscoroll::BemOptions;
using viscoroll::BemScene;
using viscoroll::BemSolverD;
using viscoroll::CrownedCylinder;
using viscoroll::EllipsoidProfile;
using viscoroll::StandardLinearSolid;
using viscoroll::Tilted;

// f = 9, mu_D = 1, nu = 0.5, tau = 1: the long-term compliance is 10 c, c = 1/(4 pi).
const StandardLinearSolid<double> rubber(1.0, 0.5, 9.0, 1.0);

BemOptions grid(int n) {
  BemOptions o;
  o.grid = n;
  return o;
}

}  // namespace

TEST_CASE("bem profile: the ellipsoid's scene and solution are the ellipsoid's", "[bem]") {
  const double c1 = 1.0, c2 = 0.0798, load = 10.0, speed = 1.0;
  const auto scene = viscoroll::bem_scene(EllipsoidProfile<double>(c1, c2), rubber, load, speed);
  CHECK(scene.c1 == c1);
  CHECK(scene.c2 == c2);
  const BemSolverD solver(rubber, grid(8));
  const auto a = solver.solve(scene);
  const auto b = solver.solve(BemScene<double>{.c1 = c1, .c2 = c2, .load = load, .speed = speed});
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  // The same gap to the last bit (c1 x^2/2 + c2 y^2/2 either way), the same grid: the same
  // iteration.
  CHECK(a.grid.hx == b.grid.hx);
  CHECK(a.grid.hy == b.grid.hy);
  CHECK(a.d == b.d);
  CHECK(a.chi == b.chi);
  CHECK(a.a0 == b.a0);
}

TEST_CASE("bem profile: along the roller, Hertz's F0(y) = (pi/2) p0 a (1 - y^2/b^2) and its ends",
          "[bem]") {
  // V tau = 0: the long-term Hertz contact (B8). On grid N the row loads are the midpoint rule of
  // a square-root profile: F0 to O(h^(3/2)) relative at the rows inside, measured 0.4% at N = 16.
  const double c1 = 1.0, c2 = 0.25, load = 2.0;
  const BemSolverD solver(rubber, grid(16));
  const BemScene<double> scene{.c1 = c1, .c2 = c2, .load = load, .speed = 0.0};
  const auto s = solver.solve(scene);
  REQUIRE(s.converged);
  const auto h = s.long_term;
  const auto along = s.along_roller();
  REQUIRE(along.y.size() >= 25);
  const double pi = std::acos(-1.0);
  double total = 0;
  for (std::size_t k = 0; k < along.y.size(); ++k) {
    total += along.f0[k] * s.grid.hy;
    const double t = along.y[k] / h.b;
    if (std::abs(t) > 0.8) continue;
    INFO("y = " << along.y[k]);
    CHECK(along.f0[k] == Approx(pi / 2 * h.p0 * h.a * (1 - t * t)).epsilon(0.01));
    CHECK(along.a[k] == Approx(h.a * std::sqrt(1 - t * t)).epsilon(0.02));
    CHECK(std::abs(along.b[k]) < 1e-12 * h.a);
    CHECK(along.p_max[k] <= h.p0 * 1.02);
  }
  // The load is the sum of the rows' loads; the ends within a row of Hertz's b; F0 peaks on y = 0.
  CHECK(total == Approx(load).epsilon(1e-12));
  CHECK(along.y_plus == Approx(h.b).margin(s.grid.hy));
  CHECK(along.y_minus == Approx(-h.b).margin(s.grid.hy));
  CHECK(along.f0_max_y == 0.0);
}

TEST_CASE("bem profile: a tilt mirrors with theta -> -theta and shifts the contact to y < 0",
          "[bem]") {
  const CrownedCylinder<double> roller(1.0, 6.0, 10.0);
  const double load = 20.0, speed = 0.5, theta = 1e-2;
  const BemSolverD solver(rubber, grid(6));
  const auto sp = solver.solve(viscoroll::bem_scene(Tilted(roller, theta), rubber, load, speed));
  const auto sm = solver.solve(viscoroll::bem_scene(Tilted(roller, -theta), rubber, load, speed));
  REQUIRE(sp.converged);
  REQUIRE(sm.converged);
  REQUIRE(sp.grid.ny == sm.grid.ny);
  REQUIRE(sp.grid.hy == sm.grid.hy);
  const auto p = sp.along_roller(), m = sm.along_roller();
  REQUIRE(p.f0.size() == m.f0.size());
  // The grid is symmetric in y, the scenes mirror images: the solutions mirror to GMRES' final
  // tolerance (1e-13) times the system's condition.
  const std::size_t n = p.f0.size();
  for (std::size_t k = 0; k < n; ++k) {
    CHECK(p.y[k] == -m.y[n - 1 - k]);
    CHECK(p.f0[k] == Approx(m.f0[n - 1 - k]).epsilon(1e-9).margin(1e-9 * p.f0_max));
  }
  CHECK(p.y_minus == Approx(-m.y_plus).epsilon(1e-9));
  CHECK(sp.chi == Approx(sm.chi).epsilon(1e-9));
  CHECK(sp.d == Approx(sm.d).epsilon(1e-9));
  // theta > 0 lowers h on y < 0: more load there, the peak and the centroid on that side.
  double moment = 0, total = 0;
  for (std::size_t k = 0; k < n; ++k) {
    moment += p.y[k] * p.f0[k];
    total += p.f0[k];
  }
  CHECK(moment / total < 0);  // measured -0.13 for a contact 22 long
  CHECK(p.f0_max_y < 0);
  CHECK(-p.y_minus > p.y_plus);
}

TEST_CASE("bem profile: a barrel (L_f = 0) is the ellipsoid C2 = 1/R_c to O((l/R_c)^2)", "[bem]") {
  // h = y^2/(2 R_c) (1 + y^2/(4 R_c^2) + ...): on the same grid the two gaps differ by at most
  // l^2/(4 R_c^2) of the drop, l the contact's half length, and so do d, chi, a(0).
  const double rc = 400.0, load = 5.0, speed = 1.0;
  const BemSolverD solver(rubber, grid(8));
  auto barrel = viscoroll::bem_scene(CrownedCylinder<double>(1.0, 0.0, rc), rubber, load, speed);
  const BemScene<double> ellipsoid{.c1 = 1.0, .c2 = 1 / rc, .load = load, .speed = speed};
  // bem_scene's grid is (B14)'s, sized by the secant curvature, a little above 1/R_c.
  CHECK(barrel.c2 > 1 / rc);
  CHECK(barrel.c2 < 1 / rc * 1.01);
  const auto own = solver.solve(barrel);
  barrel.c2 = 1 / rc;  // the ellipsoid's grid
  const auto a = solver.solve(barrel), b = solver.solve(ellipsoid);
  REQUIRE(own.converged);
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  const double bound = b.l * b.l / (4 * rc * rc);
  INFO("l/R_c = " << b.l / rc << ", bound " << bound);
  CHECK(bound < 1e-3);
  CHECK(a.d == Approx(b.d).epsilon(bound));
  CHECK(a.chi == Approx(b.chi).epsilon(bound));
  CHECK(a.a0 == Approx(b.a0).epsilon(bound));
  // On its own (B14) grid, within the grid's discretisation error at N = 8 (docs/bem.md, B13:
  // d 0.3%, chi 2%).
  CHECK(own.d == Approx(b.d).epsilon(0.003));
  CHECK(own.chi == Approx(b.chi).epsilon(0.02));
}

TEST_CASE("bem profile: away from a long flat part's ends, the plane solution at the local load",
          "[bem]") {
  // A flat part 16 times the contact's width: on y = 0 the contact is the plane one (Hunter) of
  // load per length F0(0), to the grid's error in a and b (B12: about a cell, hx = a/8 here) and
  // the end effects, which decay over a few widths.
  const CrownedCylinder<double> roller(1.0, 12.0, 20.0);
  const double load = 10.0, speed = 1.0;
  const BemSolverD solver(rubber, grid(8));
  const auto s = solver.solve(viscoroll::bem_scene(roller, rubber, load, speed));
  REQUIRE(s.converged);
  const auto along = s.along_roller();
  const auto centre = std::find(along.y.begin(), along.y.end(), 0.0) - along.y.begin();
  REQUIRE(static_cast<std::size_t>(centre) < along.y.size());
  const double f0 = along.f0[static_cast<std::size_t>(centre)];
  const auto plane = viscoroll::PlaneSolverD(rubber).solve({.c1 = 1.0, .load = f0, .speed = speed});
  REQUIRE(plane.converged);
  INFO("a: bem " << along.a[static_cast<std::size_t>(centre)] << ", plane " << plane.a);
  CHECK(along.y_plus - along.y_minus > 12 * plane.a);
  CHECK(along.a[static_cast<std::size_t>(centre)] == Approx(plane.a).margin(s.grid.hx));
  CHECK(along.b[static_cast<std::size_t>(centre)] == Approx(plane.b).margin(s.grid.hx));
  // The crowned ends carry less than the flat middle only beyond the flat part: F0 is nearly
  // uniform over the middle half of the flat part (within 2%).
  for (std::size_t k = 0; k < along.y.size(); ++k)
    if (std::abs(along.y[k]) < 3.0) CHECK(along.f0[k] == Approx(f0).epsilon(0.02));
}

TEST_CASE("bem profile: a contact that reaches the roller's end is reported", "[bem]") {
  // A cylinder of length 6.2 whose flat part (6) ends in crowns of radius 0.5, cut at |y| = 3.1
  // where they have dropped by 0.01, against a line-contact penetration of about 0.3 (a(0) = 0.14):
  // the contact reaches the end cells.
  const CrownedCylinder<double> roller(1.0, 6.0, 0.5, 6.2);
  const BemSolverD solver(rubber, grid(8));
  const auto s = solver.solve(viscoroll::bem_scene(roller, rubber, 0.3, 1.0));
  REQUIRE(s.converged);
  REQUIRE(!s.warnings.empty());
  REQUIRE(s.warning_codes.size() == s.warnings.size());
  CHECK(s.warning_codes.front() == viscoroll::WarningCode::contact_at_roller_end);
}

TEST_CASE("bem profile: invalid input names the parameter", "[bem]") {
  const EllipsoidProfile<double> e(1.0, 0.1);
  CHECK_THROWS_WITH(viscoroll::bem_scene(e, rubber, -1.0, 1.0), Catch::Contains("load"));
  CHECK_THROWS_WITH(viscoroll::bem_scene(e, rubber, 1.0, -1.0), Catch::Contains("speed"));
  BemScene<double> s{.c1 = 1.0, .c2 = 0.1, .load = 1.0, .speed = 1.0};
  s.y_max = -1.0;
  CHECK_THROWS_WITH(s.validate(), Catch::Contains("y_max"));
}

}  // namespace test_bem_profile
