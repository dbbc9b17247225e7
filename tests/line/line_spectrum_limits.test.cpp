// The line solver for a material with a spectrum (docs/theory.md section 14) in the checks that
// every solver for a spectrum must pass and that tests/plane/plane_spectrum.test.cpp makes of the
// plane one: two retardation times far apart give two peaks of chi against speed, and between them
// the plateau of the intermediate modulus, where the contact is the static line contact of the
// compliance (1 + f1) c; terms with equal retardation times are one term with the summed weight.
// (One term equal to the standard linear solid's solver, and the slow and fast limits, are in
// line_spectrum.test.cpp.)
//
// Tolerances. The plateau: its deviation from the static contact is first order in V tau1/a and
// a/(V tau2), with the bound derived at plateau_bound below (measured at most 21% of it, in d).
// Equal times: the solver merges equal times by adding their weights (merge_spectrum), exactly
// for the binary fractions used here, so both materials are the same floating-point problem:
// 4 eps, as the plane's test allows (measured 0, bit for bit).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/line/static_line_contact.hpp>
#include <viscoroll/material/prony.hpp>

#include "support/spectrum_scene.hpp"
#include "support/strict_maxima.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_spectrum_limits {

namespace {

using viscoroll::LineOptions;
using viscoroll::LineSolver;
using viscoroll::PronyCreep;

using viscoroll::testing::spectrum_scene;  // the paper's proportions, load 1
using viscoroll::testing::two_term_creep;  // (f, tau) = (3, 0.05), (6, 5)

using Solver = LineSolver<double, PronyCreep<double>>;

const double eps = std::numeric_limits<double>::epsilon();

double rel(double x, double y) { return std::abs(x - y) / std::abs(y); }

/// f1 = f2 = 4 with tau1 and tau2 far apart; mu_D = 1, nu = 0.5 (the long-term static contact on
/// spectrum_scene has a0 = 0.755, the plateau's 0.620, the glassy 0.363).
PronyCreep<double> far_apart(double tau1, double tau2) {
  return PronyCreep<double>(1.0, 0.5, {{4.0, tau1}, {4.0, tau2}});
}

/// The plateau's deviation from the static contact of compliance (1 + f1) c at speed V, with
/// lambda_k = V tau_k and lambda1 << a << lambda2 (a, l the half width and length of that static
/// contact), relative in a(0), l and d:
///  - term 1 has crept fully except in a layer of width lambda1 behind the leading edge: it lacks
///    a fraction O(lambda1/a) of its compliance f1 c, against the plateau's (1 + f1) c,
///      eps1 = f1/(1 + f1) lambda1/a
///    (the plane strip's (P5)-(P6), docs/theory.md: a = a_mid (1 - eps1/2) to first order);
///  - term 2 has hardly started: it adds f2 c times the potential averaged over lambda2 ahead of
///    each point, c f2 P (ln(lambda2/a) + O(1))/lambda2, nearly uniform over the contact (it
///    moves d; the contact's shape feels only its variation, smaller by a/lambda2). Against the
///    plateau's d = (3/2) ln(4 l/a) c (1 + f1) P/l (Eqs. 47, 48) that is at most
///      eps2 = f2/(1 + f1) (l/lambda2) ln(lambda2/a),
///    with the factor 2/(3 ln(4 l/a)) = 0.22 to spare for the O(1) in the logarithm.
/// The centroid's shift chi/C1 is likewise within (eps1 + eps2) a. At V = 1 with tau = 1e-4, 1e4:
/// eps1 = 1.3e-4, eps2 = 2.4e-3; with tau = 1e-6, 1e6: 1.3e-6 and 3.6e-5.
double plateau_bound(double f1, double f2, double lambda1, double lambda2, double a, double l) {
  const double eps1 = f1 / (1 + f1) * lambda1 / a;
  const double eps2 = f2 / (1 + f1) * (l / lambda2) * std::log(lambda2 / a);
  return eps1 + eps2;
}

}  // namespace

TEST_CASE("line spectrum limits: two times far apart give two peaks of chi, far below them between",
          "[line][spectrum]") {
  // tau1 = 1e-4, tau2 = 1e4 (eight decades apart): chi(V) peaks where V tau_k ~ a for each term
  // (measured: V = 10^-4.25, chi = 0.1075, the slow term's, and V = 10^3.75, chi = 0.2030) and
  // falls between them, where the first term's creep is complete and the second's has not
  // started. 57 speeds V = 1e-7 ... 1e7, four a decade. Below V = 1.1e-4 the first term is
  // relaxed (V tau1 <= sqrt(eps) a0) and the solve is the standard linear solid's, whose slow
  // regime ends in a least-squares minimum at one speed; the peaks are counted the same.
  const Solver solver(far_apart(1e-4, 1e4), LineOptions{.terms = 4});
  const auto chi = viscoroll::testing::chi_over_speeds(
      [&](double speed) { return solver.solve(spectrum_scene(speed)); }, -7, 0.25, 57);
  const auto peaks = viscoroll::testing::strict_maxima(chi);
  CHECK(peaks.count == 2);
  const double lower_peak = peaks.lowest;
  // V = 1 (k = 28): V tau1 = 1.6e-4 a, V tau2 = 1.6e4 a. chi there is within the plateau's bound
  // C1 (eps1 + eps2) a (measured 1.17e-4 against 1.57e-3), and so far below the lower peak.
  const auto scene = spectrum_scene(1.0);
  const double c = far_apart(1e-4, 1e4).instantaneous_compliance();
  const auto mid = viscoroll::static_line_contact(scene.c1, scene.c2, 5 * c * scene.load);
  const double bound = plateau_bound(4, 4, 1e-4, 1e4, mid.a0, mid.l);
  CAPTURE(chi[28], lower_peak, bound);
  CHECK(chi[28] >= 0);
  CHECK(chi[28] <= scene.c1 * mid.a0 * bound);
  CHECK(chi[28] < 0.05 * lower_peak);
}

TEST_CASE(
    "line spectrum limits: between two times far apart the contact is the static one of the "
    "intermediate compliance",
    "[line][spectrum]") {
  // At V = 1, the middle of the plateau, a(0), l and d are static_line_contact's with the
  // compliance (1 + f1) c, within plateau_bound. Two separations, the second a hundred times
  // wider each way: the deviation falls with them (first order), and so does the bound. Measured
  // relative deviations (a(0), l, d, chi/(C1 a)): tau = 1e-4, 1e4: 9.1e-5, 2.2e-5, 5.0e-4, 1.9e-4
  // against 2.5e-3; tau = 1e-6, 1e6: 9.1e-7, 2.2e-7, 7.6e-6, 1.9e-6 against 3.7e-5.
  for (const double tau1 : {1e-4, 1e-6}) {
    const double tau2 = 1 / tau1, speed = 1.0;
    const auto material = far_apart(tau1, tau2);
    const auto scene = spectrum_scene(speed);
    const auto mid = viscoroll::static_line_contact(
        scene.c1, scene.c2, 5 * material.instantaneous_compliance() * scene.load);
    const double bound = plateau_bound(4, 4, speed * tau1, speed * tau2, mid.a0, mid.l);
    const auto s = Solver(material, LineOptions{.terms = 4}).solve(scene);
    CAPTURE(tau1, tau2, bound, s.a(0), mid.a0, s.l(), mid.l, s.d, mid.d, s.chi);
    REQUIRE(s.converged);
    CHECK(s.active_terms == 2);
    CHECK(rel(s.a(0), mid.a0) <= bound);
    CHECK(rel(s.l(), mid.l) <= bound);
    CHECK(rel(s.d, mid.d) <= bound);
    CHECK(std::abs(s.b(0)) <= bound * mid.a0);
    CHECK(s.chi >= 0);
    CHECK(s.chi <= scene.c1 * mid.a0 * bound);
  }
}

TEST_CASE("line spectrum limits: equal times are one term with the summed weight",
          "[line][spectrum]") {
  // Against two_term_creep, (3, 0.05), (6, 5): the same spectrum with its terms split in two and
  // in five, given out of order; and three terms at tau = 0.05 only, against the one term
  // (3, 0.05), which is then the standard linear solid's solver. The weights are binary fractions
  // whose sums are exact, so merge_spectrum makes the same terms of both; 4 eps relative (b(0):
  // of a(0)), measured 0.
  const LineOptions options{.terms = 4};
  const Solver merged(two_term_creep(), options);
  const Solver split(PronyCreep<double>(1.0, 0.5, {{2.0, 0.05}, {6.0, 5.0}, {1.0, 0.05}}), options);
  const Solver five(
      PronyCreep<double>(1.0, 0.5, {{1.5, 0.05}, {4.0, 5.0}, {0.5, 0.05}, {2.0, 5.0}, {1.0, 0.05}}),
      options);
  const Solver one(PronyCreep<double>(1.0, 0.5, {{3.0, 0.05}}), options);
  const Solver three(PronyCreep<double>(1.0, 0.5, {{1.0, 0.05}, {1.5, 0.05}, {0.5, 0.05}}),
                     options);
  struct Pair {
    const Solver* terms;
    const Solver* summed;
    int active;
  };
  for (const auto& [terms, summed, active] :
       {Pair{&split, &merged, 2}, Pair{&five, &merged, 2}, Pair{&three, &one, 1}}) {
    for (const double speed : {0.5, 5.0, 50.0}) {
      const auto a = terms->solve(spectrum_scene(speed));
      const auto b = summed->solve(spectrum_scene(speed));
      CAPTURE(speed, terms->material().memory_terms().size());
      REQUIRE(a.converged);
      REQUIRE(b.converged);
      CHECK(a.active_terms == active);
      CHECK(b.active_terms == active);
      CHECK(rel(a.a(0), b.a(0)) <= 4 * eps);
      CHECK(std::abs(a.b(0) - b.b(0)) <= 4 * eps * b.a(0));
      CHECK(rel(a.l(), b.l()) <= 4 * eps);
      CHECK(rel(a.d, b.d) <= 4 * eps);
      CHECK(rel(a.chi, b.chi) <= 4 * eps);
      CHECK(rel(a.f0(0.3), b.f0(0.3)) <= 4 * eps);
    }
  }
}

}  // namespace test_line_spectrum_limits
