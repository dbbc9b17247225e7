// The line solver's least-squares minima (docs/line-solver.md, "Least-squares minima"; derivation
// in docs/theory.md section 9): where the square line equations have no root, LineSolver returns
// the minimum of |r|^2 found by Newton's method with the second-order term in the subspace where
// it matters. Checked here independently of that approximation, with a Hessian differenced in
// every coordinate:
//   - the point is a strict local minimum: gradient J^T r at the bound the convergence test
//     implies, the full Hessian positive definite;
//   - theory.md section 9: at a least-squares minimum of a square system with r != 0, J is
//     singular and r lies along its last left singular vector (to what the stop's gradient
//     allows), which the point where Levenberg-Marquardt stalled is not;
//   - it lies below the point where Levenberg-Marquardt stalled (least_squares = false);
//   - a scene with a root never enters the minimisation (results identical with it off).
// The paper's scene (f = 9, C2/C1 = (ln 20 - 1)/25, a0 = C1 = 1), V tau = 3 a0, terms = 16 in the
// variable s: no root (docs/line-solver.md: max |r| ~ 4e-5), and Levenberg-Marquardt stalls at a
// point visibly short of the minimum (|g| ~ 5e-7, sigma_n ~ 7e-6).
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>

#include "support/paper_scene.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_least_squares_minimum {

namespace {

using viscoroll::LineOptions;
using viscoroll::LineSolverD;
using viscoroll::testing::PaperScene;

}  // namespace

TEST_CASE("line least squares: a strict local minimum where the equations have no root", "[line]") {
  const double eps = std::numeric_limits<double>::epsilon();
  const PaperScene paper;
  const LineOptions options{.terms = 16, .basis = viscoroll::LineBasis::s};
  const LineSolverD solver(paper.material, options);
  const auto s = solver.solve(paper.scene(3));
  INFO(s.reason << ", residual " << s.residual << ", iterations " << s.iterations);
  REQUIRE(s.converged);
  REQUIRE_FALSE(s.root);
  CHECK(viscoroll::has_warning(s, viscoroll::WarningCode::least_squares_minimum));
  CHECK(s.residual > 64 * std::sqrt(eps));

  const auto res = solver.residual(paper.scene(3));
  const Eigen::VectorXd x = res.pack(s.shape, s.d);
  const int n = res.unknowns();
  Eigen::VectorXd r;
  Eigen::MatrixXd jac;
  REQUIRE(res.jacobian(x, r, jac));
  const double phi = r.squaredNorm() / 2;
  const Eigen::VectorXd g = jac.transpose() * r;

  // The full Hessian of phi by central differences of the gradient in every coordinate, step
  // cbrt(eps) (1 + |x|): truncation O(h^2) ~ 1e-11 and rounding ~ eps |J| |r| / h ~ 1e-15 of
  // |J|^2 ~ 1e2, both far below the smallest eigenvalue asserted positive (measured ~1e-8).
  Eigen::MatrixXd hess(n, n);
  const double h = std::cbrt(eps) * (1 + x.cwiseAbs().maxCoeff());
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd rp, rm;
    Eigen::MatrixXd jp, jm;
    Eigen::VectorXd xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    REQUIRE(res.jacobian(xp, rp, jp));
    REQUIRE(res.jacobian(xm, rm, jm));
    hess.col(j) = (jp.transpose() * rp - jm.transpose() * rm) / (2 * h);
  }
  hess = (hess + hess.transpose()).eval() / 2;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(hess);
  const double lmin = eig.eigenvalues()[0], lmax = eig.eigenvalues()[n - 1];
  INFO("phi " << phi << ", |g| " << g.norm() << ", Hessian eigenvalues " << lmin << " .. " << lmax);
  CHECK(lmin > 1e-3 * std::sqrt(eps) * lmax);  // positive definite, not merely to rounding
  // Newton's predicted decrease g^T H^-1 g / 2 <= 16 eps phi is the solver's stop (with its own
  // H, which equals this one to the difference errors above and the neglected 1e-3 of S):
  // |g|^2 <= 2 lmax x 16 eps phi, and the predicted decrease with this H within twice the bound.
  CHECK(g.norm() <= std::sqrt(32 * eps * phi * lmax));
  const double predicted = g.dot(hess.ldlt().solve(g)) / 2;
  CHECK(predicted <= 32 * eps * phi);

  // theory.md section 9: J^T r = sum_i sigma_i (u_i . r) v_i, so |g| >= sigma_n |u_n . r| and the
  // part of r off the last left singular vector u_n is at most |g| / sigma_{n-1}. With the stop's
  // |g| <= sqrt(32 eps phi lmax) (above): J is singular to sigma_n <= sqrt(16 eps lmax) / along,
  // and r lies along u_n to 1 - along <= 16 eps lmax / sigma_{n-1}^2. The point where
  // Levenberg-Marquardt stalled (below) fails the first: there J is not yet singular.
  const auto singular = [&](const Eigen::MatrixXd& j, const Eigen::VectorXd& rr, double& along) {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(j, Eigen::ComputeFullU);
    along = std::abs(svd.matrixU().col(n - 1).dot(rr)) / rr.norm();
    return Eigen::VectorXd(svd.singularValues());
  };
  double along = 0;
  const Eigen::VectorXd sigma = singular(jac, r, along);
  const double sigma_bound = std::sqrt(16 * eps * lmax) / along;
  INFO("sigma_n " << sigma[n - 1] << " (bound " << sigma_bound << "), sigma_{n-1} " << sigma[n - 2]
                  << ", u_n . r / |r| " << along);
  CHECK(sigma[n - 1] <= sigma_bound);
  CHECK(1 - along <= 16 * eps * lmax / (sigma[n - 2] * sigma[n - 2]));

  // Below the point where Levenberg-Marquardt stalled.
  LineOptions plain_options = options;
  plain_options.least_squares = false;
  const auto stalled = LineSolverD(paper.material, plain_options).solve(paper.scene(3));
  INFO("without the minimisation: " << stalled.reason << ", residual " << stalled.residual);
  CHECK_FALSE(stalled.converged);
  CHECK(stalled.code == viscoroll::StopCode::no_descent);
  Eigen::VectorXd r_stalled;
  REQUIRE(res(res.pack(stalled.shape, stalled.d), r_stalled));
  CHECK(phi < r_stalled.squaredNorm() / 2);
  Eigen::MatrixXd jac_stalled;
  REQUIRE(res.jacobian(res.pack(stalled.shape, stalled.d), r_stalled, jac_stalled));
  double along_stalled = 0;
  const Eigen::VectorXd sigma_stalled = singular(jac_stalled, r_stalled, along_stalled);
  INFO("at the stall: sigma_n " << sigma_stalled[n - 1] << ", u_n . r / |r| " << along_stalled);
  CHECK(sigma_stalled[n - 1] > std::sqrt(16 * eps * lmax) / along_stalled);
}

TEST_CASE("line least squares: a scene with a root is not touched", "[line]") {
  const PaperScene paper;
  for (const double vtau : {0.3, 1.0}) {
    const auto with = LineSolverD(paper.material, LineOptions{.terms = 4}).solve(paper.scene(vtau));
    const auto without =
        LineSolverD(paper.material, LineOptions{.terms = 4, .least_squares = false})
            .solve(paper.scene(vtau));
    INFO("V tau/a0 = " << vtau << ": " << with.reason << ", residual " << with.residual);
    REQUIRE(with.converged);
    CHECK(with.root);
    CHECK(with.code == without.code);
    CHECK(with.reason == without.reason);
    CHECK(with.iterations == without.iterations);
    CHECK(with.a(0) == without.a(0));
    CHECK(with.l() == without.l());
    CHECK(with.d == without.d);
  }
}

}  // namespace test_line_least_squares_minimum
