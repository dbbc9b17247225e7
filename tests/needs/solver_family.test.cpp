// The solver family of core/concepts.hpp: every solver is Solver<Real, Material, Quadrature>, the
// scalar may be deduced from the material, and a combination that cannot work is rejected by a
// concept (tests/needs/CMakeLists.txt checks the compiler's message for two of them). Each
// combination the README and docs/guide.md show is instantiated and solves a scene here.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <type_traits>
#include <viscoroll/material/generalized_maxwell.hpp>
#include <viscoroll/quadrature/adaptive.hpp>
#include <viscoroll/viscoroll.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_solver_family {

namespace {
using viscoroll::AdaptiveGaussKronrod;
using viscoroll::Elastic;
using viscoroll::GaussLegendre;
using viscoroll::GeneralizedMaxwell;
using viscoroll::LineSolver;
using viscoroll::PlaneSolver;
using viscoroll::PronyRelaxation;
using viscoroll::StandardLinearSolid;

// A solver template accepts <Real, Material, Quadrature> when the template-id is valid.
template <class R, class M, class Q>
concept PlaneAccepts = requires {
  typename PlaneSolver<R, M, Q>;
};
template <class R, class M, class Q>
concept LineAccepts = requires {
  typename LineSolver<R, M, Q>;
};
}  // namespace

// The materials: what each provides, as ConstitutiveModel states it.
static_assert(viscoroll::ConstitutiveModel<Elastic<float>>);
static_assert(viscoroll::ConstitutiveModel<StandardLinearSolid<long double>>);
static_assert(viscoroll::ConstitutiveModel<GeneralizedMaxwell<double>>);
static_assert(viscoroll::ConstitutiveModel<PronyRelaxation<double>>);
static_assert(viscoroll::SingleTimeModel<Elastic<double>>);
static_assert(viscoroll::SingleTimeModel<StandardLinearSolid<double>>);
static_assert(!viscoroll::SingleTimeModel<GeneralizedMaxwell<double>>);
static_assert(!viscoroll::SingleTimeModel<PronyRelaxation<double>>);

// Combinations that work ...
static_assert(PlaneAccepts<double, StandardLinearSolid<double>, GaussLegendre<double, 24>>);
static_assert(PlaneAccepts<float, Elastic<float>, AdaptiveGaussKronrod<float>>);
static_assert(LineAccepts<double, StandardLinearSolid<double>, GaussLegendre<double, 16>>);
static_assert(LineAccepts<long double, Elastic<long double>, GaussLegendre<long double, 12>>);
// The plane and the line solver take a spectrum (docs/theory.md, sections 12 and 14) ...
static_assert(PlaneAccepts<double, GeneralizedMaxwell<double>, GaussLegendre<double, 24>>);
static_assert(PlaneAccepts<double, PronyRelaxation<double>, GaussLegendre<double, 16>>);
static_assert(LineAccepts<double, PronyRelaxation<double>, GaussLegendre<double, 12>>);
// ... and those that cannot: a scalar that is not the material's, an adaptive rule where the
// line solver needs fixed nodes, a type that is not a constitutive model.
static_assert(!PlaneAccepts<float, PronyRelaxation<double>, GaussLegendre<float, 24>>);
static_assert(!LineAccepts<double, double, GaussLegendre<double, 12>>);
static_assert(!LineAccepts<float, StandardLinearSolid<double>, GaussLegendre<float, 12>>);
static_assert(!LineAccepts<double, StandardLinearSolid<double>, AdaptiveGaussKronrod<double>>);

// The scalar deduced from the material.
static_assert(std::is_same_v<decltype(PlaneSolver(StandardLinearSolid<float>(1, 0.5f, 9, 1))),
                             PlaneSolver<float, StandardLinearSolid<float>>>);
static_assert(std::is_same_v<decltype(LineSolver(Elastic<double>(1, 0.3))),
                             LineSolver<double, Elastic<double>>>);

TEST_CASE("solver family: a plane solver over another rule agrees with the default",
          "[needs][plane]") {
  // f = 9, tau = 1, c = 1/(4 pi): a0 = 1 at load pi/10; V tau = a0.
  const StandardLinearSolid<double> m(1.0, 0.5, 9.0, 1.0);
  const viscoroll::PlaneScene<double> scene{.c1 = 1.0, .load = std::acos(-1.0) / 10, .speed = 1.0};
  const auto ref = PlaneSolver(m).solve(scene);
  const auto gk =
      PlaneSolver<double, StandardLinearSolid<double>, AdaptiveGaussKronrod<double>>(m).solve(
          scene);
  REQUIRE(ref.converged);
  REQUIRE(gk.converged);
  // a, b and chi do not use the rule (closed forms given a): the same digits.
  CHECK(gk.a == ref.a);
  CHECK(gk.chi == ref.chi);
  // The pressure (35) does: the adaptive rule's tolerance (3.7e-11 in double,
  // quadrature/adaptive.hpp) against the 24-point panels' rounding-level result.
  const double x = ref.b;
  CHECK(std::abs(gk.pressure(x) - ref.pressure(x)) <= 1e-9 * ref.pressure(x));
}

TEST_CASE("solver family: a line solver over 16-point panels agrees with the default 12",
          "[needs][line]") {
  const StandardLinearSolid<double> m(1.0, 0.5, 9.0, 1.0);
  // The paper's 5:1 scene (c2 = 0.0798291 c1) with a0 = 1 at V tau = a0 (docs/validation.md).
  const viscoroll::LineScene<double> scene{
      .c1 = 1.0, .c2 = 0.0798291, .load = 2.0943951, .speed = 1.0};
  const viscoroll::LineOptions options{.terms = 4};
  const auto ref = LineSolver(m, options).solve(scene);
  const auto g16 =
      LineSolver<double, StandardLinearSolid<double>, GaussLegendre<double, 16>>(m, options)
          .solve(scene);
  REQUIRE(ref.converged);
  REQUIRE(g16.converged);
  // Both rules integrate every line integral to rounding on the graded panels (docs/theory.md
  // section 7); the roots agree to the residual tolerance's effect, 64 sqrt(eps) ~ 1e-6.
  CHECK(std::abs(g16.l() - ref.l()) <= 1e-6 * ref.l());
  CHECK(std::abs(g16.d - ref.d) <= 1e-6 * std::abs(ref.d));
  CHECK(std::abs(g16.chi - ref.chi) <= 1e-6 * ref.chi);
}

}  // namespace test_solver_family
