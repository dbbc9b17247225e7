// LineSolution::along_roller (docs/rollers.md, "Outputs along the roller"): the load per unit
// length F0(y)/((1 + f) c) integrates to the load in every regime the line solver returns (static
// closed form, rolling, glassy closed form, elastic), and the BEM's rows agree with it within the
// line theory's error.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/line/line_solver.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_along_roller {

namespace {

// The paper's scene: f = 9, C2/C1 = (ln 20 - 1)/25, (1 + f) c P = 5/3 (a0 = 1, l0 = 5).
const double f = 9, c = 0.5 / (2 * std::acos(-1.0));
const double c2 = (std::log(20.0) - 1) / 25, load = 5.0 / (3 * (1 + f) * c);

/// The trapezoid rule over the stations with F0 = 0 at the ends -l, l.
double integral(const viscoroll::AlongRoller<double>& r) {
  double sum = 0, previous_y = r.y_minus, previous_f = 0;
  for (std::size_t k = 0; k < r.y.size(); ++k) {
    sum += (r.y[k] - previous_y) * (r.f0[k] + previous_f) / 2;
    previous_y = r.y[k];
    previous_f = r.f0[k];
  }
  return sum + (r.y_plus - previous_y) * previous_f / 2;
}

}  // namespace

TEST_CASE("line along the roller: the load per length integrates to the load, every regime",
          "[line]") {
  // F0 ~ l - |y| at the ends and smooth inside: the trapezoid rule on 129 stations is accurate to
  // O(h^2) = O((2/130)^2), measured up to 1.6e-4 relative; bound 1e-3.
  const viscoroll::LineSolverD sls(viscoroll::StandardLinearSolid<double>(1.0, 0.5, f, 1.0));
  const viscoroll::LineSolver elastic(viscoroll::Elastic<double>(1.0, 0.5));
  for (const double speed : {0.0, 1.0, 1e30}) {
    const auto s = sls.solve({.c1 = 1.0, .c2 = c2, .load = load, .speed = speed});
    REQUIRE(s.converged);
    const auto r = s.along_roller(129);
    INFO("speed " << speed << ": " << s.reason);
    CHECK(integral(r) == Approx(load).epsilon(1e-3));
    CHECK(r.y_plus == s.l());
    CHECK(r.f0_max_y == Approx(0).margin(s.l() / 64));
    CHECK(r.a[64] == Approx(s.a(0.0)).epsilon(1e-12));
    CHECK(r.p_max[64] == Approx(s.strip(0.0).peak().pressure).epsilon(1e-12));
  }
  const auto e = elastic.solve({.c1 = 1.0, .c2 = c2, .load = load, .speed = 1.0});
  REQUIRE(e.converged);
  CHECK(integral(e.along_roller(129)) == Approx(load).epsilon(1e-3));
}

TEST_CASE("line along the roller: the BEM's rows within the line theory's error", "[line]") {
  // V tau = a0: the line theory's a(0) is 2.6% from the BEM's (docs/validation.md); its load per
  // length at y = 0 is measured 0.93% from the BEM's row at N = 16.
  const viscoroll::StandardLinearSolid<double> rubber(1.0, 0.5, f, 1.0);
  const auto line =
      viscoroll::LineSolverD(rubber).solve({.c1 = 1.0, .c2 = c2, .load = load, .speed = 1.0});
  viscoroll::BemOptions options;
  options.grid = 16;
  const auto bem = viscoroll::BemSolverD(rubber, options)
                       .solve({.c1 = 1.0, .c2 = c2, .load = load, .speed = 1.0});
  REQUIRE(line.converged);
  REQUIRE(bem.converged);
  const auto l = line.along_roller(65), b = bem.along_roller();
  const std::size_t centre = (b.y.size() - 1) / 2;
  REQUIRE(b.y[centre] == 0.0);
  CHECK(l.f0[32] == Approx(b.f0[centre]).epsilon(0.02));
  CHECK(l.a[32] == Approx(b.a[centre]).epsilon(0.04));
  // l: measured 3.7% at N = 16, 2.1% at N = 32 (docs/validation.md).
  CHECK(l.y_plus == Approx(bem.l).epsilon(0.045));
}

}  // namespace test_line_along_roller
