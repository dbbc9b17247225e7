// numerics::levenberg_marquardt on problems with known answers (tests/numerics/
// least_squares_problems.hpp), independent of the line solver: Rosenbrock's root reached to the
// root tolerance with the problem's Jacobian and with forward differences, trial points outside
// the residual's domain rejected on the way to a root, a start outside it reported as such, the
// iteration limit reported and never as converged, and a root-free minimum reported as a
// minimum, not converged.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/numerics/levenberg_marquardt.hpp>

#include "numerics/least_squares_problems.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_levenberg_marquardt {

namespace {

using namespace viscoroll::numerics;
using namespace viscoroll::testing;

const double eps = std::numeric_limits<double>::epsilon();

}  // namespace

TEST_CASE("numerics: Levenberg-Marquardt reaches Rosenbrock's root", "[numerics]") {
  // From Rosenbrock's start (-1.2, 1); the problem's Jacobian, forward differences by option,
  // and forward differences where the problem declines to give its Jacobian.
  const auto [problem, analytic] =
      GENERATE(std::pair{Rosenbrock{true}, true}, std::pair{Rosenbrock{true}, false},
               std::pair{Rosenbrock{false}, true});
  LsqVector x = point({-1.2, 1}), r;
  REQUIRE(problem(x, r));
  const LeastSquaresOptions<double> options{.analytic_jacobian = analytic};
  const auto out = levenberg_marquardt(problem, x, r, options);
  INFO(out.reason << " after " << out.iterations << " iterations, x = " << x.transpose());
  REQUIRE(out.converged);
  REQUIRE_FALSE(out.minimum);
  REQUIRE_FALSE(out.undefined);
  require_residual_at(problem, x, r);
  const double rmax = r.cwiseAbs().maxCoeff();
  REQUIRE(rmax <= options.root_tolerance);
  // x - (1, 1) = J^-1 r to first order, J = [-20 10; -1 0] at the root: |J^-1|_inf = 2.1.
  REQUIRE((x.array() - 1).abs().maxCoeff() <= 2.1 * rmax + 4 * eps);
}

TEST_CASE("numerics: Levenberg-Marquardt steps back from outside the domain", "[numerics]") {
  // r = 1/x - 2 from x = 10: the undamped step 2x - 2x^2 = -180 leaves x > 0; damped steps
  // inside it reach the root 1/2, where |x - 1/2| = |r| / |J| = |r| / 4 to first order.
  const Reciprocal problem;
  LsqVector x = point({10}), r;
  REQUIRE(problem(x, r));
  const auto out = levenberg_marquardt(problem, x, r);
  INFO(out.reason << " after " << out.iterations << " iterations, x = " << x[0]);
  REQUIRE(out.converged);
  REQUIRE(problem.outside > 0);
  require_residual_at(problem, x, r);
  REQUIRE(std::abs(x[0] - 0.5) <= std::abs(r[0]) / 4 + 2 * eps);

  // A start outside the domain: no Jacobian there, reported as such, x left where it was.
  LsqVector outside = point({-1}), r_outside = LsqVector::Zero(1);
  const auto stop = levenberg_marquardt(problem, outside, r_outside);
  REQUIRE(stop.undefined);
  REQUIRE_FALSE(stop.converged);
  REQUIRE(stop.code == viscoroll::StopCode::outside_domain);
  REQUIRE(stop.iterations == 0);
  REQUIRE(outside[0] == -1);
}

TEST_CASE("numerics: Levenberg-Marquardt reports its iteration limit", "[numerics]") {
  const Rosenbrock problem;
  LsqVector x = point({-1.2, 1}), r;
  REQUIRE(problem(x, r));
  const double start_cost = r.squaredNorm();
  const auto out = levenberg_marquardt(problem, x, r, {.max_iterations = 3});
  REQUIRE_FALSE(out.converged);
  REQUIRE_FALSE(out.minimum);
  REQUIRE(out.code == viscoroll::StopCode::iteration_limit);
  REQUIRE(out.iterations == 3);
  // The last accepted iterate, lower than the start: every step lowered |r|^2.
  require_residual_at(problem, x, r);
  REQUIRE(r.squaredNorm() < start_cost);
  REQUIRE(r.cwiseAbs().maxCoeff() > default_root_tolerance<double>());
}

TEST_CASE("numerics: Levenberg-Marquardt stops at a minimum with no root near", "[numerics]") {
  // Freudenstein and Roth from their start (0.5, -2) lead to the local minimum with r != 0, where
  // J is singular: the iteration stops there as a minimum, not converged.
  const FreudensteinRoth problem;
  LsqVector x = point({0.5, -2}), r;
  REQUIRE(problem(x, r));
  const auto out = levenberg_marquardt(problem, x, r);
  INFO(out.reason << " after " << out.iterations << " iterations, x = " << x.transpose());
  REQUIRE(out.minimum);
  REQUIRE_FALSE(out.converged);
  REQUIRE(out.code == viscoroll::StopCode::no_descent);
  require_residual_at(problem, x, r);
  // In the minimum's basin, phi is not below the minimum's (to its rounding).
  REQUIRE(r.squaredNorm() / 2 >= FreudensteinRoth::minimum_phi() * (1 - 4 * eps));
}

TEST_CASE("numerics: Levenberg-Marquardt's stop tolerance and starting damping", "[numerics]") {
  // From Rosenbrock's start: with stop_tolerance 1e-2 the iteration returns at the first iterate
  // with max |r| <= 1e-2, neither converged nor a minimum, reason "stage tolerance"; its r is the
  // residual there. A start already within it returns at once, with no iteration.
  const Rosenbrock problem{true};
  LsqVector x = point({-1.2, 1}), r;
  REQUIRE(problem(x, r));
  const LeastSquaresOptions<double> stop{.stop_tolerance = 1e-2};
  const auto out = levenberg_marquardt(problem, x, r, stop);
  INFO(out.reason << " after " << out.iterations << " iterations, x = " << x.transpose());
  // The code of the stage's stop, never a final one.
  REQUIRE(out.code == viscoroll::StopCode::tolerance_not_met);
  REQUIRE_FALSE(out.converged);
  REQUIRE_FALSE(out.minimum);
  REQUIRE(out.iterations >= 1);
  require_residual_at(problem, x, r);
  REQUIRE(r.cwiseAbs().maxCoeff() <= 1e-2);
  const LsqVector held = x;
  const auto again = levenberg_marquardt(problem, x, r, stop);
  REQUIRE(again.code == viscoroll::StopCode::tolerance_not_met);
  REQUIRE(again.iterations == 0);
  REQUIRE(x == held);

  // r = 1/x - 2 from x = 0.45, near the root: the undamped first step (initial_damping 1e-12)
  // is Newton's, x + x (1 - 2x) = 0.4950, against 0.45 + 0.045 / (1 + 1e-3) with the default's
  // 1e-3 on J^T J; each then converges to the root.
  const Reciprocal reciprocal;
  for (const double damping : {1e-3, 1e-12}) {
    LsqVector y = point({0.45}), ry;
    REQUIRE(reciprocal(y, ry));
    const LeastSquaresOptions<double> one{.max_iterations = 1, .initial_damping = damping};
    levenberg_marquardt(reciprocal, y, ry, one);
    INFO("initial_damping " << damping << ": x = " << y[0]);
    REQUIRE(std::abs(y[0] - (0.45 + 0.045 / (1 + damping))) <= 8 * eps);
  }
}

}  // namespace test_levenberg_marquardt
