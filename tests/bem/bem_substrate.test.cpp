// Tests of the boundary-element solver on a substrate (bem/substrate_kernel.hpp, docs/bem.md
// B15-B19): the body's radial correction against its own quadrature and the kernel's moment, a
// thick layer against the half space, a substrate written here (outside the library) against the
// library's layer, and bad substrates named.
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <viscoroll/bem/bem_profile.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/temperature_shift.hpp>
#include <viscoroll/roller/profile.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_bem_substrate {

namespace {

using viscoroll::BemOptions;
using viscoroll::BemScene;
using viscoroll::BemSolver;
using viscoroll::Layer;
using viscoroll::LayerBase;
using viscoroll::SpringBed;
using viscoroll::StandardLinearSolid;
using viscoroll::SubstrateKind;
using Sls = StandardLinearSolid<double>;

const double eps = std::numeric_limits<double>::epsilon();
const double pi = std::acos(-1.0);

/// A bonded incompressible layer written from (H2) at nu = 1/2, as a user would: the numerator
/// (sinh 2x - 2x) by its series for small x, 1 beyond x = 20 (where 1 - T < 1e-15).
struct UserLayer {
  using real_type = double;
  static constexpr SubstrateKind kind = SubstrateKind::body;
  double h;
  double surface_factor(double q, double /*nu*/) const {
    const double x = q * h;
    if (x > 20) return 1;
    double num = 0;
    if (x < 1) {
      double term = 8 * x * x * x / 6;
      for (int j = 1; j < 40; ++j) {
        num += term;
        term *= 4 * x * x / double((2 * j + 2) * (2 * j + 3));
      }
    } else {
      num = std::sinh(2 * x) - 2 * x;
    }
    return num / (std::cosh(2 * x) + 2 * x * x + 1);
  }
  double thickness() const { return h; }
};
static_assert(viscoroll::Substrate<UserLayer>);

/// A body whose T - 1 never decays: the solver must refuse it.
struct NotDecaying {
  using real_type = double;
  static constexpr SubstrateKind kind = SubstrateKind::body;
  double surface_factor(double /*q*/, double /*nu*/) const { return 0.5; }
  double thickness() const { return 1; }
};

}  // namespace

TEST_CASE("bem substrate: the radial correction (B15) interpolates its quadrature",
          "[bem][substrate]") {
  // The Chebyshev panels against the Hankel quadrature they were built from, at points between
  // their nodes: 64 eps (measured at most 17 eps), for both bases and three Poisson's ratios.
  for (const auto base : {LayerBase::bonded, LayerBase::frictionless})
    for (const double nu : {0.0, 0.3, 0.5}) {
      const auto k = viscoroll::bem::substrate_kernel<double>(Layer<double>(1.0, base), nu);
      const auto& d = *k.radial;
      double worst = 0;
      for (double rho = 0.0137; rho < d.reach(); rho += 0.0731)
        worst = std::max(worst, std::abs(d(rho) - d.direct(rho)));
      CAPTURE(nu, static_cast<int>(base), worst / eps);
      CHECK(worst <= 64 * eps);
      // Beyond the reach, d is its far field (T(0) - 1)/rho = -1/rho to 4096 eps relative.
      CHECK(std::abs(d.direct(d.reach() + 1) + 1 / (d.reach() + 1)) * (d.reach() + 1) <=
            4096 * eps);
    }
}

TEST_CASE("bem substrate: the layer's kernel has the moment its factor's slope gives",
          "[bem][substrate]") {
  // The point kernel 1/r + D(r) of (B15) integrates over the plane to its transform at q = 0,
  // 2 pi T'(0) h, so int_0^inf (1 + rho d(rho)) d rho = T'(0) h / h: (1 - 2 nu)/(2 (1 - nu)^2)
  // bonded, 1/2 frictionless ((H4)). An independent check of the transform's scale and of its far
  // field (the integrand vanishes beyond the reach); Gauss-Kronrod to 1e-13 relative.
  for (const auto base : {LayerBase::bonded, LayerBase::frictionless})
    for (const double nu : {0.0, 0.3}) {
      const auto k = viscoroll::bem::substrate_kernel<double>(Layer<double>(1.0, base), nu);
      const auto& d = *k.radial;
      double error = 0;
      const double moment = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
          [&](double rho) { return 1 + rho * d(rho); }, 0.0, d.reach(), 20, 1e-14, &error);
      const double slope =
          base == LayerBase::bonded ? (1 - 2 * nu) / (2 * (1 - nu) * (1 - nu)) : 0.5;
      CAPTURE(nu, static_cast<int>(base), moment, slope, error);
      CHECK(std::abs(moment - slope) <= 1e-13 * d.reach());
    }
}

TEST_CASE("bem substrate: a layer 1e4 long-term contacts thick is the half space",
          "[bem][substrate]") {
  // chi and the contact's size to 1e-6 (their next term is of order (a/h)^2 = 1e-8); d once the
  // layer's far-field compression is added: under a contact much smaller than h and memory
  // lengths much shorter, the correction D is its value D(0) = d(0)/h over the contact, a
  // rigid shift of the surface by c (1 + f) P d(0)/h (docs/bem.md (B15)).
  const double mu = 1, nu = 0.5, f = 2, tau = 1;
  const Sls material(mu, nu, f, tau);
  const BemScene<double> scene{.c1 = 1, .c2 = 0.5, .load = 1, .speed = 0.5};
  BemOptions options;
  options.grid = 12;
  const auto half = BemSolver<double, Sls>(material, options).solve(scene);
  REQUIRE(half.converged);
  const double h = 1e4 * half.long_term.a;
  const BemSolver<double, Sls> solver(material, options, Layer<double>(h));
  const auto layer = solver.solve(scene);
  REQUIRE(layer.converged);
  CHECK(std::abs(layer.chi / half.chi - 1) <= 1e-6);
  CHECK(std::abs(layer.a0 / half.a0 - 1) <= 1e-6);
  CHECK(std::abs(layer.l / half.l - 1) <= 1e-6);
  const double c = (1 - nu) / (2 * pi * mu);
  const auto k = viscoroll::bem::substrate_kernel<double>(Layer<double>(1.0), nu);
  const double shift = c * (1 + f) * scene.load * (*k.radial)(0.0) / h;
  CAPTURE(half.d, layer.d, shift);
  CHECK(std::abs(layer.d - (half.d + shift)) <= 1e-6 * half.d);
  // The shift itself is resolved: it is 4e-5 of d here.
  CHECK(std::abs(layer.d - half.d) >= 10 * std::abs(layer.d - (half.d + shift)));
}

TEST_CASE("bem substrate: a substrate written outside the library is the library's layer",
          "[bem][substrate]") {
  // UserLayer is (H2) at nu = 1/2 in its own words; through the solver it gives the library's
  // bonded layer to rounding of the tables (1e-10 relative allows for the contact iteration's
  // tolerance on two tables that differ by a few eps).
  const Sls material(1, 0.5, 3, 1);
  BemOptions options;
  options.grid = 10;
  options.gmres_tolerance = 1e-13;
  const BemScene<double> scene{.c1 = 1, .c2 = 1, .load = 1, .speed = 1};
  const double h = 0.3;
  const auto mine = BemSolver<double, Sls>(material, options, UserLayer{h}).solve(scene);
  const auto lib = BemSolver<double, Sls>(material, options, Layer<double>(h)).solve(scene);
  REQUIRE(mine.converged);
  REQUIRE(lib.converged);
  CHECK(std::abs(mine.d / lib.d - 1) <= 1e-10);
  CHECK(std::abs(mine.chi / lib.chi - 1) <= 1e-10);
  CHECK(mine.contact_cells == lib.contact_cells);
}

TEST_CASE("bem substrate: a layer composes with a shifted Prony rubber and a tilted crowned roller",
          "[bem][substrate]") {
  // A three-term rubber at 0 degrees C through a WLF shift, a crowned roller tilted by 1e-3,
  // on a bonded cover, a frictionless one and the spring bed of the same thickness: each solve
  // converges; the bonded cover sinks least (it cannot bulge), the frictionless one next, the bed
  // most (its points are unconnected, and its compliance h/E exceeds the frictionless layer's
  // thin limit (1 - nu^2) h/E).
  const viscoroll::WlfShift<double> wlf(8.86, 101.6, 20.0);
  const auto rubber = viscoroll::at_temperature(
      viscoroll::PronyRelaxation<double>(2e6, 0.49, {{3e6, 1e-5}, {2e6, 1e-3}, {1e6, 0.1}}), wlf,
      0.0);
  using Rubber = viscoroll::PronyRelaxation<double>;
  const viscoroll::Tilted roller(viscoroll::CrownedCylinder<double>(0.05, 0.02, 0.5), 1e-3);
  const auto scene = viscoroll::bem_scene(roller, rubber, 2000.0, 2.0);
  BemOptions options;
  options.grid = 10;
  const double h = 0.004;
  const auto bonded = BemSolver<double, Rubber>(rubber, options, Layer<double>(h)).solve(scene);
  const auto loose =
      BemSolver<double, Rubber>(rubber, options, Layer<double>(h, LayerBase::frictionless))
          .solve(scene);
  const auto bed = BemSolver<double, Rubber>(rubber, options, SpringBed<double>(h)).solve(scene);
  const auto half = BemSolver<double, Rubber>(rubber, options).solve(scene);
  for (const auto* s : {&bonded, &loose, &bed, &half}) {
    CAPTURE(s->reason, s->d, s->chi);
    CHECK(s->converged);
  }
  CHECK(bonded.d < loose.d);
  CHECK(loose.d < bed.d);
  CHECK(bonded.d < half.d);
}

TEST_CASE("bem substrate: a flat roller's contact runs to its ends on a thin layer",
          "[bem][substrate]") {
  // A flat roller (100 mm flat, 5 mm edge radii) on a bonded cover thinner than its contact is
  // wide: the layer shrinks the sized ellipse (B19's F < 1), but a flat roller's contact is as
  // long as its flat part, so the grid must cover along y what the half space's covers. Sized
  // by the shrunken ellipse in both directions the grid ended short of the flat's end and the
  // solve failed ("contact reaches the grid boundary").
  const Sls rubber(1e6, 0.5, 3, 1e-3);
  const viscoroll::CrownedCylinder<double> roller(0.05, 0.1, 0.005, 0.11);
  const auto scene = viscoroll::bem_scene(roller, rubber, 1500.0, 1.0);
  BemOptions options;
  options.grid = 8;
  const BemSolver<double, Sls> layer(rubber, options, Layer<double>(0.003));
  const auto s = layer.solve(scene);
  CAPTURE(s.reason, s.grid.nx, s.grid.ny);
  REQUIRE(s.converged);
  double y_reach = 0;
  for (int j = 0; j < s.grid.ny; ++j)
    for (int i = 0; i < s.grid.nx; ++i)
      if (s.p(i, j) > 0) y_reach = std::max(y_reach, std::abs(s.grid.y(j)));
  CHECK(y_reach >= 0.05);  // the flat's end
  const auto half_space = BemSolver<double, Sls>(rubber, options).grid_for(scene);
  const auto sized = layer.grid_for(scene);
  CHECK(sized.hx < half_space.hx);  // the cells of the stiffer body's narrower contact
  CHECK(sized.hy * (sized.ny - 1) >= half_space.hy * (half_space.ny - 1) * (1 - 1e-12));
}

TEST_CASE("bem substrate: a thick layer is the half space in long double", "[bem][substrate]") {
  // The kernel in long double (RadialCorrection<long double>): chi and a(0) of a layer 1e4
  // contacts thick equal the half space's to 1e-6, as in double.
  using Ld = long double;
  const StandardLinearSolid<Ld> material(1, 0.4L, 1, 1);
  const BemScene<Ld> scene{.c1 = 1, .c2 = 1, .load = 1, .speed = 1};
  BemOptions options;
  options.grid = 8;
  const auto half = BemSolver<Ld, StandardLinearSolid<Ld>>(material, options).solve(scene);
  const auto layer =
      BemSolver<Ld, StandardLinearSolid<Ld>>(material, options, Layer<Ld>(1e4L * half.long_term.a))
          .solve(scene);
  REQUIRE(half.converged);
  REQUIRE(layer.converged);
  CHECK(std::abs(static_cast<double>(layer.chi / half.chi) - 1) <= 1e-6);
  CHECK(std::abs(static_cast<double>(layer.a0 / half.a0) - 1) <= 1e-6);
}

TEST_CASE("bem substrate: bad substrates are named", "[bem][substrate]") {
  CHECK_THROWS_WITH(Layer<double>(0.0), Catch::Contains("thickness"));
  CHECK_THROWS_WITH(Layer<double>(-1.0), Catch::Contains("0 < thickness < inf"));
  CHECK_THROWS_WITH(SpringBed<double>(std::numeric_limits<double>::infinity()),
                    Catch::Contains("thickness"));
  CHECK_THROWS_WITH((BemSolver<double, Sls>(Sls(1, 0.5, 1, 1), BemOptions{}, NotDecaying{})),
                    Catch::Contains("surface_factor"));
}

}  // namespace test_bem_substrate
