// viscoroll: a certified strict local minimum of phi = |r|^2 / 2 by Newton's method with the
// second-order term S of the Hessian taken by differences of the gradient (docs/theory.md
// section 9, (M1)-(M4)), for where Levenberg-Marquardt stops at a least-squares minimum with no
// root near (levenberg_marquardt.hpp).
//
// There the Jacobian J is nearly singular and r lies along its smallest left singular vector
// (M1), so the Gauss-Newton model J^T J misses the curvature of phi that matters, that of
// S = sum_i r_i grad^2 r_i (M2).
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <viscoroll/numerics/least_squares_problem.hpp>

namespace viscoroll::detail {

/// How accurately detail::second_order_term takes S (docs/theory.md section 9, (M3)).
enum class SecondOrderAccuracy {
  /// To steer Newton's steps: forward differences of the gradient from g(x) (one Jacobian per
  /// direction), along the eigenvectors of J^T J whose eigenvalue is at most 10 s.
  steering,
  /// To certify the stop (M4): central differences (two Jacobians per direction), along the
  /// eigenvectors whose eigenvalue is at most 1e3 s.
  certifying,
};

/// The second-order term S = sum_i r_i grad^2 r_i of the Hessian H of |r|^2 / 2 at x, into s_part,
/// with jtj = J^T J and g = J^T r at x (docs/theory.md section 9, (M3)). H v by differences of
/// the gradient g = J^T r in the variables scaled by D = diag(|J e_j|) (Marquardt's column
/// scales): central, H v ~ (g(x + h v) - g(x - h v)) / (2h), h = eps^(1/3) / |D v|, to certify;
/// forward, H v ~ (g(x + h v) - g(x)) / h, h = eps^(1/2) / |D v|, to steer. First along the
/// eigenvector v_1 of the smallest eigenvalue of J^T J, which gives s = |S v_1|, then along every
/// eigenvector of J^T J whose eigenvalue is at most 1e3 s (certifying) or 10 s (steering). On
/// those k directions V, with E = H V - J^T J V, S ~ E V^T + V E^T - V V^T E V^T (exact on
/// span V). False where the problem's jacobian() is.
template <class Real, class Problem>
bool second_order_term(const Problem& problem, const numerics::DynamicVector<Real>& x,
                       const numerics::DynamicMatrix<Real>& jtj,
                       const numerics::DynamicVector<Real>& g, SecondOrderAccuracy accuracy,
                       numerics::DynamicMatrix<Real>& s_part) {
  using Vector = numerics::DynamicVector<Real>;
  using Matrix = numerics::DynamicMatrix<Real>;
  using std::cbrt;
  using std::sqrt;
  const int n = problem.unknowns(), m = problem.equations();
  const Real eps = std::numeric_limits<Real>::epsilon();
  const bool central = accuracy == SecondOrderAccuracy::certifying;
  const Real reach = central ? Real(1000) : Real(10);
  Matrix jac_h(m, n);
  Vector r_h(m), g_plus(n), g_minus(n);
  const Eigen::SelfAdjointEigenSolver<Matrix> gauss(jtj);  // eigenvalues ascending
  const Vector scale = jtj.diagonal().cwiseSqrt();         // |J e_j|: Marquardt's column scales
  const auto hessian_times = [&](const Vector& v, Vector& hv) {
    const Real h = (central ? cbrt(eps) : sqrt(eps)) / std::max(scale.cwiseProduct(v).norm(), eps);
    if (!problem.jacobian(x + h * v, r_h, jac_h)) return false;
    g_plus = jac_h.transpose() * r_h;
    if (!central) {
      hv = (g_plus - g) / h;
      return true;
    }
    if (!problem.jacobian(x - h * v, r_h, jac_h)) return false;
    g_minus = jac_h.transpose() * r_h;
    hv = (g_plus - g_minus) / (2 * h);
    return true;
  };
  Vector hv(n);
  if (!hessian_times(gauss.eigenvectors().col(0), hv)) return false;
  const Real s_scale = (hv - jtj * gauss.eigenvectors().col(0)).norm();
  int k = 1;
  while (k < n && gauss.eigenvalues()[k] <= reach * s_scale) ++k;
  const Matrix v = gauss.eigenvectors().leftCols(k);
  Matrix e(n, k);
  e.col(0) = hv;
  for (int j = 1; j < k; ++j) {
    if (!hessian_times(v.col(j), hv)) return false;
    e.col(j) = hv;
  }
  e -= jtj * v;
  s_part = e * v.transpose() + v * e.transpose() - v * (v.transpose() * e) * v.transpose();
  s_part = (s_part + s_part.transpose()).eval() / 2;
  return true;
}

}  // namespace viscoroll::detail

namespace viscoroll::numerics {

/// Newton's method on phi = |r|^2 / 2 from x; needs the problem's jacobian() (a false return is
/// reported `undefined`). x and r hold the last accepted iterate on return (r = problem(x)).
/// The Hessian is J^T J + S, S from detail::second_order_term, kept from step to step (it varies
/// slowly): taken to steer at the start and where a stale S finds no step, to certify where a
/// steering S finds none and before the stop is trusted. Steps solve (J^T J + S + mu I) s = -g
/// in the eigenbasis of J^T J + S, mu = 0 when that is positive definite, else from
/// 2 |lambda_min| up by factors of 8; accepted when phi falls. Converged (M4): the Hessian with
/// S taken at the point to certify positive definite and Newton's predicted decrease
/// g^T H^-1 g / 2 below the rounding of phi, 16 eps sqrt(m) |r| (each scaled equation sums terms
/// of order one): a strict local minimum. A residual below the root tolerance on the way returns
/// `root_near`.
template <class Real, LeastSquaresProblem<Real> Problem>
LeastSquaresOutcome least_squares_minimum(const Problem& problem, DynamicVector<Real>& x,
                                          DynamicVector<Real>& r,
                                          const LeastSquaresOptions<Real>& options = {}) {
  const int n = problem.unknowns(), m = problem.equations();
  const Real eps = std::numeric_limits<Real>::epsilon();
  using Vector = DynamicVector<Real>;
  using Matrix = DynamicMatrix<Real>;
  using std::abs;
  using std::sqrt;
  LeastSquaresOutcome out{.reason = "iteration limit (least-squares minimisation)"};
  Matrix jac(m, n), s_part(n, n);
  Vector rt(m);
  using detail::SecondOrderAccuracy;
  // Where and how s_part was taken: at an earlier x, or at the current x to steer or to certify.
  enum class Taken { earlier, to_steer, to_certify } taken = Taken::earlier;
  Real mu = 0;
  const auto second_order = [&](const Matrix& jtj, const Vector& g, SecondOrderAccuracy accuracy) {
    if (!detail::second_order_term(problem, x, jtj, g, accuracy, s_part)) return false;
    taken = accuracy == SecondOrderAccuracy::certifying ? Taken::to_certify : Taken::to_steer;
    return true;
  };
  for (; out.iterations < options.max_iterations; ++out.iterations) {
    if (!problem.jacobian(x, r, jac)) return out.jacobian_undefined();
    if (r.cwiseAbs().maxCoeff() <= options.root_tolerance) {
      out.root_near = true;
      out.reason = "root near";
      return out;
    }
    const Real phi = r.squaredNorm() / 2;
    const Real floor = 16 * eps * sqrt(Real(m)) * r.norm();  // rounding of phi
    const Vector g = jac.transpose() * r;
    const Matrix jtj = jac.transpose() * jac;
    if (out.iterations == 0 && !second_order(jtj, g, SecondOrderAccuracy::steering))
      return out.jacobian_undefined();
    bool accepted = false;
    for (;;) {
      const Eigen::SelfAdjointEigenSolver<Matrix> newton(jtj + s_part);
      const Vector& lambda = newton.eigenvalues();
      const Vector qg = newton.eigenvectors().transpose() * g;
      const Real lmin = lambda[0], lmax = lambda[n - 1];
      const Real predicted =
          lmin > 0 ? Real((qg.array().square() / lambda.array()).sum() / 2) : Real(0);
      if (lmin > 0 && predicted <= floor) {
        if (taken != Taken::to_certify) {
          if (!second_order(jtj, g, SecondOrderAccuracy::certifying))
            return out.jacobian_undefined();
          continue;  // the stop is trusted with S taken here to certify only
        }
        // Below the rounding of phi: converged, after one more Newton step where the model
        // still promises more than eps phi and the step delivers it (kept if it lowers phi).
        bool minimum = predicted <= 16 * eps * phi;
        if (!minimum) {
          const Vector step = -(newton.eigenvectors() * (qg.array() / lambda.array()).matrix());
          const bool lower = problem(x + step, rt) && rt.squaredNorm() / 2 < phi;
          if (lower) x += step;
          minimum = !lower || phi - rt.squaredNorm() / 2 <= floor;
          accepted = lower;
        }
        if (minimum) {
          if (accepted && !problem(x, r)) return out.jacobian_undefined();
          out.converged = true;
          out.reason = "least-squares minimum (no root here)";
          out.code = StopCode::converged;
          ++out.iterations;
          return out;
        }
        break;
      }
      mu = lmin > 0 ? Real(0) : std::max(mu, 2 * abs(lmin));
      for (int attempt = 0; attempt < 40 && !accepted; ++attempt) {
        const Vector step =
            -(newton.eigenvectors() * (qg.array() / (lambda.array() + mu)).matrix());
        if (problem(x + step, rt) && rt.squaredNorm() / 2 < phi) {
          x += step;
          accepted = true;
        } else {
          // From the smallest shift that tells: the curvature that matters is far below lmax.
          mu = std::max(8 * mu, 2 * std::max(-lmin, Real(0)) + eps * lmax);
        }
      }
      if (accepted || taken == Taken::to_certify) break;
      // A stale S: take it here to steer and try again; a steering S: take it to certify.
      if (!second_order(jtj, g,
                        taken == Taken::earlier ? SecondOrderAccuracy::steering
                                                : SecondOrderAccuracy::certifying))
        return out.jacobian_undefined();
      mu = 0;
    }
    if (!accepted) {
      out.reason = "no descent step (least-squares minimisation)";
      out.code = StopCode::no_descent;
      return out;
    }
    taken = Taken::earlier;
    mu /= 8;
  }
  problem(x, r);
  return out;
}

}  // namespace viscoroll::numerics
