// The line solver for a spectrum where its equations have no root: the certified least-squares
// minimum (docs/line-solver.md, "Least-squares minima"; the semi-analytic Jacobian of
// docs/theory.md (S17) makes it available), on the two-term material of support/spectrum_scene.hpp
// at V = 1, N = 6, where Levenberg-Marquardt stops with max |r| ~ 1e-4.
#include <catch2/catch.hpp>
#include <cmath>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony.hpp>

#include "support/spectrum_scene.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_spectrum_minimum {

namespace {

using viscoroll::testing::spectrum_scene;
using viscoroll::testing::two_term_creep;

double rel(double x, double y) { return std::abs(x - y) / std::abs(y); }

}  // namespace

TEST_CASE("line spectrum: a certified least-squares minimum where the equations have no root",
          "[line][spectrum]") {
  using Solver = viscoroll::LineSolver<double, viscoroll::PronyCreep<double>>;
  const Solver six(two_term_creep(), viscoroll::LineOptions{.terms = 6});
  const auto minimum = six.solve(spectrum_scene(1.0));
  CAPTURE(minimum.reason, minimum.residual);
  CHECK(minimum.converged);
  CHECK(minimum.code == viscoroll::StopCode::converged);
  CHECK_FALSE(minimum.root);
  CHECK(minimum.residual > viscoroll::numerics::default_root_tolerance<double>());
  CHECK(viscoroll::has_warning(minimum, viscoroll::WarningCode::least_squares_minimum));
  // The minimum is the same contact as the root at N = 4 to the discretisation's change between
  // N = 4 and 6 (measured 0.13% in a(0), 0.1% in l, 2e-5 in d and chi; docs/validation.md).
  const Solver four(two_term_creep(), viscoroll::LineOptions{.terms = 4});
  const auto root = four.solve(spectrum_scene(1.0));
  REQUIRE(root.root);
  CHECK(rel(minimum.a(0), root.a(0)) < 1e-2);
  CHECK(rel(minimum.l(), root.l()) < 1e-2);
  CHECK(rel(minimum.d, root.d) < 1e-3);
  CHECK(rel(minimum.chi, root.chi) < 1e-3);
  // Without the minimisation the same stop is reported, not returned as converged.
  const Solver plain(two_term_creep(), viscoroll::LineOptions{.terms = 6, .least_squares = false});
  const auto stop = plain.solve(spectrum_scene(1.0));
  CHECK_FALSE(stop.converged);
  CHECK(stop.code == viscoroll::StopCode::no_descent);
  CHECK_FALSE(stop.root);
}

}  // namespace test_line_spectrum_minimum
