// The paper's printed leading-edge condition (44) as a whole solver: its residual
// (PaperLineResidual, the opt-in line/paper_leading_edge.hpp) driven by the generic
// Levenberg-Marquardt iteration, from the (L6) solution. Where V tau is not small against a the
// two conditions agree within the line theory's own error O((a/l)^2) (docs/validation.md, "The
// paper's (44) against (L6)"); at V tau = 0.03 a0 (44) has no root near the physical solution
// (docs/theory.md section 4).
#include <catch2/catch.hpp>
#include <cmath>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/line/paper_leading_edge.hpp>
#include <viscoroll/numerics/levenberg_marquardt.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_paper_leading_edge_solve {

namespace {
using viscoroll::StandardLinearSolid;
using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1>;
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic>;

// The paper's residual as a numerics::LeastSquaresProblem: it has no analytic Jacobian (the
// iteration takes forward differences where jacobian() declines).
struct PaperProblem {
  const viscoroll::line::PaperLineResidual<double>& residual;
  int unknowns() const { return residual.unknowns(); }
  int equations() const { return residual.equations(); }
  bool operator()(const Vector& x, Vector& r) const { return residual(x, r); }
  bool jacobian(const Vector&, Vector&, Matrix&) const { return false; }
};

struct Compared {
  bool converged;
  double b0_l6, b0_paper, d_l6, d_paper, residual;
};

// The paper's 5:1 scene with a0 = 1, l0 = 5 (C1 a0^2 l0 / 3 = (1 + f) c P, c = 1/(4 pi)).
Compared compare(double vtau) {
  const viscoroll::LineSolver solver(StandardLinearSolid<double>(1.0, 0.5, 9.0, 1.0),
                                     viscoroll::LineOptions{.terms = 4});
  const viscoroll::LineScene<double> scene{
      .c1 = 1.0, .c2 = 0.0798291, .load = 2.0943951023931953, .speed = vtau};
  const auto l6 = solver.solve(scene);
  REQUIRE(l6.converged);
  const viscoroll::line::PaperLineResidual<double> paper(solver.residual(scene).problem(), 4);
  Vector x = paper.pack(l6.shape, l6.d), r(paper.equations());
  REQUIRE(paper(x, r));
  const auto out = viscoroll::numerics::levenberg_marquardt(
      PaperProblem{paper}, x, r,
      viscoroll::numerics::LeastSquaresOptions<double>{.analytic_jacobian = false});
  const auto shape = paper.shape(x);
  return {out.converged,          l6.b(0.0), shape.b(0.0), l6.d, paper.penetration(x),
          r.cwiseAbs().maxCoeff()};
}
}  // namespace

TEST_CASE("line: the paper's (44) solved agrees with (L6) within the line theory's error",
          "[line][paper]") {
  // (a/l)^2 = 1/25 at l/a = 5: the order of the line theory's error, which both conditions share.
  for (const double vtau : {1.0, 10.0}) {
    const Compared c = compare(vtau);
    INFO("V tau/a0 = " << vtau << ": b(0) " << c.b0_l6 << " vs " << c.b0_paper << ", d " << c.d_l6
                       << " vs " << c.d_paper);
    REQUIRE(c.converged);
    CHECK(std::abs(c.b0_paper - c.b0_l6) <= 0.04 * c.b0_l6);
    CHECK(std::abs(c.d_paper - c.d_l6) <= 0.04 * c.d_l6);
    // Two different conditions: not the same root.
    CHECK(std::abs(c.b0_paper - c.b0_l6) > 1e-6 * c.b0_l6);
  }
}

TEST_CASE("line: the paper's (44) has no root near the physical solution at V tau = 0.03 a0",
          "[line][paper]") {
  const Compared c = compare(0.03);
  INFO("residual " << c.residual);
  CHECK_FALSE(c.converged);
  CHECK(c.residual > 1e-3);
}

}  // namespace test_paper_leading_edge_solve
