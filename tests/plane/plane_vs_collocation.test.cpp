// The plane solver (pseudo-pressure (32), trailing edge (36), leading edge (P4), docs/theory.md)
// against an independent spectral collocation of Hunter's Eq. (2) (tests/support,
// docs/hunter-collocation.md), which imposes u' = -C1 x directly and uses none of (32)-(36).
#include <catch2/catch.hpp>
#include <cmath>
#include <viscoroll/plane/plane_solver.hpp>

#include "support/hunter_collocation.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_vs_collocation {

namespace {

/// Chebyshev terms for the reference: the leading-edge layer of relative width v/(1+f) needs
/// N ~ 5 sqrt((1+f)/v) for 1e-6 (docs/hunter-collocation.md, convergence table); with
/// 16 + 6 sqrt((1+f)/v) the reference is converged to better than 1e-10 on the whole range.
int terms_for(double f, double v) {
  return 8 * static_cast<int>(std::ceil((16 + 6 * std::sqrt((1 + f) / v)) / 8));
}

}  // namespace

TEST_CASE("plane: agrees with the independent collocation of Hunter's Eq. (2)",
          "[plane][reference]") {
  // The target is 0.1%; both methods are converged to ~1e-10, so the check is much tighter:
  // 1e-8 relative (pmax_x, located by the slope root here and by Brent + slope root there: 1e-7
  // of a0).
  const double pi = std::acos(-1.0), c = 1 / (2 * pi);
  for (double f : {1.0, 9.0})
    for (double v : {0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0}) {
      const double W = 1 / (4 * c * (1 + f));  // a0 = 1, C1 = 1
      const auto ref = viscoroll::testing::hunter_reference(c, f, v, 1.0, W, terms_for(f, v));
      const auto s = viscoroll::PlaneSolverD(viscoroll::StandardLinearSolid<double>(1, 0, f, v))
                         .solve({1.0, W, 1.0});
      const auto peak = s.peak();
      INFO("f = " << f << ", V tau/a0 = " << v << ", N = " << ref.n_terms);
      REQUIRE(ref.converged);
      REQUIRE(s.converged);
      CHECK(s.a == Approx(ref.a).epsilon(1e-8));
      CHECK(s.b == Approx(ref.b).epsilon(1e-8));
      CHECK(s.chi == Approx(ref.chi).epsilon(1e-8));
      CHECK(peak.pressure == Approx(ref.pmax).epsilon(1e-8));
      CHECK(std::abs(peak.x - ref.pmax_x) <= 1e-7);
      for (double x : {s.b - 0.9 * s.a, s.b, s.b + 0.5 * s.a, s.b + 0.99 * s.a})
        CHECK(std::abs(s.pressure(x) - ref.pressure(x)) <= 1e-8 * ref.pmax);
    }
}

}  // namespace test_plane_vs_collocation
