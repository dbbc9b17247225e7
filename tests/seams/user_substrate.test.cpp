// A substrate written outside the library, run through every solver that takes a substrate (the
// Substrate seam, core/concepts.hpp): the plane solver on a body (PlaneSubstrateSolver,
// docs/plane-substrate.md) and the boundary-element solver (BemSolver, docs/bem.md (B15)-(B19)).
//
// Two substrates, each written here and nowhere in the library:
//  - LiteralBondedLayer, a compressible layer bonded to a rigid base, its factor (H2) coded as
//    printed (sinh and cosh, no series), where the library's layer_factor evaluates it by a
//    series below x = 1 and scaled by e^-2x above ((H5)): the same T to a few ulps, so both
//    solvers must give the library's Layer to their tolerances;
//  - ConstrainedBed, a local (Winkler) bed that sinks by the constrained modulus' compliance,
//    w = h p / (lambda + 2 mu) = (1 - 2 nu) h p / (2 (1 - nu) mu), the bonded thin layer's limit
//    (H4), i.e. T(q) = q h (1 - 2 nu) / (2 (1 - nu)^2) in (H1): physically not the library's
//    SpringBed (the uniaxial compliance, T = q h / (2 (1 - nu^2)), (H6)), but the same law as a
//    SpringBed of the thickness h' = h (1 - 2 nu)(1 + nu) / (1 - nu). At nu = 0.3, h' = 0.743 h.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_substrate_solver.hpp>
#include <viscoroll/substrate/substrate.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_user_substrate {

namespace {

using viscoroll::Layer;
using viscoroll::PlaneScene;
using viscoroll::PlaneSubstrateOptions;
using viscoroll::PlaneSubstrateSolver;
using viscoroll::SpringBed;
using viscoroll::SubstrateKind;
using Sls = viscoroll::StandardLinearSolid<double>;

const double eps = std::numeric_limits<double>::epsilon();

/// (H2) as printed: T(x) = [(3 - 4 nu) sinh 2x - 2x] / [(3 - 4 nu) cosh 2x + 2x^2 + 5 - 12 nu +
/// 8 nu^2], x = q h; 1 beyond x = 25, where 1 - T < x e^-2x < 1e-20.
struct LiteralBondedLayer {
  using real_type = double;
  static constexpr SubstrateKind kind = SubstrateKind::body;
  double h;
  double surface_factor(double q, double nu) const {
    const double x = q * h;
    if (x > 25) return 1;
    const double k = 3 - 4 * nu;
    return (k * std::sinh(2 * x) - 2 * x) /
           (k * std::cosh(2 * x) + 2 * x * x + 5 - 12 * nu + 8 * nu * nu);
  }
  double thickness() const { return h; }
};

/// The constrained bed: T(q) = q h (1 - 2 nu) / (2 (1 - nu)^2), (H1) with (H4)'s thin limit.
struct ConstrainedBed {
  using real_type = double;
  static constexpr SubstrateKind kind = SubstrateKind::local;
  double h;
  double surface_factor(double q, double nu) const {
    return q * h * (1 - 2 * nu) / (2 * (1 - nu) * (1 - nu));
  }
  double thickness() const { return h; }
};

static_assert(viscoroll::Substrate<LiteralBondedLayer> && viscoroll::Substrate<ConstrainedBed>);

double rel(double x, double y) { return std::abs(x / y - 1); }

/// Two plane solutions on substrates, each within the solver's `tol` of the exact one: within
/// twice it of each other (chi to 1e-15 absolute where it is 0, at speed 0).
template <class Solution>
void check_within_twice_tolerance(const Solution& mine, const Solution& lib, double tol) {
  CHECK(std::abs(mine.a - lib.a) <= 2 * tol * lib.a);
  CHECK(std::abs(mine.b - lib.b) <= 2 * tol * lib.a);
  CHECK(std::abs(mine.d - lib.d) <= 2 * tol * lib.d);
  CHECK(std::abs(mine.chi - lib.chi) <= 2 * tol * lib.chi + 1e-15);
}

// nu = 0.3: a compressible rubber, where (H2)'s numerator keeps its leading term (4 - 8 nu) x
// (no cancellation: at nu = 1/2 it would lose digits as x^-2, which the library's series avoids).
const Sls rubber(1.0, 0.3, 2.0, 1.0);

}  // namespace

TEST_CASE("seams: a user's bonded layer, (H2) as printed, is the library's factor to a few ulps",
          "[seams][substrate]") {
  // sinh, cosh and the sums round a few times, and (3 - 4 nu) sinh 2x - 2x keeps at least
  // (4 - 8 nu)/(3 - 4 nu) = 0.89 of its largest term: within 16 eps relative (measured 3 eps),
  // from x = 1e-3 to 30, across the library's switch at x = 1.
  const LiteralBondedLayer mine{1.0};
  const Layer<double> lib(1.0);
  double worst = 0;
  for (int k = 0; k <= 400; ++k) {
    const double x = 1e-3 * std::pow(3e4, k / 400.0);
    const double t = lib.surface_factor(x, 0.3);
    CHECK(std::abs(mine.surface_factor(x, 0.3) - t) <= 16 * eps * t);
    worst = std::max(worst, rel(mine.surface_factor(x, 0.3), t));
  }
  CAPTURE(worst / eps);
  CHECK(mine.surface_factor(0.0, 0.3) == 0.0);
  CHECK(mine.surface_factor(1e3, 0.3) == 1.0);
}

TEST_CASE("seams: a user's bonded layer through the plane solver and the BEM is the library's",
          "[seams][substrate]") {
  // The plane solver on a body: each solution within its tolerance of the exact one (Q13), so
  // within twice it of each other (as plane_substrate_user.test.cpp's frictionless layer;
  // measured at most 4 eps relative). The BEM: the layer's radial correction (B15) is tabulated
  // from T by the same quadrature, so the two tables differ by a few eps; 1e-10 relative allows
  // for the contact iteration's tolerance on two such tables (bem_substrate.test.cpp's
  // nu = 1/2 layer; measured 1 eps).
  const double h = 0.5;
  const PlaneSubstrateOptions options{};
  const double tol = options.tolerance;
  for (const double speed : {0.0, 0.3, 3.0}) {
    const PlaneScene<double> scene{.c1 = 1.0, .load = 0.1, .speed = speed};
    const auto mine = PlaneSubstrateSolver(rubber, LiteralBondedLayer{h}, options).solve(scene);
    const auto lib = PlaneSubstrateSolver(rubber, Layer<double>(h), options).solve(scene);
    CAPTURE(speed, rel(mine.a, lib.a), rel(mine.d, lib.d), mine.chi, lib.chi);
    REQUIRE(mine.converged);
    REQUIRE(lib.converged);
    CHECK(mine.d_absolute);
    check_within_twice_tolerance(mine, lib, tol);
  }
  viscoroll::BemOptions bem_options;
  bem_options.grid = 10;
  bem_options.gmres_tolerance = 1e-13;
  for (const double speed : {0.0, 1.0}) {
    const viscoroll::BemScene<double> scene{.c1 = 1, .c2 = 1, .load = 1, .speed = speed};
    const auto mine =
        viscoroll::BemSolver<double, Sls>(rubber, bem_options, LiteralBondedLayer{0.3})
            .solve(scene);
    const auto lib =
        viscoroll::BemSolver<double, Sls>(rubber, bem_options, Layer<double>(0.3)).solve(scene);
    CAPTURE(speed, rel(mine.d, lib.d), rel(mine.chi, lib.chi));
    REQUIRE(mine.converged);
    REQUIRE(lib.converged);
    CHECK(mine.contact_cells == lib.contact_cells);
    CHECK(rel(mine.d, lib.d) <= 1e-10);
    CHECK(std::abs(mine.chi - lib.chi) <= 1e-10 * lib.chi + 1e-15);
  }
}

TEST_CASE("seams: a user's constrained bed is a spring bed of the equivalent thickness",
          "[seams][substrate]") {
  // T = q h (1 - 2 nu)/(2 (1 - nu)^2) = q h' / (2 (1 - nu^2)): the same law as SpringBed(h')
  // to rounding (the two products differ by a few eps), so the same answers: the plane solver's
  // closed form for a local bed (Q10)-(Q12) to twice its tolerance, the BEM to 1e-10 as for the
  // layer (measured: at most 1 eps). And it is not the library's bed of the same h: its contact
  // is narrower, by about (h'/h)^(1/3) = 0.906 (measured 0.89 to 0.906), far outside those
  // tolerances.
  const double h = 0.5, nu = rubber.nu();
  const double h_equivalent = h * (1 - 2 * nu) * (1 + nu) / (1 - nu);
  const PlaneSubstrateOptions options{};
  const double tol = options.tolerance;
  for (const double speed : {0.0, 0.3, 3.0}) {
    const PlaneScene<double> scene{.c1 = 1.0, .load = 0.1, .speed = speed};
    const auto mine = PlaneSubstrateSolver(rubber, ConstrainedBed{h}, options).solve(scene);
    const auto same =
        PlaneSubstrateSolver(rubber, SpringBed<double>(h_equivalent), options).solve(scene);
    const auto other = PlaneSubstrateSolver(rubber, SpringBed<double>(h), options).solve(scene);
    CAPTURE(speed, rel(mine.a, same.a), rel(mine.d, same.d), mine.a / other.a);
    REQUIRE(mine.converged);
    REQUIRE(same.converged);
    REQUIRE(other.converged);
    check_within_twice_tolerance(mine, same, tol);
    CHECK(mine.a < 0.95 * other.a);
  }
  viscoroll::BemOptions bem_options;
  bem_options.grid = 10;
  bem_options.gmres_tolerance = 1e-13;
  const viscoroll::BemScene<double> scene{.c1 = 1, .c2 = 1, .load = 1, .speed = 1};
  const auto mine =
      viscoroll::BemSolver<double, Sls>(rubber, bem_options, ConstrainedBed{0.3}).solve(scene);
  const auto same = viscoroll::BemSolver<double, Sls>(rubber, bem_options,
                                                      SpringBed<double>(0.3 * h_equivalent / h))
                        .solve(scene);
  CAPTURE(rel(mine.d, same.d), rel(mine.chi, same.chi));
  REQUIRE(mine.converged);
  REQUIRE(same.converged);
  CHECK(mine.contact_cells == same.contact_cells);
  CHECK(rel(mine.d, same.d) <= 1e-10);
  CHECK(rel(mine.chi, same.chi) <= 1e-10);
}

}  // namespace test_user_substrate
