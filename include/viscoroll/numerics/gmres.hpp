// viscoroll: restarted GMRES with right preconditioning (Saad & Schultz 1986; Saad, Iterative
// Methods for Sparse Linear Systems, 2nd ed., Alg. 9.5) for a non-symmetric linear system given
// only by the action of its matrix: modified Gram-Schmidt Arnoldi, Givens rotations. The active-set
// solver (numerics/active_set.hpp) solves its restricted systems with it.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace viscoroll::numerics {

/// What gmres() did.
struct GmresReport {
  bool converged = false;        ///< ||b - A x|| <= tol ||b|| reached
  int iterations = 0;            ///< Arnoldi steps over all cycles
  double relative_residual = 0;  ///< ||b - A x|| / ||b|| (true residual at exit)
};

/// Solves A x = b (n unknowns) from the initial guess in x, which it overwrites with the solution.
///   - apply_a(v, out): out = A v, for v a Vector or a column of an n-row Matrix (an Eigen
///     expression), out a Vector of n entries;
///   - apply_m(v, out): out = M v, the right preconditioner (A M y = b - A x0, x = x0 + M y; an
///     approximate inverse of A, or the identity); out may have to be resized to n;
///   - tol: stops at ||b - A x|| <= tol ||b||, the true residual, recomputed after each cycle (a
///     cycle ends early once the Givens estimate of the residual is under tol ||b|| / 2);
///   - restart: Arnoldi steps per cycle (the Krylov basis holds restart + 1 vectors of n);
///   - max_iterations: Arnoldi steps over all cycles; reaching it returns converged == false.
/// b = 0 returns x = 0. Each step costs one apply_m and one apply_a; each cycle one more of each
/// (the correction M V y and the true residual), the start one apply_a.
template <class Real, class ApplyA, class ApplyM>
GmresReport gmres(ApplyA&& apply_a, ApplyM&& apply_m,
                  const Eigen::Matrix<Real, Eigen::Dynamic, 1>& b,
                  Eigen::Matrix<Real, Eigen::Dynamic, 1>& x, Real tol, int restart,
                  int max_iterations) {
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  using std::abs;
  using std::sqrt;
  const Eigen::Index n = b.size();
  GmresReport report;
  const Real bnorm = b.norm();
  if (bnorm == 0) {
    x.setZero();
    report.converged = true;
    return report;
  }
  Vector r(n), w(n), z(n);
  apply_a(x, w);
  r = b - w;
  Real rnorm = r.norm();
  const int m = restart;
  Matrix v(n, m + 1), h = Matrix::Zero(m + 1, m);
  Vector cs(m), sn(m), g(m + 1);
  while (true) {
    if (rnorm <= tol * bnorm) {
      report.converged = true;
      break;
    }
    if (report.iterations >= max_iterations) break;
    v.col(0) = r / rnorm;
    g.setZero();
    g[0] = rnorm;
    h.setZero();
    int k = 0;
    for (; k < m && report.iterations < max_iterations; ++k) {
      ++report.iterations;
      apply_m(v.col(k), z);
      apply_a(z, w);
      for (int i = 0; i <= k; ++i) {
        h(i, k) = v.col(i).dot(w);
        w -= h(i, k) * v.col(i);
      }
      h(k + 1, k) = w.norm();
      if (h(k + 1, k) != 0) v.col(k + 1) = w / h(k + 1, k);
      for (int i = 0; i < k; ++i) {
        const Real t = cs[i] * h(i, k) + sn[i] * h(i + 1, k);
        h(i + 1, k) = -sn[i] * h(i, k) + cs[i] * h(i + 1, k);
        h(i, k) = t;
      }
      const Real denom = sqrt(h(k, k) * h(k, k) + h(k + 1, k) * h(k + 1, k));
      cs[k] = denom == 0 ? Real(1) : h(k, k) / denom;
      sn[k] = denom == 0 ? Real(0) : h(k + 1, k) / denom;
      h(k, k) = cs[k] * h(k, k) + sn[k] * h(k + 1, k);
      h(k + 1, k) = 0;
      g[k + 1] = -sn[k] * g[k];
      g[k] = cs[k] * g[k];
      if (abs(g[k + 1]) <= tol * bnorm / 2 || h(k, k) == 0) {
        ++k;
        break;
      }
    }
    // x += M V y, y from the triangular system.
    Vector y = h.topLeftCorner(k, k).template triangularView<Eigen::Upper>().solve(g.head(k));
    Vector corr = v.leftCols(k) * y;
    apply_m(corr, z);
    x += z;
    apply_a(x, w);
    r = b - w;
    rnorm = r.norm();
  }
  report.relative_residual = static_cast<double>(rnorm / bnorm);
  return report;
}

}  // namespace viscoroll::numerics
