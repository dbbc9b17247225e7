// The plane solver for a material with a spectrum (docs/theory.md, section 12, (S1)-(S10))
// against the standard linear solid's closed form (one term), against itself (merged terms), in
// its limits, and against the independent spectral collocation of Hunter's Eq. (2) extended to
// several memory terms (tests/support/hunter_collocation.hpp), which imposes u' = -C1 x directly
// and uses none of (S1)-(S10).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/plane/plane_solver.hpp>

#include "support/hunter_collocation.hpp"
#include "support/strict_maxima.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_spectrum {

using viscoroll::PlaneScene;
using viscoroll::PlaneSolver;
using viscoroll::PronyCreep;
using viscoroll::PronyTerm;

namespace {

const double eps = std::numeric_limits<double>::epsilon();

bool within(double x, double ref, double tolerance) {
  return std::abs(x - ref) <= tolerance * std::abs(ref);
}

/// The reference for a spectrum at speed V: memory terms (f_k, V tau_k).
viscoroll::testing::HunterReference<double> collocation(const PronyCreep<double>& m, double c1,
                                                        double load, double speed, int n) {
  std::vector<viscoroll::testing::hunter_detail::MemoryTerm<double>> terms;
  for (const auto& t : m.memory_terms()) terms.push_back({t.f, speed * t.tau});
  return viscoroll::testing::hunter_reference(m.instantaneous_compliance(), terms, c1, load, n);
}

/// Checks a, b, chi, the peak and the pressure at four points against the collocation, to 1e-8
/// (the bound; both methods are converged to ~1e-11 at the N used, measured 2e-14 for
/// two terms, 1.2e-14 for twenty).
void check_against_collocation(const PronyCreep<double>& m, double speed, int n) {
  const double c1 = 1.0, load = 0.1;
  const auto s = PlaneSolver(m).solve(PlaneScene<double>{.c1 = c1, .load = load, .speed = speed});
  const auto ref = collocation(m, c1, load, speed, n);
  const auto peak = s.peak();
  INFO("speed = " << speed << ", terms = " << m.memory_terms().size() << ", N = " << n);
  REQUIRE(ref.converged);
  REQUIRE(s.converged);
  CHECK(within(s.a, ref.a, 1e-8));
  CHECK(within(s.b, ref.b, 1e-8));
  CHECK(within(s.chi, ref.chi, 1e-8));
  CHECK(within(peak.pressure, ref.pmax, 1e-8));
  CHECK(std::abs(peak.x - ref.pmax_x) <= 1e-7 * ref.a);
  for (double x : {s.b - 0.9 * s.a, s.b, s.b + 0.5 * s.a, s.b + 0.99 * s.a})
    CHECK(std::abs(s.pressure(x) - ref.pressure(x)) <= 1e-8 * ref.pmax);
}

}  // namespace

TEST_CASE("plane spectrum: one term equals the standard linear solid", "[plane][spectrum]") {
  // (S5)-(S10) with M = 1 are (P3), (P4), (P2) and (P7): the same numbers by another route, to
  // rounding (measured <= 4.4e-16 relative; the bound allows 16 eps).
  const double f = 9, tau = 1;
  const PlaneSolver sls(viscoroll::StandardLinearSolid<double>(1.0, 0.5, f, tau));
  const PlaneSolver spectrum(PronyCreep<double>(1.0, 0.5, {{f, tau}}));
  for (double speed : {1e-3, 0.01, 0.1, 1.0, 10.0, 100.0, 1e4}) {
    const PlaneScene<double> scene{.c1 = 1.0, .load = 0.1, .speed = speed};
    const auto a = sls.solve(scene);
    const auto b = spectrum.solve(scene);
    INFO("speed = " << speed);
    REQUIRE(b.converged);
    CHECK(within(b.a, a.a, 16 * eps));
    CHECK(within(b.b, a.b, 16 * eps));
    CHECK(within(b.g, a.g, 16 * eps));
    CHECK(within(b.chi, a.chi, 16 * eps));
    CHECK(within(b.peak().pressure, a.peak().pressure, 16 * eps));
  }
}

TEST_CASE("plane spectrum: equal times are one term with the summed weight", "[plane][spectrum]") {
  const PlaneSolver split(PronyCreep<double>(1.0, 0.3, {{2.0, 0.5}, {0.5, 7.0}, {1.5, 0.5}}));
  const PlaneSolver merged(PronyCreep<double>(1.0, 0.3, {{3.5, 0.5}, {0.5, 7.0}}));
  for (double speed : {0.05, 1.0, 20.0}) {
    const PlaneScene<double> scene{.c1 = 2.0, .load = 0.3, .speed = speed};
    const auto a = split.solve(scene), b = merged.solve(scene);
    INFO("speed = " << speed);
    CHECK(within(a.a, b.a, 4 * eps));
    CHECK(within(a.b, b.b, 4 * eps));
    CHECK(within(a.chi, b.chi, 4 * eps));
  }
}

TEST_CASE("plane spectrum: slow and fast limits are Hertz with the long-term and glassy moduli",
          "[plane][spectrum]") {
  // Every term relaxed (V tau_k <= eps a) or glassy (strip_is_glassy): Hertz's a with the
  // long-term compliance c (1 + sum f) or the glassy c, and no rolling friction.
  const PronyCreep<double> m(1.0, 0.5, {{1.0, 1e-2}, {3.0, 1.0}, {5.0, 1e2}});
  const double c = m.instantaneous_compliance(), c1 = 1.0, load = 0.1;
  const double a_long = std::sqrt(4 * c * 10 * load / c1), a_glassy = std::sqrt(4 * c * load / c1);
  const auto slow = PlaneSolver(m).solve({.c1 = c1, .load = load, .speed = 1e-20});
  CHECK(within(slow.a, a_long, 4 * eps));
  CHECK(slow.chi == 0);
  const auto fast = PlaneSolver(m).solve({.c1 = c1, .load = load, .speed = 1e20});
  CHECK(within(fast.a, a_glassy, 4 * eps));
  CHECK(fast.chi == 0);
  // Near the limits the rolling solution approaches them: chi -> 0, a -> a_long or a_glassy.
  const auto slower = PlaneSolver(m).solve({.c1 = c1, .load = load, .speed = 1e-6});
  CHECK(slower.active_terms == 3);
  CHECK(within(slower.a, a_long, 1e-3));
  const auto faster = PlaneSolver(m).solve({.c1 = c1, .load = load, .speed = 1e6});
  CHECK(faster.active_terms == 3);
  CHECK(within(faster.a, a_glassy, 1e-3));
}

TEST_CASE("plane spectrum: two times far apart give two peaks of chi with a plateau between",
          "[plane][spectrum]") {
  // tau_1 = 1e-3, tau_2 = 1e3: chi(V) peaks where V tau_k ~ a for each term and falls between,
  // where the first term's creep is complete and the second's has not started (the plateau of
  // the intermediate modulus).
  const PlaneSolver s(PronyCreep<double>(1.0, 0.5, {{4.0, 1e-3}, {4.0, 1e3}}));
  std::vector<double> chi;
  for (int k = 0; k <= 120; ++k)
    chi.push_back(s.solve({.c1 = 1.0, .load = 0.1, .speed = std::pow(10.0, -6 + 0.1 * k)}).chi);
  CHECK(viscoroll::testing::strict_maxima(chi).count == 2);
  // Between them (V = 1: V tau_1 = 1e-3 a0-ish, V tau_2 = 1e3) chi is far below either peak.
  const double top = *std::max_element(chi.begin(), chi.end());
  CHECK(chi[60] < 0.05 * top);
}

TEST_CASE("plane spectrum: agrees with the independent collocation, two terms",
          "[plane][spectrum][reference]") {
  const PronyCreep<double> m(1.0, 0.5, {{2.0, 0.3}, {5.0, 30.0}});
  for (double speed : {0.1, 1.0, 10.0}) check_against_collocation(m, speed, 96);
  // One term far into its glassy range (V tau_2 / a ~ 1e5 ... 1e6): its effect on b and chi is
  // O(a / V tau_2) and must not be lost to rounding of numbers of order V tau_2 ((S5)).
  const PronyCreep<double> glassy(1.0, 0.5, {{2.0, 0.3}, {5.0, 3e4}});
  for (double speed : {1.0, 10.0}) check_against_collocation(glassy, speed, 96);
}

TEST_CASE("plane spectrum: agrees with the independent collocation, twenty terms",
          "[plane][spectrum][reference][slow]") {
  // 20 terms over four decades (adjacent times a factor 1.6 apart), weights 0.5 ... 1.5.
  std::vector<PronyTerm<double>> terms;
  for (int k = 0; k < 20; ++k)
    terms.push_back({1.0 + 0.5 * std::sin(k), std::pow(10.0, -2 + 4.0 * k / 19)});
  const PronyCreep<double> m(1.0, 0.5, terms);
  for (double speed : {0.3, 3.0}) check_against_collocation(m, speed, 200);
}

}  // namespace test_plane_spectrum
