// A semi-analytic Jacobian against central differences of its residual, for the line residuals'
// Jacobian tests (tests/line/line_jacobian.test.cpp, line_spectrum_jacobian.test.cpp).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

namespace viscoroll_test {

/// Largest relative column error of res.jacobian at x against central differences of res, and a
/// check that the Jacobian's residual is operator()'s bit for bit. h = 1e-5 (scaled by |x_j| > 1):
/// the central difference's truncation error, O(h^2), and its rounding error, O(eps/h), are both
/// below 1e-9 of a column (changing h tenfold either way moves the measured error by less than
/// 1e-9 in the one-term residual).
template <class Residual>
double worst_column_error(const Residual& res, const Eigen::VectorXd& x) {
  const int m = res.equations(), n = res.unknowns();
  Eigen::VectorXd r(m), rp(m), rm(m), r_op(m);
  Eigen::MatrixXd jac(m, n);
  REQUIRE(res.jacobian(x, r, jac));
  REQUIRE(res(x, r_op));
  CHECK((r - r_op).cwiseAbs().maxCoeff() == 0);  // the same residual, bit for bit
  double worst = 0;
  for (int j = 0; j < n; ++j) {
    const double h = 1e-5 * std::max(1.0, std::abs(x[j]));
    Eigen::VectorXd xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    REQUIRE(res(xp, rp));
    REQUIRE(res(xm, rm));
    const Eigen::VectorXd column = (rp - rm) / (2 * h);
    worst = std::max(worst, (jac.col(j) - column).norm() / column.norm());
  }
  return worst;
}

}  // namespace viscoroll_test
