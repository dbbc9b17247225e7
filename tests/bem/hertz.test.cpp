// Tests of the Hertz reference (docs/bem.md B8): the elliptic-integral forms (B8b) of Ferrers'
// integrals against quadrature, the circle, and the contact matching S = d - h inside the ellipse.
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/bem/hertz.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_hertz {

using viscoroll::bem::hertz_contact;
using viscoroll::bem::hertz_curvature_ratio;

TEST_CASE("bem: Ferrers' integrals (B8b) in elliptic integrals", "[bem]") {
  boost::math::quadrature::exp_sinh<double> rule;
  for (const double kp : {0.9, 0.5, 0.2, 0.05}) {
    const double a = 1.3 * kp, b = 1.3, e2 = 1 - kp * kp, e = std::sqrt(e2);
    const double K = boost::math::ellint_1(e), E = boost::math::ellint_2(e);
    const auto delta = [&](double w) { return std::sqrt(w * (a * a + w) * (b * b + w)); };
    const double tol = 1e-13;
    const double i0 = rule.integrate([&](double w) { return 1 / delta(w); }, tol);
    const double ia = rule.integrate([&](double w) { return 1 / ((a * a + w) * delta(w)); }, tol);
    const double ib = rule.integrate([&](double w) { return 1 / ((b * b + w) * delta(w)); }, tol);
    CHECK(i0 == Approx(2 * K / b).epsilon(1e-11));
    CHECK(ia == Approx(2 * (E - kp * kp * K) / (a * a * b * e2)).epsilon(1e-11));
    CHECK(ib == Approx(2 * (K - E) / (b * b * b * e2)).epsilon(1e-11));
  }
}

TEST_CASE("bem: Hertz contact, circle and ellipse", "[bem]") {
  const double pi = std::acos(-1.0), eps = std::numeric_limits<double>::epsilon();
  // Circle: a^3 = 3 pi c P / (4 C1), d = a^2 C1 (Hertz: d = a^2/R).
  const auto circle = hertz_contact(2.0, 2.0, 0.1, 3.0);
  CHECK(circle.a == Approx(std::cbrt(3 * pi * 0.1 * 3.0 / 8)).epsilon(4 * eps));
  CHECK(circle.b == circle.a);
  CHECK(circle.d == Approx(circle.a * circle.a * 2.0).epsilon(8 * eps));
  // Near-circle continuity of the ratio (B8c) at e -> 0.
  CHECK(hertz_curvature_ratio(1e-4) == Approx(1).epsilon(1e-6));
  // Ellipse: the curvature ratio is reproduced, the semi-axis order follows the curvatures, and
  // P = (2/3) pi a b p0.
  for (const double ratio : {0.9, 0.3, (std::log(20.0) - 1) / 25, 1e-4}) {
    const auto h = hertz_contact(1.0, ratio, 0.05, 2.0);
    const double kp = h.a / h.b, e = std::sqrt(1 - kp * kp);
    // e recomputed from a/b loses digits as e -> 1 (C2/C1 = 1e-4 has 1 - e ~ 1e-5).
    CHECK(hertz_curvature_ratio(e) == Approx(ratio).epsilon(1e-10));
    CHECK(h.a < h.b);
    CHECK(2 * pi * h.a * h.b * h.p0 / 3 == Approx(2.0).epsilon(8 * eps));
    const auto swapped = hertz_contact(ratio, 1.0, 0.05, 2.0);
    CHECK(swapped.a == Approx(h.b).epsilon(8 * eps));
    CHECK(swapped.d == Approx(h.d).epsilon(8 * eps));
  }
  // The 5:1 line-contact scene is a 5.18:1 Hertz ellipse (line theory's static error, a few %).
  const auto scene = hertz_contact(1.0, (std::log(20.0) - 1) / 25, 1.0, 1.0);
  CHECK(scene.b / scene.a == Approx(5.183).epsilon(1e-3));
  CHECK_THROWS_WITH(hertz_contact(-1.0, 1.0, 1.0, 1.0), Catch::Contains("c1 = -1"));
  CHECK_THROWS_WITH(hertz_contact(1.0, 1.0, 1.0, 0.0), Catch::Contains("load = 0"));
}

TEST_CASE("bem: Hertz pressure gives S = d - h inside the ellipse (B8a)", "[bem]") {
  // c int int p / r at a point inside, by quadrature in polar coordinates around the point:
  // int_0^{2 pi} int_0^{rho(theta)} p(x + r cos, y + r sin) dr dtheta (the 1/r cancels r dr).
  const double c = 0.07, load = 1.7, c1 = 1.0, c2 = 0.25;
  const auto h = hertz_contact(c1, c2, c, load);
  boost::math::quadrature::tanh_sinh<double> rule;
  for (const auto& pt :
       {std::pair{0.0, 0.0}, std::pair{0.5 * h.a, 0.3 * h.b}, std::pair{-0.2 * h.a, -0.8 * h.b}}) {
    const double x = pt.first, y = pt.second;
    const auto inner = [&](double theta) {
      const double ct = std::cos(theta), st = std::sin(theta);
      // Distance to the ellipse boundary along theta.
      const double qa = ct * ct / (h.a * h.a) + st * st / (h.b * h.b);
      const double qb = 2 * (x * ct / (h.a * h.a) + y * st / (h.b * h.b));
      const double qc = x * x / (h.a * h.a) + y * y / (h.b * h.b) - 1;
      const double rho = (-qb + std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
      return rule.integrate([&](double r) { return h.pressure(x + r * ct, y + r * st); }, 0.0, rho,
                            1e-12);
    };
    const double u = c * rule.integrate(inner, 0.0, 2 * std::acos(-1.0), 1e-11);
    CHECK(u == Approx(h.d - c1 * x * x / 2 - c2 * y * y / 2).epsilon(1e-9));
  }
}

}  // namespace test_hertz
