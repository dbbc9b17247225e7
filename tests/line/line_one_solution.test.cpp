// One LineSolution for every material (docs/line-solver.md, "Outputs"): the standard linear
// solid and a spectrum give the same type. A spectrum with one active term has the standard linear
// solid's strips, pressure and peak (to the 1e-12 of "line spectrum: one active term is the
// standard linear solid's solver"); with two or more the strips are carried by their moments
// (S14): no pressure, Q NaN, and G0 = gamma a^2 consistent with F0 of (33) with (S8).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony.hpp>

#include "support/spectrum_scene.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_one_solution {

namespace {

using viscoroll::LineOptions;
using viscoroll::LineSolver;
using viscoroll::PronyCreep;
using viscoroll::StandardLinearSolid;
using viscoroll::testing::spectrum_scene;  // the paper's proportions, load 1
using viscoroll::testing::two_term_creep;  // (f, tau) = (3, 0.05), (6, 5)

static_assert(std::is_same_v<LineSolver<double, StandardLinearSolid<double>>::Solution,
                             LineSolver<double, PronyCreep<double>>::Solution>);
static_assert(std::is_same_v<LineSolver<double, viscoroll::Elastic<double>>::Solution,
                             LineSolver<double, viscoroll::PronyRelaxation<double>>::Solution>);

double rel(double x, double y) { return std::abs(x - y) / std::abs(y); }

}  // namespace

TEST_CASE("line: a spectrum with one active term has the standard linear solid's pressure",
          "[line][spectrum]") {
  const LineOptions options{.terms = 4};
  const double pi = 3.14159265358979323846;
  const PronyCreep<double> one(1.0, 0.5, {{3.0, 0.05}});
  const double c = one.instantaneous_compliance();
  const LineSolver<double, StandardLinearSolid<double>> sls(
      StandardLinearSolid<double>(1 / (2 * pi * c), 0.0, 3.0, 0.05), options);
  const LineSolver<double, PronyCreep<double>> spectrum(one, options);
  for (const double speed : {2.0, 20.0}) {
    const auto ref = sls.solve(spectrum_scene(speed));
    const auto s = spectrum.solve(spectrum_scene(speed));
    CAPTURE(speed);
    REQUIRE(s.converged);
    REQUIRE(ref.converged);
    CHECK(s.active_terms == 1);
    CHECK(ref.active_terms == 1);
    CHECK(s.has_pressure());
    const double y = 0.3 * s.l();
    const auto peak = s.strip(y).peak(), ref_peak = ref.strip(y).peak();
    CHECK(rel(peak.pressure, ref_peak.pressure) <= 1e-12);
    CHECK(std::abs(peak.x - ref_peak.x) <= 1e-12 * s.a(y));
    CHECK(rel(s.pressure(s.b(y), y), ref.pressure(ref.b(y), y)) <= 1e-12);
    CHECK(rel(s.q(y), ref.q(y)) <= 1e-12);
    const auto along = s.along_roller(9);
    CHECK(rel(along.p_max[4], ref.strip(along.y[4]).peak().pressure) <= 1e-12);
  }
}

TEST_CASE("line: a spectrum with two active terms carries its strips by their moments",
          "[line][spectrum]") {
  const LineSolver<double, PronyCreep<double>> solver(two_term_creep(), LineOptions{.terms = 4});
  const auto s = solver.solve(spectrum_scene(5.0));
  REQUIRE(s.converged);
  CHECK(s.active_terms == 2);
  CHECK_FALSE(s.has_pressure());
  CHECK_THROWS_AS(s.strip(0.0), std::logic_error);
  CHECK_THROWS_AS(s.pressure(0.0, 0.0), std::logic_error);
  const double eps = std::numeric_limits<double>::epsilon();
  for (const double t : {0.0, 0.4, 0.9}) {
    const double y = t * s.l(), a = s.a(y);
    CAPTURE(y);
    CHECK(std::isnan(s.q(y)));
    CHECK(std::isnan(s.along_roller(3).p_max[1]));
    // F0 = C1 (a^2/4 + G0/2), (33) with (S8): the two roundings of the same sum, a few eps.
    CHECK(std::abs(s.f0(y) - s.c1 * (a * a / 4 + s.g(y) / 2)) <= 8 * eps * s.f0(y));
  }
}

}  // namespace test_line_one_solution
