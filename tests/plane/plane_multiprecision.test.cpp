// The plane solver over boost::multiprecision::cpp_bin_float_50: the policies compose with a
// class-type scalar, and the 50-digit solution agrees with the long double one to long double's
// accuracy while satisfying the load identity (P2) to its own epsilon.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_multiprecision {

TEST_CASE("plane: multiprecision solution", "[plane][multiprecision]") {
  using mp = boost::multiprecision::cpp_bin_float_50;
  using viscoroll::StandardLinearSolid;
  const mp pi = boost::math::constants::pi<mp>();
  const mp f = 9, vtau = 1, c = 1 / (2 * pi);
  const mp W = 1 / (4 * c * (1 + f));  // a0 = 1
  // 48 points: a panel on which e^-u falls by e^8 is then exact far below 1e-50 (theory.md sec. 2).
  const viscoroll::PlaneSolver<mp, StandardLinearSolid<mp>, viscoroll::GaussLegendre<mp, 48>>
      solver(StandardLinearSolid<mp>(mp(1), mp(0), f, vtau));
  const auto s = solver.solve({mp(1), W, mp(1)});
  const long double ld_pi = boost::math::constants::pi<long double>(), ld_c = 1 / (2 * ld_pi);
  const auto r = viscoroll::PlaneSolver<long double, StandardLinearSolid<long double>>(
                     StandardLinearSolid<long double>(1, 0, 9, 1))
                     .solve({1.0L, 1 / (4 * ld_c * 10), 1.0L});
  const mp eps50 = std::numeric_limits<mp>::epsilon();
  const long double eps_ld = std::numeric_limits<long double>::epsilon();
  REQUIRE(s.converged);
  // (P2): a^2 + 2G = a0^2 = 1, to the 50-digit epsilon (16 ulps for the few operations).
  CHECK(abs(s.a * s.a + 2 * s.g - 1) <= 16 * eps50);
  // Long double is accurate to a few of its ulps: Bessel ratios <= 2 eps
  // (docs/special-functions.md), the root to 4 eps, a condition number of order 1
  // (measured: 1-3 ulps).
  CHECK(abs(s.a - mp(r.a)) <= 16 * eps_ld);
  CHECK(abs(s.b - mp(r.b)) <= 16 * eps_ld);
  CHECK(abs(s.chi - mp(r.chi)) <= 16 * eps_ld);
  const mp x = s.b + s.a / 3;
  CHECK(abs(s.pressure(x) - mp(r.pressure(static_cast<long double>(x)))) <=
        32 * eps_ld * W);  // panel sums: measured 1.5 ulps of W
}

}  // namespace test_plane_multiprecision
