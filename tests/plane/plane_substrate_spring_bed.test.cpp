// PlaneSubstrateSolver on a spring bed (docs/plane-substrate.md (Q10)-(Q12)) against an
// independent solution for a standard linear solid: the memory m(x) = int_0^inf e^-eta
// p(x + L eta) d eta obeys L m' = m - p, and with u = kappa (p + f m) = g(x) on the contact the
// first-order ODE L m' = (1 + f) m - g/kappa, m(x2) = 0, gives
//   m(x) = 1/(kappa L) int_x^{x2} exp(-(1 + f)(s - x)/L) g(s) ds,   p = g/kappa - f m,
// here in closed form by the exponential's three moments (the solver uses the eigenvectors and
// scaled moments of (Q11)), p(x1) = 0 found by TOMS 748, int p and int x p by adaptive
// Gauss-Kronrod (the solver: graded Gauss-Legendre panels) and the load by a root in x2.
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_substrate_solver.hpp>
#include <viscoroll/substrate/substrate.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_substrate_spring_bed {

using viscoroll::PlaneScene;
using viscoroll::PlaneSubstrateSolver;
using viscoroll::SpringBed;

struct BedReference {
  double x1, x2, chi;
};

/// The independent solution of the rolling spring bed, one memory term (f, L = V tau),
/// compliance kappa = h / E.
BedReference reference(double kappa, double f, double length, double c1, double load) {
  using boost::math::quadrature::gauss_kronrod;
  const double beta = (1 + f) / length;
  const auto pressure = [&](double x, double x2) {
    // m(x) in closed form: with t = s - x, Delta = x2 - x, E = exp(-beta Delta),
    // int_0^Delta e^{-beta t} (x2^2 - x^2 - 2 x t - t^2) dt from the three moments
    // (1 - E)/beta, (1 - E (1 + beta Delta))/beta^2, (2 - E (2 + 2 beta Delta + (beta
    // Delta)^2))/beta^3. Below beta Delta = 1, where these cancel, 20-point Gauss-Legendre on [0,
    // Delta] instead.
    const double delta = x2 - x, y = beta * delta, e = std::exp(-y);
    double integral = 0;
    if (y < 1) {
      integral = boost::math::quadrature::gauss<double, 20>::integrate(
          [&](double t) { return std::exp(-beta * t) * ((x2 - x) * (x2 + x) - 2 * x * t - t * t); },
          0.0, delta);
    } else {
      const double m0 = -std::expm1(-y) / beta, m1 = (1 - e * (1 + y)) / (beta * beta),
                   m2 = (2 - e * (2 + 2 * y + y * y)) / (beta * beta * beta);
      integral = (x2 - x) * (x2 + x) * m0 - 2 * x * m1 - m2;
    }
    const double m = c1 / 2 * integral / (kappa * length);
    return c1 / 2 * (x2 - x) * (x2 + x) / kappa - f * m;
  };
  const auto tol = boost::math::tools::eps_tolerance<double>(50);
  const auto trailing = [&](double x2) {
    double hi = x2 * (1 - 1e-6), lo = hi - x2 / 64;
    while (pressure(lo, x2) > 0) {
      hi = lo;
      lo -= x2 / 64;
    }
    std::uintmax_t it = 200;
    const auto r = boost::math::tools::toms748_solve([&](double x) { return pressure(x, x2); }, lo,
                                                     hi, tol, it);
    return (r.first + r.second) / 2;
  };
  const auto moment = [&](double x2, int k) {
    const double x1 = trailing(x2);
    return gauss_kronrod<double, 31>::integrate(
        [&](double x) { return (k == 0 ? 1.0 : x) * pressure(x, x2); }, x1, x2, 15, 1e-14);
  };
  std::uintmax_t it = 200;
  const double glassy = std::cbrt(3 * load * kappa / (2 * c1));
  const auto r =
      boost::math::tools::toms748_solve([&](double x2) { return moment(x2, 0) - load; }, glassy / 2,
                                        2 * glassy * std::cbrt(1 + f), tol, it);
  const double x2 = (r.first + r.second) / 2;
  return {trailing(x2), x2, c1 * moment(x2, 1) / moment(x2, 0)};
}

TEST_CASE("plane substrate: the spring bed equals the SLS's ODE solution", "[plane][substrate]") {
  const double nu = 0.3, mu = 1.0, h = 0.1, f = 2.0, c1 = 1.0, load = 0.1;
  const viscoroll::StandardLinearSolid<double> m(mu, nu, f, 1.0);
  const double kappa = h / (2 * (1 + nu) * mu);  // u = h p / E
  const double a_long = std::cbrt(3 * load * kappa * (1 + f) / (2 * c1));
  const viscoroll::PlaneSubstrateOptions options{};
  for (double ratio : {0.01, 0.1, 1.0, 10.0, 100.0}) {
    const double speed = ratio * a_long;  // tau = 1
    const auto s = PlaneSubstrateSolver(m, SpringBed<double>(h), options)
                       .solve(PlaneScene<double>{.c1 = c1, .load = load, .speed = speed});
    const auto ref = reference(kappa, f, speed, c1, load);
    const double a = (ref.x2 - ref.x1) / 2, b = (ref.x2 + ref.x1) / 2, d = c1 * ref.x2 * ref.x2 / 2;
    INFO("V tau / a = " << ratio << ": a " << s.a << " vs " << a << ", b " << s.b << " vs " << b
                        << ", chi " << s.chi << " vs " << ref.chi << ", d " << s.d << " vs " << d);
    REQUIRE(s.converged);
    CHECK(s.d_absolute);
    const double tol = options.tolerance;
    CHECK(std::abs(s.a - a) <= tol * a);
    CHECK(std::abs(s.b - b) <= tol * a);
    CHECK(std::abs(s.chi - ref.chi) <= tol * std::abs(ref.chi));
    CHECK(std::abs(s.d - d) <= tol * d);
    CHECK(s.pressure(ref.x2 + 1e-3 * a) == 0);
    CHECK(s.peak().pressure > 0);
  }
}

TEST_CASE("plane substrate: the static spring bed is the closed form", "[plane][substrate]") {
  // V = 0: p = (d - C1 x^2/2) / (kappa (1 + f)), a^3 = 3 W kappa (1 + f) / (2 C1).
  const viscoroll::StandardLinearSolid<double> m(2.0, 0.4, 3.0, 1.0);
  const double h = 0.05, c1 = 2.0, load = 0.3, kappa = h / (2 * 1.4 * 2.0);
  const auto s = PlaneSubstrateSolver(m, SpringBed<double>(h))
                     .solve(PlaneScene<double>{.c1 = c1, .load = load, .speed = 0.0});
  const double a = std::cbrt(3 * load * kappa * 4 / (2 * c1));
  const double eps = std::numeric_limits<double>::epsilon();
  REQUIRE(s.converged);
  CHECK(std::abs(s.a - a) <= 64 * eps * a);
  CHECK(std::abs(s.b) <= 64 * eps * a);
  CHECK(std::abs(s.chi) <= 64 * eps * c1 * a);
  CHECK(std::abs(s.peak().pressure - c1 * a * a / (2 * kappa * 4)) <= 64 * eps * s.peak().pressure);
}

}  // namespace test_plane_substrate_spring_bed
