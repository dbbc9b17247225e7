// The line solver at the ends of the floating-point range: every finite scene whose
// solution is representable is solved, in units of powers of two in which nothing overflows or
// underflows (docs/theory.md, "Scaling"), and one whose solution is not throws
// std::invalid_argument naming the quantity and the inputs (docs/errors.md). Checked through the
// exact invariance of the line problem under a change of the units of length and force.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <viscoroll/line/line_solver.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_extremes {

namespace {

using viscoroll::LineScene;
using viscoroll::StandardLinearSolid;

/// A line scene of the CLI's reproductions: mu_D, nu = 0.5, f = 9, tau = 1; c1, c2, load, speed.
struct Scene {
  double mu_d, c1, c2, load, speed;
  auto solve(int terms = 4) const {
    viscoroll::LineOptions options;
    options.terms = terms;
    return viscoroll::LineSolverD(StandardLinearSolid<double>(mu_d, 0.5, 9, 1), options)
        .solve(LineScene<double>{.c1 = c1, .c2 = c2, .load = load, .speed = speed});
  }
  /// The same scene with lengths in units s times smaller and pressures in units m times larger:
  /// C1, C2 -> C1/s, C2/s, mu_D -> m mu_D (c -> c/m), V -> s V and, by (47) (C1 a0^2 l/3 =
  /// (1 + f) c P), P -> s^2 m P. Every length of the solution (a, b, l, d) is then s times what it
  /// was and chi the same; for powers of two s and m, bit for bit.
  Scene scaled(double s, double m) const {
    return {m * mu_d, c1 / s, c2 / s, s * s * m * load, s * speed};
  }
};

/// The paper's scene (a0 = 1, l0 = 5) at V tau = vtau.
Scene paper(double vtau) {
  const double c = 0.5 / (2 * std::acos(-1.0));
  return {1, 1, (std::log(20.0) - 1) / 25, 5.0 / (3 * 10 * c), vtau};
}

bool same_bits(double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); }

/// A converged result whose numbers are finite, a(0), l, d and the long-term ones positive.
template <class Solution>
void check_valid(const Solution& s) {
  REQUIRE(s.converged);
  for (double x :
       {s.a(0.0), s.b(0.0), s.l(), s.d, s.chi, s.a_long_term, s.l_long_term, s.d_long_term})
    CHECK(std::isfinite(x));
  CHECK(s.a(0.0) > 0);
  CHECK(s.l() > 0);
  CHECK(s.d > 0);
  CHECK(s.a_long_term > 0);
  CHECK(s.l_long_term > 0);
  CHECK(s.d_long_term > 0);
}

}  // namespace

TEST_CASE(
    "line extremes: scenes at the ends of the floating-point range are solved, bit for bit as "
    "in ordinary units",
    "[line][extremes]") {
  const double two = 2;
  struct Case {
    Scene scene;
    int k, j;  // the ordinary scene is scene.scaled(2^-k, 2^-j)
  };
  // The CLI's --mu-d 1e-308, --load 1e308, and c1, c2 1e-300 times the paper's, each at the speed
  // where V tau is about a0 (rolling, N = 4): a0 = 4.6e102, 4.6e102, 1.3e100.
  const Scene base = paper(1);
  for (const Case& c : {Case{{1e-308, base.c1, base.c2, base.load, 4.6e102}, 340, -1023},
                        Case{{1, base.c1, base.c2, 1e308, 4.6e102}, 340, 0},
                        Case{{1, 1e-300, 1e-300 * base.c2, base.load, 1.3e100}, 332, 0}}) {
    INFO("mu_d = " << c.scene.mu_d << ", c1 = " << c.scene.c1 << ", load = " << c.scene.load
                   << ", speed = " << c.scene.speed);
    const auto s = c.scene.solve();
    check_valid(s);
    CHECK(s.root);
    CHECK(s.iterations > 0);  // rolling, not a closed form
    const double sk = std::pow(two, -c.k), mj = std::pow(two, -c.j);
    const Scene ordinary = c.scene.scaled(sk, mj);
    REQUIRE(std::isnormal((1 + 9) * 0.5 / (2 * std::acos(-1.0) * ordinary.mu_d) * ordinary.load /
                          ordinary.c1));  // the plain formula (47) for a0^3 l is normal there
    const auto o = ordinary.solve();
    REQUIRE(o.iterations == s.iterations);
    CHECK(same_bits(o.a(0.0), sk * s.a(0.0)));
    CHECK(same_bits(o.b(0.0), sk * s.b(0.0)));
    CHECK(same_bits(o.l(), sk * s.l()));
    CHECK(same_bits(o.d, sk * s.d));
    CHECK(same_bits(o.chi, s.chi));
    CHECK(same_bits(o.a_long_term, sk * s.a_long_term));
  }
  // V tau = 1e308 (--speed 1e308): the glassy closed form, a0 (1 + f)^(-1/3).
  const auto glassy = Scene{1, base.c1, base.c2, base.load, 1e308}.solve();
  check_valid(glassy);
  CHECK(glassy.code == viscoroll::StopCode::converged);
  // Which closed form has no code of its own: the reason names it.
  CHECK(glassy.reason == "glassy limit (closed form)");
  CHECK(std::abs(glassy.a(0.0) - glassy.a_long_term / std::cbrt(10.0)) <=
        8 * std::numeric_limits<double>::epsilon());
  // The static closed forms of --load 1e308 and --mu-d 1e-308 (at speed 1: V tau/a0 = 2e-103).
  for (const Scene& s :
       {Scene{1, base.c1, base.c2, 1e308, 1}, Scene{1e-308, base.c1, base.c2, base.load, 1}}) {
    const auto st = s.solve();
    check_valid(st);
    CHECK(st.code == viscoroll::StopCode::converged);
    CHECK(st.reason == "static (closed form)");
    CHECK(std::abs(st.l() / st.a(0.0) - 5) <= 1e-5);  // l0/a0 = 5 for this C2/C1
  }
  // --c1 1e308 with c2 = 0.08: C2/C1 = 8e-310 is not a normal number.
  CHECK_THROWS_WITH((Scene{1, 1e308, base.c2, base.load, 1}.solve()),
                    Catch::Contains("c2/c1 = 7.98e-310 is below the smallest normal number") &&
                        Catch::Contains("c1 = 1e+308") && Catch::Contains("c2 = 0.0798"));
}

TEST_CASE("line extremes: unrepresentable solutions throw naming the quantity and the inputs",
          "[line][extremes]") {
  const auto throws = [](const Scene& s, const char* what) {
    INFO(what);
    CHECK_THROWS_AS(s.solve(), std::invalid_argument);
    CHECK_THROWS_WITH(s.solve(), Catch::Contains(what) && Catch::Contains("c1 = ") &&
                                     Catch::Contains("load = ") &&
                                     Catch::Contains("compliance = ") &&
                                     Catch::Contains("rescale the units"));
  };
  const double ratio = paper(1).c2;
  // mu_D = 1e308: 2 pi mu_D overflows, c = 0.
  throws({1e308, 1, ratio, 1, 1}, "the instantaneous compliance c = 0 is below");
  // a0^3 = 3 (1 + f) c P / (C1 rho) = 1e-934: a0 = 1e-311.
  throws({1e305, 1e308, 1e308 * ratio, 1e-320, 0}, "the half width a(0) = ");
  // a0 = 1e200, d ~ C1 a0^2 = 1e400.
  throws({1e-300, 1, ratio, 1e300, 0}, "the penetration d = ");
  // a0 = 7.8e-301 rolling at V tau = 1e-310 = 1.3e-10 a0: b(0) ~ V tau f/(1 + f) is subnormal.
  throws({1e300, 1e300, 1e300 * ratio, 1e-300, 1e-310}, "the offset b(0) = ");
}

TEST_CASE(
    "line extremes: random scenes over the range of double end in a finite result or an "
    "error",
    "[line][extremes]") {
  // Inputs log-uniform over 1e-300..1e300 (c2/c1 over 1e-6..0.39, speed relative to a0 over
  // 1e-3..1e3 half the time), N = 3: a converged result has finite, positive a(0), l and d; any
  // other is not converged or an invalid_argument.
  std::mt19937_64 gen(24);
  std::uniform_real_distribution<double> u(-300, 300), ur(-6, std::log10(0.39)), uv(-3, 3);
  int solved = 0, rejected = 0, rolling = 0;
  for (int i = 0; i < 60; ++i) {
    const double mu_d = std::pow(10.0, u(gen)), c1 = std::pow(10.0, u(gen));
    const double c2 = c1 * std::pow(10.0, ur(gen)), load = std::pow(10.0, u(gen));
    double speed = std::pow(10.0, u(gen));
    if (i % 2 == 0) {
      try {  // near V tau = a0, where the line equations are solved
        speed =
            std::pow(10.0, uv(gen)) *
            viscoroll::static_line_contact(c1, c2, 10 * 0.5 / (2 * std::acos(-1.0) * mu_d) * load)
                .a0;
      } catch (const std::invalid_argument&) {
      }
    }
    INFO("mu_d = " << mu_d << ", c1 = " << c1 << ", c2 = " << c2 << ", load = " << load
                   << ", speed = " << speed);
    try {
      const auto s = Scene{mu_d, c1, c2, load, speed}.solve(3);
      if (s.converged) {
        check_valid(s);
        ++solved;
        if (s.iterations > 0) ++rolling;
      }
    } catch (const std::invalid_argument&) {
      ++rejected;
    }
  }
  CHECK(solved >= 30);
  CHECK(rolling >= 10);
  CHECK(rejected >= 1);
}

}  // namespace test_line_extremes
