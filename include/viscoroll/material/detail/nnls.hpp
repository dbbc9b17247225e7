// viscoroll: non-negative least squares, min ||A x - b|| subject to x >= 0, by the active-set
// method of Lawson & Hanson (Solving Least Squares Problems, 1974, ch. 23, algorithm NNLS).
// Debian's Eigen 3.4.0 ships no NNLS module (unsupported/Eigen/NNLS came later).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace viscoroll::detail {

template <class Real>
struct NnlsResult {
  Eigen::Matrix<Real, Eigen::Dynamic, 1> x;
  Real residual_norm;  // ||A x - b||
  int iterations;      // outer iterations (variables freed)
  bool converged;      // the Kuhn–Tucker conditions hold to the tolerance
};

/// Lawson–Hanson NNLS. The columns are scaled to unit norm first (x >= 0 is unchanged by a
/// positive scaling). Kuhn–Tucker test: w = A^T (b - A x) <= tol on the zero set, with
/// tol = 10 eps max(m, n) max_j ||a_j||_1 (of the scaled A) times ||b||.
template <class Real>
NnlsResult<Real> nnls(const Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>& a_in,
                      const Eigen::Matrix<Real, Eigen::Dynamic, 1>& b, int max_iterations = 0) {
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  const Eigen::Index m = a_in.rows(), n = a_in.cols();
  Vector scale(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const Real s = a_in.col(j).norm();
    scale(j) = s > 0 ? s : Real(1);
  }
  const Matrix a = a_in * scale.cwiseInverse().asDiagonal();
  if (max_iterations <= 0) max_iterations = int(3 * n + 10);
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real tol = 10 * eps * Real((std::max)(m, n)) * a.cwiseAbs().colwise().sum().maxCoeff() *
                   (std::max)(b.norm(), std::numeric_limits<Real>::min());

  Vector x = Vector::Zero(n);
  std::vector<bool> passive(std::size_t(n), false), skip(std::size_t(n), false);
  int iterations = 0;
  bool converged = false;
  auto solve_passive = [&](Vector& z) {
    std::vector<Eigen::Index> idx;
    for (Eigen::Index j = 0; j < n; ++j)
      if (passive[std::size_t(j)]) idx.push_back(j);
    Matrix ap(m, Eigen::Index(idx.size()));
    for (std::size_t k = 0; k < idx.size(); ++k) ap.col(Eigen::Index(k)) = a.col(idx[k]);
    const Vector zp = ap.colPivHouseholderQr().solve(b);
    z.setZero(n);
    for (std::size_t k = 0; k < idx.size(); ++k) z(idx[k]) = zp(Eigen::Index(k));
  };
  while (iterations < max_iterations) {
    const Vector w = a.transpose() * (b - a * x);
    Eigen::Index t = -1;
    Real best = tol;
    for (Eigen::Index j = 0; j < n; ++j)
      if (!passive[std::size_t(j)] && !skip[std::size_t(j)] && w(j) > best) {
        best = w(j);
        t = j;
      }
    if (t < 0) {
      converged = true;
      break;
    }
    ++iterations;
    passive[std::size_t(t)] = true;
    Vector z;
    bool first = true;
    for (;;) {
      solve_passive(z);
      if (first && !(z(t) > 0)) {
        // Rounding made the freed variable non-positive: undo, and do not choose it again until
        // the passive set changes (Lawson & Hanson's step 6 safeguard).
        passive[std::size_t(t)] = false;
        skip[std::size_t(t)] = true;
        break;
      }
      first = false;
      bool feasible = true;
      for (Eigen::Index j = 0; j < n; ++j)
        if (passive[std::size_t(j)] && !(z(j) > 0)) feasible = false;
      if (feasible) {
        x = z;
        std::fill(skip.begin(), skip.end(), false);
        break;
      }
      Real alpha = 1;
      Eigen::Index blocking = -1;
      for (Eigen::Index j = 0; j < n; ++j)
        if (passive[std::size_t(j)] && !(z(j) > 0)) {
          const Real aj = x(j) / (x(j) - z(j));
          if (blocking < 0 || aj < alpha) {
            alpha = aj;
            blocking = j;
          }
        }
      x += alpha * (z - x);
      x(blocking) = 0;  // the blocking variable reaches its bound exactly
      for (Eigen::Index j = 0; j < n; ++j)
        if (passive[std::size_t(j)] && !(x(j) > 0)) {
          passive[std::size_t(j)] = false;
          x(j) = 0;
        }
    }
  }
  NnlsResult<Real> r;
  r.residual_norm = (a * x - b).norm();
  r.x = x.cwiseQuotient(scale);
  r.iterations = iterations;
  r.converged = converged;
  return r;
}

}  // namespace viscoroll::detail
