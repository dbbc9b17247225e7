#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_material {

using viscoroll::Elastic;
using viscoroll::StandardLinearSolid;

static_assert(viscoroll::ConstitutiveModel<StandardLinearSolid<double>>);
static_assert(viscoroll::ConstitutiveModel<Elastic<float>>);

TEMPLATE_TEST_CASE("standard linear solid compliances", "[material]", float, double, long double) {
  const StandardLinearSolid<TestType> m(TestType(2), TestType(0.25), TestType(9), TestType(0.5));
  const TestType pi = std::acos(TestType(-1));
  const TestType eps = std::numeric_limits<TestType>::epsilon();
  // Eq. (7): (1 - nu) / (2 pi mu_D); the long-term modulus is mu_D / (1 + f).
  CHECK(std::abs(m.instantaneous_compliance() - TestType(0.75) / (4 * pi)) <=
        4 * eps * m.instantaneous_compliance());
  CHECK(std::abs(m.long_term_compliance() - 10 * m.instantaneous_compliance()) <=
        4 * eps * m.long_term_compliance());
}

TEMPLATE_TEST_CASE("material parameters are validated", "[material][validation]", float, double) {
  using T = TestType;
  const T inf = std::numeric_limits<T>::infinity();
  CHECK_THROWS_AS(StandardLinearSolid<T>(T(0), T(0.3), T(1), T(1)), std::invalid_argument);
  CHECK_THROWS_AS(StandardLinearSolid<T>(T(1), T(0.6), T(1), T(1)), std::invalid_argument);
  CHECK_THROWS_AS(StandardLinearSolid<T>(T(1), T(-1), T(1), T(1)), std::invalid_argument);
  CHECK_THROWS_AS(StandardLinearSolid<T>(T(1), T(0.3), T(-1), T(1)), std::invalid_argument);
  CHECK_THROWS_AS(StandardLinearSolid<T>(T(1), T(0.3), T(1), -inf), std::invalid_argument);
  CHECK_THROWS_AS(StandardLinearSolid<T>(T(1), T(0.3), inf, T(1)), std::invalid_argument);
  CHECK_THROWS_AS(Elastic<T>(std::numeric_limits<T>::quiet_NaN(), T(0.3)), std::invalid_argument);
  CHECK_THROWS_WITH(
      StandardLinearSolid<T>(T(1), T(0.7), T(1), T(1)),
      Catch::Contains("nu") && Catch::Contains("0.7") && Catch::Contains("-1 < nu <= 0.5"));
  CHECK_NOTHROW(StandardLinearSolid<T>(T(1), T(0.5), T(0), T(0)));
}

TEMPLATE_TEST_CASE("the spectrum each single-time material gives the solvers", "[material]", float,
                   double, long double) {
  using T = TestType;
  // Eq. (1): the standard linear solid is the one term (f, tau); an elastic solid has none.
  const StandardLinearSolid<T> sls(T(2), T(0.25), T(9), T(0.5));
  STATIC_REQUIRE(StandardLinearSolid<T>::memory_term_count == 1);
  STATIC_REQUIRE(Elastic<T>::memory_term_count == 0);
  REQUIRE(sls.memory_terms().size() == 1);
  CHECK(sls.memory_terms()[0].f == T(9));
  CHECK(sls.memory_terms()[0].tau == T(0.5));
  CHECK(sls.creep_ratio() == sls.memory_terms()[0].f);
  CHECK(Elastic<T>(T(1), T(0.3)).memory_terms().size() == 0);
  // What the plane and line solvers read: the term itself, or (0, 0) without one.
  const auto one = viscoroll::detail::single_memory_term(sls);
  CHECK(one.f == T(9));
  CHECK(one.tau == T(0.5));
  const auto none = viscoroll::detail::single_memory_term(Elastic<T>(T(1), T(0.3)));
  CHECK(none.f == T(0));
  CHECK(none.tau == T(0));
}

}  // namespace test_material
