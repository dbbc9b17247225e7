// A roller profile written outside the library, run through every solver that takes a profile
// (the RollerProfile seam, roller/profile.hpp): the line solver's profile path (line_profile.hpp,
// docs/theory.md section 16) and the BEM's (bem_profile.hpp, docs/bem.md (B14)).
//
// Two profiles, each written here and nowhere in the library:
//  - CrownByAngle, the library's CrownedCylinder (a flat part and circular crowns) by another
//    formula: at the angle theta = asin(s / R_c) round the crown circle, s = |y| - L_f/2,
//      h = R_c (1 - cos theta) = 2 R_c sin^2(theta / 2),  h' = sign(y) tan theta,         (U2)
//    where the library evaluates s^2 / (R_c + sqrt(R_c^2 - s^2)) and s / sqrt(R_c^2 - s^2): the
//    same h to a few ulps, so every answer must be the library profile's to the solvers' own
//    iteration tolerances;
//  - QuarticCrown, h = C2 y^2/2 (1 + y^2 / Y^2) (U3), a physically different roller whose answers
//    must differ from the ellipsoid C2's by no more than the profiles' relative difference at the
//    contact's ends, l^2 / Y^2 (the bound of `line profile: a barrel is the ellipsoid C2 = 1/R_c
//    to the profiles' difference`, line_profile.test.cpp, whose barrel differs from its ellipsoid
//    by l^2 / (4 R_c^2)).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/bem/bem_profile.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/roller/profile.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_user_profile {

namespace {

using viscoroll::CrownedCylinder;
using viscoroll::LineProfileScene;
using viscoroll::StandardLinearSolid;
using Sls = StandardLinearSolid<double>;

const double eps = std::numeric_limits<double>::epsilon();

/// (U2): a cylinder of radius R, flat over |y| <= L_f/2, with crowns of radius R_c, length L.
class CrownByAngle {
 public:
  using real_type = double;
  CrownByAngle(double radius, double flat, double crown, double length)
      : radius_(radius), flat_(flat), crown_(crown), length_(length) {}
  double c1() const { return 1 / radius_; }
  double drop(double y) const {
    const double s = std::abs(y) - flat_ / 2;
    if (s <= 0) return 0;
    const double half = std::sin(std::asin(s / crown_) / 2);
    return 2 * crown_ * half * half;
  }
  double drop_slope(double y) const {
    const double s = std::abs(y) - flat_ / 2;
    if (s <= 0) return 0;
    const double slope = std::tan(std::asin(s / crown_));
    return y < 0 ? -slope : slope;
  }
  double y_max() const { return std::min(length_ / 2, flat_ / 2 + crown_); }
  double y_min() const { return -y_max(); }
  bool symmetric() const { return true; }

 private:
  double radius_, flat_, crown_, length_;
};

/// (U3): h = C2 y^2/2 (1 + y^2/Y^2), unbounded.
struct QuarticCrown {
  using real_type = double;
  double curvature, c2, y_scale;
  double c1() const { return curvature; }
  double drop(double y) const { return c2 * y * y / 2 * (1 + y * y / (y_scale * y_scale)); }
  double drop_slope(double y) const { return c2 * y * (1 + 2 * y * y / (y_scale * y_scale)); }
  double y_min() const { return -std::numeric_limits<double>::infinity(); }
  double y_max() const { return std::numeric_limits<double>::infinity(); }
  bool symmetric() const { return true; }
};

static_assert(viscoroll::RollerProfile<CrownByAngle> && viscoroll::RollerProfile<QuarticCrown>);

double rel(double x, double y) { return std::abs(x / y - 1); }

// The roller and rubber of line_profile_bem.test.cpp: C1 = 1, a flat part 10 long, crowns of
// radius 20, here 24 long; the standard linear solid f = 2, tau = 1, its long-term static a(0)
// 0.2878 at the load 0.3/(3 c).
const CrownedCylinder<double> library_roller(1.0, 10.0, 20.0, 24.0);
const CrownByAngle user_roller(1.0, 10.0, 20.0, 24.0);
const Sls rubber(1.0, 0.5, 2.0, 1.0);

}  // namespace

TEST_CASE("seams: a user's profile by another formula is the library's to a few ulps",
          "[seams][profile]") {
  // (U2) against CrownedCylinder: sin, asin and the product each round once, and the angle's
  // halving is exact: h within 8 eps relative (measured 3 eps); the slope, through asin and tan,
  // within 8 eps (measured 2 eps) away from the crown circle's end.
  double worst_h = 0, worst_slope = 0;
  for (int k = -1199; k <= 1199; ++k) {
    const double y = 12.0 * k / 1200;
    const double h = library_roller.drop(y), s = library_roller.drop_slope(y);
    CHECK(std::abs(user_roller.drop(y) - h) <= 8 * eps * h);
    CHECK(std::abs(user_roller.drop_slope(y) - s) <= 8 * eps * std::abs(s));
    if (h > 0) worst_h = std::max(worst_h, std::abs(user_roller.drop(y) / h - 1));
    if (s != 0) worst_slope = std::max(worst_slope, std::abs(user_roller.drop_slope(y) / s - 1));
  }
  CAPTURE(worst_h / eps, worst_slope / eps);
  CHECK(user_roller.y_max() == library_roller.y_max());
}

TEST_CASE("seams: a user's profile through the line solver and the BEM is the library's",
          "[seams][profile]") {
  // The line solver: both iterations converge to a root of equations whose drop differs by a few
  // ulps, from cold starts that differ as much: within the iteration's tolerance, 1e-9 (as for
  // the ellipsoid through the profile's path, line_profile.test.cpp; measured at most 6 eps).
  // The BEM: the grid is sized by (B14) from the profile's drop through two bisections, whose
  // ends move with the drop's last bits (measured: hy 118 eps apart); the cells' gaps differ by
  // 8 eps of the drop and, through the cell centres, by twice the grid's relative change. On the
  // same active set the answers move by the operator's condition number (at most 1e3,
  // bem_spectrum.test.cpp) times the change of its coefficients (the grid's, delta_grid) and of
  // the gap (8 eps + 2 delta_grid), plus GMRES' 2 x 32 eps of the final solve (final_tolerance
  // 1e-15, raised to 32 eps): 1e3 (3 delta_grid + 72 eps) = 8.6e-11 here (measured: d 15.5 eps,
  // chi 27 eps, a(0) 195 eps of hx).
  viscoroll::LineOptions options;
  options.terms = 12;
  const viscoroll::LineSolver<double, Sls> line(rubber, options);
  viscoroll::BemOptions bem_options;
  bem_options.grid = 12;
  bem_options.final_tolerance = 1e-15;
  const viscoroll::BemSolver<double, Sls> bem(rubber, bem_options);
  const double load = 0.3 / (3 * rubber.instantaneous_compliance());
  for (const double speed : {0.0, 0.02878, 0.2878, 2.878}) {
    const auto mine = line.solve(LineProfileScene<CrownByAngle>{user_roller, load, speed});
    const auto lib =
        line.solve(LineProfileScene<CrownedCylinder<double>>{library_roller, load, speed});
    CAPTURE(speed, mine.reason, rel(mine.d, lib.d) / eps, rel(mine.a(0), lib.a(0)) / eps,
            rel(mine.l(), lib.l()) / eps, rel(mine.chi, lib.chi) / eps);
    REQUIRE(mine.converged);
    REQUIRE(lib.converged);
    CHECK(rel(mine.a(0.0), lib.a(0.0)) <= 1e-9);
    CHECK(std::abs(mine.b(0.0) - lib.b(0.0)) <= 1e-9 * lib.a(0.0));
    CHECK(rel(mine.l(), lib.l()) <= 1e-9);
    CHECK(rel(mine.d, lib.d) <= 1e-9);
    CHECK(std::abs(mine.chi - lib.chi) <= 1e-9 * std::abs(lib.chi) + 1e-15);

    const auto e = bem.solve(viscoroll::bem_scene(user_roller, rubber, load, speed));
    const auto g = bem.solve(viscoroll::bem_scene(library_roller, rubber, load, speed));
    CAPTURE(e.reason, rel(e.d, g.d) / eps, rel(e.chi, g.chi) / eps, rel(e.grid.hy, g.grid.hy) / eps,
            std::abs(e.a0 - g.a0) / g.grid.hx / eps, std::abs(e.l - g.l) / g.grid.hy / eps);
    REQUIRE(e.converged);
    REQUIRE(g.converged);
    CHECK(e.contact_cells == g.contact_cells);
    const double delta_grid = std::max(rel(e.grid.hx, g.grid.hx), rel(e.grid.hy, g.grid.hy));
    const double bem_tol = 1e3 * (3 * delta_grid + 72 * eps);
    CHECK(rel(e.d, g.d) <= bem_tol);
    CHECK(std::abs(e.chi - g.chi) <= bem_tol * std::abs(g.chi) + 1e-15);
    CHECK(std::abs(e.a0 - g.a0) <= bem_tol * g.grid.hx);
    CHECK(std::abs(e.l - g.l) <= bem_tol * g.grid.hy);
  }
}

TEST_CASE("seams: a user's quartic crown is the ellipsoid to the profiles' difference",
          "[seams][profile]") {
  // (U3) with Y = 9.6 against the ellipsoid C2 (the scene of line_profile.test.cpp, l/Y = 0.11
  // to 0.13): the drops differ by l^2/Y^2 of themselves at the contact's ends, and the solutions
  // by at most that, relative (as a barrel's do). The line solver: its discretisation is common
  // to the two rollers, so that bound alone (measured 0.10 to 0.15 of it in d and a(0), 0.55 in
  // l). The BEM: each roller on the grid (B14) sizes for it, each solution
  // within B13's discretisation error of its exact contact, (hx/a)^2/5 relative in d and hy/4 in
  // l (h/a the cell over the semi-axis in contact; docs/bem.md, bem_spectrum.test.cpp): the bound
  // plus both errors.
  const StandardLinearSolid<double> material(1.0, 0.0, 2.0, 1.0);
  const double c2 = 0.04, load = 0.01 / (3 * material.instantaneous_compliance());
  const double y_scale = 9.6;
  const QuarticCrown quartic{1.0, c2, y_scale};
  const viscoroll::EllipsoidProfile<double> ellipsoid(1.0, c2);
  viscoroll::LineOptions options;
  options.terms = 4;
  const viscoroll::LineSolver<double, StandardLinearSolid<double>> line(material, options);
  viscoroll::BemOptions bem_options;
  bem_options.grid = 12;
  const viscoroll::BemSolver<double, StandardLinearSolid<double>> bem(material, bem_options);
  for (const double speed : {0.0, 0.03, 0.3, 3.0}) {
    const auto q = line.solve(LineProfileScene<QuarticCrown>{quartic, load, speed});
    const auto e =
        line.solve(LineProfileScene<viscoroll::EllipsoidProfile<double>>{ellipsoid, load, speed});
    REQUIRE(q.converged);
    REQUIRE(e.converged);
    const double bound = e.l() * e.l() / (y_scale * y_scale);
    CAPTURE(speed, bound, rel(q.d, e.d), rel(q.a(0), e.a(0)), rel(q.l(), e.l()), q.chi, e.chi);
    CHECK(rel(q.d, e.d) <= bound);
    CHECK(rel(q.a(0.0), e.a(0.0)) <= bound);
    CHECK(rel(q.l(), e.l()) <= bound);
    CHECK(std::abs(q.chi - e.chi) <= bound * e.chi + 1e-15);
    // The quartic rises faster: its contact is shorter and, under the same load, deeper.
    CHECK(q.l() < e.l());
    CHECK(q.d > e.d);

    const auto gq = bem.solve(viscoroll::bem_scene(quartic, material, load, speed));
    const auto ge = bem.solve(viscoroll::bem_scene(ellipsoid, material, load, speed));
    REQUIRE(gq.converged);
    REQUIRE(ge.converged);
    const double hq = gq.grid.hx / gq.a0, he = ge.grid.hx / ge.a0;
    CAPTURE(rel(gq.d, ge.d), rel(gq.l, ge.l), hq, he, gq.grid.hy, ge.grid.hy);
    CHECK(rel(gq.d, ge.d) <= bound + (hq * hq + he * he) / 5);
    CHECK(std::abs(gq.l - ge.l) <= bound * ge.l + (gq.grid.hy + ge.grid.hy) / 4);
  }
}

}  // namespace test_user_profile
