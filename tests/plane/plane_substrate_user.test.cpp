// PlaneSubstrateSolver with a substrate written outside the library (the Substrate concept's
// extension contract, core/concepts.hpp): a frictionless layer whose factor (H3) the user codes
// directly, which must give the library's Layer; a body whose T is 1 at every q, which must give
// the half space; and the bad inputs, each named with its valid range.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_substrate_solver.hpp>
#include <viscoroll/substrate/substrate.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_substrate_user {

using Catch::Matchers::Contains;
using viscoroll::HalfSpace;
using viscoroll::Layer;
using viscoroll::LayerBase;
using viscoroll::PlaneScene;
using viscoroll::PlaneSubstrateOptions;
using viscoroll::PlaneSubstrateSolver;
using viscoroll::SpringBed;

/// A user's frictionless layer: (H3) as written, T = (cosh 2x - 1)/(sinh 2x + 2x), x = q h
/// (0 at x = 0, 1 beyond x = 20 where it is 1 to rounding), its small-x cancellation left in.
struct MyFrictionlessLayer {
  using real_type = double;
  static constexpr viscoroll::SubstrateKind kind = viscoroll::SubstrateKind::body;
  double h;
  double surface_factor(double q, double /*nu*/) const {
    const double x = q * h;
    if (x == 0) return 0.0;  // no layer
    if (x > 20) return 1.0;
    return (std::cosh(2 * x) - 1) / (std::sinh(2 * x) + 2 * x);
  }
  double thickness() const { return h; }
};

/// A body identical to the half space: T = 1 (T(0) = 1: d keeps the half space's convention).
struct Uniform {
  using real_type = double;
  static constexpr viscoroll::SubstrateKind kind = viscoroll::SubstrateKind::body;
  double surface_factor(double /*q*/, double /*nu*/) const { return 1.0; }
  double thickness() const { return 1.0; }
};

static_assert(viscoroll::Substrate<MyFrictionlessLayer> && viscoroll::Substrate<Uniform>);

TEST_CASE("plane substrate: a user's layer runs through the solver", "[plane][substrate]") {
  const viscoroll::StandardLinearSolid<double> m(1.0, 0.3, 2.0, 1.0);
  const PlaneScene<double> scene{.c1 = 1.0, .load = 0.1, .speed = 0.3};
  const PlaneSubstrateOptions options{};
  const double tol = options.tolerance;
  const auto mine = PlaneSubstrateSolver(m, MyFrictionlessLayer{0.5}, options).solve(scene);
  const auto lib =
      PlaneSubstrateSolver(m, Layer<double>(0.5, LayerBase::frictionless), options).solve(scene);
  REQUIRE(mine.converged);
  REQUIRE(lib.converged);
  CHECK(mine.d_absolute);
  // Each within its tolerance of the exact solution: within twice it of each other.
  CHECK(std::abs(mine.a - lib.a) <= 2 * tol * lib.a);
  CHECK(std::abs(mine.b - lib.b) <= 2 * tol * lib.a);
  CHECK(std::abs(mine.chi - lib.chi) <= 2 * tol * lib.chi);
  CHECK(std::abs(mine.d - lib.d) <= 2 * tol * lib.d);

  const auto uniform = PlaneSubstrateSolver(m, Uniform{}, options).solve(scene);
  const auto hs = PlaneSubstrateSolver(m, HalfSpace<double>{}, options).solve(scene);
  REQUIRE(uniform.converged);
  CHECK_FALSE(uniform.d_absolute);
  CHECK(std::abs(uniform.a - hs.a) <= 2 * tol * hs.a);
  CHECK(std::abs(uniform.chi - hs.chi) <= 2 * tol * hs.chi);
  CHECK(std::abs(uniform.d - hs.d) <= 2 * tol * std::abs(hs.d));
}

TEST_CASE("plane substrate: bad inputs are named with their ranges", "[plane][substrate]") {
  const viscoroll::Elastic<double> m(1.0, 0.3);
  const auto solver = PlaneSubstrateSolver(m, Layer<double>(1.0));
  CHECK_THROWS_WITH(solver.solve(PlaneScene<double>{.c1 = 0.0, .load = 1.0, .speed = 0.0}),
                    Contains("c1") && Contains("c1 > 0"));
  CHECK_THROWS_WITH(solver.solve(PlaneScene<double>{.c1 = 1.0, .load = -1.0, .speed = 0.0}),
                    Contains("load") && Contains("load > 0"));
  CHECK_THROWS_WITH(solver.solve(PlaneScene<double>{.c1 = 1.0, .load = 1.0, .speed = -2.0}),
                    Contains("speed") && Contains("speed >= 0"));
  CHECK_THROWS_WITH(solver.solve(PlaneScene<double>{
                        .c1 = 1.0, .load = std::numeric_limits<double>::infinity(), .speed = 0.0}),
                    Contains("load"));
  const auto with = [&](auto change) {
    PlaneSubstrateOptions o;
    change(o);
    return PlaneSubstrateSolver(m, Layer<double>(1.0), o);
  };
  CHECK_THROWS_WITH(with([](auto& o) { o.tolerance = 0; }), Contains("tolerance"));
  CHECK_THROWS_WITH(with([](auto& o) { o.tolerance = 1e-17; }),
                    Contains("tolerance") && Contains("64 eps"));
  CHECK_THROWS_WITH(with([](auto& o) { o.initial_terms = 2; }), Contains("initial_terms"));
  CHECK_THROWS_WITH(with([](auto& o) { o.max_terms = 20; }), Contains("max_terms"));
  CHECK_THROWS_WITH(with([](auto& o) { o.max_iterations = 0; }), Contains("max_iterations"));
  CHECK_THROWS_WITH(Layer<double>(0.0), Contains("thickness"));
  // T(0) = 0/0 (a user's (H3) without its x = 0 case) is named.
  struct NaNAtZero : Uniform {
    double surface_factor(double q, double /*nu*/) const { return q == 0 ? std::nan("") : 1.0; }
  };
  CHECK_THROWS_WITH(PlaneSubstrateSolver(m, NaNAtZero{})
                        .solve(PlaneScene<double>{.c1 = 1.0, .load = 1.0, .speed = 0.0}),
                    Contains("surface_factor(0, nu)") && Contains("0 <= T(0) < inf"));
  CHECK_THROWS_WITH(SpringBed<double>(-1.0), Contains("thickness"));
  CHECK_NOTHROW(PlaneSubstrateSolver(viscoroll::Elastic<double>(1.0, 0.5), SpringBed<double>(1.0))
                    .solve(PlaneScene<double>{.c1 = 1.0, .load = 1.0, .speed = 0.0}));
}

TEST_CASE("plane substrate: a solution short of the tolerance says why", "[plane][substrate]") {
  // A thin bonded layer with too few terms allowed: not converged, with the estimates.
  const viscoroll::Elastic<double> m(1.0, 0.5);
  PlaneSubstrateOptions options;
  options.initial_terms = 4;
  options.max_terms = 8;
  const auto s = PlaneSubstrateSolver(m, Layer<double>(0.1), options)
                     .solve(PlaneScene<double>{.c1 = 1.0, .load = 100.0, .speed = 0.0});
  CHECK_FALSE(s.converged);
  CHECK(s.code == viscoroll::StopCode::tolerance_not_met);
  // The reason names the limit that stopped it, with its value.
  CHECK_THAT(s.reason, Contains("exceed the tolerance") && Contains("max_terms = 8"));
}

}  // namespace test_plane_substrate_user
