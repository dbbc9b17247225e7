// viscoroll: Levenberg-Marquardt with Marquardt's diagonal scaling and Broyden's update, for
// systems of scaled equations that may have no root (docs/line-solver.md, "Iteration" and
// "Least-squares minima").
//
// The Jacobian (the problem's, or forward differences) is refreshed only when needed: after an
// accepted step s it takes Broyden's rank-one update J += (dr - J s) s^T / (s^T s), which
// satisfies the secant condition J s = dr (Dennis & Schnabel, Numerical Methods for Unconstrained
// Optimization, Sec. 8.1). When the updated Jacobian finds no descent step within a few dampings,
// the Jacobian is recomputed; "no descent step" is decided with a fresh one only, so the stopping
// reasons are those of the plain method. Two stops recognise a least-squares minimum with no root
// near, where the method crawls (docs/theory.md section 9, (M2)); least_squares_minimum.hpp takes
// over there.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>
#include <viscoroll/numerics/least_squares_problem.hpp>

namespace viscoroll::numerics {

/// Levenberg-Marquardt from x, with r = problem(x) on entry; x and r hold the last accepted
/// iterate on return. Steps solve (J^T J + mu diag(J^T J)) s = -J^T r (Marquardt's scaling, the
/// column norms floored at 1e-12), mu from options.initial_damping (1e-3), times 8 per rejected
/// try (40 tries with a fresh Jacobian, 4 with an updated one), divided by 4 per accepted step
/// (floor 1e-12); a step is accepted when r is defined there and |r|^2 falls. Stops:
/// - converged: max |r| <= root_tolerance after a step below eps^0.6 (1 + max |x|) taken with a
///   fresh Jacobian or one refreshed below that tolerance; or max |r| <= 4 eps (rounding level);
/// - minimum (not converged): no descent step with a fresh Jacobian; |r|^2 down by less than 5%
///   over 20 accepted steps; or three steps from a fresh Jacobian each lowering |r|^2 by less
///   than sqrt(eps) of itself (MINPACK's ftol test), the residual above tolerance in both;
/// - stage tolerance (not converged, not a minimum): max |r| <= options.stop_tolerance > 0, at
///   once, before any test above;
/// - undefined: the Jacobian could not be evaluated;
/// - the iteration limit.
/// `jac` is the iteration's Jacobian: on return it holds the one at the last accepted iterate
/// (fresh or carried there by Broyden's update; at a converged root within O(|last step|) of
/// J(x), the step below eps^0.6 (1 + max |x|) taken from a Jacobian refreshed at or below the
/// root tolerance), unless the return is undefined or at once by the stage tolerance.
template <class Real, LeastSquaresProblem<Real> Problem>
LeastSquaresOutcome levenberg_marquardt(const Problem& problem, DynamicVector<Real>& x,
                                        DynamicVector<Real>& r,
                                        const LeastSquaresOptions<Real>& options,
                                        DynamicMatrix<Real>& jac) {
  using Vector = DynamicVector<Real>;
  using Matrix = DynamicMatrix<Real>;
  using std::pow;
  using std::sqrt;
  const int n = problem.unknowns();
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real step_tol = pow(eps, Real(0.6));
  Real cost = r.squaredNorm();
  Real mu = options.initial_damping;
  jac.resize(problem.equations(), n);
  Vector trial(n), rt(problem.equations());
  LeastSquaresOutcome out{.reason = "iteration limit"};
  bool fresh = false;
  bool near_jacobian = false;  // the Jacobian was refreshed at a residual below tolerance
  int stalled = 0;
  // |r|^2 at the ends of the last iterations, for the slow-progress test below.
  std::vector<Real> history;
  const auto refresh_jacobian = [&]() {
    if (!(options.analytic_jacobian && problem.jacobian(x, rt, jac)) &&
        !difference_jacobian(problem, x, r, jac, trial, rt))
      return false;
    fresh = true;
    return true;
  };
  const auto at_stop_tolerance = [&]() {
    if (!(options.stop_tolerance > 0) || !(r.cwiseAbs().maxCoeff() <= options.stop_tolerance))
      return false;
    out.reason = "stage tolerance";
    out.code = StopCode::tolerance_not_met;  // the stage's looser tolerance: never a final stop
    return true;
  };
  if (at_stop_tolerance()) return out;
  for (; out.iterations < options.max_iterations; ++out.iterations) {
    if (out.iterations == 0 && !refresh_jacobian()) return out.jacobian_undefined();
    bool accepted = false;
    Vector step;
    for (;;) {
      const Vector grad = jac.transpose() * r;
      Vector diag = jac.colwise().squaredNorm().transpose();
      for (int j = 0; j < n; ++j) diag[j] = std::max(diag[j], Real(1e-12));
      // A fresh Jacobian gets the full damping range; an updated one a few tries before refresh.
      const int attempts = fresh ? 40 : 4;
      for (int attempt = 0; attempt < attempts; ++attempt) {
        Matrix a = jac.transpose() * jac;
        for (int j = 0; j < n; ++j) a(j, j) += mu * diag[j];
        step = a.ldlt().solve(-grad);
        trial = x + step;
        if (problem(trial, rt)) {
          const Real trial_cost = rt.squaredNorm();
          if (trial_cost < cost) {
            accepted = true;
            break;
          }
        }
        mu *= 8;
      }
      if (accepted || fresh) break;
      mu = std::max(Real(mu / pow(Real(8), Real(attempts))),
                    Real(1e-12));  // the damping of before the tries
      if (!refresh_jacobian()) return out.jacobian_undefined();
    }
    if (!accepted) {
      out.reason = "no descent step (Levenberg-Marquardt damping exhausted)";
      out.code = StopCode::no_descent;
      out.minimum = true;
      return out;
    }
    // Broyden's update with the accepted step s and the change of residual rt - r.
    const bool newton_step = fresh;
    const Real reduction = (cost - rt.squaredNorm()) / cost;
    const Real ss = step.squaredNorm();
    if (ss > 0) jac += ((rt - r) - jac * step) * (step.transpose() / ss);
    fresh = false;
    x = trial;
    r = rt;
    cost = r.squaredNorm();
    mu = std::max(mu / 4, Real(1e-12));
    if (at_stop_tolerance()) {
      ++out.iterations;
      return out;
    }
    const Real rmax = r.cwiseAbs().maxCoeff();
    // Near the root (residual below tolerance) the Jacobian is refreshed once: the next step is
    // Newton's, which about squares the residual (5.7e-8 to 1.1e-11 in the line equations at
    // V tau = a0, N = 4, from a neighbouring speed's solution), and the updated Jacobian after it
    // differs from the true one by O(the error at the refresh) (the secant condition), so that
    // its step measures the remaining error.
    if (rmax <= options.root_tolerance) {
      if (step.cwiseAbs().maxCoeff() <= step_tol * (1 + x.cwiseAbs().maxCoeff()) &&
          (newton_step || near_jacobian)) {
        out.converged = true;
        out.reason = "converged";
        out.code = StopCode::converged;
        ++out.iterations;
        return out;
      }
      if (!near_jacobian) {
        if (!refresh_jacobian()) return out.jacobian_undefined();
        near_jacobian = true;
      }
    }
    if (rmax <= 4 * eps) {
      out.converged = true;
      out.reason = "converged (residual at rounding level)";
      out.code = StopCode::converged;
      ++out.iterations;
      return out;
    }
    // Slow progress: |r|^2 fell by less than 5% over the last 20 accepted steps while the
    // residual is above tolerance. Near a root the steps converge quadratically; this is the
    // crawl along the valley of a least-squares minimum with no root near (in the line equations,
    // at a fold of the discrete equations where the scaled Jacobian's smallest singular value
    // falls to ~1e-5, docs/line-solver.md). Passing a near-fold on the way to a root, the
    // iteration crawls too, but for fewer steps (line equations at V tau = a0, N = 8: 12 steps,
    // 3% in all).
    history.push_back(cost);
    if (rmax > options.root_tolerance && history.size() > 20 &&
        history[history.size() - 21] - cost < Real(0.05) * history[history.size() - 21]) {
      return out.stalled(
          "stalled: |r|^2 fell by less than 5% over 20 steps (a least-squares minimum, no root "
          "near)");
    }
    // Stagnation (MINPACK's ftol test): a step that lowers |r|^2 by less than sqrt(eps) of
    // itself. From an updated Jacobian, refresh it; from a fresh one three times running, the
    // iterate sits at a least-squares minimum with no root of the equations near it.
    if (rmax > options.root_tolerance && reduction < sqrt(eps)) {
      if (!newton_step) {
        if (!fresh && !refresh_jacobian()) return out.jacobian_undefined();
      } else if (++stalled >= 3) {
        return out.stalled(
            "stalled at a least-squares minimum, no root near (|r|^2 falls by < sqrt(eps) per "
            "step)");
      }
    } else {
      stalled = 0;
    }
  }
  return out;
}

/// Levenberg-Marquardt as above, its Jacobian kept to itself.
template <class Real, LeastSquaresProblem<Real> Problem>
LeastSquaresOutcome levenberg_marquardt(const Problem& problem, DynamicVector<Real>& x,
                                        DynamicVector<Real>& r,
                                        const LeastSquaresOptions<Real>& options = {}) {
  DynamicMatrix<Real> jac;
  return levenberg_marquardt(problem, x, r, options, jac);
}

}  // namespace viscoroll::numerics
