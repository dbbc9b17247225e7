// Tests of restarted right-preconditioned GMRES (numerics/gmres.hpp) against Eigen's dense LU on
// a non-symmetric system, with and without a preconditioner, restarted (restart < n); the
// iteration limit is reported as not converged with the true residual.
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <viscoroll/numerics/gmres.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_gmres {

namespace {

using Matrix = Eigen::MatrixXd;
using Vector = Eigen::VectorXd;
using viscoroll::numerics::gmres;

/// A non-symmetric 40 x 40 matrix: diagonal 1 .. 100 plus a random part of norm about 2, so
/// that the diagonal is a good preconditioner and the system is not symmetric.
Matrix test_matrix() {
  constexpr int n = 40;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uni(-1, 1);
  Matrix a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a(i, j) = uni(rng) / std::sqrt(double(n));
  for (int i = 0; i < n; ++i) a(i, i) += 1 + 99 * double(i) / (n - 1);
  return a;
}

}  // namespace

TEST_CASE("numerics: GMRES solves a non-symmetric system as LU does", "[numerics]") {
  const Matrix a = test_matrix();
  const auto n = a.rows();
  Vector b(n);
  for (Eigen::Index i = 0; i < n; ++i) b[i] = std::cos(double(i));
  const Vector want = a.partialPivLu().solve(b);
  const Eigen::JacobiSVD<Matrix> svd(a);
  const double cond = svd.singularValues()[0] / svd.singularValues()[n - 1];
  const auto apply_a = [&](const auto& v, Vector& out) { out = a * v; };
  const auto identity = [](const auto& v, Vector& out) { out = v; };
  const auto jacobi = [&](const auto& v, Vector& out) { out = v.cwiseQuotient(a.diagonal()); };
  const double tol = 1e-12;
  const int restart = 10;
  // Relative residual <= tol bounds the relative error by cond(A) tol; LU adds cond(A) n eps.
  const double bound =
      cond * (tol + double(n) * std::numeric_limits<double>::epsilon()) * want.norm();

  Vector plain = Vector::Zero(n);
  const auto r1 = gmres<double>(apply_a, identity, b, plain, tol, restart, 10000);
  CHECK(r1.converged);
  CHECK(r1.relative_residual <= tol);
  CHECK(r1.iterations > restart);  // restarted at least once
  CHECK((plain - want).norm() <= bound);

  Vector preconditioned = Vector::Zero(n);
  const auto r2 = gmres<double>(apply_a, jacobi, b, preconditioned, tol, restart, 10000);
  CHECK(r2.converged);
  CHECK(r2.relative_residual <= tol);
  CHECK(r2.iterations < r1.iterations);
  CHECK((preconditioned - want).norm() <= bound);

  // From the solution itself: converged at once, x unchanged.
  Vector exact = want;
  const auto r3 = gmres<double>(apply_a, jacobi, b, exact, 1e-8, restart, 10000);
  CHECK(r3.converged);
  CHECK(r3.iterations == 0);
  CHECK(exact == want);

  // b = 0: x = 0.
  Vector zero = Vector::Ones(n);
  CHECK(gmres<double>(apply_a, identity, Vector::Zero(n).eval(), zero, tol, restart, 10).converged);
  CHECK(zero.isZero(0));
}

TEST_CASE("numerics: GMRES reports its iteration limit", "[numerics]") {
  const Matrix a = test_matrix();
  const auto n = a.rows();
  const Vector b = Vector::Ones(n);
  const auto apply_a = [&](const auto& v, Vector& out) { out = a * v; };
  const auto identity = [](const auto& v, Vector& out) { out = v; };
  Vector x = Vector::Zero(n);
  const auto report = gmres<double>(apply_a, identity, b, x, 1e-12, 4, 6);
  CHECK_FALSE(report.converged);
  CHECK(report.iterations == 6);
  // The reported residual is the true one of the returned x.
  const double residual = (b - a * x).norm() / b.norm();
  CHECK(report.relative_residual == Approx(residual).epsilon(1e-12));
  CHECK(report.relative_residual > 1e-12);
  CHECK(report.relative_residual < 1);  // but six steps did reduce it
}

}  // namespace test_gmres
