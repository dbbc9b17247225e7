// One PlaneSolution for every material (docs/reference.md, "Plane solver"): the standard linear
// solid and a spectrum give the same type; a one-term solution carries the spectrum's fields
// (active_terms, amplification 1, linear_residual 0, spectrum_error 0) and a chi_rounding that
// bounds its chi against long double (docs/theory.md (P7)); a spectrum's strip has no
// pseudo-pressure.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/plane/plane_solver.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_one_solution {

namespace {

using viscoroll::PlaneSolver;
using viscoroll::PronyCreep;
using viscoroll::StandardLinearSolid;

static_assert(std::is_same_v<PlaneSolver<double, StandardLinearSolid<double>>::Solution,
                             PlaneSolver<double, PronyCreep<double>>::Solution>);
static_assert(std::is_same_v<PlaneSolver<double, viscoroll::Elastic<double>>::Solution,
                             PlaneSolver<double, viscoroll::PronyRelaxation<double>>::Solution>);

}  // namespace

TEST_CASE("plane: one term's chi_rounding bounds its chi against long double", "[plane]") {
  // (P7) sums non-negative terms, each to a few eps, and xbar < 2a: the (S20) bound at
  // amplification 1, 64 eps C1 a, holds over the paper's 100 speeds (V tau/a0 = 1e-3 ... 1e3).
  const double f = 9;
  const PlaneSolver<double, StandardLinearSolid<double>> solver(
      StandardLinearSolid<double>(1.0, 0.5, f, 1.0));
  const PlaneSolver<long double, StandardLinearSolid<long double>> reference(
      StandardLinearSolid<long double>(1.0L, 0.5L, 9.0L, 1.0L));
  const double c1 = 2, load = 1;
  const double a0 = std::sqrt(4 * solver.material().long_term_compliance() * load / c1);
  int rolling = 0;
  for (int k = 0; k < 100; ++k) {
    const double speed = a0 * std::pow(10.0, -3 + 6 * k / 99.0);
    const auto s = solver.solve({.c1 = c1, .load = load, .speed = speed});
    const auto r = reference.solve({.c1 = 2.0L, .load = 1.0L, .speed = (long double)speed});
    CAPTURE(k, speed, s.chi, double(r.chi), s.chi_rounding);
    REQUIRE(s.converged);
    CHECK(s.amplification == 1);
    CHECK(s.linear_residual == 0);
    CHECK(s.spectrum_error == 0);
    CHECK(s.strip.terms() == 1);
    if (s.active_terms == 0) {  // glassy: Hertz's strip, chi exactly 0
      CHECK(s.chi == 0);
      CHECK(s.chi_rounding == 0);
      continue;
    }
    ++rolling;
    CHECK(s.active_terms == 1);
    CHECK(s.chi_rounding == 64 * std::numeric_limits<double>::epsilon() * c1 * s.a);
    CHECK(std::abs(s.chi - double(r.chi)) <= s.chi_rounding);
  }
  CHECK(rolling >= 90);
}

TEST_CASE("plane: a spectrum's strip is the sum of its terms, without a pseudo-pressure",
          "[plane][spectrum]") {
  // Two active terms: (S9) sums two one-term strips, whose pseudo-pressures do not sum to
  // (S4); with every term relaxed the strip is Hertz's, one term, with its (32).
  const PronyCreep<double> material(1.0, 0.5, {{3.0, 0.05}, {6.0, 5.0}});
  const PlaneSolver<double, PronyCreep<double>> solver(material);
  const double c1 = 2, load = 1;
  const auto s = solver.solve({.c1 = c1, .load = load, .speed = 1.0});
  REQUIRE(s.converged);
  CHECK(s.active_terms == 2);
  CHECK(s.strip.terms() == 2);
  CHECK(std::isnan(s.q));
  CHECK_THROWS_AS(s.pseudo_pressure(0.0), std::logic_error);
  const double x = s.b;  // the contact's centre
  CHECK(s.pressure(x) > 0);
  const auto relaxed = solver.solve({.c1 = c1, .load = load, .speed = 1e-30});
  REQUIRE(relaxed.converged);
  CHECK(relaxed.active_terms == 0);
  CHECK(relaxed.strip.terms() == 1);
  // Hertz's strip: Eq. (7) with V tau = 0, p* = c (1 + F) p, to the rounding of the two
  // evaluations and the compliance's product (a few eps; bound 16 eps).
  const double p0 = relaxed.pressure(0.0), q0 = relaxed.pseudo_pressure(0.0);
  CHECK(std::abs(p0 * material.long_term_compliance() - q0) <=
        16 * std::numeric_limits<double>::epsilon() * q0);
}

}  // namespace test_plane_one_solution
