// The bounds of the rolling contact of a standard linear solid (docs/theory.md, "Bounds of the
// rolling contact"): G(y) >= 0 where 0 <= b(y) <= V tau f/(1 + f), then (B1) int a^2 dy <= that of
// the long-term static contact; (B2) a(0) <= a0, l <= l0 and (B3) b(0) >= 0, checked by the
// solver on every converged solution and warned when broken (line_bound_warnings); and the sweep
// of the paper's 100 log-spaced speeds: every speed converged or a certified least-squares minimum.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <string>
#include <vector>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/sweep.hpp>

#include "support/paper_scene.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_bounds {

namespace {

using viscoroll::has_warning;
using viscoroll::WarningCode;

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
  for (const auto& w : warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

/// How many of a solution's warnings carry `code`.
template <class Solution>
std::ptrdiff_t warnings_with(const Solution& s, WarningCode code) {
  return std::count(s.warning_codes.begin(), s.warning_codes.end(), code);
}

/// int_{-l}^{l} a(y)^2 dy by the midpoint rule in theta, y = l sin(theta) (a^2 ~ cos^2 theta
/// times a smooth function: the rule converges spectrally).
template <class Solution>
double mean_square_width(const Solution& s, int n = 400) {
  const double pi = std::acos(-1.0);
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    const double theta = -pi / 2 + pi * (k + 0.5) / n, y = s.l() * std::sin(theta);
    const double a = s.a(y);
    sum += a * a * s.l() * std::cos(theta);
  }
  return sum * pi / n;
}

}  // namespace

TEST_CASE("line bounds: the paper's scene keeps G >= 0, (B1), (B2) and (B3) at every speed",
          "[line][bounds]") {
  // V tau/a0 from 0.2 (above the slow regime, where N = 6 resolves the solution) to 1e3, N = 6:
  // no bound warning, and each bound with its margin.
  const viscoroll::testing::PaperScene paper;
  const viscoroll::LineSolverD solver = paper.solver(6);
  const double f = 9;
  for (double v : {0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 50.0, 200.0, 1000.0}) {
    INFO("V tau/a0 = " << v);
    const auto s = solver.solve(paper.scene(v));
    REQUIRE(s.converged);
    CHECK_FALSE(has_warning(s, WarningCode::rolling_bound));
    CHECK(s.a(0.0) <= s.a_long_term);
    CHECK(s.l() <= s.l_long_term);
    CHECK(s.b(0.0) >= 0);
    for (int k = 0; k < 64; ++k) {
      const double y = s.l() * k / 64.0;
      CHECK(s.b(y) <= v * f / (1 + f));  // G(y) >= 0, Eq. (36)
      CHECK(s.g(y) >= 0);
    }
    // (B1): int a^2 dy <= int a_static^2 dy = (4/3) a0^2 l0.
    const double bound = 4.0 / 3 * s.a_long_term * s.a_long_term * s.l_long_term;
    CHECK(mean_square_width(s) <= bound);
  }
}

TEST_CASE("line bounds: a solution that breaks a bound is warned (--grid 12)", "[line][bounds]") {
  // At N = 12 the root has l/l0 = 1.0037 and a(0)/a0 = 1.0002 (its
  // discretisation error, V tau = 1.8e-3 a0, exceeds the distance to the bound); N = 6 stays
  // within them (a least-squares minimum, l/l0 = 0.99995).
  const viscoroll::StandardLinearSolid<double> material(0.8039135086325981, 0.30003219277831694,
                                                        2.785164659360882, 0.004466981994343957);
  const viscoroll::LineScene<double> scene{.c1 = 20.762562182128647,
                                           .c2 = 0.681408522179955,
                                           .load = 23.306722647201934,
                                           .speed = 0.23336242599102316};
  viscoroll::LineOptions options;
  options.terms = 12;
  const auto s12 = viscoroll::LineSolverD(material, options).solve(scene);
  REQUIRE(s12.converged);
  CHECK(s12.l() / s12.l_long_term > 1.003);
  // The warning prints the ratio that breaks the bound.
  CHECK(mentions(s12.warnings, "l/l0 = 1.0037"));
  // Two bounds broken, l <= l0 and a(0) <= a0: a warning each.
  CHECK(has_warning(s12, WarningCode::rolling_bound));
  CHECK(warnings_with(s12, WarningCode::rolling_bound) >= 2);
  options.terms = 6;
  const auto s6 = viscoroll::LineSolverD(material, options).solve(scene);
  REQUIRE(s6.converged);
  CHECK(s6.l() <= s6.l_long_term);
  CHECK_FALSE(has_warning(s6, WarningCode::rolling_bound));
}

TEST_CASE("line bounds: the sweep of the figures' 100 speeds converges at the default N",
          "[line][bounds]") {
  // The paper's scene over 100 log-spaced speeds 1e-3 ... 1e3 at N = 6 (the CLI's
  // default), swept as viscoroll-solve sweeps (chunks of 16, each speed seeded with its chunk's
  // last solution): every speed converged, a root or a certified least-squares minimum.
  const viscoroll::testing::PaperScene paper;
  const viscoroll::LineSolverD solver = paper.solver(6);
  std::vector<double> speeds;
  for (int i = 0; i < 100; ++i) speeds.push_back(std::pow(10.0, -3 + 6 * i / 99.0));
  viscoroll::SweepOptions sweep;
  sweep.threads = 1;
  const auto got = viscoroll::sweep(solver, paper.scene(0), speeds, sweep);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    INFO("V tau/a0 = " << speeds[i] << ": " << got[i].reason);
    CHECK(got[i].converged);
  }
}

TEST_CASE("line bounds: the paper's 100 log-spaced speeds converge at the default N",
          "[line][bounds][slow]") {
  // The paper's scene over log-spaced speeds 1e-4 ... 1e4 at N = 6: every speed converged (a
  // root or a certified least-squares minimum), never "iteration limit", "no descent step" or
  // "Jacobian undefined". 1,000 speeds (about 25 s of CPU); VISCOROLL_SWEEP_SPEEDS=10000 runs
  // the 10,000 of docs/line-solver.md (about 10 min of CPU).
  const viscoroll::testing::PaperScene paper;
  const viscoroll::LineSolverD solver = paper.solver(6);
  int count = 1000;
  if (const char* text = std::getenv("VISCOROLL_SWEEP_SPEEDS")) count = std::atoi(text);
  REQUIRE(count >= 2);
  std::vector<double> speeds;
  for (int i = 0; i < count; ++i) speeds.push_back(std::pow(10.0, -4 + 8.0 * i / (count - 1)));
  viscoroll::SweepOptions sweep;
  const auto got = viscoroll::sweep(solver, paper.scene(0), speeds, sweep);
  int failed = 0;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    INFO("V tau/a0 = " << speeds[i] << ": " << got[i].reason);
    CHECK(got[i].converged);
    if (!got[i].converged) ++failed;
  }
  CHECK(failed == 0);
}

}  // namespace test_line_bounds
