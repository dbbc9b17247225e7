// The line solver in the slow regime (docs/theory.md section 10; docs/line-solver.md,
// "Oversampling"): the mapped variable LineBasis::s_mapped and the least-squares fit over more
// collocation points than unknowns (LineOptions::oversampling).
//   - (O3): the map and its inverse, and its limit (the variable s) for a large scale;
//   - (O4): Chebyshev coefficients of a function with G's poles (s = +-i j_{0,1} e) decay at the
//     rate of the Bernstein ellipse through the nearest pole, in s and in the mapped variable;
//   - (O1)-(O2): the oversampled least-squares solution converges with N at V tau = 0.1 a0, where
//     the square system's roots move by 1e-3 in l, and its discrete norm is converged at k = 2.
//
// Measured values next to the tolerances: Release build, GCC 12, x86-64.
#include <boost/math/special_functions/bessel.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <complex>
#include <limits>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/special/bessel_ratio.hpp>

#include "support/paper_scene.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_slow_regime {

namespace {

using viscoroll::LineBasis;
using viscoroll::LineShape;
using viscoroll::testing::PaperScene;

/// ln rho of the Bernstein ellipse of [-1, 1] through z.
double log_rho(std::complex<double> z) {
  const std::complex<double> root = std::sqrt(z - 1.0) * std::sqrt(z + 1.0);
  return std::log(std::max(std::abs(z + root), std::abs(z - root)));
}

/// The decay rate of Chebyshev coefficients c_k (in the variable `basis`) of I1(s/e)/I0(s/e),
/// s = sqrt(w), measured between the envelopes max_{k in [k1, k1 + 8)} |c_k| and the same at k2.
double measured_log_rho(LineBasis basis, double scale, int k1, int k2) {
  const auto c = LineShape<double>::interpolate(basis, scale, 96, [&](double w) {
    return viscoroll::special::bessel_i1_over_i0(std::sqrt(w) / scale);
  });
  const auto envelope = [&](int k0) {
    double m = 0;
    for (int k = k0; k < k0 + 8; ++k) m = std::max(m, std::abs(c[k]));
    return m;
  };
  return std::log(envelope(k1) / envelope(k2)) / (k2 - k1);
}

}  // namespace

TEMPLATE_TEST_CASE("line shape: the mapped variable and its inverse (O3)", "[line]", double,
                   long double) {
  using Real = TestType;
  using Shape = LineShape<Real>;
  const Real eps = std::numeric_limits<Real>::epsilon();
  for (const Real scale : {Real(1e-4), Real(1e-2), Real(1)}) {
    for (int i = 0; i <= 40; ++i) {
      const Real v = Real(-1) + Real(i) / 20;
      const Real w = Shape::one_minus_t2_at(LineBasis::s_mapped, scale, v);
      INFO("scale " << double(scale) << ", v = " << double(v));
      // v -> w -> v: asinh and sinh, each to a few eps; the factor asinh(1/e) <= 10.
      CHECK(std::abs(Shape::coordinate(LineBasis::s_mapped, scale, w) - v) <= 64 * eps);
    }
    // The ends: v = -1 at s = 0 (the contact's end), v = 1 at s = 1 (y = 0).
    CHECK(Shape::one_minus_t2_at(LineBasis::s_mapped, scale, Real(-1)) == 0);
    CHECK(std::abs(Shape::one_minus_t2_at(LineBasis::s_mapped, scale, Real(1)) - 1) <= 8 * eps);
  }
  // A large scale is the variable s: e sinh(h asinh(1/e)) = h (1 + O(asinh(1/e)^2)), below
  // rounding once e > 1/sqrt(eps); at e = 1e3 the difference is h^3/(6e^2) <= 1.7e-7.
  for (int i = 0; i <= 10; ++i) {
    const Real v = Real(-1) + Real(i) / 5;
    const Real ws = Shape::one_minus_t2_at(LineBasis::s, Real(0), v);
    CHECK(Shape::one_minus_t2_at(LineBasis::s_mapped, 2 / std::sqrt(eps), v) == ws);
    CHECK(Shape::one_minus_t2_at(LineBasis::s_mapped, Real(0), v) == ws);  // scale unset
    CHECK(std::abs(Shape::one_minus_t2_at(LineBasis::s_mapped, Real(1e3), v) - ws) <= 2e-7);
  }
}

TEST_CASE("line shape: Chebyshev series of the strips' Bessel ratio converge as predicted (O4)",
          "[line]") {
  // G (36) carries I1/I0((1 + f) a/V tau), with poles where I0 = 0: at s = +-i j_{0,k} e near the
  // ends (a ~ a_ref s, e = V tau/((1 + f) a_ref)). The coefficients of a function with poles
  // decay as rho^-k, rho of the smallest Bernstein ellipse through one (Trefethen, ATAP,
  // Thm 8.1). In s (v = 2s - 1) the poles are at v = -1 + 2i j_{0,k} e, the first the nearest; in
  // the mapped variable at v = -1 + 2 asinh(i j_{0,k})/asinh(1/e)
  // = -1 + 2 (acosh j_{0,k} + i pi/2)/asinh(1/e): all at the same height, the nearest ellipse
  // through the one closest to v = 0 (k = 7 at e = 1e-3, j_{0,k} e ~ sqrt(e)).
  for (const double scale : {1e-3, 1e-2}) {
    const double big = std::asinh(1 / scale);
    const double pred_s = log_rho({-1.0, 2 * boost::math::cyl_bessel_j_zero(0.0, 1) * scale});
    double pred_m = std::numeric_limits<double>::infinity();
    for (int k = 1; boost::math::cyl_bessel_j_zero(0.0, k) * scale < 100; ++k) {
      const double j0k = boost::math::cyl_bessel_j_zero(0.0, k);
      pred_m = std::min(pred_m, log_rho({-1 + 2 * std::acosh(j0k) / big,
                                         boost::math::constants::pi<double>() / big}));
    }
    const double got_s = measured_log_rho(LineBasis::s, scale, 40, 80);
    const double got_m = measured_log_rho(LineBasis::s_mapped, scale, 8, 40);
    INFO("e = " << scale << ": ln rho in s " << got_s << " (predicted " << pred_s << "), mapped "
                << got_m << " (predicted " << pred_m << ")");
    // Measured: e = 1e-3: s 0.0636 (predicted 0.0694), mapped 0.419 (0.402); e = 1e-2: s 0.224
    // (0.220), mapped 0.552 (0.564). The envelope ratio carries a k^p factor and the windows'
    // phase: 10%.
    CHECK(std::abs(got_s / pred_s - 1) < 0.1);
    CHECK(std::abs(got_m / pred_m - 1) < 0.1);
    // What the map buys: 1e-6 needs ln(1e6)/ln rho terms, 200 in s against 34 mapped at 1e-3.
    if (scale == 1e-3) CHECK(pred_m > 3 * pred_s);
  }
}

TEST_CASE("line solver: oversampled least squares converge in the slow regime (O1, O2)",
          "[line][slow]") {
  // V tau = 0.1 a0 in the variable s. The square system's roots there move by 1e-3 in l between
  // N = 32, 48 and 64 (docs/line-solver.md): they vanish at the N + 1 points and leave 1e-4
  // between them. The least-squares fit over 2 (N + 1) points converges: N = 24 -> 32 measured
  // a(0) 3.0e-7, b(0) 3.8e-6, l 1.0e-6, d 7e-11, chi 0 (relative); bound 1e-5, the size of the
  // residual the line equations keep at this speed (max |r| = 9.6e-6).
  const PaperScene paper;
  const auto scene = paper.scene(0.1);
  const auto solve = [&](int terms, int oversampling) {
    const viscoroll::LineSolverD solver(
        paper.material, {.terms = terms, .basis = LineBasis::s, .oversampling = oversampling});
    return solver.solve(scene);
  };
  const auto n24 = solve(24, 2), n32 = solve(32, 2);
  for (const auto* s : {&n24, &n32}) {
    INFO(s->reason);
    REQUIRE(s->converged);
    CHECK_FALSE(s->root);  // a certified least-squares minimum, max |r| ~ 1e-5
    CHECK(s->residual < 2e-5);
    CHECK(s->residual > 1e-6);
  }
  const auto rel = [](double a, double b) { return std::abs(a / b - 1); };
  CHECK(rel(n24.a(0), n32.a(0)) < 1e-5);
  CHECK(rel(n24.b(0), n32.b(0)) < 1e-5);
  CHECK(rel(n24.l(), n32.l()) < 1e-5);
  CHECK(rel(n24.d, n32.d) < 1e-5);
  CHECK(rel(n24.chi, n32.chi) < 1e-5);
  // (O2) The discrete norm is converged at k = 2: k = 3 at N = 24 moves a(0) by 4e-9, b(0) by
  // 6e-8, l by 1.3e-8 (measured), far below the change with N. Bound 1e-6.
  const auto k3 = solve(24, 3);
  REQUIRE(k3.converged);
  CHECK(rel(k3.a(0), n24.a(0)) < 1e-6);
  CHECK(rel(k3.b(0), n24.b(0)) < 1e-6);
  CHECK(rel(k3.l(), n24.l()) < 1e-6);
}

TEST_CASE("line solver: oversampling is validated", "[line]") {
  const PaperScene paper;
  for (const int k : {0, 9}) {
    try {
      const viscoroll::LineSolverD solver(paper.material, {.terms = 4, .oversampling = k});
      FAIL("oversampling " << k << " accepted");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()).find("oversampling") != std::string::npos);
    }
  }
}

}  // namespace test_slow_regime
