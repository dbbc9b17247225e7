// LineOptions::fast() (5 terms, integrals to 1e-4), on the default 12-point and on 6-point panels
// (FastLineSolverD): within 1% of the converged least-squares
// solution (basis s, oversampling 2, 24 terms, 1000 iterations; docs/performance.md, "The fast
// setting") in a(0), b(0) (relative to a(0)), l, d and chi at six speeds of the paper's scene,
// among them V tau/a0 = 0.231, where the fast setting's l is 0.86% off (the largest of its errors
// over the 100 speeds). And quadrature_tolerance: 1e-4 moves the solution at N = 5 by far less than
// the discretisation's 1% (measured at most 6e-8: the panels' error bound is pessimistic), and a
// tolerance outside [0, 1e-4] is an error naming it.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <viscoroll/line/line_solver.hpp>

#include "support/paper_scene.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_fast_setting {

TEST_CASE("line fast setting: within 1% of the converged solution", "[line]") {
  const viscoroll::testing::PaperScene paper;
  const viscoroll::LineSolverD solver(paper.material, viscoroll::LineOptions::fast());
  struct Reference {
    double vtau, a0, b0, l, d, chi;
  };
  // Basis s, oversampling 2, 24 terms, max_iterations 1000 (each a least-squares minimum but the
  // last, a root); V tau/a0 = 10^(-3 + 6 i/99) for i = 0, 25, 39, 50, 66, 99.
  const Reference references[] = {
      {1e-3, 0.9993422081, 0.0002496565288, 5.000430118, 1.497866055, 0.0008989871066},
      {0.03274549162877728, 0.9845965727, 0.01404011266, 5.00202035, 1.497628541, 0.02879410368},
      {0.2310129700083161, 0.8953833654, 0.09501898554, 5.002585606, 1.486661107, 0.1761658108},
      {1.072267222010323, 0.5868882417, 0.3197238066, 4.547682355, 1.343967394, 0.416032717},
      {10, 0.4082207627, 0.1714820926, 2.93431353, 0.699261847, 0.1634009199},
      {1000, 0.4631857065, 0.002404459472, 2.328111543, 0.3333094871, 0.002308178531},
  };
  // The same setting on 6-point panels (FastLineSolverD): its own errors over the 100 speeds are
  // those of the 12-point rule to the digits of docs/performance.md (l 8.63e-3 at most).
  const viscoroll::FastLineSolverD six(paper.material, viscoroll::LineOptions::fast());
  for (const auto& ref : references) {
    INFO("V tau/a0 = " << ref.vtau);
    const auto check = [&ref](const auto& s, int points) {
      INFO(points << "-point panels");
      REQUIRE(s.converged);
      CHECK(std::abs(s.a(0) / ref.a0 - 1) < 0.01);
      CHECK(std::abs(s.b(0) - ref.b0) / ref.a0 < 0.01);
      CHECK(std::abs(s.l() / ref.l - 1) < 0.01);
      CHECK(std::abs(s.d / ref.d - 1) < 0.01);
      CHECK(std::abs(s.chi / ref.chi - 1) < 0.01);
    };
    check(solver.solve(paper.scene(ref.vtau)), 12);
    check(six.solve(paper.scene(ref.vtau)), 6);
  }
}

TEST_CASE("line fast setting: the quadrature tolerance and its range", "[line]") {
  const viscoroll::testing::PaperScene paper;
  viscoroll::LineOptions exact;
  exact.terms = 5;
  viscoroll::LineOptions loose = exact;
  loose.quadrature_tolerance = 1e-4;
  for (const double vtau : {0.01, 1.0, 100.0}) {
    const auto a = viscoroll::LineSolverD(paper.material, exact).solve(paper.scene(vtau));
    const auto b = viscoroll::LineSolverD(paper.material, loose).solve(paper.scene(vtau));
    INFO("V tau/a0 = " << vtau);
    REQUIRE(a.converged);
    REQUIRE(b.converged);
    // Bound: the tolerance itself (the Jacobian's condition times the integrals' actual error,
    // measured 1e-7 at most); the discretisation's error is 1e-2.
    CHECK(std::abs(b.a(0) / a.a(0) - 1) < 1e-4);
    CHECK(std::abs(b.l() / a.l() - 1) < 1e-4);
    CHECK(std::abs(b.d / a.d - 1) < 1e-4);
    CHECK(std::abs(b.chi / a.chi - 1) < 1e-4);
  }
  viscoroll::LineOptions bad;
  bad.quadrature_tolerance = 1e-3;  // beyond the panels' analysis (docs/theory.md section 7)
  CHECK_THROWS_AS(viscoroll::LineSolverD(paper.material, bad), std::invalid_argument);
  bad.quadrature_tolerance = -1;
  CHECK_THROWS_AS(viscoroll::LineSolverD(paper.material, bad), std::invalid_argument);
}

}  // namespace test_line_fast_setting
