// The line solver for a spectrum with a seed (docs/line-solver.md, "Materials with a spectrum"):
// the cold start first, the seed only where the cold start stops short, so that a neighbouring
// speed's solution never decides the answer where the cold start converges. The 12-term
// rubber of examples/scenes/rubber_prony_bem.json at 0 degC, 0.01 m/s, seeded from 0.001 m/s as
// viscoroll-solve's sweep does, stopped at l/a(0) = 0.69 (the cold start's root has l/a(0) = 16),
// and on the two-term material of support/spectrum_scene.hpp the seed from V = 1 reached a root
// at V = 10 with l/a(0) = 0.67 and b(0) < 0.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/material/temperature_shift.hpp>

#include "support/spectrum_scene.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_spectrum_seed {

namespace {

using viscoroll::testing::spectrum_scene;
using viscoroll::testing::two_term_creep;

/// The same solution bit for bit: the cold start's, whatever the seed.
template <class Solution>
void check_same(const Solution& s, const Solution& cold) {
  CHECK(s.converged == cold.converged);
  CHECK(s.root == cold.root);
  CHECK(s.iterations == cold.iterations);
  CHECK(s.a(0.0) == cold.a(0.0));
  CHECK(s.b(0.0) == cold.b(0.0));
  CHECK(s.l() == cold.l());
  CHECK(s.d == cold.d);
  CHECK(s.chi == cold.chi);
}

/// The material of examples/scenes/rubber_prony_bem.json: G_inf = 2.5 MPa, 12 relaxation terms
/// one per decade 1e-7 ... 1e4 s at 25 degC, nu = 0.5, WLF (8.86, 101.6 K, 25 degC).
viscoroll::PronyRelaxation<double> rubber(double temperature) {
  const double g[] = {3e8,    1.06e8, 3.78e7, 1.34e7, 4.75e6, 1.69e6,
                      5.99e5, 2.12e5, 7.54e4, 2.67e4, 9490,   3370};
  std::vector<viscoroll::RelaxationTerm<double>> terms;
  double rho = 1e-7;
  for (const double gk : g) {
    terms.push_back({gk, rho});
    rho *= 10;
  }
  return viscoroll::at_temperature(viscoroll::PronyRelaxation<double>(2.5e6, 0.5, terms),
                                   viscoroll::WlfShift<double>(8.86, 101.6, 25.0), temperature);
}

}  // namespace

TEST_CASE("line spectrum: a seed from a neighbouring speed gives the cold start's root",
          "[line][spectrum]") {
  using Solver = viscoroll::LineSolver<double, viscoroll::PronyCreep<double>>;
  const Solver solver(two_term_creep(), viscoroll::LineOptions{.terms = 4});
  const auto near = solver.solve(spectrum_scene(1.0));
  REQUIRE(near.root);
  const auto cold = solver.solve(spectrum_scene(10.0));
  REQUIRE(cold.root);
  CHECK(cold.l() > 3 * cold.a(0.0));
  check_same(solver.solve(spectrum_scene(10.0), &near), cold);
}

TEST_CASE("line spectrum: the 12-term rubber at 0 degC, 0.01 m/s, seeded from 0.001 m/s",
          "[line][spectrum]") {
  using Solver = viscoroll::LineSolver<double, viscoroll::PronyRelaxation<double>>;
  const Solver solver(rubber(0.0), viscoroll::LineOptions{.terms = 6});
  const viscoroll::LineScene<double> slow{.c1 = 20.0, .c2 = 0.5, .load = 100.0, .speed = 0.001};
  auto scene = slow;
  scene.speed = 0.01;
  const auto seed = solver.solve(slow);
  REQUIRE(seed.root);
  const auto cold = solver.solve(scene);
  CAPTURE(cold.reason, cold.residual);
  REQUIRE(cold.converged);
  CHECK(cold.root);
  // Three of its terms' share of the dissipation is within the line method's budget (S21): they
  // are folded into the compliance or dropped, the other nine solved for.
  CHECK(cold.active_terms == 9);
  CHECK(cold.spectrum_error <= viscoroll::line::line_spectrum_budget<double>());
  // Inside the line theory's domain and its bounds (docs/theory.md section 13).
  CHECK(cold.l() > 3 * cold.a(0.0));
  CHECK(cold.a(0.0) <= cold.a_long_term);
  CHECK(cold.l() <= cold.l_long_term);
  CHECK(cold.b(0.0) >= 0);
  check_same(solver.solve(scene, &seed), cold);
}

TEST_CASE("line spectrum: where the cold start stops short the seed is tried, and said",
          "[line][spectrum]") {
  using Solver = viscoroll::LineSolver<double, viscoroll::PronyCreep<double>>;
  // Two terms, one stage: the seed is the root of the same scene, from which Levenberg-Marquardt
  // needs no more than the two iterations allowed; the cold start needs more.
  const Solver full(two_term_creep(), viscoroll::LineOptions{.terms = 2});
  const viscoroll::LineOptions short_options{
      .terms = 2, .max_iterations = 2, .least_squares = false};
  const Solver short_of_it(two_term_creep(), short_options);
  const auto root = full.solve(spectrum_scene(1.0));
  REQUIRE(root.root);
  const auto cold = short_of_it.solve(spectrum_scene(1.0));
  REQUIRE_FALSE(cold.converged);
  const auto seeded = short_of_it.solve(spectrum_scene(1.0), &root);
  CAPTURE(seeded.reason, seeded.warnings);
  CHECK(seeded.root);
  CHECK(viscoroll::has_warning(seeded, viscoroll::WarningCode::solved_from_seed));
  CHECK(seeded.iterations > cold.iterations);
  // The root to the iteration's step tolerance eps^0.6 (docs/line-solver.md, "Jacobian").
  const double step = std::pow(std::numeric_limits<double>::epsilon(), 0.6);
  CHECK(std::abs(seeded.a(0.0) - root.a(0.0)) <= step * root.a_long_term);
  CHECK(std::abs(seeded.l() - root.l()) <= step * root.l_long_term);
  // A seed from which two iterations do not reach the root either (V = 1000 for V = 1) leaves
  // the cold start's failure, said, never a plausible number.
  const auto far = full.solve(spectrum_scene(1000.0));
  REQUIRE(far.root);
  const auto both = short_of_it.solve(spectrum_scene(1.0), &far);
  CAPTURE(both.reason, both.warnings);
  CHECK_FALSE(both.converged);
  CHECK(both.code == viscoroll::StopCode::iteration_limit);
  CHECK(viscoroll::has_warning(both, viscoroll::WarningCode::seed_failed));
  CHECK(both.code == cold.code);
  CHECK(both.reason == cold.reason);
  CHECK(both.a(0.0) == cold.a(0.0));
  CHECK(both.l() == cold.l());
  CHECK(both.iterations > cold.iterations);
  // Every solution's warnings and their codes, index for index (core/outcome.hpp).
  for (const auto* s : {&root, &cold, &seeded, &far, &both})
    CHECK(s->warning_codes.size() == s->warnings.size());
}

}  // namespace test_line_spectrum_seed
