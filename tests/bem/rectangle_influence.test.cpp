// Tests of the rectangle influence coefficients (docs/bem.md B1-B5): the closed form (B1) against
// its square-cell value and additivity, the far-field evaluation (B2) against (B1) and the
// multipole expansion, and the memory coefficient (B3) by the recurrence (B4)-(B5) against a
// brute-force tanh-sinh quadrature of (B3) split at the kinks.
#include <algorithm>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>
#include <viscoroll/bem/rectangle_influence.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_rectangle_influence {

namespace {

using viscoroll::bem::memory_row;
using viscoroll::bem::rectangle_influence;
using viscoroll::bem::rectangle_influence_closed_form;

template <class Real>
Real eps() {
  return std::numeric_limits<Real>::epsilon();
}

}  // namespace

TEMPLATE_TEST_CASE("bem: self coefficient of a square is 4 h ln(1 + sqrt 2)", "[bem]", float,
                   double, long double) {
  using Real = TestType;
  using std::log;
  using std::sqrt;
  for (const Real h : {Real(0.25), Real(1), Real(3)}) {
    const Real exact = 4 * h * log(1 + sqrt(Real(2)));
    CHECK(std::abs(rectangle_influence_closed_form(Real(0), Real(0), h, h) - exact) <=
          16 * eps<Real>() * exact);
    CHECK(std::abs(rectangle_influence(Real(0), Real(0), h, h) - exact) <=
          16 * eps<Real>() * exact);
  }
}

TEST_CASE("bem: coefficients add up to the coefficient of the union (B1)", "[bem]") {
  // A 2a x 2b rectangle split into 5 x 3 cells: sum of the cells' coefficients = the big one's,
  // at field points inside, near and far (each term to ~100 eps, 15 terms).
  const double a = 0.7, b = 1.3;
  const int nx = 5, ny = 3;
  const double hx = 2 * a / nx, hy = 2 * b / ny;
  for (const auto& pt : std::vector<std::pair<double, double>>{
           {0, 0}, {0.1, 0.2}, {0.9, -1.4}, {3, 1}, {40, -25}, {1e3, 2e3}}) {
    double sum = 0;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double xc = -a + (i + 0.5) * hx, yc = -b + (j + 0.5) * hy;
        sum += rectangle_influence(pt.first - xc, pt.second - yc, hx, hy);
      }
    const long double big =
        rectangle_influence_closed_form<long double>(pt.first, pt.second, 2 * a, 2 * b);
    // The long-double closed form itself loses (R^2/(4ab)) ln R ulps of long double.
    CHECK(std::abs(sum - static_cast<double>(big)) <=
          2000 * eps<double>() * static_cast<double>(big));
  }
}

TEST_CASE("bem: far-field coefficient (B2) against the closed form and the multipole series",
          "[bem]") {
  const double hx = 0.1, hy = 0.5;
  for (double x : {0.0, 0.3, 1.0, 3.0, 10.0})
    for (double y : {0.0, 0.5, 2.0}) {
      // Where (B1) in long double is still exact to ~1e-15, (B2) must agree to ~100 eps.
      const long double ref = rectangle_influence_closed_form<long double>(x, y, hx, hy);
      CHECK(std::abs(rectangle_influence(x, y, hx, hy) - static_cast<double>(ref)) <=
            100 * eps<double>() * static_cast<double>(ref));
    }
  // At R >= 6e3 h: A/R + A [hx^2 (2X^2 - Y^2) + hy^2 (2Y^2 - X^2)] / (24 R^5), remainder
  // O((h/R)^4) < 1e-15 relative.
  for (double x : {1e4, 3e3})
    for (double y : {0.0, 7e3}) {
      const double r = std::hypot(x, y), area = hx * hy;
      const double multipole =
          area / r + area * (hx * hx * (2 * x * x - y * y) + hy * hy * (2 * y * y - x * x)) /
                         (24 * std::pow(r, 5));
      CHECK(std::abs(rectangle_influence(x, y, hx, hy) - multipole) <=
            100 * eps<double>() * multipole);
    }
}

namespace {

/// (B3) by tanh-sinh in long double on [0, eta_1], [eta_1, eta_2], ... with breaks at the kinks
/// eta = (+-hx/2 - X)/L and doubling panels to eta = 60.
double memory_brute_force(double x, double y, double hx, double hy, double length) {
  boost::math::quadrature::tanh_sinh<long double> rule;
  const auto g = [&](long double eta) {
    return std::exp(-eta) * rectangle_influence<long double>(x + length * eta, y, hx, hy);
  };
  std::vector<long double> breaks{0};
  for (double e : {-hx / 2, hx / 2}) {
    const long double t = (e - x) / static_cast<long double>(length);
    if (t > 0) breaks.push_back(t);
  }
  std::sort(breaks.begin(), breaks.end());
  long double s = 0;
  const long double tol = 1e-17L;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
    s += rule.integrate(g, breaks[k], breaks[k + 1], tol);
  long double a = breaks.back();
  long double step =
      std::min<long double>(1, std::max<long double>(1e-4L, (std::abs(x) + hx) / length));
  while (a < 60) {
    const long double b = std::min<long double>(a + step, 60);
    s += rule.integrate(g, a, b, tol);
    a = b;
    step *= 2;
  }
  return static_cast<double>(s);
}

}  // namespace

TEST_CASE("bem: memory coefficient (B4)-(B5) against brute-force quadrature of (B3)", "[bem]") {
  const double hx = 0.1, hy = 0.5;
  const int m = 12;
  for (double length : {1e-3, 0.05, 0.3, 2.0, 50.0, 1e4})
    for (double y : {0.0, 0.5, 1.5}) {
      const auto row = memory_row<double>(m, y, hx, hy, length);
      for (int i = -m; i <= m; i += 4) {
        const double ref = memory_brute_force(i * hx, y, hx, hy, length);
        INFO("L = " << length << ", X = " << i * hx << ", Y = " << y);
        // Both sides to ~1e-14: the recurrence sums O(m) panel integrals, each to ~10 eps.
        CHECK(std::abs(row[static_cast<std::size_t>(i + m)] - ref) <= 1000 * eps<double>() * ref);
      }
    }
}

TEST_CASE("bem: memory coefficient limits", "[bem]") {
  const double hx = 0.2, hy = 0.2;
  const int m = 6;
  // L = 0: M = K_e (Eq. B3 with the weight e^-eta integrating to 1).
  const auto zero = memory_row<double>(m, 0.2, hx, hy, 0.0);
  for (int i = -m; i <= m; ++i)
    CHECK(zero[static_cast<std::size_t>(i + m)] == rectangle_influence(i * hx, 0.2, hx, hy));
  // L -> 0+: M -> K_e(X) + L dK_e/dX (first order in L).
  const double small = 1e-6;
  const auto near = memory_row<double>(m, 0.2, hx, hy, small);
  for (int i = -m; i <= m; ++i) {
    const double x = i * hx, h = 1e-4;
    const double slope =
        (rectangle_influence(x + h, 0.2, hx, hy) - rectangle_influence(x - h, 0.2, hx, hy)) /
        (2 * h);
    const double k = rectangle_influence(x, 0.2, hx, hy);
    CHECK(std::abs(near[static_cast<std::size_t>(i + m)] - (k + small * slope)) <= 1e-10 * k);
  }
  // L -> inf: M = (A / L) (ln L + const + O(h / L)), so L M / A - ln L settles (B3).
  const auto settled = [&](double length) {
    const auto row = memory_row<double>(m, 0.0, hx, hy, length);
    return row[static_cast<std::size_t>(m)] * length / (hx * hy) - std::log(length);
  };
  CHECK(std::abs(settled(1e10) - settled(1e12)) <= 1e-6);
  CHECK(std::abs(settled(1e8) - settled(1e12)) <= 1e-5);
}

TEST_CASE("bem: memory coefficients of a long memory", "[bem]") {
  // docs/bem.md, "Glassy memory terms": for L >> the grid, M_L = (hx hy / L)(ln(L/h) + C) with
  // C from the near field eta < h/L; BemSolver drops a term on the bound C <= 10 + |ln(hx/hy)|
  // (measured C: 7.2 square, 8.8 at hy = hx/5, on the row Y = 0; less on the others).
  const double hx = 1.0;
  for (const double hy : {1.0, 0.2}) {
    const double h = std::min(hx, hy), shape = 10 + std::abs(std::log(hx / hy));
    for (const double length : {1e3, 1e6, 1e9, 1e12}) {
      for (const int j : {0, 3, 10}) {
        const auto row = memory_row<double>(20, j * hy, hx, hy, length);
        double largest = 0;
        for (const double m : row) largest = std::max(largest, m);
        INFO("hy = " << hy << ", L = " << length << ", Y = " << j << " cells: max M_L " << largest);
        CHECK(largest <= hx * hy / length * (std::log(length / h) + shape));
        // and it is of that order: at least (hx hy / L) ln(L / max(h, |Y|)), the far part alone.
        CHECK(largest >= hx * hy / length * std::log(length / std::max(h, j * hy)));
      }
    }
  }
}

TEST_CASE("bem: the far field's rule selection equals the point count formula", "[bem]") {
  // gauss_rule_for (thresholds, no logarithms) picks the smallest rule of gauss_sum_n with at
  // least gauss_points_needed points, away from the thresholds themselves.
  const int rules[] = {3, 4, 5, 6, 8, 10, 13, 16, 24};
  for (double q = 1.01; q < 1e6; q *= 1.013) {
    const int needed = viscoroll::detail::gauss_points_needed<double>(q);
    int want = 24;
    for (const int r : rules)
      if (r >= needed) {
        want = r;
        break;
      }
    INFO("q = " << q);
    CHECK(viscoroll::detail::gauss_rule_for<double>(q) == want);
  }
}

}  // namespace test_rectangle_influence
