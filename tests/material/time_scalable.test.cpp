// One at_temperature for every material that models TimeScalable (material/temperature_shift.hpp,
// docs/theory.md (R13)): a material written outside the library, with its own time_scaled, is
// shifted by the same function as the library's, and it solves by the plane method. A type whose
// time_scaled returns another type does not model the concept.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <viscoroll/material/temperature_shift.hpp>
#include <viscoroll/plane/plane_solver.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_time_scalable {

/// A user's two-time solid in creep form (Eq. (1) with two terms; theory.md (R6)): written here,
/// not in the library. It models ConstitutiveModel (a fixed spectrum of two terms) and
/// TimeScalable (time_scaled).
struct TwoTimeSolid {
  using real_type = double;
  static constexpr bool is_viscoelastic = true;
  static constexpr int memory_term_count = 2;
  double mu_d, nu;
  std::array<viscoroll::PronyTerm<double>, 2> terms;
  double instantaneous_compliance() const {
    return (1 - nu) / (2 * std::numbers::pi * mu_d);  // Eq. (3)
  }
  double creep_ratio() const { return terms[0].f + terms[1].f; }
  std::array<viscoroll::PronyTerm<double>, 2> memory_terms() const { return terms; }
  TwoTimeSolid time_scaled(double a) const {
    TwoTimeSolid out = *this;
    for (auto& t : out.terms) t.tau *= a;
    return out;
  }
};

/// time_scaled that returns another type: not TimeScalable.
struct Mistyped : TwoTimeSolid {
  TwoTimeSolid time_scaled(double a) const { return TwoTimeSolid::time_scaled(a); }
};

static_assert(viscoroll::TimeScalable<TwoTimeSolid>);
static_assert(!viscoroll::TimeScalable<Mistyped>);
static_assert(viscoroll::TimeScalable<viscoroll::Elastic<double>>);
static_assert(viscoroll::TimeScalable<viscoroll::StandardLinearSolid<double>>);
static_assert(viscoroll::TimeScalable<viscoroll::PronyCreep<double>>);
static_assert(viscoroll::TimeScalable<viscoroll::PronyRelaxation<double>>);

TEST_CASE("time scalable: a user's material shifts by the library's at_temperature (R13)",
          "[material][temperature][seams]") {
  const viscoroll::WlfShift<double> wlf(8.86, 101.6, 20.0);
  const double t = -10.0, a = wlf.factor(t);
  const TwoTimeSolid m{3e6, 0.5, {{{4.0, 1e-3}, {5.0, 1e-1}}}};
  const TwoTimeSolid cold = viscoroll::at_temperature(m, wlf, t);
  // Exact: one product per time, the moduli unchanged.
  CHECK(cold.terms[0].tau == 1e-3 * a);
  CHECK(cold.terms[1].tau == 1e-1 * a);
  CHECK(cold.terms[0].f == 4.0);
  CHECK(cold.mu_d == m.mu_d);
  // The library's own materials through the same function: the same products.
  const viscoroll::PronyCreep<double> prony(3e6, 0.5, {{4.0, 1e-3}, {5.0, 1e-1}});
  const auto shifted = viscoroll::at_temperature(prony, wlf, t);
  CHECK(shifted.terms()[0].tau == cold.terms[0].tau);
  CHECK(shifted.terms()[1].tau == cold.terms[1].tau);
  const viscoroll::StandardLinearSolid<double> sls(3e6, 0.5, 9.0, 0.01);
  CHECK(viscoroll::at_temperature(sls, wlf, t).relaxation_time() == 0.01 * a);
  CHECK(viscoroll::at_temperature(viscoroll::Elastic<double>(3e6, 0.5), wlf, t).mu_d() == 3e6);
  // The user's material solves by the plane method as the library's Prony series of the same
  // terms does: the same spectrum, so the same numbers to rounding (both go through the
  // spectrum's closed form, theory.md section 12).
  const viscoroll::PlaneScene<double> scene{.c1 = 20.0, .load = 1000.0, .speed = 0.5};
  const auto mine = viscoroll::PlaneSolver<double, TwoTimeSolid>(cold).solve(scene);
  const auto theirs =
      viscoroll::PlaneSolver<double, viscoroll::PronyCreep<double>>(shifted).solve(scene);
  REQUIRE(mine.converged);
  REQUIRE(theirs.converged);
  CHECK(mine.a == Approx(theirs.a).epsilon(64 * std::numeric_limits<double>::epsilon()));
  CHECK(mine.chi == Approx(theirs.chi).epsilon(64 * std::numeric_limits<double>::epsilon()));
}

}  // namespace test_time_scalable
