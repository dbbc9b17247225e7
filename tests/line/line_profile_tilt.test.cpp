// LineSolver::solve for a tilted roller (docs/theory.md (RP6), (RP7), (RP9)): the asymmetric
// contact [c - l, c + l] with odd parts of a(y), b(y). A tilted ellipsoid is the untilted one
// shifted by -theta/C2 with d lowered by theta^2/(2 C2) (RP10.2), on one memory term and on a
// spectrum, and theta -> -theta mirrors the contact.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_profile_tilt {

using viscoroll::EllipsoidProfile;
using viscoroll::LineProfileScene;
using viscoroll::Tilted;

namespace {

// The paper's proportions (C1 = 1, C2 = (ln 20 - 1)/25, load 1 on c = 1/(2 pi), f = 3, tau = 1):
// a0 = 1.33, l0 = 6.7. The tilts shift the contact by theta/C2 = 0.06 to 0.63 (1% to 9% of l).
const double c2 = (std::log(20.0) - 1) / 25;
const viscoroll::StandardLinearSolid<double> rubber(1 / (2 * M_PI), 0.0, 3.0, 1.0);

viscoroll::LineSolverD solver(int terms) {
  viscoroll::LineOptions options;
  options.terms = terms;
  return viscoroll::LineSolverD(rubber, options);
}

using Ellipsoid = LineProfileScene<EllipsoidProfile<double>>;
using TiltedEllipsoid = LineProfileScene<Tilted<EllipsoidProfile<double>>>;

}  // namespace

TEST_CASE("line profile tilt: a tilted ellipsoid is the ellipsoid shifted", "[line][profile]") {
  // h = C2 y^2/2 + theta y = C2 (y - y_c)^2/2 - theta^2/(2 C2), y_c = -theta/C2 (RP9): the same
  // equations in y - y_c, so the same root; both iterations stop once a step is below
  // eps^0.6 (1 + |x|) of the unknowns (~4e-10, line-solver.md), which bounds their difference.
  const double tol = 4 * std::pow(std::numeric_limits<double>::epsilon(), 0.6);
  const EllipsoidProfile<double> roller(1.0, c2);
  const auto line = solver(4);
  for (const double speed : {0.0, 0.1, 1.0, 10.0}) {
    const auto e = line.solve(Ellipsoid{roller, 1.0, speed});
    for (const double theta : {0.005, -0.05}) {
      const auto t = line.solve(TiltedEllipsoid{{roller, theta}, 1.0, speed});
      INFO("V tau = " << speed << ", theta = " << theta << ": " << t.reason);
      REQUIRE(e.converged);
      REQUIRE(t.converged);
      CHECK(t.shape.asymmetric());
      const double shift = -theta / c2, a0 = e.a(0.0);
      CHECK(std::abs(t.shape.centre - shift) < tol * e.l());
      CHECK(std::abs(t.l() - e.l()) < tol * e.l());
      CHECK(std::abs(t.d + theta * theta / (2 * c2) - e.d) < tol * e.d);
      CHECK(std::abs(t.chi - e.chi) <= tol * std::abs(e.chi) + 1e-15);
      for (const double s : {-0.9, -0.4, 0.0, 0.6, 0.95}) {
        CHECK(std::abs(t.a(shift + s * t.l()) - e.a(s * e.l())) < tol * a0);
        CHECK(std::abs(t.b(shift + s * t.l()) - e.b(s * e.l())) < tol * a0);
      }
      CHECK(t.y_minus() == t.shape.centre - t.l());
      const auto along = t.along_roller(9);
      CHECK(along.y_minus == t.y_minus());
      CHECK(along.y_plus == t.y_plus());
    }
  }
}

TEST_CASE("line profile tilt: theta -> -theta mirrors the contact", "[line][profile]") {
  // A crowned roller (flat part 10, crowns of radius 20; the proportions of validation.md's
  // "Rolling rollers of any profile", f = 2 under (1 + f) c P = 0.3) misaligned both ways: the
  // residual is equivariant under t -> -t exactly, the solutions mirror to the iteration's
  // tolerance (pivoted factorisations are not equivariant, (RP9)). The load shifts to the side
  // pressed harder: y < 0 for theta > 0 (h lowered there).
  const viscoroll::StandardLinearSolid<double> m(1 / (2 * M_PI), 0.0, 2.0, 1.0);
  viscoroll::LineOptions options;
  options.terms = 8;
  const viscoroll::LineSolverD line(m, options);
  const viscoroll::CrownedCylinder<double> crowned(1.0, 10.0, 20.0);
  const double load = 0.3 / (3 * m.instantaneous_compliance()), theta = 0.003;
  using Scene = LineProfileScene<Tilted<viscoroll::CrownedCylinder<double>>>;
  const double tol = 4 * std::pow(std::numeric_limits<double>::epsilon(), 0.6);
  for (const double speed : {0.0, 0.3}) {
    const auto p = line.solve(Scene{{crowned, theta}, load, speed});
    const auto q = line.solve(Scene{{crowned, -theta}, load, speed});
    INFO("V tau = " << speed << ": " << p.reason << " / " << q.reason);
    REQUIRE(p.converged);
    REQUIRE(q.converged);
    CHECK(std::abs(p.y_minus() + q.y_plus()) < tol * p.l());
    CHECK(std::abs(p.y_plus() + q.y_minus()) < tol * p.l());
    CHECK(std::abs(p.d - q.d) < tol * p.d);
    CHECK(std::abs(p.chi - q.chi) <= tol * p.chi + 1e-15);
    const double a_mid = p.a(p.shape.centre);
    for (const double s : {-0.8, -0.3, 0.2, 0.7}) {
      const double y = p.shape.centre + s * p.l();
      CHECK(std::abs(p.a(y) - q.a(-y)) < tol * a_mid);
      CHECK(std::abs(p.b(y) - q.b(-y)) < tol * a_mid);
    }
    // The load's line of action, over the stations: on the side pressed harder.
    const auto along = p.along_roller(201);
    double m0 = 0, m1 = 0;
    for (std::size_t k = 0; k < along.y.size(); ++k) {
      m0 += along.f0[k];
      m1 += along.f0[k] * along.y[k];
    }
    CHECK(m1 / m0 < -0.1);
    CHECK(along.f0_max_y < 0);
    CHECK(p.shape.centre < 0);
  }
}

TEST_CASE("line profile tilt: on a spectrum, a tilted ellipsoid is the ellipsoid shifted",
          "[line][profile]") {
  // The spectrum's residual (docs/theory.md (RP5) with (RP7)): the same identity (RP9) as for
  // one term, two terms (f, tau) = (3, 0.05), (6, 5) of validation.md at V = 1, both active;
  // and theta -> -theta mirrors the ends.
  const viscoroll::PronyCreep<double> spectrum(1.0, 0.5, {{3.0, 0.05}, {6.0, 5.0}});
  viscoroll::LineOptions options;
  options.terms = 4;
  const viscoroll::LineSolver<double, viscoroll::PronyCreep<double>> line(spectrum, options);
  const EllipsoidProfile<double> roller(1.0, c2);
  const double tol = 4 * std::pow(std::numeric_limits<double>::epsilon(), 0.6), theta = 0.01;
  const auto e = line.solve(Ellipsoid{roller, 1.0, 1.0});
  const auto t = line.solve(TiltedEllipsoid{{roller, theta}, 1.0, 1.0});
  const auto m = line.solve(TiltedEllipsoid{{roller, -theta}, 1.0, 1.0});
  INFO(t.reason);
  REQUIRE(e.converged);
  REQUIRE(t.converged);
  REQUIRE(m.converged);
  REQUIRE(t.active_terms == 2);
  const double shift = -theta / c2, a0 = e.a(0.0);
  CHECK(t.shape.asymmetric());
  CHECK(std::abs(t.shape.centre - shift) < tol * e.l());
  CHECK(std::abs(t.l() - e.l()) < tol * e.l());
  CHECK(std::abs(t.d + theta * theta / (2 * c2) - e.d) < tol * e.d);
  CHECK(std::abs(t.chi - e.chi) <= tol * e.chi);
  for (const double s : {-0.8, 0.0, 0.5}) {
    CHECK(std::abs(t.a(shift + s * t.l()) - e.a(s * e.l())) < tol * a0);
    CHECK(std::abs(t.b(shift + s * t.l()) - e.b(s * e.l())) < tol * a0);
    CHECK(std::abs(t.f0(shift + s * t.l()) - e.f0(s * e.l())) < tol * e.f0(0.0));
  }
  CHECK(std::abs(t.y_minus() + m.y_plus()) < tol * e.l());
  CHECK(std::abs(t.y_plus() + m.y_minus()) < tol * e.l());
  const auto along = t.along_roller(9);
  CHECK(along.y_minus == t.y_minus());
  CHECK(along.y_plus == t.y_plus());
}

}  // namespace test_line_profile_tilt
