// viscoroll: the steps of the line solver's iteration (line_solver.hpp) shared by a material of
// one relaxation time and one with a spectrum: the continuation stages in N, the certified
// least-squares minimum where the last stage stops short of a root, and the error estimate of a
// root (docs/line-solver.md, "Continuation in N", "Least-squares minima", "Stops short of a root").
#pragma once

#include <Eigen/Core>
#include <Eigen/QR>
#include <limits>
#include <string>
#include <vector>
#include <viscoroll/numerics/least_squares_minimum.hpp>
#include <viscoroll/numerics/least_squares_problem.hpp>
#include <viscoroll/numerics/levenberg_marquardt.hpp>

namespace viscoroll::detail {

/// Terms of the continuation stages that lead to `terms`: 2, 4, 8, 16, 32 below it, then `terms`
/// itself (docs/line-solver.md, "Continuation in N").
inline std::vector<int> continuation_stages(int terms) {
  std::vector<int> stages;
  for (int n : {2, 4, 8, 16, 32})
    if (n < terms) stages.push_back(n);
  stages.push_back(terms);
  return stages;
}

/// max |r| of the scaled line equations below which the iterate is a root (LineSolution::root):
/// 64 sqrt(eps), the minimisers' stop at a root and the solution's flag.
template <class Real>
Real line_root_tolerance() {
  return numerics::default_root_tolerance<Real>();
}

/// Where Levenberg-Marquardt stopped short of a root (at a minimum with no root near, without a
/// descent step or at the iteration limit): the paper's least-squares solution (Section 7), the
/// certified minimum of |r|^2 (numerics::least_squares_minimum), whose Newton iteration converges
/// linearly where the minimum is flat (10 times the iterations). Needs the residual's
/// semi-analytic Jacobian. Adds the iterations taken to `iterations`.
template <class Real, class Residual>
numerics::LeastSquaresOutcome least_squares_solution(
    const Residual& res, numerics::DynamicVector<Real>& x, numerics::DynamicVector<Real>& r,
    const numerics::LeastSquaresOptions<Real>& settings, int& iterations) {
  numerics::LeastSquaresOptions<Real> minimisation = settings;
  minimisation.max_iterations = 10 * settings.max_iterations;
  numerics::LeastSquaresOutcome out = numerics::least_squares_minimum(res, x, r, minimisation);
  iterations += out.iterations;
  // A residual below the root tolerance on the way: Levenberg-Marquardt certifies the root, or
  // stops at a minimum again, which the minimisation then certifies (at most 4 turns).
  for (int turn = 0; turn < 4 && out.root_near; ++turn) {
    out = numerics::levenberg_marquardt(res, x, r, settings);
    iterations += out.iterations;
    if (out.converged || out.undefined || !out.minimum) break;
    out = numerics::least_squares_minimum(res, x, r, minimisation);
    iterations += out.iterations;
  }
  const Real tolerance = line_root_tolerance<Real>();
  if (out.converged && !out.root_near && r.cwiseAbs().maxCoeff() > tolerance)
    out.reason = "least-squares minimum (no root of the line equations here)";
  // Below the root tolerance with no step that lowers |r| (the residual's rounding floor): a root
  // to the accuracy with which the equations are evaluated.
  if (!out.converged && !out.undefined && r.cwiseAbs().maxCoeff() <= tolerance) {
    out.converged = true;
    out.reason = "converged (max |r| below the root tolerance, no step lowers it)";
    out.code = StopCode::converged;
  }
  return out;
}

/// max |J^+ r| from a given Jacobian, J^+ r by the complete orthogonal decomposition (the
/// minimum-norm least-squares solution, as the singular value decomposition gives it, at a
/// fraction of its cost): the error estimate of a root.
template <class Real>
Real newton_correction(const numerics::DynamicMatrix<Real>& jac,
                       const numerics::DynamicVector<Real>& r) {
  const Eigen::CompleteOrthogonalDecomposition<numerics::DynamicMatrix<Real>> cod(jac);
  return cod.solve(r).cwiseAbs().maxCoeff();
}

/// max |J^+ r| at x, with the residual's semi-analytic Jacobian there. Infinite where the
/// Jacobian is undefined.
template <class Real, class Residual>
Real newton_correction(const Residual& res, const numerics::DynamicVector<Real>& x) {
  numerics::DynamicVector<Real> r;
  numerics::DynamicMatrix<Real> jac;
  if (!res.jacobian(x, r, jac)) return std::numeric_limits<Real>::infinity();
  return newton_correction<Real>(jac, r);
}

/// The warning of a certified least-squares minimum (a converged solution that is not a root).
template <class Real>
std::string minimum_warning(Real rmax) {
  return "the line equations have no root here: a least-squares minimum with max |r| = " +
         std::to_string(double(rmax)) +
         " (the line theory does not close at this speed and discretisation; "
         "docs/line-solver.md, \"Least-squares minima\")";
}

}  // namespace viscoroll::detail
