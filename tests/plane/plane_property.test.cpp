// Property test of the plane solver: random scenes, inside and outside the valid ranges.
// Each ends in std::invalid_argument or in a converged solution satisfying the invariants of
// docs/theory.md (P2)-(P7); none in NaN, a crash or a hang. Fixed seed: reproducible.
#include <boost/math/special_functions/fpclassify.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_property {

TEST_CASE("plane: random scenes end in a valid solution or a clear error", "[plane][property]") {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(0, 1);
  const double nan = std::numeric_limits<double>::quiet_NaN(),
               inf = std::numeric_limits<double>::infinity();
  // Mostly log-uniform valid values; 1 in 12 draws replaced by an invalid one.
  auto draw = [&](double lo_exp, double hi_exp, double sign = 1) {
    const double u = unit(rng);
    if (u < 1.0 / 12) {
      const double bad[] = {0.0, -1.0, nan, inf, -inf};
      return bad[static_cast<int>(unit(rng) * 5)];
    }
    return sign * std::pow(10.0, lo_exp + (hi_exp - lo_exp) * unit(rng));
  };
  const double eps = std::numeric_limits<double>::epsilon();
  int solved = 0, rejected = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    const double mu_d = draw(-6, 9), f = unit(rng) < 0.1 ? 0.0 : draw(-3, 4), tau = draw(-6, 4);
    const double nu = unit(rng) < 0.05 ? 0.75 : -0.99 + 1.49 * unit(rng);
    const double c1 = draw(-3, 3), load = draw(-6, 6), speed = unit(rng) < 0.05 ? 0.0 : draw(-3, 3);
    INFO("trial " << trial << ": mu_d " << mu_d << " nu " << nu << " f " << f << " tau " << tau
                  << " c1 " << c1 << " load " << load << " speed " << speed);
    try {
      const viscoroll::PlaneSolverD solver(
          viscoroll::StandardLinearSolid<double>(mu_d, nu, f, tau));
      const auto s = solver.solve({c1, load, speed});
      ++solved;
      REQUIRE(s.converged);
      REQUIRE((boost::math::isfinite)(s.a));
      REQUIRE((boost::math::isfinite)(s.b));
      REQUIRE((boost::math::isfinite)(s.chi));
      // (P5): the glassy and long-term Hertz widths bound a; b >= 0; chi >= 0 (P7).
      CHECK(s.a <= s.a_long_term * (1 + 4 * eps));
      CHECK(s.a >= s.a_long_term / std::sqrt(1 + f) * (1 - 4 * eps));
      CHECK(s.b >= 0);
      CHECK(s.chi >= 0);
      CHECK(s.b - s.a < s.b + s.a);
      // (P2): a^2 + 2G = a0^2.
      CHECK(std::abs(s.a * s.a + 2 * s.g - s.a_long_term * s.a_long_term) <=
            16 * eps * s.a_long_term * s.a_long_term);
      // p >= 0 and finite on the contact (scale W/a), zero at both edges.
      const double pscale = load / s.a;
      for (int i = 1; i < 16; ++i) {
        const double p = s.pressure(s.b - s.a * std::cos(3.141592653589793 * i / 16));
        REQUIRE((boost::math::isfinite)(p));
        CHECK(p >= -1024 * eps * pscale);
      }
      CHECK(s.pressure(s.b + s.a) == 0);
      CHECK(s.pressure(s.b - s.a) == 0);
    } catch (const std::invalid_argument& e) {
      ++rejected;
      CHECK(std::string(e.what()).find("outside the valid range") != std::string::npos);
    }
  }
  INFO(solved << " solved, " << rejected << " rejected");
  CHECK(solved > 4000);
  CHECK(rejected > 2000);
}

}  // namespace test_plane_property
