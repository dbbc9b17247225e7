// Stability matrix of the boundary-element solver on coarse grids (docs/stability.md). Scenes of
// the line theory's a0 = 1 and l0 = rho a0 (C2/C1 = (ln 4 rho - 1)/rho^2, P = C1 rho/(3 (1+f) c)),
// tau = 1, so the speed is V tau/a0; the BEM's own references are the exact Hertz ellipses of the
// long-term compliance (1 + f) c and of the instantaneous compliance c (bem/hertz.hpp, B8).
//
// Every converged cell: every number and every cell's p and g finite; p >= 0; the load and the
// complementarity residual to 4 tol sqrt(cells + 1) (tests/bem/bem_property.test.cpp); l, a(0) > 0;
// d between the glassy and the long-term Hertz penetrations to (h/a)^2; and the limit of its cell:
// V tau/a0 = 1e-4 and f = 0 against long-term Hertz, |a(0) - a_H| <= hx/4, |l - b_H| <= hy/4,
// |d - d_H|/d_H <= (hx/a_H)^2/5 (docs/bem.md B13) plus the O(V tau/a0) departure; V tau/a0 = 1e4
// against glassy Hertz, a(0) to hx/4 and d to (hx/a)^2/5 (B13), plus the approach
// e = alpha ln(1/alpha) + l/(V tau) (line_stability.test.cpp), l to hy/4 + e l.
// A cell whose contact the grid cannot resolve must say so (converged == false with the reason).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/bem/hertz.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>

#include "stability_support.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_bem_stability {

namespace {

using stability::eps;
using stability::finite;
using stability::rel;
using stability::report;
using stability::str;
using viscoroll::BemOptions;
using viscoroll::BemScene;
using viscoroll::BemSolution;
using viscoroll::BemSolver;
using viscoroll::StandardLinearSolid;

template <class Real>
Real exact(double x) {
  return x < 1 ? 1 / Real(std::round(1 / x)) : Real(x);
}

template <class Real>
struct Cell {
  double v, f, rho;
  int grid;
  StandardLinearSolid<Real> material() const {
    return {Real(1), Real(1) / 2, exact<Real>(f), Real(1)};
  }
  Real c() const { return material().instantaneous_compliance(); }
  Real ratio() const {
    const Real r = Real(rho);
    return (std::log(4 * r) - 1) / (r * r);
  }
  Real load() const { return Real(rho) / (3 * (1 + exact<Real>(f)) * c()); }
  BemScene<Real> scene() const { return {Real(1), ratio(), load(), exact<Real>(v)}; }
  std::string name() const {
    return "v=" + str(v) + " f=" + str(f) + " l0/a0=" + str(rho) + " grid " + std::to_string(grid);
  }
};

template <class Real>
BemSolution<Real> solve(const Cell<Real>& cell) {
  BemOptions o;
  o.grid = cell.grid;
  return BemSolver<Real, StandardLinearSolid<Real>>(cell.material(), o).solve(cell.scene());
}

/// The invariants of a converged solution (bem_property.test.cpp).
template <class Real>
void check_invariants(const Cell<Real>& cell, const BemSolution<Real>& s) {
  using std::abs;
  for (const Real& x : {s.d, s.a0, s.b0, s.l, s.chi, s.load, s.residual}) REQUIRE(finite(x));
  REQUIRE(s.pressure.size() == s.grid.size());
  int negative = 0, not_finite = 0;
  Real sum = 0;
  for (std::size_t q = 0; q < s.pressure.size(); ++q) {
    if (!finite(s.pressure[q]) || !finite(s.gap[q])) ++not_finite;
    if (s.pressure[q] < 0) ++negative;
    sum += s.pressure[q];
  }
  CHECK(not_finite == 0);
  CHECK(negative == 0);
  const Real tol = std::max(Real(BemOptions{}.gmres_tolerance), 32 * eps<Real>());
  const Real bound = 4 * tol * std::sqrt(Real(s.contact_cells + 1));
  CHECK(abs(s.grid.hx * s.grid.hy * sum / cell.load() - 1) <= bound);
  CHECK(abs(s.load / cell.load() - 1) <= bound);
  CHECK(s.residual <= bound);
  CHECK(s.l > 0);
  CHECK(s.a0 > 0);
  CHECK(s.b0 - s.a0 < s.b0 + s.a0);
  const auto glassy = viscoroll::bem::hertz_contact(Real(1), cell.ratio(), cell.c(), cell.load());
  const Real n = Real(cell.grid);
  const Real ha_long = 1 / n,
             ha_glassy = std::cbrt(s.long_term.a * s.long_term.b / (glassy.a * glassy.b)) / n;
  CHECK(s.d <= s.long_term.d * (1 + ha_long * ha_long));
  CHECK(s.d >= glassy.d * (1 - ha_glassy * ha_glassy));
}

/// One cell: the invariants if converged, then its limit. Returns the solution.
template <class Real>
BemSolution<Real> check_cell(const Cell<Real>& cell) {
  const auto s = solve(cell);
  const std::string name = "bem " + stability::type_name<Real>() + " " + cell.name();
  INFO(name << ": " << s.reason << ", a(0) = " << s.a0 << ", l = " << s.l << ", d = " << s.d
            << ", chi = " << s.chi << ", cells " << s.contact_cells);
  if (!s.converged) {
    CHECK_FALSE(s.reason.empty());
    CHECK(s.code != viscoroll::StopCode::converged);
    report(name + ": NOT CONVERGED (" + s.reason + ")");
    return s;
  }
  check_invariants(cell, s);
  const Real v = exact<Real>(cell.v), f = exact<Real>(cell.f);
  long double ea = 0, el = 0, ed = 0, ba = 0, bl = 0, bd = 0;
  if (cell.v <= 1e-4 || cell.f == 0) {
    const auto& h = s.long_term;
    const Real speed = cell.f == 0 ? Real(0) : v;
    ea = std::abs(static_cast<long double>(s.a0 - h.a));
    el = std::abs(static_cast<long double>(s.l - h.b));
    ed = rel(s.d, static_cast<long double>(h.d));
    const Real ha = s.grid.hx / h.a;
    ba = static_cast<long double>(s.grid.hx / 4 + speed * h.a);
    bl = static_cast<long double>(s.grid.hy / 4 + speed * h.b);
    bd = static_cast<long double>(ha * ha / 5 + speed);
  } else if (cell.v >= 1e4) {
    const auto h = viscoroll::bem::hertz_contact(Real(1), cell.ratio(), cell.c(), cell.load());
    const Real alpha = (1 + f) * h.a / v;
    const Real e = alpha * std::log(1 / alpha) + h.b / v;
    ea = std::abs(static_cast<long double>(s.a0 - h.a));
    el = std::abs(static_cast<long double>(s.l - h.b));
    ed = rel(s.d, static_cast<long double>(h.d));
    const Real ha = s.grid.hx / h.a;
    ba = static_cast<long double>(s.grid.hx / 4 + e * h.a);
    bl = static_cast<long double>(s.grid.hy / 4 + e * h.b);
    bd = static_cast<long double>(ha * ha / 5 + 6 * e);
  }
  if (ba > 0) {
    CHECK(ea <= ba);
    CHECK(el <= bl);
    CHECK(ed <= bd);
  }
  report(name + ": converged" + (s.warnings.empty() ? "" : " with warning") + ", a(0) " +
         str(s.a0) + " l " + str(s.l) + " d " + str(s.d) + " chi " + str(s.chi) + " cells " +
         std::to_string(s.contact_cells) + "; limit errors a " + str(ea) + " (bound " + str(ba) +
         ") l " + str(el) + " (" + str(bl) + ") d " + str(ed) + " (" + str(bd) + "), " +
         str(s.seconds_setup + s.seconds_solve) + " s");
  return s;
}

}  // namespace

TEST_CASE("stability: BEM over V tau/a0 x f x l0/a0 (grid 8)", "[stability][bem]") {
  // Speed axis (f = 9, l0/a0 = 5), aspect at both speed limits, f = 0 and f = 1e4 at the slow
  // limit: all against Hertz.
  for (const Cell<double>& cell : std::vector<Cell<double>>{{1e-4, 9, 5, 8},
                                                            {1, 9, 5, 8},
                                                            {1e4, 9, 5, 8},
                                                            {1e-4, 9, 3, 8},
                                                            {1e4, 9, 3, 8},
                                                            {1e-4, 9, 1000, 8},
                                                            {1, 9, 1000, 8},
                                                            {1e4, 9, 1000, 8},
                                                            {1, 0, 5, 8},
                                                            {1e4, 0, 1000, 8},
                                                            {1e-4, 1e4, 5, 8}}) {
    const auto s = check_cell(cell);
    INFO(cell.name() << ": " << s.reason);
    CHECK(s.converged);  // measured: every one of these converges
    CHECK(s.warnings.empty());
    CHECK(s.warning_codes.empty());
  }
}

TEST_CASE("stability: BEM says so when the grid cannot resolve the contact", "[stability][bem]") {
  // f = 1e4 at V tau = 1e4 a0: the glassy contact is (1 + f)^(-1/3) = 0.046 of the long-term one
  // that sizes the grid, under one cell at grid 8 (a(0) was reported converged 35% off before the
  // check, docs/stability.md).
  const Cell<double> cell{1e4, 1e4, 5, 8};
  const auto s = check_cell(cell);
  CHECK_FALSE(s.converged);
  CHECK(s.code == viscoroll::StopCode::under_resolved);
  // Refined to grid 32 (hx = 0.031 a0 against the glassy a = 0.045 a0) it is resolved: converged,
  // with the invariants and the glassy limit of its cell (measured: 9 contact cells, d 1.6% from
  // the line theory's 0.00517 C1 a0^2).
  const auto fine = check_cell(Cell<double>{1e4, 1e4, 5, 32});
  CHECK(fine.converged);
  // f = 1e4 at V tau = a0: the leading-edge layer V tau/(1 + f) = 1e-4 a0 is a step on the grid
  // (hx = 0.12 a0): converged, d and the load hold, but a(0) and b(0) carry the warning.
  const Cell<double> layer{1, 1e4, 5, 8};
  const auto t = check_cell(layer);
  if (t.converged) {
    REQUIRE(t.warnings.size() == 1);
    REQUIRE(t.warning_codes.size() == 1);
    CHECK(t.warning_codes[0] == viscoroll::WarningCode::edge_layer_unresolved);
  }
}

TEST_CASE("stability: BEM at f = 1e4, V tau = a0 against the line theory",
          "[stability][bem][slow]") {
  // The line theory's d differs from the 3-D solution by its static error, 0.44% (docs/bem.md);
  // the BEM's d at grid 8 is within 1e-4 of its grid limit (B13). Measured difference 1e-5.
  // chi and a(0) carry no documented bound at this f: reported only.
  const Cell<double> cell{1, 1e4, 5, 8};
  const auto s = check_cell(cell);
  REQUIRE(s.converged);
  const viscoroll::LineSolverD line(cell.material(), viscoroll::LineOptions{.terms = 4});
  const auto ls = line.solve({1.0, cell.ratio(), cell.load(), 1.0});
  REQUIRE(ls.converged);
  CHECK(rel(s.d, ls.d) <= 0.0044 + 1e-4);
  CHECK(s.chi > 0);
  report("bem vs line at v=1 f=1e4 l0/a0=5: d " + str(rel(s.d, ls.d)) + ", chi " +
         str(rel(s.chi, ls.chi)) + ", a(0) " + str(rel(s.a0, ls.a(0.0))) + " (BEM a(0) " +
         str(s.a0) + ", line " + str(ls.a(0.0)) + ")");
}

TEMPLATE_TEST_CASE("stability: BEM in float and long double agrees with double", "[stability][bem]",
                   float, long double) {
  // Both solve the same discrete problem (B11) only to the GMRES tolerance in use,
  // tol = max(1e-10, 32 eps), which bounds the load and the complementarity residual by
  // 4 tol sqrt(cells + 1) (bem_property.test.cpp); the solutions differ by that much for each
  // type, plus the rounding of the coefficients (docs/bem.md: 1e4 eps of the scalar).
  using Real = TestType;
  const auto tol_in_use = [](long double e) { return std::max(1e-10L, 32 * e); };
  for (const double rho : {5.0, 1000.0}) {
    const Cell<Real> cell{1, 9, rho, 4};
    const auto s = check_cell(cell);
    const auto r = check_cell(Cell<double>{1, 9, rho, 4});
    REQUIRE(s.converged);
    REQUIRE(r.converged);
    const long double root = std::sqrt(static_cast<long double>(s.contact_cells + 1));
    const long double tol =
        4 * root * (tol_in_use(eps<Real>()) + tol_in_use(eps<double>())) + 1e4L * eps<Real>();
    const long double da = rel(s.a0, r.a0), dl = rel(s.l, r.l), dd = rel(s.d, r.d),
                      dc = rel(s.chi, r.chi);
    CHECK(da <= tol);
    CHECK(dl <= tol);
    CHECK(dd <= tol);
    CHECK(dc <= tol);
    report("bem " + stability::type_name<Real>() + " l0/a0=" + str(rho) + " against double: a(0) " +
           str(da) + " l " + str(dl) + " d " + str(dd) + " chi " + str(dc) + " (bound " + str(tol) +
           ")");
  }
}

}  // namespace test_bem_stability
