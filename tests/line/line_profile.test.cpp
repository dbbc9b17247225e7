// LineSolver::solve for a roller profile (docs/theory.md section 16): the paper's ellipsoid through
// the profile's path is the paper's solver (the two share the residual and differ in the cold
// start only, (RP8), so they agree to the iteration's tolerance); a barrel (a crowned cylinder
// without a flat part) is the ellipsoid C2 = 1/R_c to the two profiles' difference; a nearby
// solution seeds the profile's solve to the same answer; bad input and a contact that reaches the
// roller's end are refused or reported (tilted rollers: line_profile_tilt.test.cpp).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <viscoroll/line/line_solver.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_profile {

namespace {

using viscoroll::CrownedCylinder;
using viscoroll::EllipsoidProfile;
using viscoroll::LineProfileScene;

// A standard linear solid (c = 1/(2 pi) (1 - nu), f = 2, tau = 1) and a slender scene: C1 = 1,
// C2 = 0.04, (1 + f) c P = 0.01, so that a0 = 0.121, l0 = 0.96 (l0/a0 = 7.9).
struct Scene {
  viscoroll::StandardLinearSolid<double> material{1.0, 0.0, 2.0, 1.0};
  double c2 = 0.04;
  double load = 0.01 / (3 * material.instantaneous_compliance());
};

viscoroll::LineSolverD solver(const Scene& s, int terms) {
  viscoroll::LineOptions options;
  options.terms = terms;
  return viscoroll::LineSolverD(s.material, options);
}

double relative(double x, double y) { return std::abs(x - y) / std::abs(y); }

}  // namespace

TEST_CASE("line profile: the ellipsoid through the profile's path is the paper's solver",
          "[line]") {
  // Both converge to a root of the same equations from different cold starts: the iteration's
  // tolerance, as between seeds (line_seed.test.cpp). V tau/a0 from the slow to the fast regime,
  // the static and the glassy limit.
  const Scene s;
  const auto line = solver(s, 4);
  const EllipsoidProfile<double> roller(1.0, s.c2);
  for (const double speed : {0.0, 0.003, 0.03, 0.3, 3.0, 1e5}) {
    const auto e = line.solve({.c1 = 1.0, .c2 = s.c2, .load = s.load, .speed = speed});
    const auto p = line.solve(LineProfileScene<EllipsoidProfile<double>>{roller, s.load, speed});
    INFO("V tau = " << speed << ": " << p.reason);
    REQUIRE(e.converged);
    REQUIRE(p.converged);
    CHECK(relative(p.a(0.0), e.a(0.0)) < 1e-9);
    CHECK(std::abs(p.b(0.0) - e.b(0.0)) < 1e-9 * e.a(0.0));
    CHECK(relative(p.l(), e.l()) < 1e-9);
    CHECK(relative(p.d, e.d) < 1e-9);
    CHECK(std::abs(p.chi - e.chi) <= 1e-9 * std::abs(e.chi) + 1e-15);
    CHECK(relative(p.a_long_term, e.a_long_term) < 1e-9);
  }
}

TEST_CASE("line profile: a barrel is the ellipsoid C2 = 1/R_c to the profiles' difference",
          "[line]") {
  // h_barrel - h_ellipsoid = y^4/(8 R_c^3) (1 + O(y^2/R_c^2)) is l^2/(4 R_c^2) of the drop
  // l^2/(2 R_c) at the ends: the solutions differ by that relative amount at most (measured:
  // 0.15 to 0.6 of it in d, a(0), l, chi).
  const Scene s;
  const double rc = 1 / s.c2;
  const auto line = solver(s, 4);
  for (const double speed : {0.0, 0.01, 0.1, 1.0}) {
    const auto e = line.solve({.c1 = 1.0, .c2 = s.c2, .load = s.load, .speed = speed});
    const auto b = line.solve(LineProfileScene<CrownedCylinder<double>>{
        CrownedCylinder<double>(1.0, 0.0, rc), s.load, speed});
    REQUIRE(b.converged);
    const double bound = e.l() * e.l() / (4 * rc * rc);
    INFO("V tau = " << speed << ", l^2/(4 R_c^2) = " << bound);
    CHECK(relative(b.d, e.d) < bound);
    CHECK(relative(b.a(0.0), e.a(0.0)) < bound);
    CHECK(relative(b.l(), e.l()) < bound);
    CHECK(std::abs(b.chi - e.chi) <= bound * e.chi);
    // The barrel's drop exceeds the parabola's: the contact is shorter and wider.
    CHECK(b.l() < e.l());
    CHECK(b.a(0.0) > e.a(0.0));
  }
}

TEST_CASE("line profile: a neighbouring solution seeds the same answer", "[line]") {
  const Scene s;
  const auto line = solver(s, 6);
  const CrownedCylinder<double> roller(1.0, 1.0, 10.0);
  const auto near = line.solve(LineProfileScene<CrownedCylinder<double>>{roller, s.load, 0.1});
  REQUIRE(near.converged);
  const auto cold = line.solve(LineProfileScene<CrownedCylinder<double>>{roller, s.load, 0.12});
  const auto seeded =
      line.solve(LineProfileScene<CrownedCylinder<double>>{roller, s.load, 0.12}, &near);
  REQUIRE(cold.converged);
  REQUIRE(seeded.converged);
  CHECK(seeded.warnings.size() == cold.warnings.size());
  CHECK(seeded.warning_codes == cold.warning_codes);
  CHECK(relative(seeded.a(0.0), cold.a(0.0)) < 1e-9);
  CHECK(relative(seeded.l(), cold.l()) < 1e-9);
  CHECK(relative(seeded.d, cold.d) < 1e-9);
  CHECK(relative(seeded.chi, cold.chi) < 1e-9);
}

TEST_CASE("line profile: a contact that reaches the roller's end is reported", "[line]") {
  // A flat part of 1 and crowns of radius 10, the body ending 0.2 beyond the flat part (|y| = 0.7):
  // the long-term static contact of the same load on an endless crown reaches |y| = 1.19 (it bounds
  // the rolling contacts' length, so the static contact's report is the solve's).
  const Scene s;
  const auto line = solver(s, 4);
  const CrownedCylinder<double> roller(1.0, 1.0, 10.0, 1.4);
  for (const double speed : {0.0, 0.1}) {
    const auto p = line.solve(LineProfileScene<CrownedCylinder<double>>{roller, s.load, speed});
    INFO(p.reason);
    CHECK_FALSE(p.converged);
    CHECK(p.code == viscoroll::StopCode::contact_reaches_body_end);
  }
}

TEST_CASE("line profile: invalid scenes name the parameter", "[line][errors]") {
  const Scene s;
  const auto line = solver(s, 4);
  const CrownedCylinder<double> roller(1.0, 1.0, 10.0);
  const auto message = [&](auto scene) {
    try {
      (void)line.solve(scene);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  using Crowned = LineProfileScene<CrownedCylinder<double>>;
  CHECK(message(Crowned{roller, 0.0, 1.0}).find("load") != std::string::npos);
  CHECK(message(Crowned{roller, s.load, -1.0}).find("speed") != std::string::npos);
}

}  // namespace test_line_profile
