// chi's integrals on the graded panels of rolling_friction (docs/line-solver.md, "Rolling
// friction"): to rounding on a 6-point rule where the solver's integrals are exact
// (quadrature_tolerance 0, the 12-point rule takes over), on the solver's own rule with a
// tolerance; against tanh-sinh quadrature in long double of the same solution's strips.
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/line/line_solver.hpp>

#include "support/paper_scene.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_chi_rule {

namespace {

using SixPointSolver = viscoroll::FastLineSolverD;  // 6-point Gauss-Legendre panels

// chi = C1 int V n dy / int F0 dy over [0, l] (Eq. 54 in the form (P7)), the strips of `sol`
// in double, the Bessel ratios and the integrals in long double (tanh-sinh: exact to long
// double's rounding for the square-root end, far below double's).
long double reference_chi(const SixPointSolver::Solution& sol) {
  using boost::math::cyl_bessel_i;
  const auto vn = [&](long double y) -> long double {
    const auto s = sol.functions(double(y));
    if (!(s.a > 0)) return 0;
    const long double alpha = viscoroll::plane::strip_alpha<long double>(s.a, sol.vtau, sol.f);
    const long double i0 = cyl_bessel_i(0, alpha);
    return sol.c1 / 4.0L *
           viscoroll::plane::strip_first_moment<long double>(s.a, s.b, s.g, sol.vtau, sol.f,
                                                             cyl_bessel_i(1, alpha) / i0,
                                                             cyl_bessel_i(2, alpha) / i0);
  };
  const auto f0 = [&](long double y) -> long double { return sol.functions(double(y)).f0; };
  boost::math::quadrature::tanh_sinh<long double> rule;  // integrate() is not const in Boost 1.74
  const long double l = sol.l();
  return sol.c1 * rule.integrate(vn, 0.0L, l) / rule.integrate(f0, 0.0L, l);
}

}  // namespace

TEST_CASE("line: chi to rounding on a 6-point rule", "[line]") {
  // 32 eps: the Bessel interpolants within 2.5 eps, the strip moment's few operations and the
  // sums of ~600 positive terms (measured 1.5e-15 = 7 eps on the 12-point rule).
  const double eps = std::numeric_limits<double>::epsilon();
  const viscoroll::testing::PaperScene paper;
  viscoroll::LineOptions exact;
  exact.terms = 6;  // quadrature_tolerance 0: every integral exact to rounding
  const SixPointSolver six(paper.material, exact);
  const SixPointSolver fast(paper.material, viscoroll::LineOptions::fast());
  for (const double v : {0.3, 2.15}) {
    INFO("V tau/a0 = " << v);
    const auto sol = six.solve(paper.scene(v));
    REQUIRE(sol.converged);
    const long double ref = reference_chi(sol);
    CHECK(std::abs((sol.chi - ref) / ref) <= 32 * eps);
    // With a tolerance the solver's own rule serves: 6-point panels err by ~(3 + sqrt 8)^-12
    // = 6.7e-10 at the end, far below the fast setting's 1e-4, and above rounding.
    const auto coarse = fast.solve(paper.scene(v));
    REQUIRE(coarse.converged);
    const long double coarse_ref = reference_chi(coarse);
    const double err = std::abs(double((coarse.chi - coarse_ref) / coarse_ref));
    CHECK(err > 32 * eps);
    CHECK(err < 1e-8);
  }
}

}  // namespace test_line_chi_rule
