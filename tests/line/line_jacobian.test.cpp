// Tests of LineResidual::jacobian (viscoroll/line/line_residual.hpp), the semi-analytic Jacobian
// of the line equations (docs/line-solver.md, "Jacobian"), against central differences of the
// residual itself, and of the line solver with it against the solver with forward differences.
//
// The paper's scene: StandardLinearSolid(mu_D = 1, nu = 0.5, f = 9, tau = 1), C1 = 1,
// C2/C1 = (ln 20 - 1)/25 and the load of a long-term static a0 = 1, l0 = 5 (as in
// line_solver.test.cpp). Measured values next to the tolerances: Release build, GCC 12, x86-64.
#include <Eigen/Dense>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/line/paper_leading_edge.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>

#include "support/jacobian_check.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_jacobian {

namespace {

using viscoroll::LineJacobian;
using viscoroll::LineOptions;
using viscoroll::LineSolverD;
using viscoroll::StandardLinearSolid;

const StandardLinearSolid<double> kRubber(1, 0.5, 9, 1);

viscoroll::LineScene<double> paper_scene(double vtau) {
  const double c1 = 1, ratio = (std::log(20.0) - 1) / 25;
  const double load = 5 * c1 / (3 * (1 + 9) * kRubber.instantaneous_compliance());
  return {c1, ratio * c1, load, vtau};
}

template <class Residual>
concept HasJacobian = requires(const Residual& res, Eigen::VectorXd& v, Eigen::MatrixXd& j) {
  res.jacobian(v, v, j);
};

/// Largest relative column error of J against central differences of the residual, at the
/// solver's last iterate (converged, except at V tau/a0 = 0.003, where the iteration stops at a
/// residual of 6e-5, docs/line-solver.md) moved by `offset` (x_k += offset sin(3k + 1)).
double worst_column_error(double vtau, int terms, double offset) {
  LineOptions options;
  options.terms = terms;
  const LineSolverD solver(kRubber, options);
  const auto scene = paper_scene(vtau);
  const auto sol = solver.solve(scene);
  const auto res = solver.residual(scene);
  Eigen::VectorXd x = res.pack(sol.shape, sol.d);
  for (int k = 0; k < x.size(); ++k) x[k] += offset * std::sin(3.0 * k + 1);
  return viscoroll_test::worst_column_error(res, x);
}

}  // namespace

TEST_CASE("line: the semi-analytic Jacobian against central differences of the residual",
          "[line][jacobian]") {
  // The Jacobian holds the quadrature nodes fixed in t = y/l, while the residual's panels follow
  // the leading edge x0 and the t-nodes of (L6) its scale x0/V; both integrate to rounding
  // (docs/theory.md section 7), and the kernels' slopes in x0 and l are analytic, so the difference
  // is the central difference's own error (O(h^2) = 1e-10 of a column where the residual is
  // smooth on the scale h). Measured: 1.1e-9 (V tau/a0 = 0.1), 1e-10 (1), 2e-10 (10), 1.5e-9
  // (1000) at the solution, N = 4, 1.2e-9 at N = 8, 2e-10 to 1e-9 with every coefficient moved by
  // 0.01; largest 9.5e-8 at 0.003, the central difference's own O(h^2) error there (with h = 1e-6
  // it falls to 1e-9). (Before the slopes were analytic: 7.4e-9 at a0, 3.3e-7 at 1000.)
  // Bound: 4e-7, four times the largest.
  const double bound = 4e-7;
  for (const double vtau : {0.003, 0.1, 1.0, 10.0, 1000.0}) {
    for (const double offset : {0.0, 0.01}) {
      INFO("V tau/a0 = " << vtau << ", offset " << offset);
      const double worst = worst_column_error(vtau, 4, offset);
      CAPTURE(worst);
      CHECK(worst <= bound);
    }
  }
  INFO("N = 8, V tau = a0");
  CHECK(worst_column_error(1.0, 8, 0.0) <= bound);
}

TEST_CASE("line: the solver reaches the same root with either Jacobian", "[line][jacobian]") {
  // Both iterations end at a residual of ~1e-15 of the same square system. The scaled Jacobian's
  // smallest singular value at these N is ~1e-2-1e-3 (docs/theory.md section 5), so the two
  // roots may differ by ~1e3 residuals: 1e-12. Bound 1e-10 relative; measured <= 7e-14 (the
  // iteration counts are the same, or differ by one).
  for (const double vtau : {0.1, 1.0, 10.0}) {
    for (const int terms : {4, 6}) {
      LineOptions analytic, difference;
      analytic.terms = difference.terms = terms;
      difference.jacobian = LineJacobian::difference;
      const auto a = LineSolverD(kRubber, analytic).solve(paper_scene(vtau));
      const auto b = LineSolverD(kRubber, difference).solve(paper_scene(vtau));
      INFO("V tau/a0 = " << vtau << ", N = " << terms << ": " << a.reason << " / " << b.reason);
      REQUIRE(a.converged);
      REQUIRE(b.converged);
      const double tol = 1e-10;
      CHECK(std::abs(a.a(0) / b.a(0) - 1) <= tol);
      CHECK(std::abs(a.b(0) / b.b(0) - 1) <= tol);
      CHECK(std::abs(a.l() / b.l() - 1) <= tol);
      CHECK(std::abs(a.d / b.d - 1) <= tol);
      CHECK(std::abs(a.chi / b.chi - 1) <= tol);
    }
  }
}

TEST_CASE("line: the paper's (44) closes the same equations with another leading-edge row",
          "[line][jacobian]") {
  // PaperLineResidual (paper_leading_edge.hpp) differs from the (L6) residual only in the
  // leading-edge rows, and has no Jacobian. At the (L6) root, V tau = a0, N = 4: (34) (row i
  // minus V/a0 times row m + i) and the load agree to rounding, and the (44) rows are the
  // distance to the (44) root in b/a0, which docs/validation.md measures as 0.5% of
  // b(0) = 0.306 a0 (1.5e-3; the rows at all points lie between 1e-4 and 1e-1).
  using Paper = viscoroll::line::PaperLineResidual<double>;
  static_assert(
      HasJacobian<viscoroll::line::LineResidual<double, viscoroll::GaussLegendre<double, 12>>>);
  static_assert(!HasJacobian<Paper>);
  LineOptions options;
  options.terms = 4;
  const LineSolverD solver(kRubber, options);
  const auto scene = paper_scene(1.0);
  const auto sol = solver.solve(scene);
  REQUIRE(sol.converged);
  const auto res = solver.residual(scene);
  const Paper paper(res.problem(), options.terms);
  const Eigen::VectorXd x = res.pack(sol.shape, sol.d);
  Eigen::VectorXd r6(res.equations()), r44(paper.equations());
  REQUIRE(res(x, r6));
  REQUIRE(paper(x, r44));
  const int m = res.points();
  const double v = res.problem().vtau / res.problem().a_ref;
  CHECK(r44[2 * m] == r6[2 * m]);
  for (int i = 0; i < m; ++i) {
    INFO("point " << i << ": (44) row " << r44[m + i] << ", (L6) row " << r6[m + i]);
    CHECK(std::abs((r44[i] - v * r44[m + i]) - (r6[i] - v * r6[m + i])) <= 1e-14);
    CHECK(std::abs(r6[m + i]) <= 1e-12);
    CHECK(std::abs(r44[m + i]) >= 1e-4);
    CHECK(std::abs(r44[m + i]) <= 1e-1);
  }
}

}  // namespace test_line_jacobian
