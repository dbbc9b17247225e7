// Tests of viscoroll/quadrature/gauss_legendre.hpp.
#include <boost/math/quadrature/gauss.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/quadrature/gauss_legendre.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_gauss_legendre {

using viscoroll::GaussLegendre;
using Mp50 = boost::multiprecision::cpp_bin_float_50;

static_assert(viscoroll::QuadratureRule<GaussLegendre<double, 8>, double>);
static_assert(viscoroll::QuadratureRule<GaussLegendre<float, 1>, float>);
static_assert(viscoroll::QuadratureRule<GaussLegendre<long double, 64>, long double>);
static_assert(viscoroll::QuadratureRule<GaussLegendre<Mp50, 10>, Mp50>);

namespace {

template <class T, int N>
void check_structure() {
  using std::abs;
  const T eps = std::numeric_limits<T>::epsilon();
  const auto& x = GaussLegendre<T, N>::nodes();
  const auto& w = GaussLegendre<T, N>::weights();
  const auto& y = GaussLegendre<T, N>::complements();
  INFO("N = " << N);
  T sum = 0;
  for (int j = 0; j < N; ++j) {
    CHECK(x[j] == -x[N - 1 - j]);
    CHECK(w[j] == w[N - 1 - j]);
    CHECK(w[j] > 0);
    CHECK(abs(x[j]) < 1);
    if (j > 0) CHECK(x[j - 1] < x[j]);
    // 1 - |x_j| rounds the complement to an absolute eps/2 (plus eps/2 for x_j itself).
    CHECK(abs(y[j] - (1 - abs(x[j]))) <= eps);
    sum += w[j];
  }
  // Recursive summation of N positive terms of total 2 errs by at most (N - 1) eps * 2, and each
  // weight is rounded by at most eps/2 of itself: 2N eps in all.
  CHECK(abs(sum - 2) <= 2 * N * eps);
}

/// int_0^1 x^k dx = 1/(k + 1) for k <= 2N - 1. The mapped nodes (1 + t_j)/2 carry an absolute
/// rounding of eps/2, which x^k amplifies to k eps/2 relative to the integral (times k + 1 over k);
/// summation adds at most 2N eps and pow one more: (k + 2N + 2) eps.
template <class T, int N>
void check_exactness() {
  using std::abs;
  using std::pow;
  const T eps = std::numeric_limits<T>::epsilon();
  for (int k = 0; k <= 2 * N - 1; ++k) {
    const T integral = GaussLegendre<T, N>::integrate([k](T t) { return pow(t, k); }, T(0), T(1));
    const T exact = T(1) / T(k + 1);
    INFO("N = " << N << ", k = " << k << ": " << integral << " vs " << exact);
    CHECK(abs(integral - exact) <= T(k + 2 * N + 2) * eps * exact);
  }
}

/// Degree 2N is not integrated exactly: the error for x^{2N} on [0, 1] is
/// (N!)^4 / ((2N + 1) ((2N)!)^2) (A&S 25.4.30 with f^{(2N)} = (2N)!), and the rule falls short.
template <class T, int N>
void check_degree_is_sharp() {
  using std::abs;
  using std::pow;
  T factorial_n = 1, factorial_2n = 1;
  for (int i = 1; i <= N; ++i) factorial_n *= i;
  for (int i = 1; i <= 2 * N; ++i) factorial_2n *= i;
  const T predicted = pow(factorial_n, 4) / (T(2 * N + 1) * factorial_2n * factorial_2n);
  const T integral = GaussLegendre<T, N>::integrate([](T t) { return pow(t, 2 * N); }, T(0), T(1));
  const T shortfall = T(1) / T(2 * N + 1) - integral;
  INFO("N = " << N << ": shortfall " << shortfall << ", predicted " << predicted);
  CHECK(abs(shortfall - predicted) <= predicted / 1000 + 8 * std::numeric_limits<T>::epsilon());
}

}  // namespace

TEMPLATE_TEST_CASE("Gauss-Legendre nodes and weights have their closed forms for N <= 4",
                   "[quadrature]", float, double, long double, Mp50) {
  using T = TestType;
  using std::abs;
  using std::sqrt;
  // Each closed form is computed in T with at most two roundings of its own: 4 eps relative.
  const T tol = 4 * std::numeric_limits<T>::epsilon();
  auto close = [tol](const T& a, const T& b) { return abs(a - b) <= tol * abs(b); };
  CHECK(GaussLegendre<T, 1>::nodes()[0] == 0);
  CHECK(GaussLegendre<T, 1>::weights()[0] == 2);
  CHECK(close(GaussLegendre<T, 2>::nodes()[1], 1 / sqrt(T(3))));
  CHECK(close(GaussLegendre<T, 2>::weights()[0], T(1)));
  CHECK(GaussLegendre<T, 3>::nodes()[1] == 0);
  CHECK(close(GaussLegendre<T, 3>::nodes()[2], sqrt(T(3) / 5)));
  CHECK(close(GaussLegendre<T, 3>::weights()[1], T(8) / 9));
  CHECK(close(GaussLegendre<T, 3>::weights()[2], T(5) / 9));
  // A&S 25.4 table, N = 4: sqrt(3/7 -+ (2/7) sqrt(6/5)), weights (18 +- sqrt(30)) / 36.
  CHECK(close(GaussLegendre<T, 4>::nodes()[2], sqrt(T(3) / 7 - T(2) / 7 * sqrt(T(6) / 5))));
  CHECK(close(GaussLegendre<T, 4>::nodes()[3], sqrt(T(3) / 7 + T(2) / 7 * sqrt(T(6) / 5))));
  CHECK(close(GaussLegendre<T, 4>::weights()[2], (18 + sqrt(T(30))) / 36));
  CHECK(close(GaussLegendre<T, 4>::weights()[3], (18 - sqrt(T(30))) / 36));
}

TEMPLATE_TEST_CASE("Gauss-Legendre rules are symmetric, ordered and their weights sum to 2",
                   "[quadrature]", float, double, long double) {
  check_structure<TestType, 1>();
  check_structure<TestType, 2>();
  check_structure<TestType, 5>();
  check_structure<TestType, 8>();
  check_structure<TestType, 33>();
  check_structure<TestType, 64>();
  check_structure<TestType, 150>();
}

TEMPLATE_TEST_CASE("Gauss-Legendre is exact for polynomials of degree 2N - 1", "[quadrature]",
                   float, double, long double) {
  check_exactness<TestType, 1>();
  check_exactness<TestType, 2>();
  check_exactness<TestType, 3>();
  check_exactness<TestType, 5>();
  check_exactness<TestType, 8>();
  check_exactness<TestType, 20>();
}

TEMPLATE_TEST_CASE("Gauss-Legendre is not exact for degree 2N", "[quadrature]", float, double,
                   long double) {
  check_degree_is_sharp<TestType, 1>();
  check_degree_is_sharp<TestType, 2>();
  check_degree_is_sharp<TestType, 3>();
  check_degree_is_sharp<TestType, 4>();
}

TEST_CASE("Gauss-Legendre in cpp_bin_float_50", "[quadrature][multiprecision]") {
  check_structure<Mp50, 12>();
  check_exactness<Mp50, 12>();
  check_degree_is_sharp<Mp50, 6>();
}

TEST_CASE("Gauss-Legendre agrees with Boost's tabulated rules", "[quadrature]") {
  // boost::math::quadrature::gauss<double, N> stores the non-negative abscissas and their weights
  // from 35-digit tables: an independent source, equal to ours within one ulp each.
  auto compare = [](const auto& ours_x, const auto& ours_w, const auto& boost_x,
                    const auto& boost_w, int n) {
    const double eps = std::numeric_limits<double>::epsilon();
    for (std::size_t i = 0; i < boost_x.size(); ++i) {
      const int index =
          n / 2 + static_cast<int>(i);  // Boost lists the zero (odd N) and positive nodes
      INFO("N = " << n << ", i = " << i);
      CHECK(std::abs(ours_x[index] - boost_x[i]) <= eps * boost_x[i]);
      CHECK(std::abs(ours_w[index] - boost_w[i]) <= eps * boost_w[i]);
    }
  };
  compare(GaussLegendre<double, 7>::nodes(), GaussLegendre<double, 7>::weights(),
          boost::math::quadrature::gauss<double, 7>::abscissa(),
          boost::math::quadrature::gauss<double, 7>::weights(), 7);
  compare(GaussLegendre<double, 20>::nodes(), GaussLegendre<double, 20>::weights(),
          boost::math::quadrature::gauss<double, 20>::abscissa(),
          boost::math::quadrature::gauss<double, 20>::weights(), 20);
  compare(GaussLegendre<double, 30>::nodes(), GaussLegendre<double, 30>::weights(),
          boost::math::quadrature::gauss<double, 30>::abscissa(),
          boost::math::quadrature::gauss<double, 30>::weights(), 30);
}

TEMPLATE_TEST_CASE("Gauss-Legendre complements keep full relative precision near the ends",
                   "[quadrature]", double, long double) {
  // 1 - x_j for the nodes nearest 1, against the same rule computed in 50 digits: within one ulp
  // of the complement itself, which 1 - x_j formed from the rounded x_j (error eps/2 absolute,
  // about 600 eps relative for the outermost of 64 nodes) is not.
  using T = TestType;
  using std::abs;
  const auto& y = GaussLegendre<T, 64>::complements();
  const auto& y_ref = GaussLegendre<Mp50, 64>::complements();
  const T eps = std::numeric_limits<T>::epsilon();
  for (int j = 0; j < 8; ++j) {
    const T ref = static_cast<T>(y_ref[j]);
    INFO("j = " << j);
    CHECK(abs(y[j] - ref) <= eps * ref);
  }
}

TEMPLATE_TEST_CASE("Gauss-Legendre integrates over reversed, empty and general intervals",
                   "[quadrature]", float, double, long double) {
  using T = TestType;
  using std::abs;
  using std::exp;
  const T eps = std::numeric_limits<T>::epsilon();
  using Rule = GaussLegendre<T, 16>;
  auto f = [](T t) { return exp(t); };
  const T e_minus_1 = exp(T(1)) - 1;
  // Gauss' error for e^t with N = 16 is e (16!)^4 / (33 (32!)^3) < 1e-40: what remains is rounding,
  // 2N eps for the sum (as for the weights) plus 2 eps for exp and the reference.
  CHECK(abs(Rule::integrate(f, T(0), T(1)) - e_minus_1) <= T(2 * 16 + 2) * eps * e_minus_1);
  CHECK(abs(Rule::integrate(f, T(1), T(0)) + e_minus_1) <= T(2 * 16 + 2) * eps * e_minus_1);
  CHECK(Rule::integrate(f, T(0.5), T(0.5)) == 0);
  CHECK(abs(Rule::integrate([](T) { return T(3); }, T(-2), T(5)) - 21) <= T(2 * 16 + 2) * eps * 21);
}

}  // namespace test_gauss_legendre
