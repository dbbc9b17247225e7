// viscoroll: the residual concept of the least-squares minimisers (levenberg_marquardt.hpp,
// least_squares_minimum.hpp), their outcome and the forward-difference Jacobian.
//
// A problem is a residual r: R^n -> R^m (m >= n) in the shape of Eigen's LevenbergMarquardt
// functor (unsupported/Eigen/NonLinearOptimization: inputs(), values(), operator(), df()), with a
// domain: outside it the residual is undefined and the minimisers step back. The tolerances of the
// minimisers assume scaled equations, each r_i a sum of terms of order one.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <concepts>
#include <limits>
#include <string>
#include <utility>
#include <viscoroll/core/outcome.hpp>

namespace viscoroll::numerics {

template <class Real>
using DynamicVector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
template <class Real>
using DynamicMatrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

/// A least-squares problem over the scalar Real: a model `P` has the members
///
///   int unknowns() const;                               // n, the length of x
///   int equations() const;                              // m >= n, the length of r
///   bool operator()(const Vector& x, Vector& r) const;  // r = r(x); false: x outside the domain
///                                                       // (r then unspecified)
///   bool jacobian(const Vector& x, Vector& r, Matrix& J) const;
///       // r = r(x) and J = dr/dx (m x n); false: x outside the domain, or no Jacobian for this
///       // problem (the Levenberg-Marquardt iteration then takes forward differences)
///
/// with Vector = DynamicVector<Real>, Matrix = DynamicMatrix<Real>; both resize r and J.
/// LineResidual (line/line_residual.hpp) is one.
template <class P, class Real>
concept LeastSquaresProblem = requires(const P& p, const DynamicVector<Real>& x,
                                       DynamicVector<Real>& r, DynamicMatrix<Real>& jac) {
  { p.unknowns() } -> std::convertible_to<int>;
  { p.equations() } -> std::convertible_to<int>;
  { p(x, r) } -> std::convertible_to<bool>;
  { p.jacobian(x, r, jac) } -> std::convertible_to<bool>;
};

/// max |r| below which an iterate of scaled equations (terms of order one) counts as a root:
/// 64 sqrt(eps), from where a Newton step, which about squares the residual, ends at rounding
/// level.
template <class Real>
Real default_root_tolerance() {
  using std::sqrt;
  return 64 * sqrt(std::numeric_limits<Real>::epsilon());
}

/// Settings of levenberg_marquardt() and least_squares_minimum().
template <class Real>
struct LeastSquaresOptions {
  /// Iterations allowed: Levenberg-Marquardt steps (each one residual per damping try, plus one
  /// Jacobian when it is refreshed), or Newton steps of the minimum (each one Jacobian, plus 2k
  /// where the second-order term is taken afresh along k directions).
  int max_iterations = 100;
  /// max |r| below which the iterate is a root: Levenberg-Marquardt's convergence test, and the
  /// minimum's hand-back (`root_near`).
  Real root_tolerance = default_root_tolerance<Real>();
  /// Levenberg-Marquardt's Jacobian: true, the problem's jacobian() (forward differences where it
  /// returns false); false, forward differences always (difference_jacobian). The minimum always
  /// takes the problem's.
  bool analytic_jacobian = true;
  /// Levenberg-Marquardt's damping mu at the first step (Marquardt's scaling, below).
  Real initial_damping = Real(1e-3);
  /// Levenberg-Marquardt returns as soon as max |r| falls to this level (0: never), with
  /// `converged` false and the reason "stage tolerance": the stop of a continuation stage whose
  /// iterate only seeds the next one (LineOptions::stage_tolerance).
  Real stop_tolerance = Real(0);
};

/// How a least-squares minimiser stopped; x and r hold its last accepted iterate.
struct LeastSquaresOutcome {
  bool converged = false;  ///< met its stopping test (a root, or a certified minimum)
  bool undefined = false;  ///< the Jacobian could not be evaluated (x left the domain)
  bool minimum = false;    ///< Levenberg-Marquardt stopped at a least-squares minimum with no
                           ///< root near (or found no descent step): least_squares_minimum's cue
  bool root_near = false;  ///< least_squares_minimum met a residual below the root tolerance:
                           ///< Levenberg-Marquardt's cue
  std::string reason;      ///< why it stopped, in words
  StopCode code = StopCode::iteration_limit;  ///< why it stopped, as a code (core/outcome.hpp)
  int iterations = 0;                         ///< iterations taken

  /// This outcome, stopped where the Jacobian could not be evaluated.
  LeastSquaresOutcome jacobian_undefined() const {
    LeastSquaresOutcome stop = *this;
    stop.undefined = true;
    stop.reason = "Jacobian undefined";
    stop.code = StopCode::outside_domain;
    return stop;
  }
  /// This outcome, stopped one iteration on at a least-squares minimum with no root near, for
  /// the reason `why`.
  LeastSquaresOutcome stalled(std::string why) const {
    LeastSquaresOutcome stop = *this;
    stop.minimum = true;
    stop.reason = std::move(why);
    stop.code = StopCode::no_descent;
    ++stop.iterations;
    return stop;
  }
};

/// J = dr/dx (jac, m x n) by forward differences at x, where r = r(x): column j from x + h e_j,
/// h = sqrt(eps) max(1, |x_j|), or backward from x - h e_j where x + h e_j is outside the domain.
/// `trial` and `rt` are workspace. False when both sides of some x_j are outside.
template <class Real, LeastSquaresProblem<Real> Problem>
bool difference_jacobian(const Problem& problem, const DynamicVector<Real>& x,
                         const DynamicVector<Real>& r, DynamicMatrix<Real>& jac,
                         DynamicVector<Real>& trial, DynamicVector<Real>& rt) {
  using std::abs;
  using std::sqrt;
  const Real eps = std::numeric_limits<Real>::epsilon();
  for (int j = 0; j < problem.unknowns(); ++j) {
    const Real h = sqrt(eps) * std::max(Real(1), Real(abs(x[j])));
    trial = x;
    trial[j] += h;
    if (!problem(trial, rt)) {
      trial[j] = x[j] - h;
      if (!problem(trial, rt)) return false;
      jac.col(j) = (r - rt) / h;
    } else {
      jac.col(j) = (rt - r) / h;
    }
  }
  return true;
}

}  // namespace viscoroll::numerics
