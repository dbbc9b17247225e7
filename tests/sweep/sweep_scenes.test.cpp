// Tests of viscoroll::sweep_scenes (a list of scenes whose loads, or any field, vary) and
// viscoroll::sweep_solvers (one scene over speeds with each of several solvers: a spectrum at
// several temperatures): each returns, in its order, what the serial continuation it describes
// returns, bit for bit and whatever the thread count; a row of sweep_solvers is the speed sweep of
// its solver; an invalid scene is rethrown with the library's message.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/material/temperature_shift.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/sweep.hpp>

#include "support/paper_scene.hpp"
#include "support/same_line_solution.hpp"
#include "support/serial_continuation.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_sweep_scenes {

using viscoroll::SweepOptions;
using viscoroll::testing::require_same_solution;
using viscoroll::testing::same_bits;

TEST_CASE("sweep scenes: loads in chunks of continuation, bit for bit for any thread count",
          "[sweep]") {
  const viscoroll::testing::PaperScene paper;
  const viscoroll::LineSolverD solver = paper.solver(3);
  std::vector<viscoroll::LineScene<double>> scenes;
  for (int i = 0; i < 7; ++i) {
    auto s = paper.scene(0.5);
    s.load *= std::pow(2.0, 0.5 * i);  // loads over a factor 8: a(0) over a factor 2
    scenes.push_back(s);
  }
  // The serial continuation: chunks of 3 (3, 3, 1 scenes).
  const auto expected = viscoroll::testing::serial_continuation(solver, scenes, 3);
  for (unsigned threads : {1u, 2u, 3u}) {
    SweepOptions options;
    options.chunk = 3;
    options.threads = threads;
    const auto got = viscoroll::sweep_scenes(solver, scenes, options);
    REQUIRE(got.size() == scenes.size());
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      INFO("threads " << threads << ", scene " << i);
      REQUIRE(got[i].converged);
      require_same_solution(got[i], expected[i]);
    }
  }
  // A heavier load presses a wider contact: d and a(0) grow along the list.
  for (std::size_t i = 1; i < scenes.size(); ++i) {
    CHECK(expected[i].d > expected[i - 1].d);
    CHECK(expected[i].a(0) > expected[i - 1].a(0));
  }
}

TEST_CASE("sweep scenes: an invalid scene is rethrown with the library's message", "[sweep]") {
  const viscoroll::PlaneSolverD solver(viscoroll::StandardLinearSolid<double>(1, 0.5, 9, 1));
  const std::vector<viscoroll::PlaneScene<double>> scenes{{1, 1, 1}, {1, -2, 1}, {1, 3, 1}};
  SweepOptions options;
  options.chunk = 1;
  options.threads = 2;
  REQUIRE_THROWS_WITH(viscoroll::sweep_scenes(solver, scenes, options),
                      Catch::Contains("load = -2"));
  REQUIRE(viscoroll::sweep_scenes(solver, std::vector<viscoroll::PlaneScene<double>>{}).empty());
}

TEST_CASE("sweep solvers: a spectrum at several temperatures, each row its speed sweep",
          "[sweep]") {
  // A two-term creep spectrum shifted by WLF (c1 = 8.86, c2 = 101.6, T_ref = 20 degC) to
  // 0, 20 and 60 degC: the plane solver (a spectrum in closed form) and the line solver at N = 3.
  const viscoroll::PronyCreep<double> rubber(1.0, 0.5, {{3.0, 0.05}, {6.0, 5.0}});
  const viscoroll::WlfShift<double> wlf(8.86, 101.6, 20.0);
  const std::vector<double> temperatures{0.0, 20.0, 60.0};
  const std::vector<double> speeds{0.01, 0.1, 1.0, 10.0};
  std::vector<viscoroll::PlaneSolver<double, viscoroll::PronyCreep<double>>> planes;
  std::vector<viscoroll::LineSolver<double, viscoroll::PronyCreep<double>>> lines;
  for (const double t : temperatures) {
    const auto m = viscoroll::at_temperature(rubber, wlf, t);
    planes.emplace_back(m);
    lines.emplace_back(m, viscoroll::LineOptions{.terms = 3});
  }
  SweepOptions options;
  options.chunk = 2;
  const viscoroll::PlaneScene<double> plane_scene{.c1 = 1.0, .load = 0.1, .speed = 0.0};
  const viscoroll::LineScene<double> line_scene{
      .c1 = 1.0, .c2 = (std::log(20.0) - 1) / 25, .load = 1.0, .speed = 0.0};
  for (unsigned threads : {1u, 2u}) {
    options.threads = threads;
    const auto plane = viscoroll::sweep_solvers(planes, plane_scene, speeds, options);
    const auto line = viscoroll::sweep_solvers(lines, line_scene, speeds, options);
    REQUIRE(plane.size() == temperatures.size() * speeds.size());
    REQUIRE(line.size() == plane.size());
    for (std::size_t k = 0; k < temperatures.size(); ++k) {
      const auto plane_row = viscoroll::sweep(planes[k], plane_scene, speeds, options);
      const auto line_row = viscoroll::sweep(lines[k], line_scene, speeds, options);
      for (std::size_t i = 0; i < speeds.size(); ++i) {
        INFO("threads " << threads << ", T = " << temperatures[k] << ", V = " << speeds[i]);
        const auto& p = plane[k * speeds.size() + i];
        const auto& q = line[k * speeds.size() + i];
        REQUIRE(p.converged);
        REQUIRE(q.converged);
        CHECK(same_bits(p.a, plane_row[i].a));
        CHECK(same_bits(p.chi, plane_row[i].chi));
        CHECK(same_bits(q.a(0), line_row[i].a(0)));
        CHECK(same_bits(q.d, line_row[i].d));
        CHECK(same_bits(q.chi, line_row[i].chi));
      }
    }
    // Time-temperature superposition: at T every time is a_T times its reference value, so the
    // plane contact at speed V and T is the reference one at V a_T; here V = 0.1 at 60 degC
    // against the reference solver at 0.1 a_T (the plane solution depends on V only through
    // V tau_k). Bound: rounding of the products V tau_k in both, 16 eps.
    const double a_t = wlf.factor(60.0);
    const auto reference = planes[1].solve({.c1 = 1.0, .load = 0.1, .speed = 0.1 * a_t});
    const auto& hot = plane[2 * speeds.size() + 1];
    CHECK(std::abs(hot.a / reference.a - 1) <= 16 * std::numeric_limits<double>::epsilon());
    CHECK(std::abs(hot.chi / reference.chi - 1) <= 16 * std::numeric_limits<double>::epsilon());
  }
  REQUIRE(viscoroll::sweep_solvers(planes, plane_scene, std::vector<double>{}).empty());
}

}  // namespace test_sweep_scenes
