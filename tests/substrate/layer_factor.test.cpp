// The layer's surface factor T (substrate/layer_factor.hpp, docs/theory.md section 19): the closed
// forms (H2), (H3) against an independent solve of Navier's equations through the layer, the thin
// and thick limits (H4), and the evaluation (H5) at every x.
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>
#include <viscoroll/substrate/layer_factor.hpp>

namespace test_layer_factor {

using viscoroll::layer_factor;
using viscoroll::LayerBase;

/// T by Navier's equations in plane strain (mu = 1, q = 1): u_x = U(z) sin x, u_z = W(z) cos x in
/// 0 <= z <= x (z into the layer) give mu U'' = (lambda + 2 mu) U + (lambda + mu) W' and
/// (lambda + 2 mu) W'' = mu W - (lambda + mu) U', y = (U, U', W, W') and y' = M y. On z = 0 the
/// pressure cos x: sigma_xz = U' - W = 0, sigma_zz = lambda (U + W') + 2 W' = -1; at the base
/// U = W = 0 (bonded) or U' = W = 0 (frictionless, sigma_xz = U' - W = 0 there). y(h) = e^(M h)
/// y(0) by Eigen's matrix exponential; T = W(0) mu q / ((1 - nu) p).
double navier_factor(double h, double nu, LayerBase base) {
  const double lambda = 2 * nu / (1 - 2 * nu);
  Eigen::Matrix4d m;
  m << 0, 1, 0, 0, lambda + 2, 0, 0, lambda + 1, 0, 0, 0, 1, 0, -(lambda + 1) / (lambda + 2),
      1 / (lambda + 2), 0;
  const Eigen::Matrix4d e = (m * h).exp();
  // y(0) = U0 (1, 0, 0, -lambda/(lambda + 2)) + W0 (0, 1, 1, 0) + (0, 0, 0, -1/(lambda + 2)).
  const Eigen::Vector4d ea = e * Eigen::Vector4d(1, 0, 0, -lambda / (lambda + 2));
  const Eigen::Vector4d eb = e * Eigen::Vector4d(0, 1, 1, 0);
  const Eigen::Vector4d ec = e * Eigen::Vector4d(0, 0, 0, -1 / (lambda + 2));
  const int first = base == LayerBase::bonded ? 0 : 1;  // U or U' at the base, and W
  Eigen::Matrix2d a;
  a << ea(first), eb(first), ea(2), eb(2);
  const Eigen::Vector2d s = a.fullPivLu().solve(Eigen::Vector2d(-ec(first), -ec(2)));
  return s(1) / (1 - nu);
}

TEST_CASE("layer factor: the closed forms solve Navier's equations through the layer",
          "[substrate]") {
  // The Navier solve forms e^(M h), whose growing modes swamp the decaying ones by e^(2x), with
  // M's entries up to lambda/mu: it carries about eps (1 + lambda/mu) e^(2x) (measured: 1e-13 at
  // nu = 0.49, x = 5, where that is 5e-10). Its tolerance: 1e-12 (1 + lambda/mu), x <= 5.
  for (const double nu : {-0.5, 0.0, 0.3, 0.45, 0.49})
    for (const double x : {0.01, 0.1, 0.5, 1.0, 2.0, 5.0})
      for (const LayerBase base : {LayerBase::bonded, LayerBase::frictionless}) {
        const double lambda = 2 * nu / (1 - 2 * nu), navier = navier_factor(x, nu, base);
        INFO("nu " << nu << " x " << x << " bonded " << (base == LayerBase::bonded));
        CHECK(std::abs(layer_factor(x, nu, base) / navier - 1) <= 1e-12 * (1 + std::abs(lambda)));
      }
}

TEST_CASE("layer factor: thin and thick limits", "[substrate]") {
  const double eps = std::numeric_limits<double>::epsilon();
  // (H4) with its next terms, docs/theory.md: bonded, T = lead x (1 + C x^2 + E x^4 + O(x^6)),
  // (1 + a x^2 + b x^4)/(1 + g x^2 + h x^4) with a = k/(3 (1 - 2 nu)), b = a/5,
  // g = (k + 1)/(4 (1 - nu)^2), h = k/(12 (1 - nu)^2), k = 3 - 4 nu: C = a - g,
  // E = b - h - g C; incompressible,
  // T = (2/3) x^3 (1 - 1.8 x^2 + O(x^4)); frictionless, T = (x/2)(1 - x^4/45 + O(x^6)). The
  // tolerance: the next term's size, twice, and rounding.
  for (const double x : {1e-3, 1e-5, 1e-7}) {
    for (const double nu : {0.0, 0.3, 0.45, 0.49}) {
      INFO("nu " << nu << " x " << x);
      const double k = 3 - 4 * nu, lead = (1 - 2 * nu) / (2 * (1 - nu) * (1 - nu));
      const double a = k / (3 * (1 - 2 * nu)), g = (k + 1) / (4 * (1 - nu) * (1 - nu));
      const double c = a - g, e = a / 5 - k / (12 * (1 - nu) * (1 - nu)) - g * c;
      const double bonded = layer_factor(x, nu, LayerBase::bonded) / (lead * x) - 1;
      CHECK(std::abs(bonded - c * x * x) <= 2 * std::abs(e) * std::pow(x, 4) + 16 * eps);
      CHECK(std::abs(layer_factor(x, nu, LayerBase::frictionless) / (x / 2) - 1) <=
            2 * std::pow(x, 4) / 45 + 16 * eps);
    }
    // Incompressible and bonded, where the naive (H2) would cancel to eps/x^2.
    const double incompressible = layer_factor(x, 0.5, LayerBase::bonded) / (2 * x * x * x / 3);
    CHECK(std::abs(incompressible - 1 + 1.8 * x * x) <= 2 * std::pow(1.8 * x * x, 2) + 16 * eps);
  }
  // Thick: 1 - T = O(x^2 e^-2x), under eps at x = 30; the half space at x = inf.
  for (const LayerBase base : {LayerBase::bonded, LayerBase::frictionless}) {
    CHECK(std::abs(layer_factor(30.0, 0.3, base) - 1) <= 2 * eps);
    CHECK(layer_factor(std::numeric_limits<double>::infinity(), 0.3, base) == 1);
    CHECK(layer_factor(800.0, 0.3, base) == Approx(1).epsilon(2 * eps));
    CHECK(layer_factor(0.0, 0.3, base) == 0);
  }
}

TEST_CASE("layer factor: continuous and rising across the switch at x = 1", "[substrate]") {
  // The two evaluations of (H2) meet at x = 1 to rounding, and T rises with x (a thicker layer
  // is more compliant).
  for (const double nu : {0.0, 0.3, 0.5}) {
    const double below = layer_factor(std::nextafter(1.0, 0.0), nu, LayerBase::bonded);
    const double at = layer_factor(1.0, nu, LayerBase::bonded);
    CHECK(std::abs(at / below - 1) <= 8 * std::numeric_limits<double>::epsilon());
    double last = 0;
    for (double x = 1e-4; x < 12; x *= 1.1) {  // beyond, T is 1 to rounding
      const double t = layer_factor(x, nu, LayerBase::bonded);
      CHECK(t > last);
      last = t;
    }
  }
  // long double agrees with double to double's rounding.
  for (const double x : {1e-6, 0.3, 0.999, 1.0, 4.0, 40.0}) {
    const long double t = layer_factor<long double>(x, 0.4L, LayerBase::bonded);
    CHECK(std::abs(layer_factor(x, 0.4, LayerBase::bonded) / double(t) - 1) <=
          8 * std::numeric_limits<double>::epsilon());
  }
}

TEST_CASE("layer factor: bad input names x or nu", "[substrate]") {
  CHECK_THROWS_WITH(layer_factor(-1.0, 0.3, LayerBase::bonded),
                    Catch::Contains("x = -1 is outside the valid range x = |q| h >= 0"));
  CHECK_THROWS_WITH(layer_factor(std::nan(""), 0.3, LayerBase::bonded), Catch::Contains("x = "));
  CHECK_THROWS_WITH(layer_factor(1.0, 0.6, LayerBase::frictionless),
                    Catch::Contains("nu = 0.6 is outside the valid range -1 < nu <= 0.5"));
}

}  // namespace test_layer_factor
