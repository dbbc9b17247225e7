// The plane solver at the ends of the floating-point range: every finite scene whose
// solution is representable is solved, in units in which nothing overflows or underflows
// (docs/theory.md, "Scaling"), and one whose solution is not throws std::invalid_argument naming
// the quantity and the inputs (docs/errors.md). Checked through the exact invariance of the plane
// problem under a change of the units of length and force.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <viscoroll/plane/plane_solver.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_extremes {

namespace {

using viscoroll::PlaneScene;
using viscoroll::StandardLinearSolid;

template <class Real>
using Solver = viscoroll::PlaneSolver<Real, StandardLinearSolid<Real>>;

/// A scene of the CLI's reproductions: mu_D, nu = 0.5, f, tau; c1, load, speed.
template <class Real>
struct Scene {
  Real mu_d, f, tau, c1, load, speed;
  auto solve() const {
    return Solver<Real>(StandardLinearSolid<Real>(mu_d, Real(0.5), f, tau))
        .solve({c1, load, speed});
  }
  /// The same scene with lengths in units s times smaller and forces in units m s times smaller
  /// (pressures m times larger): C1 -> C1/s, W -> s m W, mu_D -> m mu_D, V -> s V, tau and f
  /// unchanged. Then a0^2 = 4 c (1 + f) W / C1 -> s^2 a0^2 (c = (1 - nu)/(2 pi mu_D) -> c/m) and
  /// V tau/a0 is unchanged: every length of the solution is s times, G s^2 times, F0 and Q
  /// (C1 times a length squared) s times, chi the same and the pressure m times what it was.
  Scene scaled(Real s, Real m) const { return {m * mu_d, f, tau, c1 / s, s * m * load, s * speed}; }
};

template <class Real>
Real eps() {
  return std::numeric_limits<Real>::epsilon();
}

/// |x - y| <= tol |y|.
template <class Real>
bool close(Real x, Real y, Real tol) {
  return std::abs(x - y) <= tol * std::abs(y);
}

/// A converged solution that is finite and has the signs of (P5)-(P7): a0, a, F0 and the peak
/// positive, b, G, Q and chi non-negative, a between the glassy and long-term widths.
template <class Solution, class Real>
void check_valid(const Solution& s, Real f) {
  CHECK(s.converged);
  for (Real x : {s.a, s.b, s.g, s.a_long_term, s.f0, s.q, s.chi}) CHECK(std::isfinite(x));
  CHECK(s.a_long_term > 0);
  CHECK(s.a > 0);
  CHECK(s.a <= s.a_long_term * (1 + 4 * eps<Real>()));
  CHECK(s.a >= s.a_long_term / std::sqrt(1 + f) * (1 - 4 * eps<Real>()));
  CHECK(s.b >= 0);
  CHECK(s.g >= 0);
  CHECK(s.f0 > 0);
  CHECK(s.q >= 0);
  CHECK(s.chi >= 0);
  const auto peak = s.peak();
  CHECK(std::isfinite(peak.pressure));
  CHECK(peak.pressure > 0);
  CHECK(std::isfinite(peak.x));
}

/// `big` is `small` in units s and m (Scene::scaled) to `tol` relative (each quantity) and the
/// peak location to `tol_x` of a.
template <class Solution, class Real>
void check_scaled(const Solution& big, const Solution& small, Real s, Real m, Real tol,
                  Real tol_x) {
  CHECK(close(big.a_long_term, s * small.a_long_term, tol));
  CHECK(close(big.a, s * small.a, tol));
  CHECK(close(big.b, s * small.b, tol));
  CHECK(close(big.g, s * s * small.g, tol));
  CHECK(close(big.f0, s * small.f0, tol));
  CHECK(close(big.q, s * small.q, tol));
  CHECK(close(big.chi, small.chi, tol));
  const auto p = big.peak(), q = small.peak();
  CHECK(close(p.pressure, m * q.pressure, tol));
  CHECK(std::abs((p.x - big.b) - s * (q.x - small.b)) <= tol_x * big.a);
  // p relative to its peak: near the trailing edge p -> 0 is the difference of O(peak) terms.
  for (Real t : {Real(-0.9), Real(0), Real(0.6)})
    CHECK(std::abs(big.pressure(big.b + t * big.a) - m * small.pressure(small.b + t * small.a)) <=
          tol * p.pressure);
}

/// The location of the peak: the root of the slope (7), whose rounding is amplified by alpha =
/// (1 + f) a / V tau (StripPressure::peak_between), or Brent's estimate, sqrt(eps) of the width,
/// on a static strip.
template <class Real>
Real peak_tolerance(Real f, Real a, Real vtau_over_a0) {
  if (vtau_over_a0 <= eps<Real>() || vtau_over_a0 > 1 / eps<Real>())
    return 4 * std::sqrt(eps<Real>());
  return 256 * eps<Real>() * (1 + (1 + f) * a / vtau_over_a0);
}

}  // namespace

TEST_CASE(
    "plane extremes: scenes at the ends of the floating-point range are solved or rejected by name",
    "[plane][extremes]") {
  using S = Scene<double>;
  const double two = 2, pi = std::acos(-1.0);
  // c1 = 1e-308, load = 1e308, mu_D = 1e-308, c1 = 1e-300 with load = 1e300: 4 c (1 + f) W / C1
  // overflows, a0 ~ 1e154 and 1e300 do not. Each equals, bit for bit, the same scene in units
  // 2^-k smaller, where that product is a normal number (a power of two scales exactly).
  struct Case {
    S scene;
    int k, j;  // the ordinary scene is scene.scaled(2^-k, 2^-j)
  };
  for (const Case& c :
       {Case{{1, 9, 1, 1e-308, 1, 1}, 600, 0}, Case{{1, 9, 1, 1, 1e308, 1}, 600, 0},
        Case{{1e-308, 9, 1, 1, 1, 1}, 600, -1000}, Case{{1, 9, 1, 1e-300, 1e300, 1}, 900, 0}}) {
    INFO("c1 = " << c.scene.c1 << ", load = " << c.scene.load << ", mu_d = " << c.scene.mu_d);
    const auto s = c.scene.solve();
    check_valid(s, c.scene.f);
    const double sk = std::pow(two, -c.k), mj = std::pow(two, -c.j);
    const S ordinary = c.scene.scaled(sk, mj);
    const double x = 4 * (0.5 / (2 * pi * ordinary.mu_d)) * 10 * ordinary.load / ordinary.c1;
    REQUIRE(std::isnormal(x));  // the plain formula for a0^2 does not overflow there
    check_scaled(ordinary.solve(), s, sk, mj, 0.0, 0.0);
  }
  // V tau = 1e308 is the glassy closed form (V tau/a0 = 5.6e308 overflows: glassy, (P6));
  // tau = 1e-300 at the same speed rolls at V tau/a0 = 5.6e8.
  const auto glassy = S{1, 9, 1, 1, 0.01, 1e308}.solve();
  check_valid(glassy, 9.0);
  CHECK(glassy.b == 0);
  CHECK(close(glassy.a * std::sqrt(10.0), glassy.a_long_term, 4 * eps<double>()));
  const auto fast = S{1, 9, 1e-300, 1, 0.01, 1e308}.solve();
  check_valid(fast, 9.0);
  CHECK(fast.b > 0);
  // The glassy width sqrt(4 c W / C1) = 1.2e-162 of load = 4.9e-324 is representable; F0 = c W
  // is not.
  CHECK_THROWS_WITH(
      (S{1, 9, 1, 1, 4.9e-324, 1}.solve()),
      Catch::Contains("F0 of Eq. (33) = 3.93e-325 is below the smallest normal number 2.23e-308") &&
          Catch::Contains("load = 4.94065645841247e-324") && Catch::Contains("rescale the units"));
}

TEST_CASE("plane extremes: unrepresentable solutions throw naming the quantity and the inputs",
          "[plane][extremes]") {
  using S = Scene<double>;
  const auto throws = [](const S& s, const char* what) {
    INFO(what);
    CHECK_THROWS_AS(s.solve(), std::invalid_argument);
    CHECK_THROWS_WITH(s.solve(), Catch::Contains(what) && Catch::Contains("c1 = ") &&
                                     Catch::Contains("load = ") &&
                                     Catch::Contains("compliance = ") &&
                                     Catch::Contains("rescale the units"));
  };
  // mu_D = 1e308: 2 pi mu_D overflows, c = 0; mu_D = 1e307: c subnormal.
  throws({1e308, 9, 1, 1, 1, 1}, "the instantaneous compliance c = 0 is below");
  throws({1e307, 9, 1, 1, 1, 1}, "the instantaneous compliance c = 7.96e-309 is below");
  // a0 = 5.6e308 and 1.8e-313.
  throws({0.1, 9, 1, 1e-308, 1e308, 1},
         "the long-term half width a0 = sqrt(4 c (1+f) load/c1) = 5.64e+308 is beyond");
  throws({1e10, 9, 1, 1e308, 1e-308, 1},
         "the long-term half width a0 = sqrt(4 c (1+f) load/c1) = 1.78e-313 is below");
  // G ~ a0^2 / 5 at V tau = a0 = 5.6e154 overflows.
  throws({1, 9, 1, 1e-300, 1e10, 5.64e154}, "G of Eq. (36) = ");
  // b ~ 0.45 V tau = 8e-311 at V tau = 1e-10 a0, a0 = 1.8e-300.
  throws({1, 9, 1e-10, 1e300, 1e-300, 1.78e-300}, "the offset b of the contact = ");
  // The mean pressure W/(2 a) = 2.8e308.
  throws({1e300, 9, 1, 1e10, 1e308, 0}, "the mean pressure load / (2 a) = 2.8");
  // The mean pressure 1.6e308 is finite, the peak (4/pi of it, static Hertz) is not: peak() throws.
  const double c = 0.3125 * 0.3125 / 40 * 1e10 / 1e308;  // a0 = 0.3125 = sqrt(4 c 10 W / C1)
  const S edge{0.5 / (2 * std::acos(-1.0) * c), 9, 1, 1e10, 1e308, 0};
  const auto s = edge.solve();
  CHECK(std::isfinite(s.f0));
  CHECK_THROWS_WITH(s.peak(), Catch::Contains("the pressure peak of the strip = 2.0") &&
                                  Catch::Contains("beyond the largest finite number"));
}

TEMPLATE_TEST_CASE("plane extremes: solutions scale exactly with the units of length and force",
                   "[plane][extremes]", float, double) {
  using Real = TestType;
  using S = Scene<Real>;
  // Lengths in units s, pressures in units m, over the whole exponent range of Real (1e-38..1e38
  // in float, 1e-308..1e308 in double, for every input and product of them: s^2 m and s m up to
  // 10^(2 max10/3)). Static, rolling (V tau/a0 = 0.01, 1, 100) and glassy scenes, f = 9. The
  // inputs of the scaled scene carry one to two roundings each (s m W two), so every quantity
  // agrees to a few eps: 64 eps; the peak location to peak_tolerance.
  const int max10 = std::numeric_limits<Real>::max_exponent10;
  const Real c = Real(0.5) / (2 * std::acos(Real(-1)));
  const Real load = 1 / (4 * c * 10);                       // a0 = 1 at mu_D = c1 = 1
  const Real glassy = std::pow(Real(10), Real(max10 / 2));  // V tau/a0 beyond 40/eps
  for (Real v : {Real(0), Real(0.01), Real(1), Real(100), glassy}) {
    const S base{1, 9, 1, 1, load, v};
    const auto reference = base.solve();
    check_valid(reference, Real(9));
    for (int i : {-2 * max10 / 3, -max10 / 3, -1, 0, 3, max10 / 3, 2 * max10 / 3})
      for (int j : {-max10 / 2, 0, max10 / 3}) {
        const Real s = std::pow(Real(10), Real(i) / 2), m = std::pow(Real(10), Real(j));
        INFO("V tau/a0 = " << v << ", s = " << s << ", m = " << m);
        const auto scaled = base.scaled(s, m).solve();
        check_valid(scaled, Real(9));
        check_scaled(scaled, reference, s, m, 64 * eps<Real>(),
                     peak_tolerance(Real(9), reference.a, v));
      }
  }
}

TEST_CASE("plane extremes: float reproductions", "[plane][extremes]") {
  using S = Scene<float>;
  // 4 c (1 + f) W / C1 = 3e39 overflows float; a0 = 5.6e19 does not.
  const auto s = S{1, 9, 1, 1e-38f, 10, 1}.solve();
  check_valid(s, 9.0f);
  CHECK(close(s.a_long_term, 5.64e19f, 1e-3f));
  CHECK_THROWS_WITH((S{1, 9, 1, 1, 1e-45f, 1}.solve()),
                    Catch::Contains("is below the smallest normal number 1.18e-38"));
  CHECK_THROWS_WITH((S{0.1f, 9, 1, 1e-38f, 1e38f, 1}.solve()),
                    Catch::Contains("a0 = sqrt(4 c (1+f) load/c1)") &&
                        Catch::Contains("beyond the largest finite number 3.4e+38"));
}

}  // namespace test_plane_extremes
