// numerics::least_squares_minimum on problems with known answers (tests/numerics/
// least_squares_problems.hpp), independent of the line solver: Freudenstein and Roth's local
// minimum with r != 0, at a singular J where the Gauss-Newton model has no curvature, certified
// from where Levenberg-Marquardt stops and checked against its closed form; its second-order
// term taken to steer and to certify, against the closed form of S; a root met on the way
// handed back (root_near); a problem without Jacobian reported undefined; the iteration limit
// reported and never as converged.
#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/numerics/least_squares_minimum.hpp>
#include <viscoroll/numerics/levenberg_marquardt.hpp>

#include "numerics/least_squares_problems.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_numerics_least_squares_minimum {

namespace {

using namespace viscoroll::numerics;
using namespace viscoroll::testing;

const double eps = std::numeric_limits<double>::epsilon();

}  // namespace

TEST_CASE("numerics: least-squares minimum of Freudenstein and Roth, certified", "[numerics]") {
  const FreudensteinRoth problem;
  LsqVector x = point({0.5, -2}), r;
  REQUIRE(problem(x, r));
  const auto stall = levenberg_marquardt(problem, x, r);
  REQUIRE(stall.minimum);
  const auto out = least_squares_minimum(problem, x, r);
  INFO(out.reason << " after " << out.iterations << " iterations, x = " << x.transpose());
  REQUIRE(out.converged);
  REQUIRE_FALSE(out.root_near);
  REQUIRE(out.code == viscoroll::StopCode::converged);
  require_residual_at(problem, x, r);
  // The stop (M4): Newton's predicted decrease below the rounding of phi, 16 eps sqrt(m) |r|;
  // phi - phi* is that decrease to second order, and phi* itself is rounded by as much, so
  // |phi - phi*| <= 32 eps sqrt(2) |r|, and (x - x*)^T H (x - x*) / 2 <= that with H the Hessian
  // of phi at x*: |x - x*| <= sqrt(2 |phi - phi*| / lambda_min(H)).
  const double phi = r.squaredNorm() / 2, phi_star = FreudensteinRoth::minimum_phi();
  const double phi_tol = 32 * eps * std::sqrt(2.0) * r.norm();
  REQUIRE(std::abs(phi - phi_star) <= phi_tol);
  const Eigen::SelfAdjointEigenSolver<LsqMatrix> hessian(FreudensteinRoth::minimum_hessian());
  REQUIRE(hessian.eigenvalues()[0] > 0);
  REQUIRE((x - FreudensteinRoth::minimum()).norm() <=
          std::sqrt(2 * phi_tol / hessian.eigenvalues()[0]));
}

TEST_CASE("numerics: second-order term to steer within sqrt(eps), to certify within eps^(2/3)",
          "[numerics]") {
  // Freudenstein and Roth: r is cubic in x2 alone, so S = diag(0, r1 p'' + r2 q'') in closed
  // form (least_squares_problems.hpp). The differences of the gradient along v (docs/theory.md
  // section 9, (M3)) err by O(h) forward, h = sqrt(eps) / |D v|, and by O(h^2) central,
  // h = eps^(1/3) / |D v|, each relative to the scale |J^T J| of the Hessian.
  using viscoroll::detail::SecondOrderAccuracy;
  const FreudensteinRoth problem;
  for (const double offset : {0.0, 0.3}) {  // at the minimum, and off it
    LsqVector x = FreudensteinRoth::minimum(), r;
    x[0] -= offset;
    x[1] += offset;
    LsqMatrix jac;
    REQUIRE(problem.jacobian(x, r, jac));
    const LsqMatrix jtj = jac.transpose() * jac;
    const LsqVector g = jac.transpose() * r;
    const double y = x[1];
    LsqMatrix s_exact = LsqMatrix::Zero(2, 2);
    s_exact(1, 1) = r[0] * (10 - 6 * y) + r[1] * (6 * y + 2);
    const Eigen::SelfAdjointEigenSolver<LsqMatrix> gauss(jtj);
    const LsqVector v1 = gauss.eigenvectors().col(0);
    const double scale = gauss.eigenvalues()[1];
    const double s1 = (s_exact * v1).norm();
    INFO("offset " << offset << ": eigenvalues of J^T J " << gauss.eigenvalues().transpose()
                   << ", |S v1| " << s1);
    LsqMatrix steer, certify;
    REQUIRE(viscoroll::detail::second_order_term(problem, x, jtj, g, SecondOrderAccuracy::steering,
                                                 steer));
    REQUIRE(viscoroll::detail::second_order_term(problem, x, jtj, g,
                                                 SecondOrderAccuracy::certifying, certify));
    // Both exact on v1 to their difference error.
    CHECK(((steer - s_exact) * v1).norm() <= 8 * std::sqrt(eps) * scale);
    CHECK(((certify - s_exact) * v1).norm() <= 8 * std::cbrt(eps * eps) * scale);
    // The other eigenvalue lies above 10 s and below 1e3 s: the certifying term takes its
    // direction too, so it is the whole S; the steering one leaves it out.
    REQUIRE(scale > 10 * s1);
    REQUIRE(scale < 1000 * s1);
    CHECK((certify - s_exact).norm() <= 8 * std::cbrt(eps * eps) * scale);
    CHECK((steer - s_exact).norm() >= s_exact(1, 1) / 2);
  }
}

TEST_CASE("numerics: least-squares minimum hands back a root it meets", "[numerics]") {
  // Near Rosenbrock's root the Newton steps on phi reach max |r| below the root tolerance.
  const Rosenbrock problem;
  LsqVector x = point({1.001, 1}), r;
  REQUIRE(problem(x, r));
  const auto out = least_squares_minimum(problem, x, r);
  INFO(out.reason << " after " << out.iterations << " iterations, x = " << x.transpose());
  REQUIRE(out.root_near);
  REQUIRE_FALSE(out.converged);
  REQUIRE(r.cwiseAbs().maxCoeff() <= default_root_tolerance<double>());
}

TEST_CASE("numerics: least-squares minimum reports a missing Jacobian and its limit",
          "[numerics]") {
  LsqVector x = point({0.5, -2}), r;
  const Rosenbrock without_jacobian{false};
  REQUIRE(without_jacobian(x, r));
  const auto undefined = least_squares_minimum(without_jacobian, x, r);
  REQUIRE(undefined.undefined);
  REQUIRE_FALSE(undefined.converged);
  REQUIRE(undefined.code == viscoroll::StopCode::outside_domain);

  // One Newton step from Freudenstein and Roth's start, far from the minimum.
  const FreudensteinRoth problem;
  REQUIRE(problem(x, r));
  const double start_phi = r.squaredNorm() / 2;
  const auto out = least_squares_minimum(problem, x, r, {.max_iterations = 1});
  INFO(out.reason);
  REQUIRE_FALSE(out.converged);
  REQUIRE_FALSE(out.root_near);
  REQUIRE(out.code == viscoroll::StopCode::iteration_limit);
  REQUIRE(out.iterations == 1);
  REQUIRE(r.squaredNorm() / 2 < start_phi);
}

}  // namespace test_numerics_least_squares_minimum
