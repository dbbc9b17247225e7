// The boundary-element solver's quadrature parameter: the rule of the memory panels (B4)-(B5).
// The default, 16-point Gauss-Legendre, is at rounding level (a 24-point rule and a 32-point rule
// in long double agree with it to about 10 eps, measured 2.7e-15); an 8-point rule is not (about
// 1e-12 .. 2e-11), so the parameter is seen to reach the panels. A BemSolver over a non-default
// rule solves a scene as the default does, to the GMRES tolerance; a rule without nodes is
// rejected by the NodalQuadratureRule constraint.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/quadrature/adaptive.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_bem_quadrature {

namespace {

using viscoroll::GaussLegendre;
using viscoroll::StandardLinearSolid;
using SLS = StandardLinearSolid<double>;

template <class Quadrature>
concept BemQuadrature = requires {
  typename viscoroll::BemSolver<double, SLS, Quadrature>;
};

static_assert(BemQuadrature<GaussLegendre<double, 24>>);
static_assert(BemQuadrature<GaussLegendre<long double, 32>>);
static_assert(!BemQuadrature<viscoroll::AdaptiveGaussKronrod<double>>);

/// The largest relative difference between the memory rows of the default rule and Quadrature,
/// over memory lengths L = hx/10 .. 100 hx and rows through, next to and away from the cell.
template <class Quadrature>
double largest_difference() {
  double e = 0;
  const double hx = 0.1, hy = 0.1;
  for (const double length : {0.01, 0.1, 1.0, 10.0})
    for (const double y : {0.0, 0.1, 0.3}) {
      const auto a = viscoroll::bem::memory_row<double>(20, y, hx, hy, length);
      const auto b = viscoroll::bem::memory_row<double, Quadrature>(20, y, hx, hy, length);
      for (std::size_t i = 0; i < a.size(); ++i) e = std::max(e, std::abs(a[i] - b[i]) / a[i]);
    }
  return e;
}

}  // namespace

TEST_CASE("bem: the memory panels' rule is a parameter, the default at rounding", "[bem]") {
  const double eps = std::numeric_limits<double>::epsilon();
  CHECK(largest_difference<GaussLegendre<double, 24>>() <= 64 * eps);
  CHECK(largest_difference<GaussLegendre<long double, 32>>() <= 64 * eps);
  CHECK(largest_difference<GaussLegendre<double, 8>>() > 1e-13);
}

TEST_CASE("bem: a BemSolver over a 24-point panel rule solves as the default", "[bem]") {
  const double pi = std::acos(-1.0), f = 9, c = 0.5 / (2 * pi);
  const SLS material(1.0, 0.5, f, 1.0);
  viscoroll::BemOptions o;
  o.grid = 4;
  o.gmres_tolerance = 1e-13;
  // The paper's scene (line-contact a0 = 1, l0 = 5) at V tau = a0.
  const viscoroll::BemScene<double> scene{1.0, (std::log(20.0) - 1) / 25, 5.0 / (3 * (1 + f) * c),
                                          1.0};
  const auto ref = viscoroll::BemSolverD(material, o).solve(scene);
  const auto sol =
      viscoroll::BemSolver<double, SLS, GaussLegendre<double, 24>>(material, o).solve(scene);
  REQUIRE(ref.converged);
  REQUIRE(sol.converged);
  REQUIRE(sol.contact_cells == ref.contact_cells);
  // Coefficients equal to ~10 eps and GMRES to 1e-13, amplified by the active-set system's
  // condition number (~1e2 on this grid).
  CHECK(sol.d == Approx(ref.d).epsilon(1e-10));
  CHECK(sol.chi == Approx(ref.chi).epsilon(1e-10));
  CHECK(sol.a0 == Approx(ref.a0).epsilon(1e-10));
  double largest = 0;
  for (const double p : ref.pressure) largest = std::max(largest, p);
  for (std::size_t q = 0; q < ref.pressure.size(); ++q)
    CHECK(std::abs(sol.pressure[q] - ref.pressure[q]) <= 1e-10 * largest);
}

}  // namespace test_bem_quadrature
