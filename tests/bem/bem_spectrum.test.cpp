// The boundary-element solver for a material with a spectrum (docs/bem.md, B9-B10) in the
// checks asked of every solver for a spectrum and that tests/plane/plane_spectrum.test.cpp makes of
// the plane one: two retardation times far apart give two peaks of chi against speed, and between
// them the plateau of the intermediate modulus, the Hertz contact of the compliance (1 + f1) c;
// the slow and fast limits of a spectrum are Hertz with the long-term and the instantaneous
// compliance; terms with equal retardation times are one term with the summed weight. (One term
// equal to the standard linear solid is "bem: the Prony-series material", bem_solver.test.cpp.)
//
// Tolerances. Against Hertz, the discretisation error of docs/bem.md, B13, as
// bem_solver.test.cpp states it: |a0 - a_H| <= hx/4, |l - b_H| <= hy/4 and
// |d - d_H|/d_H <= (h/a)^2/5, h/a the cell over the semi-axis actually in contact (the grid is
// sized by the long-term contact: the plateau's has (5/9)^(1/3) N = 0.82 N cells per semi-axis,
// the glassy one 0.46 N), plus where the speed is finite the contact's own first-order distance
// from the limit (plateau_bound, limit_bound below). Equal times: the operators differ by the
// rounding of the weighted sums of the same memory rows, and GMRES is run to 32 eps; the bound
// is that times the active set's condition number (equal_times_tolerance).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/bem/hertz.hpp>
#include <viscoroll/material/prony.hpp>

#include "support/strict_maxima.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_bem_spectrum {

namespace {

using viscoroll::BemOptions;
using viscoroll::BemScene;
using viscoroll::BemSolution;
using viscoroll::PronyCreep;
using viscoroll::bem::hertz_contact;
using viscoroll::bem::HertzContact;

using Solver = viscoroll::BemSolver<double, PronyCreep<double>>;

const double eps = std::numeric_limits<double>::epsilon();

/// The paper's proportions (C2/C1 = (ln 20 - 1)/25, a 5:1 contact), C1 = 1, load 1, as
/// tests/support/spectrum_scene.hpp.
BemScene<double> scene(double speed) {
  return BemScene<double>{.c1 = 1.0, .c2 = (std::log(20.0) - 1) / 25, .load = 1.0, .speed = speed};
}

Solver solver(const PronyCreep<double>& material, int grid, double final_tolerance = 1e-13) {
  BemOptions o;
  o.grid = grid;
  o.final_tolerance = final_tolerance;
  return Solver(material, o);
}

/// f1 = f2 = 4 with tau1 and tau2 far apart; mu_D = 1, nu = 0.5 (compliance c = 1/(4 pi)).
PronyCreep<double> far_apart(double tau1, double tau2) {
  return PronyCreep<double>(1.0, 0.5, {{4.0, tau1}, {4.0, tau2}});
}

/// B13's bounds on the distance of a solution from Hertz's contact h, widened by `relative` (the
/// solution's own distance from the contact h describes, relative to it).
void check_hertz(const BemSolution<double>& s, const HertzContact<double>& h,
                 double relative) {
  const double ha = s.grid.hx / h.a;
  CAPTURE(s.a0, h.a, s.l, h.b, s.d, h.d, s.grid.hx, s.grid.hy, relative);
  CHECK(std::abs(s.a0 - h.a) <= s.grid.hx / 4 + relative * h.a);
  CHECK(std::abs(s.l - h.b) <= s.grid.hy / 4 + relative * h.b);
  CHECK(std::abs(s.d - h.d) / h.d <= ha * ha / 5 + relative);
}

/// The plateau's distance from the static contact of compliance (1 + f1) c, relative in a(0), l
/// and d (lambda_k = V tau_k, lambda1 << a << lambda2; a, l the semi-axes of that contact), as
/// for the line solver (tests/line/line_spectrum_limits.test.cpp):
///  - term 1 has crept fully except in a layer lambda1 behind the leading edge: it lacks a
///    fraction O(lambda1/a) of its compliance, eps1 = f1/(1 + f1) lambda1/a (the plane strip's
///    (P5)-(P6), docs/theory.md: a = a_mid (1 - eps1/2) to first order);
///  - term 2 has hardly started: it adds f2 c times the potential averaged over lambda2 ahead,
///    c f2 P (ln(lambda2/a) + O(1))/lambda2, nearly uniform (it moves d). Against Hertz's
///    d = 3 c (1 + f1) P K(e)/(2 l) (B8c; K(e) = 3.05 here) that is at most
///    eps2 = f2/(1 + f1) (l/lambda2) ln(lambda2/a), with the factor 2/(3 K) = 0.22 to spare.
/// chi/C1 is within (eps1 + eps2) a. At V = 1 with tau = 1e-4, 1e4: 1.3e-4 + 2.4e-3; with
/// tau = 1e-6, 1e6: 1.3e-6 + 3.6e-5.
double plateau_bound(double f1, double f2, double lambda1, double lambda2, double a, double l) {
  return f1 / (1 + f1) * lambda1 / a + f2 / (1 + f1) * (l / lambda2) * std::log(lambda2 / a);
}

/// The same first-order distance of a spectrum from its limits: near the slow one every term
/// lacks f_k/(1 + F) lambda_k/a of the long-term compliance (1 + F) c; near the fast one every
/// term adds f_k (l/lambda_k) ln(lambda_k/a) to the glassy c.
double limit_bound(const PronyCreep<double>& m, double speed, double a, double l, bool slow) {
  double sum = 0;
  for (const auto& t : m.memory_terms()) {
    const double lambda = speed * t.tau;
    sum +=
        slow ? t.f / (1 + m.creep_ratio()) * lambda / a : t.f * (l / lambda) * std::log(lambda / a);
  }
  return sum;
}

/// Equal times, split against summed: the memory rows of each distinct time are the same (the
/// shared rows of MemoryRows, or memory_row's, which agree with them to m hx eps/L_min:
/// tests/bem/memory_rows.test.cpp), weighted and summed in another order: the coefficients
/// differ by at most (M + m hx/L_min) eps <= 45 eps here (M = 3 terms, m = 26 offsets,
/// hx <= 0.076, L_min = 0.05). GMRES' final solve runs to 32 eps (final_tolerance = 1e-15,
/// raised to 32 eps), so the solutions of the two operators on the same active set differ by
/// cond (45 + 2 x 32) eps <= 128 cond eps: the restricted operator's condition number is 42 to
/// 104 here (N = 8, V = 0.1 ... 10, by SVD of the active rows in a scratch run), doubled for the
/// load row's d and rounded up to 1e3 for GMRES' own rounding: 1e3 x 128 eps = 2.8e-11, for d,
/// chi and every cell pressure relative to the largest.
const double equal_times_tolerance = 1e3 * 128 * eps;

}  // namespace

TEST_CASE("bem spectrum: two times far apart give two peaks of chi, far below them between",
          "[bem][spectrum]") {
  // tau1 = 1e-4, tau2 = 1e4 at N = 8: chi(V) peaks where V tau_k ~ a for each term (measured:
  // V = 10^-4.25, chi = 0.1070, and V = 10^3.75, chi = 0.2024; the line solver: 0.1075, 0.2030)
  // and falls between them. 57 speeds V = 1e-7 ... 1e7, four a decade, as the line solver's test.
  const auto s = solver(far_apart(1e-4, 1e4), 8);
  const auto chi = viscoroll::testing::chi_over_speeds(
      [&](double speed) { return s.solve(scene(speed)); }, -7, 0.25, 57);
  const auto peaks = viscoroll::testing::strict_maxima(chi);
  CHECK(peaks.count == 2);
  const double lower_peak = peaks.lowest;
  // V = 1 (k = 28): within the plateau's bound C1 (eps1 + eps2) a (measured 1.07e-4 against
  // 1.6e-3), and so far below the lower peak.
  const auto mid = hertz_contact(1.0, scene(1.0).c2,
                                      5 * far_apart(1e-4, 1e4).instantaneous_compliance(), 1.0);
  const double bound = plateau_bound(4, 4, 1e-4, 1e4, mid.a, mid.b);
  CAPTURE(chi[28], lower_peak, bound);
  CHECK(chi[28] >= 0);
  CHECK(chi[28] <= mid.a * bound);
  CHECK(chi[28] < 0.05 * lower_peak);
}

TEST_CASE(
    "bem spectrum: between two times far apart the contact is Hertz of the intermediate "
    "compliance",
    "[bem][spectrum]") {
  // At V = 1, N = 8, two separations (the second a hundred times wider each way). Against Hertz
  // of (1 + f1) c: B13's bounds plus plateau_bound (measured: a(0) -0.040 hx, l -0.068 hy, d
  // -8.6e-4 and -1.35e-3 against 0.25 hx, 0.25 hy, 4.6e-3 + 2.6e-3 and + 3.7e-5). Against the
  // BEM's own static contact of (1 + f1) c on the same grid (term 1 with tau = 0, relaxed, L = 0;
  // term 2 with tau = 1e300, dropped as glassy) the grid's error cancels and what is left is the
  // plateau's own deviation, within plateau_bound alone (measured: a(0) 3.5e-5, l 3.6e-5,
  // d 5.0e-4 against 2.6e-3 at 1e-4, 1e4; 8e-6 in d against 3.7e-5 at 1e-6, 1e6; the line
  // solver's d moves by the same 5.0e-4 and 7.6e-6).
  const double c = far_apart(1e-4, 1e4).instantaneous_compliance();
  const auto mid = hertz_contact(1.0, scene(1.0).c2, 5 * c, 1.0);
  const auto still = solver(far_apart(0.0, 1e300), 8).solve(scene(1.0));
  REQUIRE(still.converged);
  check_hertz(still, mid, 0);
  for (const double tau1 : {1e-4, 1e-6}) {
    const double tau2 = 1 / tau1;
    const double bound = plateau_bound(4, 4, tau1, tau2, mid.a, mid.b);
    const auto s = solver(far_apart(tau1, tau2), 8).solve(scene(1.0));
    CAPTURE(tau1, bound, s.a0, still.a0, s.l, still.l, s.d, still.d, s.chi);
    REQUIRE(s.converged);
    check_hertz(s, mid, bound);
    CHECK(s.contact_cells == still.contact_cells);
    CHECK(std::abs(s.a0 - still.a0) <= bound * still.a0);
    CHECK(std::abs(s.l - still.l) <= bound * still.l);
    CHECK(std::abs(s.d - still.d) <= bound * still.d);
    CHECK(std::abs(s.b0) <= bound * mid.a);
    CHECK(s.chi >= 0);
    CHECK(s.chi <= mid.a * bound);
  }
}

TEST_CASE(
    "bem spectrum: slow and fast limits are Hertz with the long-term and instantaneous "
    "compliances",
    "[bem][spectrum]") {
  // Three terms, F = 9 (the standard linear solid's f of B13's table, so the glassy contact has
  // its 0.46 N cells per semi-axis), at N = 8 and 10. V = 0 (every term L = 0) and V = 1e30
  // (every term dropped, glassy) are the limits themselves; V = 1e-6 (V tau_k <= 1e-4, under
  // 1e-3 of a cell) and 1e6 (V tau_k >= 1e4) roll, within limit_bound of them. Measured at
  // N = 8 (N = 10): slow a(0) 0.031 hx (0.030), l 0.050 hy (0.051), d -1.6e-5 (-9.3e-5) against
  // 0.25 hx, 0.25 hy, 3.1e-3 (2.0e-3); fast a(0) 0.224 hx (0.052), l -0.046 hy (-0.053), d
  // -3.1e-3 (-2.9e-3) against 0.25 hx, 0.25 hy, 1.45e-2 (9.3e-3): B13's table, 5:1 rows.
  // chi: zero at the limits; near them the first order, C1 sum_k f_k V tau_k/(1 + F) (the plane's
  // (P7) term by term; measured 0.90 of it at N = 8, the unresolved leading-edge layer) and
  // C1 a (limit_bound) (measured 0.02 of it).
  const PronyCreep<double> material(1.0, 0.5, {{1.0, 1e-2}, {3.0, 1.0}, {5.0, 1e2}});
  const double c = material.instantaneous_compliance(), f = material.creep_ratio();
  const auto long_term = hertz_contact(1.0, scene(0).c2, (1 + f) * c, 1.0);
  const auto glassy = hertz_contact(1.0, scene(0).c2, c, 1.0);
  for (const int n : {8, 10}) {
    const auto s = solver(material, n);
    for (const double speed : {0.0, 1e-6}) {
      const auto sol = s.solve(scene(speed));
      const double bound =
          speed > 0 ? limit_bound(material, speed, long_term.a, long_term.b, true) : 0.0;
      double first_order = 0;
      for (const auto& t : material.memory_terms()) first_order += t.f * speed * t.tau / (1 + f);
      CAPTURE(n, speed, bound, sol.chi, first_order);
      REQUIRE(sol.converged);
      check_hertz(sol, long_term, bound);
      CHECK(sol.chi >= -1e-12);
      CHECK(sol.chi <= first_order + 1e-12);
    }
    for (const double speed : {1e6, 1e30}) {
      const auto sol = s.solve(scene(speed));
      const double bound =
          speed < 1e20 ? limit_bound(material, speed, glassy.a, glassy.b, false) : 0.0;
      CAPTURE(n, speed, bound, sol.chi);
      REQUIRE(sol.converged);
      check_hertz(sol, glassy, bound);
      CHECK(sol.chi >= -1e-12);
      CHECK(sol.chi <= glassy.a * bound + 1e-12);
    }
  }
}

TEST_CASE("bem spectrum: equal times are one term with the summed weight", "[bem][spectrum]") {
  // (2, 0.5), (0.5, 7), (1.5, 0.5) against (3.5, 0.5), (0.5, 7): both on shared memory rows; and
  // (1, 0.5), (1.5, 0.5), (0.5, 0.5) against (3, 0.5), shared rows against memory_row's. N = 8,
  // V = 0.1, 1, 10. Within equal_times_tolerance (2.8e-11) in d, chi and every cell pressure;
  // the same contact cells; the sub-cell edges (B12) from the last two cells' pressures, whose
  // error they amplify by a factor measured <= 1.8 here: within 10 x the tolerance in cells.
  // Measured: d <= 5.6e-16, chi <= 8.9e-16, pressures <= 6.7e-14, edges <= 1.1e-13 cells.
  const double final_tolerance = 1e-15;
  struct Pair {
    PronyCreep<double> terms, summed;
  };
  const std::vector<Pair> pairs{{PronyCreep<double>(1.0, 0.5, {{2.0, 0.5}, {0.5, 7.0}, {1.5, 0.5}}),
                                 PronyCreep<double>(1.0, 0.5, {{3.5, 0.5}, {0.5, 7.0}})},
                                {PronyCreep<double>(1.0, 0.5, {{1.0, 0.5}, {1.5, 0.5}, {0.5, 0.5}}),
                                 PronyCreep<double>(1.0, 0.5, {{3.0, 0.5}})}};
  const double tol = equal_times_tolerance;
  for (const auto& pair : pairs) {
    const auto split = solver(pair.terms, 8, final_tolerance);
    const auto merged = solver(pair.summed, 8, final_tolerance);
    for (const double speed : {0.1, 1.0, 10.0}) {
      const auto a = split.solve(scene(speed));
      const auto b = merged.solve(scene(speed));
      CAPTURE(pair.terms.memory_terms().size(), pair.summed.memory_terms().size(), speed);
      REQUIRE(a.converged);
      REQUIRE(b.converged);
      REQUIRE(a.contact_cells == b.contact_cells);
      CHECK(std::abs(a.d - b.d) <= tol * b.d);
      CHECK(std::abs(a.chi - b.chi) <= tol * b.chi);
      double largest = 0, worst = 0;
      for (const double p : b.pressure) largest = std::max(largest, p);
      for (std::size_t q = 0; q < b.pressure.size(); ++q)
        worst = std::max(worst, std::abs(a.pressure[q] - b.pressure[q]));
      CHECK(worst <= tol * largest);
      CHECK(std::abs(a.a0 - b.a0) <= 10 * tol * b.grid.hx);
      CHECK(std::abs(a.b0 - b.b0) <= 10 * tol * b.grid.hx);
      CHECK(std::abs(a.l - b.l) <= 10 * tol * b.grid.hy);
    }
  }
}

}  // namespace test_bem_spectrum
