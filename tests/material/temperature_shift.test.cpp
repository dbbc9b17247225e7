// Time–temperature superposition (docs/theory.md (R11)–(R13), docs/materials.md).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <viscoroll/material/temperature_shift.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_temperature_shift {

using viscoroll::ArrheniusShift;
using viscoroll::WlfShift;

TEMPLATE_TEST_CASE("temperature: a_T(T_ref) = 1 and hand values of WLF and Arrhenius (R11), (R12)",
                   "[material][temperature]", float, double, long double) {
  using T = TestType;
  // Catch's Approx is in double: the bound is that of the coarser type.
  const double eps =
      std::max(double(std::numeric_limits<T>::epsilon()), std::numeric_limits<double>::epsilon());
  const WlfShift<T> wlf(T(17.44), T(51.6), T(20));
  CHECK(wlf.factor(T(20)) == T(1));
  CHECK(wlf.log10_factor(T(20)) == T(0));
  // T = 30: log10 a_T = -17.44 * 10 / 61.6 = -2.831168831...
  CHECK(wlf.log10_factor(T(30)) == Approx(-2.8311688311688312).epsilon(8 * eps));
  CHECK(wlf.factor(T(30)) == Approx(1.4751329666105512e-3).epsilon(64 * eps));
  // T = 0: -17.44 * (-20) / 31.6 = 11.037974683544304.
  CHECK(wlf.log10_factor(T(0)) == Approx(11.037974683544304).epsilon(8 * eps));
  const ArrheniusShift<T> arr(T(1e5), T(25));
  CHECK(arr.factor(T(25)) == T(1));
  // T = 50 degC: ln a_T = 1e5 / 8.31446261815324 (1/323.15 - 1/298.15) = -3.1208065561...
  CHECK(arr.log_factor(T(50)) == Approx(-3.120806556173878).epsilon(16 * eps));
  CHECK(arr.factor(T(50)) == Approx(0.04412156754186686).epsilon(64 * eps));
  CHECK(arr.log10_factor(T(0)) > 0);  // colder: slower, a_T > 1
}

TEST_CASE("temperature: every time of the material is scaled by a_T (R13)",
          "[material][temperature]") {
  const WlfShift<double> wlf(8.86, 101.6, 20.0);
  const double t = 45.0, a = wlf.factor(t);
  const viscoroll::PronyRelaxation<double> m(1e6, 0.49, {{1e8, 1e-6}, {3e7, 1e-3}, {1e7, 1.0}});
  const auto hot = viscoroll::at_temperature(m, wlf, t);
  REQUIRE(hot.terms().size() == 3);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(hot.terms()[i].rho == m.terms()[i].rho * a);
    CHECK(hot.terms()[i].g == m.terms()[i].g);
    CHECK(hot.memory_terms()[i].tau == Approx(m.memory_terms()[i].tau * a).epsilon(1e-14));
    CHECK(hot.memory_terms()[i].f == Approx(m.memory_terms()[i].f).epsilon(1e-14));
  }
  CHECK(hot.g_inf() == m.g_inf());
  // A material at a temperature is a material: its moduli at f are those at f a_T at T_ref.
  CHECK(hot.storage_modulus(10.0) == Approx(m.storage_modulus(10.0 * a)).epsilon(1e-14));
  CHECK(hot.loss_modulus(10.0) == Approx(m.loss_modulus(10.0 * a)).epsilon(1e-14));
  const auto creep = viscoroll::at_temperature(m.to_creep(), wlf, t);
  for (std::size_t k = 0; k < 3; ++k)
    CHECK(creep.terms()[k].tau == m.to_creep().terms()[k].tau * a);
  const viscoroll::StandardLinearSolid<double> sls(1.0, 0.3, 9.0, 2.0);
  const viscoroll::ShiftLaw<double> law = viscoroll::ArrheniusShift<double>(8e4, 20.0);
  const auto s = viscoroll::at_temperature(sls, law, 60.0);
  CHECK(s.relaxation_time() == 2.0 * viscoroll::shift_factor(law, 60.0));
  CHECK(s.creep_ratio() == 9.0);
  const auto e = viscoroll::at_temperature(viscoroll::Elastic<double>(1.0, 0.3), wlf, t);
  CHECK(e.mu_d() == 1.0);
}

TEST_CASE("temperature: the singular WLF temperature and invalid constants are rejected by name",
          "[material][temperature][validation]") {
  const WlfShift<double> wlf(17.44, 51.6, 20.0);
  CHECK_THROWS_WITH(wlf.factor(-31.6), Catch::Contains("temperature = -31.6") &&
                                           Catch::Contains("temperature > t_ref - c2 = -31.6"));
  CHECK_THROWS_AS(wlf.factor(-40.0), std::invalid_argument);
  CHECK_NOTHROW(wlf.factor(-25.0));
  CHECK_THROWS_WITH(viscoroll::at_temperature(viscoroll::Elastic<double>(1.0, 0.3), wlf, -50.0),
                    Catch::Contains("temperature"));
  CHECK_THROWS_WITH(wlf.factor(std::numeric_limits<double>::quiet_NaN()),
                    Catch::Contains("temperature"));
  CHECK_THROWS_WITH(WlfShift<double>(0.0, 51.6, 20.0), Catch::Contains("c1 = 0"));
  CHECK_THROWS_WITH(WlfShift<double>(17.44, -1.0, 20.0), Catch::Contains("c2 = -1"));
  CHECK_THROWS_WITH(ArrheniusShift<double>(-5.0, 20.0), Catch::Contains("activation_energy = -5"));
  CHECK_THROWS_WITH(ArrheniusShift<double>(1e5, -300.0), Catch::Contains("t_ref = -300"));
  CHECK_THROWS_WITH(ArrheniusShift<double>(1e5, 20.0).factor(-273.15),
                    Catch::Contains("temperature = -273.15"));
  // a_T overflowing is an error naming the temperature, not an infinite time.
  CHECK_THROWS_WITH(WlfShift<double>(1e3, 51.6, 20.0).factor(-31.0),
                    Catch::Contains("temperature"));
}

}  // namespace test_temperature_shift
