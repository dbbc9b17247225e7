// "Only what a scene needs": an elastic material, V tau = 0 (or below eps a0) and the
// glassy limit (V tau beyond ~a0/eps, or +inf) are answered by the closed forms, not by the
// rolling solvers. The closed forms are checked against independent truth: Hertz's strip (the
// plane, docs/theory.md (P6)) and Kalker's static line contact (docs/paper.md, "Checked by
// derivation": a = a0 sqrt(1 - y^2/l^2), C2/C1 = (a0/l)^2 (ln(4 l/a0) - 1),
// d = (1/2) C1 a0^2 ln(4 l/a0), C1 a0^2 l / 3 = compliance load). That the rolling path was not
// taken shows in what only the closed form returns exactly: b = G = chi = 0 (the rolling
// solutions have b, chi > 0 and, glassy, G -> f a^2/2), no iterations, the closed form's reason.
// The run time of either path is in bench_needs (docs/performance.md).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <viscoroll/viscoroll.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_closed_forms {

namespace {

template <class Real>
Real eps() {
  return std::numeric_limits<Real>::epsilon();
}

template <class Real>
Real pi() {
  return boost::math::constants::pi<Real>();
}

/// Checks a plane solution against Hertz's strip of half width a_H = sqrt(4 c_eff W / C1) under
/// the compliance c_eff: p = (C1 / (2 pi c_eff)) sqrt(a_H^2 - x^2) (Eq. 7 at V tau = 0 with (32),
/// G = b = 0).
template <class Real, class Solution>
void check_hertz_strip(const Solution& s, Real c1, Real load, Real c_eff, Real a_long_term) {
  using std::abs;
  using std::sqrt;
  const Real a_hertz = sqrt(4 * c_eff * load / c1);
  INFO("a = " << s.a << ", Hertz " << a_hertz);
  // sqrt of a product of four factors: a few roundings.
  CHECK(abs(s.a - a_hertz) <= 4 * eps<Real>() * a_hertz);
  CHECK(abs(s.a_long_term - a_long_term) <= 4 * eps<Real>() * a_long_term);
  CHECK(s.b == 0);
  CHECK(s.g == 0);
  CHECK(s.q == 0);
  CHECK(s.chi == 0);
  CHECK(s.iterations == 0);
  CHECK(s.converged);
  CHECK(s.residual == 0);
  for (const Real xi : {Real(-0.75), Real(0), Real(0.5)}) {
    const Real x = xi * a_hertz;
    const Real hertz = c1 / (2 * pi<Real>() * c_eff) * sqrt((a_hertz - x) * (a_hertz + x));
    INFO("x / a = " << xi);
    // p* has the form sqrt(a^2 - x^2) + 0 / sqrt(...): a few roundings, times sqrt's 1/2 of the
    // relative error of a in the edge distance a - |x| >= a / 4.
    CHECK(abs(s.pressure(x) - hertz) <= 16 * eps<Real>() * hertz);
  }
  CHECK(s.pressure(a_hertz * (1 + 4 * eps<Real>())) == 0);
}

}  // namespace

TEMPLATE_TEST_CASE("needs: elastic, static and glassy plane scenes are Hertz's strip", "[needs]",
                   float, double, long double) {
  using Real = TestType;
  using viscoroll::PlaneSolver;
  using viscoroll::StandardLinearSolid;
  const Real f = 9, mu_d = 1, nu = Real(0.3), c1 = 2, load = Real(0.7);
  const StandardLinearSolid<Real> probe(mu_d, nu, f, Real(1));
  const Real c = probe.instantaneous_compliance();
  const Real a0 = std::sqrt(4 * (1 + f) * c * load / c1);

  SECTION("elastic material (the long-term modulus)") {
    const viscoroll::Elastic<Real> elastic(mu_d / (1 + f), nu);
    const auto s = PlaneSolver<Real, viscoroll::Elastic<Real>>(elastic).solve(
        {.c1 = c1, .load = load, .speed = Real(3)});
    check_hertz_strip(s, c1, load, elastic.instantaneous_compliance(), a0);
  }
  SECTION("V tau = 0 and V tau <= eps a0: the long-term compliance") {
    for (const Real speed : {Real(0), eps<Real>() * a0 / 2}) {
      INFO("speed = " << speed);
      const auto s = PlaneSolver<Real, StandardLinearSolid<Real>>(probe).solve(
          {.c1 = c1, .load = load, .speed = speed});
      check_hertz_strip(s, c1, load, (1 + f) * c, a0);
    }
  }
  SECTION("f = 0: no memory at any speed") {
    const StandardLinearSolid<Real> no_creep(mu_d, nu, Real(0), Real(1));
    const auto s = PlaneSolver<Real, StandardLinearSolid<Real>>(no_creep).solve(
        {.c1 = c1, .load = load, .speed = Real(1)});
    check_hertz_strip(s, c1, load, c, std::sqrt(4 * c * load / c1));
  }
  SECTION("glassy: V tau = 1e30 a0 and V tau = +inf, the instantaneous compliance") {
    // V tau = 1e30 * 1e30 overflows to +inf in every type here.
    for (const Real tau : {Real(1), Real(1e30)}) {
      INFO("tau = " << tau);
      const StandardLinearSolid<Real> m(mu_d, nu, f, tau);
      const auto s = PlaneSolver<Real, StandardLinearSolid<Real>>(m).solve(
          {.c1 = c1, .load = load, .speed = Real(1e30)});
      check_hertz_strip(s, c1, load, c, a0);
    }
  }
  SECTION("the rolling path just below the glassy switch is within its stated bound of it") {
    // docs/theory.md (P6): b/a0 <= (u/2)(ln(2 sqrt(1+f)/u) - gamma) + O(u^2), u = a0/V tau;
    // PlaneSolver switches where u (ln(2/u) + ln(1+f)/2 + 1) <= eps. At u = 1e-4 (well inside
    // the rolling range) the bound is checked against the rolling solution itself.
    const Real u = Real(1e-4);
    const StandardLinearSolid<Real> m(mu_d, nu, f, a0 / u);
    const auto s = PlaneSolver<Real, StandardLinearSolid<Real>>(m).solve(
        {.c1 = c1, .load = load, .speed = Real(1)});
    using std::log;
    using std::sqrt;
    const Real bound = u * (log(2 / u) + log(1 + f) / 2 + 1);
    CHECK(s.b > 0);
    CHECK(s.b / a0 <= bound);
    CHECK(s.chi / (c1 * a0) <= bound);
    CHECK(std::abs(s.a * sqrt(1 + f) / a0 - 1) <= bound);
  }
}

namespace {

/// Checks a line solution against Kalker's static contact of compliance c_eff (identities of
/// docs/paper.md, "Checked by derivation") and the closed form's bookkeeping.
template <class Real, class Solution>
void check_static_line(const Solution& s, Real c1, Real c2, Real load, Real c_eff,
                       Real a0_long_term, const std::string& reason) {
  using std::abs;
  using std::log;
  using std::sqrt;
  const Real a0 = s.a(Real(0)), l = s.l();
  INFO("a(0) = " << a0 << ", l = " << l << ", d = " << s.d << ", reason " << s.reason);
  // Which closed form has no code of its own (converged, 0 iterations): the reason names it.
  CHECK(s.reason == reason);
  CHECK(s.converged);
  CHECK(s.code == viscoroll::StopCode::converged);
  CHECK(s.iterations == 0);
  CHECK(s.residual == 0);
  CHECK(s.chi == 0);
  CHECK(s.vtau == 0);
  // The root rho = l/a0 is found to 2 eps (TOMS 748 on digits - 1 bits); the curvature ratio
  // amplifies it by |1/(ln 4 rho - 1) - 2| < 2 for rho > 2, plus the roundings of a log.
  const Real ratio = (a0 / l) * (a0 / l) * (log(4 * l / a0) - 1);
  CHECK(abs(ratio - c2 / c1) <= 32 * eps<Real>() * (c2 / c1));
  // Load (47) with (48): C1 a0^2 l / 3 = c_eff P; a cube root of the product, a few roundings.
  CHECK(abs(c1 * a0 * a0 * l / 3 - c_eff * load) <= 32 * eps<Real>() * (c_eff * load));
  CHECK(abs(s.d - c1 * a0 * a0 * log(4 * l / a0) / 2) <= 16 * eps<Real>() * s.d);
  CHECK(abs(s.a_long_term - a0_long_term) <= 16 * eps<Real>() * a0_long_term);
  for (const Real t : {Real(0.25), Real(0.5), Real(0.9)}) {
    INFO("y / l = " << t);
    const Real y = t * l;
    const Real a_y = a0 * sqrt((1 - t) * (1 + t));
    CHECK(abs(s.a(y) - a_y) <= 16 * eps<Real>() * a0);
    CHECK(s.b(y) == 0);
    CHECK(s.g(y) == 0);
    // Hertz's strip at y: p = C1 sqrt(a^2 - x^2) / (2 pi c_eff), Eqs. (7), (32) with G = b = 0.
    const Real x = a_y / 3;
    const Real p = c1 * sqrt((a_y - x) * (a_y + x)) / (2 * pi<Real>() * c_eff);
    CHECK(abs(s.pressure(x, y) - p) <= 64 * eps<Real>() * p);
  }
}

}  // namespace

TEMPLATE_TEST_CASE("needs: elastic, static and glassy line scenes are Kalker's static contact",
                   "[needs]", float, double, long double) {
  using Real = TestType;
  using std::cbrt;
  using std::log;
  using viscoroll::LineSolver;
  using viscoroll::StandardLinearSolid;
  // The paper's 5:1 contact, f = 9.
  const Real f = 9, mu_d = 1, nu = Real(0.5), c1 = 1, c2 = (log(Real(20)) - 1) / 25;
  const StandardLinearSolid<Real> probe(mu_d, nu, f, Real(1));
  const Real c = probe.instantaneous_compliance();
  const Real load = 5 / (3 * (1 + f) * c);  // a0 = 1 at the long-term compliance
  const Real a0 = viscoroll::static_line_contact(c1, c2, (1 + f) * c * load).a0;
  CHECK(std::abs(a0 - 1) <= 16 * eps<Real>());

  SECTION("elastic material (the long-term modulus)") {
    const viscoroll::Elastic<Real> elastic(mu_d / (1 + f), nu);
    const auto s = LineSolver<Real, viscoroll::Elastic<Real>>(elastic).solve(
        {.c1 = c1, .c2 = c2, .load = load, .speed = Real(2)});
    check_static_line(s, c1, c2, load, elastic.instantaneous_compliance(), a0,
                      "static (closed form)");
  }
  SECTION("V tau = 0 and V tau <= eps a0: the long-term compliance") {
    for (const Real speed : {Real(0), eps<Real>() * a0 / 2}) {
      INFO("speed = " << speed);
      const auto s = LineSolver<Real, StandardLinearSolid<Real>>(probe).solve(
          {.c1 = c1, .c2 = c2, .load = load, .speed = speed});
      check_static_line(s, c1, c2, load, (1 + f) * c, a0, "static (closed form)");
    }
  }
  SECTION("glassy: V tau = 1e30 a0 and V tau = +inf, the instantaneous compliance") {
    for (const Real tau : {Real(1), Real(1e30)}) {
      INFO("tau = " << tau);
      const StandardLinearSolid<Real> m(mu_d, nu, f, tau);
      const auto s = LineSolver<Real, StandardLinearSolid<Real>>(m).solve(
          {.c1 = c1, .c2 = c2, .load = load, .speed = Real(1e30)});
      check_static_line(s, c1, c2, load, c, a0, "glassy limit (closed form)");
      // The 3-D glassy contact: a and l scale by (1 + f)^(-1/3) (docs/paper.md, correction 7).
      CHECK(std::abs(s.a(Real(0)) - a0 / cbrt(1 + f)) <= 32 * eps<Real>() * a0);
    }
  }
}

}  // namespace test_closed_forms
