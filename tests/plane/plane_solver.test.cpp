// Tests of the plane (Hunter) solver against closed forms, limits and identities of
// docs/theory.md section 1. The comparison with an independent discretisation of Hunter's
// Eq. (2) is in plane_vs_collocation.test.cpp.
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/quadrature/adaptive.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_solver {

namespace {

using viscoroll::PlaneScene;
using viscoroll::PlaneSolver;
using viscoroll::StandardLinearSolid;

template <class Real>
Real eps() {
  return std::numeric_limits<Real>::epsilon();
}

/// A scene with a0 = 1: c = 1/(2 pi) (mu_D = 1, nu = 0), W = C1 / (4 c (1+f)).
template <class Real>
struct Scene {
  Real f, vtau;
  StandardLinearSolid<Real> material() const { return {Real(1), Real(0), f, vtau}; }
  PlaneScene<Real> scene() const {
    const Real c = 1 / (2 * std::acos(Real(-1)));
    return {Real(1), 1 / (4 * c * (1 + f)), Real(1)};  // speed 1, so V tau = tau
  }
};

/// int_{b-a}^{b+a} x^n p(x) dx by adaptive Gauss-Kronrod in x = b + a cos(theta), which removes
/// the square-root edges; tolerance `tol` relative.
template <class Solution, class Real>
Real moment(const Solution& s, int n, Real tol) {
  using std::cos;
  using std::pow;
  using std::sin;
  auto integrand = [&](Real theta) {
    const Real x = s.b + s.a * cos(theta);
    return pow(x, n) * s.pressure(x) * s.a * sin(theta);
  };
  Real error = 0;
  const Real pi = std::acos(Real(-1));
  const Real value = boost::math::quadrature::gauss_kronrod<Real, 31>::integrate(
      integrand, Real(0), pi, 15, tol, &error);
  return value;
}

}  // namespace

TEMPLATE_TEST_CASE("plane: slow and fast limits", "[plane]", float, double, long double) {
  using Real = TestType;
  // (P6): V tau -> 0 is Hertz with the long-term compliance (a = a0, b = 0); V tau -> inf Hertz
  // with the instantaneous one, a = a0 (1+f)^(-1/2). The departure is O(V tau / a0) resp.
  // O((a0 / V tau) ln(V tau / a0)): at V tau = 1e-9 a0 resp. 1e9 a0 it is below 1e-6.
  for (Real f : {Real(1), Real(9)}) {
    const Scene<Real> slow{f, Real(1e-9)};
    const auto s =
        PlaneSolver<Real, StandardLinearSolid<Real>>(slow.material()).solve(slow.scene());
    INFO("f = " << f);
    CHECK(s.converged);
    CHECK(std::abs(s.a - 1) <= Real(1e-6));
    CHECK(std::abs(s.b) <= Real(1e-6));
    const Scene<Real> fast{f, Real(1e9)};
    const auto t =
        PlaneSolver<Real, StandardLinearSolid<Real>>(fast.material()).solve(fast.scene());
    CHECK(t.converged);
    CHECK(std::abs(t.a * std::sqrt(1 + f) - 1) <= Real(1e-6));
    CHECK(std::abs(t.b) <= Real(1e-6));
    CHECK(std::abs(t.chi) <= Real(1e-6));
  }
}

TEMPLATE_TEST_CASE("plane: static and elastic scenes are Hertz", "[plane]", float, double,
                   long double) {
  using Real = TestType;
  const Real pi = std::acos(Real(-1));
  const Scene<Real> rest{Real(9), Real(0)};
  const auto s = PlaneSolver<Real, StandardLinearSolid<Real>>(rest.material()).solve(rest.scene());
  const viscoroll::Elastic<Real> elastic(Real(1) / 10, Real(0));  // mu = mu_D / (1 + f)
  const auto e = PlaneSolver<Real, viscoroll::Elastic<Real>>(elastic).solve(rest.scene());
  for (const auto& sol : {s, e}) {
    CHECK(std::abs(sol.a - 1) <= 4 * eps<Real>());
    CHECK(sol.b == 0);
    CHECK(sol.chi == 0);
    const Real W = rest.scene().load;
    for (Real x : {Real(-0.9), Real(0), Real(0.5)})
      CHECK(std::abs(sol.pressure(x) - 2 * W / pi * std::sqrt(1 - x * x)) <= 16 * eps<Real>() * W);
    const auto peak = sol.peak();
    CHECK(std::abs(peak.pressure - 2 * W / pi) <= 16 * eps<Real>() * W);
  }
}

TEMPLATE_TEST_CASE("plane: one root", "[plane]", double) {
  using Real = TestType;
  // (P5): h(A) changes sign exactly once between the glassy and long-term widths.
  for (Real f : {Real(1), Real(9), Real(1000)})
    for (Real v : {Real(1e-3), Real(0.1), Real(1), Real(10), Real(1e3)}) {
      auto h = [&](Real A) {
        const Real ri = viscoroll::special::bessel_i1_over_i0((1 + f) * A / v);
        const Real rk = viscoroll::special::bessel_k1_over_k0(A / v);
        return A * A + 2 * f / (1 + f) * v * A * ri * rk / (ri + rk) - 1;
      };
      const Real lo = 1 / std::sqrt(1 + f);
      int changes = 0;
      Real prev = h(lo);
      for (int i = 1; i <= 2000; ++i) {
        const Real cur = h(lo + (1 - lo) * i / 2000);
        changes += (prev < 0) != (cur < 0);
        prev = cur;
      }
      INFO("f = " << f << ", V tau / a0 = " << v);
      CHECK(changes == 1);
    }
}

TEMPLATE_TEST_CASE("plane: pressure invariants", "[plane]", float, double, long double) {
  using Real = TestType;
  // p >= 0, zero at both edges (trailing edge: P3), integrating to W; the moments are taken by
  // adaptive quadrature to `tol`, so they agree to tol plus the rounding of p (a few hundred eps
  // of accumulated panel sums).
  const Real tol = std::max(Real(1e-12), 64 * eps<Real>());
  for (Real f : {Real(1), Real(9)})
    for (Real vtau : {Real(0.01), Real(0.3), Real(1), Real(10), Real(100)}) {
      const Scene<Real> sc{f, vtau};
      const auto s = PlaneSolver<Real, StandardLinearSolid<Real>>(sc.material()).solve(sc.scene());
      INFO("f = " << f << ", V tau = " << vtau);
      REQUIRE(s.converged);
      const Real W = sc.scene().load, pscale = W / s.a;
      CHECK(s.pressure(s.b + s.a) == 0);
      CHECK(s.pressure(s.b - s.a) == 0);
      // Just inside the edges p is small (square-root behaviour), and never negative.
      CHECK(std::abs(s.pressure(s.b - s.a * (1 - Real(1e-6)))) <= Real(1e-2) * pscale);
      Real pmin = 0;
      for (int i = 1; i < 400; ++i)
        pmin = std::min(pmin, s.pressure(s.b - s.a * std::cos(std::acos(Real(-1)) * i / 400)));
      CHECK(pmin >= -256 * eps<Real>() * pscale);
      const Real load = moment(s, 0, tol);
      CHECK(std::abs(load - W) <= (tol + 512 * eps<Real>()) * W);
    }
}

TEMPLATE_TEST_CASE("plane: chi from the pressure", "[plane]", double, long double) {
  using Real = TestType;
  // (P7) against C1 int x p / int p of the reconstructed pressure (Eq. 51), and against the
  // paper's (54) where it does not cancel (V tau <= 10 a0: at most one digit lost).
  const Real tol = std::max(Real(1e-13), 64 * eps<Real>());
  for (Real f : {Real(1), Real(9)})
    for (Real vtau : {Real(0.01), Real(0.1), Real(1), Real(10), Real(100)}) {
      const Scene<Real> sc{f, vtau};
      const auto s = PlaneSolver<Real, StandardLinearSolid<Real>>(sc.material()).solve(sc.scene());
      INFO("f = " << f << ", V tau = " << vtau << ", chi = " << s.chi);
      const Real chi_p = sc.scene().c1 * moment(s, 1, tol) / moment(s, 0, tol);
      // The moments carry an error relative to their L1 norms, W a0 and W: so chi_p's error is
      // relative to C1 a0 (= 1), not to chi, which is small at small V tau.
      CHECK(std::abs(chi_p - s.chi) <= 4 * tol + 1024 * eps<Real>());
      if (vtau <= 10) {
        const Real chi54 = sc.scene().c1 * vtau * (f / (1 + f) - s.q / s.f0);  // Eq. (54)
        CHECK(std::abs(chi54 - s.chi) <= 64 * eps<Real>() * (sc.scene().c1 * vtau));
      }
    }
}

TEST_CASE("plane: a pressure peak sits at the leading edge at small speed", "[plane]") {
  // Section 7 and Fig. 6: at small V tau a local pressure maximum forms inside the leading-edge
  // layer of width ~ V tau / (1 + f) (the global maximum stays near the centre, at the Hertz
  // value).
  const Scene<double> slow{9.0, 0.01};
  const auto s =
      PlaneSolver<double, StandardLinearSolid<double>>(slow.material()).solve(slow.scene());
  const double layer = 0.01 / 10, edge = s.b + s.a, window = 20 * layer;
  const auto local = s.strip.peak_between(edge - window, edge);
  INFO("local peak at " << local.x << ", leading edge " << edge);
  CHECK(local.x > edge - window / 2);  // strictly inside the window: a genuine local maximum
  CHECK(local.x < edge);
  CHECK(s.strip.pressure_slope(local.x - layer) > 0);
  CHECK(s.strip.pressure_slope(local.x + layer / 4) < 0);
  // Far above the Hertz pressure there (which is (2W/(pi a^2)) sqrt(a^2 - xi^2)).
  const double xi = local.x - s.b, W = slow.scene().load;
  CHECK(local.pressure >
        3 * 2 * W / (std::acos(-1.0) * s.a * s.a) * std::sqrt(s.a * s.a - xi * xi));
}

TEST_CASE("plane: the scene is validated", "[plane][validation]") {
  const viscoroll::PlaneSolverD solver(StandardLinearSolid<double>(1, 0.3, 9, 1));
  CHECK_THROWS_WITH(solver.solve({0.0, 1.0, 1.0}), Catch::Contains("c1"));
  CHECK_THROWS_WITH(solver.solve({1.0, -1.0, 1.0}), Catch::Contains("load"));
  CHECK_THROWS_WITH(solver.solve({1.0, 1.0, std::nan("")}), Catch::Contains("speed"));
  CHECK_THROWS_AS(viscoroll::PlaneSolverD(StandardLinearSolid<double>(1, 0.3, 9, 1),
                                          viscoroll::PlaneOptions{0}),
                  std::invalid_argument);
}

TEST_CASE("plane: the quadrature policy only changes rounding", "[plane][quadrature]") {
  // The reconstruction (35) is exact to rounding with the default 24-point rule on its panels
  // (docs/theory.md section 2); a 16-point rule and the adaptive Gauss-Kronrod rule (tolerance
  // eps^(2/3) on |K - G|, error ~ eps for these smooth panel integrands) give the same pressure.
  using SLS = StandardLinearSolid<double>;
  for (double vtau : {0.01, 1.0, 100.0}) {
    const Scene<double> sc{9.0, vtau};
    const auto fixed = PlaneSolver<double, SLS>(sc.material()).solve(sc.scene());
    const auto g16 = PlaneSolver<double, SLS, viscoroll::GaussLegendre<double, 16>>(sc.material())
                         .solve(sc.scene());
    const auto adaptive =
        PlaneSolver<double, SLS, viscoroll::AdaptiveGaussKronrod<double>>(sc.material())
            .solve(sc.scene());
    const double scale = sc.scene().load / fixed.a;
    for (double s : {-0.999, -0.5, 0.0, 0.7, 0.999}) {
      const double x = fixed.b + s * fixed.a;
      INFO("V tau = " << vtau << ", s = " << s);
      CHECK(std::abs(g16.pressure(x) - fixed.pressure(x)) <= 256 * eps<double>() * scale);
      CHECK(std::abs(adaptive.pressure(x) - fixed.pressure(x)) <= 256 * eps<double>() * scale);
    }
  }
}

TEMPLATE_TEST_CASE("plane: extreme speeds and creep ratios", "[plane][stiff]", float, double,
                   long double) {
  using Real = TestType;
  // Nothing overflows or loses digits for V tau/a0 from 1e-4 to 1e4, here with f up to
  // 1e4 (alpha = (1+f) a/(V tau) up to 1e8). The load is met to the moment quadrature's
  // tolerance plus the rounding of p; p >= 0 to rounding.
  const Real tol = std::max(Real(1e-12), 64 * eps<Real>());
  for (Real f : {Real(0), Real(1), Real(1e4)})
    for (Real vtau : {Real(1e-4), Real(1e4)}) {
      const Scene<Real> sc{f, vtau};
      const auto s = PlaneSolver<Real, StandardLinearSolid<Real>>(sc.material()).solve(sc.scene());
      INFO("f = " << f << ", V tau/a0 = " << vtau << ", a = " << s.a << ", b = " << s.b
                  << ", chi = " << s.chi);
      REQUIRE(s.converged);
      CHECK(std::isfinite(static_cast<double>(s.chi)));
      CHECK(s.a <= 1 + 4 * eps<Real>());
      CHECK(s.a >= 1 / std::sqrt(1 + f) * (1 - 4 * eps<Real>()));
      CHECK(s.b >= 0);
      CHECK(s.chi >= 0);
      const Real W = sc.scene().load;
      const auto peak = s.peak();
      CHECK(std::isfinite(static_cast<double>(peak.pressure)));
      CHECK(peak.pressure > 0);
      CHECK(std::abs(moment(s, 0, tol) - W) <= (tol + 4096 * eps<Real>()) * W);
    }
}

}  // namespace test_plane_solver
