// Tests of viscoroll/quadrature/adaptive.hpp.
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <viscoroll/core/errors.hpp>
#include <viscoroll/quadrature/adaptive.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_adaptive {

using viscoroll::AdaptiveGaussKronrod;
using Mp50 = boost::multiprecision::cpp_bin_float_50;

static_assert(viscoroll::QuadratureRule<AdaptiveGaussKronrod<double>, double>);
static_assert(viscoroll::QuadratureRule<AdaptiveGaussKronrod<float, 15, 5>, float>);
static_assert(viscoroll::QuadratureRule<AdaptiveGaussKronrod<long double, 61>, long double>);
static_assert(viscoroll::QuadratureRule<AdaptiveGaussKronrod<Mp50>, Mp50>);

TEMPLATE_TEST_CASE("adaptive Gauss-Kronrod tolerance is eps^(2/3)", "[quadrature]", float, double,
                   long double) {
  using T = TestType;
  using std::cbrt;
  using std::sqrt;
  const T eps = std::numeric_limits<T>::epsilon();
  const T tol = AdaptiveGaussKronrod<T>::tolerance();
  CHECK(tol == cbrt(eps) * cbrt(eps));
  CHECK(tol > eps);
  CHECK(tol < sqrt(eps));
}

TEMPLATE_TEST_CASE("adaptive Gauss-Kronrod integrates smooth integrands to rounding",
                   "[quadrature]", float, double, long double) {
  using T = TestType;
  using std::abs;
  using std::cos;
  using std::exp;
  using std::sin;
  using Rule = AdaptiveGaussKronrod<T>;
  const T eps = std::numeric_limits<T>::epsilon();
  const T pi = boost::math::constants::pi<T>();
  // For integrands analytic around the interval the Kronrod error is far below the accepted
  // |K - G| <= eps^(2/3) L1 (adaptive.hpp); what remains is rounding in a 31-term sum of positive
  // terms and in the reference: 8 eps of the L1 norm.
  SECTION("exp on [0, 1]") {
    const T exact = exp(T(1)) - 1;
    CHECK(abs(Rule::integrate([](T x) { return exp(x); }, T(0), T(1)) - exact) <= 8 * eps * exact);
  }
  SECTION("1/(1 + x^2) on [0, 1]") {
    CHECK(abs(Rule::integrate([](T x) { return 1 / (1 + x * x); }, T(0), T(1)) - pi / 4) <=
          8 * eps * (pi / 4));
  }
  SECTION("cos on [0, 10], cancelling: error relative to its L1 norm") {
    // L1 = int_0^10 |cos| = 6 (three half periods to 3 pi) + sin(10 - 3 pi).
    const T norm = 6 + sin(T(10) - 3 * pi);
    CHECK(abs(Rule::integrate([](T x) { return cos(x); }, T(0), T(10)) - sin(T(10))) <=
          8 * eps * norm);
  }
  SECTION("reversed and empty intervals") {
    const T forward = Rule::integrate([](T x) { return exp(x); }, T(0), T(1));
    CHECK(Rule::integrate([](T x) { return exp(x); }, T(1), T(0)) == -forward);
    CHECK(Rule::integrate([](T x) { return exp(x); }, T(2), T(2)) == 0);
  }
  SECTION("infinite limits") {
    const T inf = std::numeric_limits<T>::infinity();
    CHECK(abs(Rule::integrate([](T x) { return exp(-x); }, T(0), inf) - 1) <= 8 * eps);
    CHECK(abs(Rule::integrate([](T x) { return 1 / (1 + x * x); }, -inf, inf) - pi) <=
          8 * eps * pi);
    CHECK(abs(Rule::integrate([](T x) { return exp(-x); }, inf, T(0)) + 1) <= 8 * eps);
  }
}

TEMPLATE_TEST_CASE("adaptive Gauss-Kronrod reports failure instead of a wrong number",
                   "[quadrature]", float, double, long double) {
  using T = TestType;
  SECTION("a jump that three bisections cannot resolve") {
    // After 3 levels the panel holding the jump at 1/3 is 1/8 wide: |K - G| there is ~0.1, far
    // above eps^(2/3) times the L1 norm 2/3.
    auto step = [](T x) { return x < T(1) / 3 ? T(0) : T(1); };
    using Shallow = AdaptiveGaussKronrod<T, 15, 3>;
    CHECK_THROWS_AS(Shallow::integrate(step, T(0), T(1)), viscoroll::ConvergenceError);
    CHECK_THROWS_WITH(Shallow::integrate(step, T(0), T(1)), Catch::Contains("[0, 1]") &&
                                                                Catch::Contains("error estimate") &&
                                                                Catch::Contains("15 points"));
  }
  SECTION("an integrand that is NaN somewhere") {
    auto bad = [](T x) { return x > T(0.5) ? std::numeric_limits<T>::quiet_NaN() : x; };
    CHECK_THROWS_AS(AdaptiveGaussKronrod<T>::integrate(bad, T(0), T(1)),
                    viscoroll::ConvergenceError);
  }
  SECTION("NaN limits") {
    CHECK_THROWS_AS(AdaptiveGaussKronrod<T>::integrate([](T x) { return x; },
                                                       std::numeric_limits<T>::quiet_NaN(), T(1)),
                    std::invalid_argument);
  }
}

TEST_CASE("adaptive Gauss-Kronrod in cpp_bin_float_50", "[quadrature][multiprecision]") {
  using std::abs;
  using std::exp;
  const Mp50 exact = exp(Mp50(1)) - 1;
  const Mp50 integral =
      AdaptiveGaussKronrod<Mp50>::integrate([](const Mp50& x) { return exp(x); }, Mp50(0), Mp50(1));
  // As for the built-in types, plus cpp_bin_float_50's own exp error (up to 3.4 eps measured): 16
  // eps.
  CHECK(abs(integral - exact) <= 16 * std::numeric_limits<Mp50>::epsilon() * exact);
}

}  // namespace test_adaptive
