// ProfileView (roller/profile.hpp): a view of any RollerProfile is itself one and has the viewed
// profile's values; the line solver, which takes every profile through its view, gives a profile
// type of one's own the same digits as the library's profile of the same drop.
#include <catch2/catch.hpp>
#include <limits>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/roller/profile.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_profile_view {

/// A profile of one's own: the paper's ellipsoid written out with RollerProfile's members only,
/// in the same arithmetic as EllipsoidProfile.
struct OwnEllipsoid {
  using real_type = double;
  double curvature_across, curvature_along;
  double c1() const { return curvature_across; }
  double drop(double y) const { return curvature_along * y * y / 2; }
  double drop_slope(double y) const { return curvature_along * y; }
  double y_min() const { return -std::numeric_limits<double>::infinity(); }
  double y_max() const { return std::numeric_limits<double>::infinity(); }
  bool symmetric() const { return true; }
};
static_assert(viscoroll::RollerProfile<OwnEllipsoid>);
static_assert(viscoroll::RollerProfile<viscoroll::ProfileView<double>>);

TEST_CASE("profile view: a view has the viewed profile's values", "[roller]") {
  const viscoroll::CrownedCylinder<double> crowned(1.0, 10.0, 20.0);
  const viscoroll::Tilted<viscoroll::CrownedCylinder<double>> tilted(crowned, 0.01);
  const viscoroll::ProfileView<double> view(tilted);
  const viscoroll::ProfileView<double> copy(view);  // a copy views the same profile
  CHECK(view.c1() == tilted.c1());
  CHECK(view.y_min() == tilted.y_min());
  CHECK(view.y_max() == tilted.y_max());
  CHECK_FALSE(view.symmetric());
  CHECK(viscoroll::ProfileView<double>(crowned).symmetric());
  for (const double y : {-14.0, -7.5, -1.0, 0.0, 2.5, 5.0, 9.0, 14.0}) {
    INFO("y = " << y);
    CHECK(view.drop(y) == tilted.drop(y));
    CHECK(view.drop_slope(y) == tilted.drop_slope(y));
    CHECK(copy.drop(y) == tilted.drop(y));
  }
}

TEST_CASE("profile view: a profile type of one's own solves as the library's profile",
          "[roller][line]") {
  const viscoroll::StandardLinearSolid<double> rubber(1, 0.5, 2, 1);
  viscoroll::LineOptions options;
  options.terms = 4;
  const viscoroll::LineSolverD solver(rubber, options);
  const double c1 = 1, c2 = 0.1, load = 0.3 / (3 * rubber.instantaneous_compliance());
  for (const double speed : {0.0, 0.3, 3.0}) {
    INFO("V = " << speed);
    const auto own =
        solver.solve(viscoroll::LineProfileScene<OwnEllipsoid>{OwnEllipsoid{c1, c2}, load, speed});
    const auto lib = solver.solve(viscoroll::LineProfileScene<viscoroll::EllipsoidProfile<double>>{
        viscoroll::EllipsoidProfile<double>(c1, c2), load, speed});
    REQUIRE(lib.converged);
    REQUIRE(own.converged);
    // The same operations on the same numbers: the same digits.
    CHECK(own.d == lib.d);
    CHECK(own.chi == lib.chi);
    CHECK(own.a(0.0) == lib.a(0.0));
    CHECK(own.l() == lib.l());
    CHECK(own.iterations == lib.iterations);
  }
}

}  // namespace test_profile_view
