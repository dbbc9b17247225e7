// viscoroll: the static (elastic, V tau = 0) line contact of a roller of any profile.
//
// Panek & Kalker (1980), Eqs. (33), (34), (47) at V tau = 0 for a drop h(y) in place of
// C2 y^2/2 and a contact [y_-, y_+] that need not be symmetric (docs/theory.md, "Line contact for
// any roller profile (static)"): with b = 0, G = 0 and F0 = C1 a^2/4,
//   (G1)  FP[F0](y) + F0(y) ln[16 (y_+ - y)(y - y_-)/a^2] + C1 a^2/4 + h(y) - d = 0,
//   (G2)  int_{y_-}^{y_+} F0 dy = compliance * load,
// the log term being (34)'s 16 (l^2 - y^2) = 16 (l - y)(l + y) with the distances to the ends.
// The half width is
//   (G3)  a(y) = a_ref sqrt(omega(t)) exp(g(t)),  g = sum_{k<N} alpha_k T_k(t),
//         t = (2y - y_+ - y_-)/(y_+ - y_-),  omega = (1 + e^2)(1 - t^2)/(1 - t^2 + e^2),
// a square root at both ends as in (48), no parity, and an end layer e (omega = 1 - t^2 for
// e = +inf, which makes alpha = 0 Kalker's ellipse; a small e is a flat contact with short ends),
// chosen once from the sliced starting guess. The unknowns alpha_k, ln l (l the half length), the
// centre c = (y_+ + y_-)/2 and d meet (G1) at the N + 2 roots of T_{N+2}(t) and (G2): a square
// system, solved by Newton's method with an analytic Jacobian and backtracking.
//
// In t, F0 = (C1 a_ref^2/4) omega(t) exp(2 g(t)) is analytic on [-1, 1], and the finite part is
// scale free, FP[F0](y) = int_{-1}^{1} (F(t') - F(t))/|t' - t| dt'
// (dy' = l dt', |y' - y| = l|t' - t|): F is interpolated at M + 1 Chebyshev-Lobatto points, and
// FP of each T_n is a polynomial in closed form (G4), so that FP at the collocation points and the
// load are fixed matrices applied to the values of F; M doubles until F's Chebyshev tail is below
// eps^(2/3).
//
// The result is StaticProfileContact (static_profile_solution.hpp); the discretisation's matrices
// and the solver's steps are in line/detail/ (static_profile_matrices.hpp,
// static_profile_solver.hpp).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/detail/static_profile_solver.hpp>
#include <viscoroll/line/static_profile_solution.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>
#include <viscoroll/roller/profile.hpp>

namespace viscoroll {

/// The static line contact of `profile` under compliance_load = (1 - nu)/(2 pi mu) * P > 0 (Eq.
/// (47)), with N = terms coefficients in (G3) (1 <= terms <= 64; the default 12 keeps the points
/// more than a half width apart for contacts 15 or more half widths long, docs/theory.md (G5)).
/// Throws std::invalid_argument naming the parameter; a Newton iteration that does not converge, or
/// a contact that reaches the roller's body end, is returned with converged == false, the reason
/// and (for the end) a warning.
template <RollerProfile P>
StaticProfileContact<typename P::real_type> static_profile_contact(
    const P& profile, typename P::real_type compliance_load, int terms = 12) {
  using Real = typename P::real_type;
  detail::require_positive("compliance * load", compliance_load);
  detail::require(terms >= 1 && terms <= 64, "terms", terms, "1 <= terms <= 64");
  const Real c1 = profile.c1();
  detail::require_positive("c1", c1);
  const Real ymin = profile.y_min(), ymax = profile.y_max();
  detail::require(ymin < ymax, "y_min", ymin, "y_min < y_max");
  // The starting guess by slicing, Newton's method on (G1), (G2), the result and its verdicts.
  detail::StaticProfileSolver<P> solver(profile, compliance_load, terms);
  if (!solver.lowest_point()) return std::move(solver.out);
  solver.slice();
  typename detail::StaticProfileSolver<P>::Vector x = solver.start();
  if (solver.newton(x)) solver.finish(x);
  return std::move(solver.out);
}

}  // namespace viscoroll
