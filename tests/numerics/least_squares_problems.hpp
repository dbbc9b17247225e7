// Least-squares problems with known answers for the tests of the minimisers
// (numerics/levenberg_marquardt.hpp, numerics/least_squares_minimum.hpp), models of
// numerics::LeastSquaresProblem over double:
// - Rosenbrock's function as residuals, r = (10 (x2 - x1^2), 1 - x1): the root (1, 1);
// - Freudenstein and Roth's (Moré, Garbow & Hillstrom 1981, problem 2), whose local minimum with
//   r != 0 is at a singular J, in closed form below;
// - r = 1/x - 2 on the domain x > 0: the root 1/2.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <initializer_list>
#include <viscoroll/numerics/least_squares_problem.hpp>

namespace viscoroll::testing {

using LsqVector = numerics::DynamicVector<double>;
using LsqMatrix = numerics::DynamicMatrix<double>;

/// The point of these coordinates.
inline LsqVector point(std::initializer_list<double> coordinates) {
  LsqVector x(int(coordinates.size()));
  int j = 0;
  for (double c : coordinates) x[j++] = c;
  return x;
}

/// x and r as a minimiser left them, with r the problem's residual at x.
template <class Problem>
void require_residual_at(const Problem& problem, const LsqVector& x, const LsqVector& r) {
  LsqVector r_here;
  REQUIRE(problem(x, r_here));
  REQUIRE(r_here == r);
}

/// r = (10 (x2 - x1^2), 1 - x1); with_jacobian = false: jacobian() declines (returns false).
struct Rosenbrock {
  bool with_jacobian = true;
  int unknowns() const { return 2; }
  int equations() const { return 2; }
  bool operator()(const LsqVector& x, LsqVector& r) const {
    r.resize(2);
    r << 10 * (x[1] - x[0] * x[0]), 1 - x[0];
    return true;
  }
  bool jacobian(const LsqVector& x, LsqVector& r, LsqMatrix& jac) const {
    if (!with_jacobian) return false;
    jac.resize(2, 2);
    jac << -20 * x[0], 10, -1, 0;
    return (*this)(x, r);
  }
};

/// r1 = -13 + x1 + ((5 - x2) x2 - 2) x2, r2 = -29 + x1 + ((x2 + 1) x2 - 14) x2. With r1 = x1 + p,
/// r2 = x1 + q: phi = |r|^2 / 2 is least over x1 at x1 = -(p + q)/2, where phi = (p - q)^2 / 4 =
/// c^2, c = (q - p)/2 = x2^3 - 2 x2^2 - 6 x2 - 8. c' = 3 x2^2 - 4 x2 - 6 = 0 at
/// x2 = (2 - sqrt 22)/3, a local minimum of c^2 with c != 0 (c = (x2 - 4)(x2^2 + 2 x2 + 2) has
/// the one real zero 4, the root (5, 4)); there p' = q', so J = [1 p'; 1 q'] is singular and only
/// S = r1 grad^2 r1 + r2 grad^2 r2 gives phi its curvature in x2.
struct FreudensteinRoth {
  int unknowns() const { return 2; }
  int equations() const { return 2; }
  bool operator()(const LsqVector& x, LsqVector& r) const {
    r.resize(2);
    r << -13 + x[0] + ((5 - x[1]) * x[1] - 2) * x[1], -29 + x[0] + ((x[1] + 1) * x[1] - 14) * x[1];
    return true;
  }
  bool jacobian(const LsqVector& x, LsqVector& r, LsqMatrix& jac) const {
    jac.resize(2, 2);
    jac << 1, (10 - 3 * x[1]) * x[1] - 2, 1, (3 * x[1] + 2) * x[1] - 14;
    return (*this)(x, r);
  }
  /// The local minimum with r != 0 (above).
  static LsqVector minimum() {
    const double y = (2 - std::sqrt(22.0)) / 3;
    LsqVector x(2);
    x << (8 - 3 * y) * y + 21, y;  // -(p + q)/2 = -3 y^2 + 8 y + 21
    return x;
  }
  /// phi = |r|^2 / 2 there: c^2.
  static double minimum_phi() {
    const double y = minimum()[1], c = ((y - 2) * y - 6) * y - 8;
    return c * c;
  }
  /// The Hessian of phi there: J^T J + S, S = diag(0, r1 p'' + r2 q''), r1 = -r2 = -c.
  static LsqMatrix minimum_hessian() {
    const double y = minimum()[1], c = ((y - 2) * y - 6) * y - 8;
    const double dp = (10 - 3 * y) * y - 2, dq = (3 * y + 2) * y - 14;
    LsqMatrix h(2, 2);
    h << 2, dp + dq, dp + dq, dp * dp + dq * dq - c * (10 - 6 * y) + c * (6 * y + 2);
    return h;
  }
};

/// r = 1/x - 2, defined for x > 0 only (false elsewhere, counted in `outside`): the root 1/2,
/// J = -1/x^2.
struct Reciprocal {
  mutable int outside = 0;
  int unknowns() const { return 1; }
  int equations() const { return 1; }
  bool operator()(const LsqVector& x, LsqVector& r) const {
    if (!(x[0] > 0)) {
      ++outside;
      return false;
    }
    r.resize(1);
    r[0] = 1 / x[0] - 2;
    return true;
  }
  bool jacobian(const LsqVector& x, LsqVector& r, LsqMatrix& jac) const {
    if (!(*this)(x, r)) return false;
    jac.resize(1, 1);
    jac(0, 0) = -1 / (x[0] * x[0]);
    return true;
  }
};

}  // namespace viscoroll::testing
