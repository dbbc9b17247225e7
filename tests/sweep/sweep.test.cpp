// Tests of viscoroll/sweep.hpp: a sweep returns, in the order of the speeds, what the serial
// continuation it describes returns (each chunk from a cold start, each later speed seeded with
// the previous converged, iterated solution of its chunk), bit for bit and whatever the thread
// count; a solver without seeds (plane) is solved speed by speed; an invalid speed is rethrown
// with the library's message; the options validate themselves; a stop flag stops the threads
// before their next solve, and a flag never set changes nothing; a timed solver (TimedSolver)
// gives the plain sweep's solutions.
#include <atomic>
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/sweep.hpp>

#include "support/paper_scene.hpp"
#include "support/same_line_solution.hpp"
#include "support/serial_continuation.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_sweep {

namespace {

using viscoroll::testing::require_same_solution;
using viscoroll::testing::same_bits;

using viscoroll::SweepOptions;

std::vector<double> log_speeds(double lo, double hi, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(lo * std::pow(hi / lo, double(i) / (n - 1)));
  return v;
}

}  // namespace

TEST_CASE("sweep: the line solver's chunked continuation, bit for bit for any thread count",
          "[sweep]") {
  const viscoroll::testing::PaperScene paper;
  const viscoroll::LineSolverD solver = paper.solver(3);
  const std::vector<double> speeds = log_speeds(0.05, 20, 10);  // tau = 1: V tau/a0 = speed

  // The serial continuation the sweep promises: chunks of 4 (4, 4, 2 speeds).
  std::vector<viscoroll::LineScene<double>> scenes;
  for (const double v : speeds) scenes.push_back(paper.scene(v));
  const auto expected = viscoroll::testing::serial_continuation(solver, scenes, 4);

  for (unsigned threads : {1u, 2u, 3u}) {
    SweepOptions options;
    options.chunk = 4;
    options.threads = threads;
    std::size_t calls = 0, last_total = 0;
    options.progress = [&](std::size_t done, std::size_t total) {
      ++calls;
      REQUIRE(done == calls);  // one call at a time, counting up
      last_total = total;
    };
    const auto got = viscoroll::sweep(solver, paper.scene(0), speeds, options);
    REQUIRE(got.size() == speeds.size());
    REQUIRE(calls == speeds.size());
    REQUIRE(last_total == speeds.size());
    for (std::size_t i = 0; i < speeds.size(); ++i) {
      INFO("threads " << threads << ", speed " << speeds[i]);
      REQUIRE(got[i].converged);
      require_same_solution(got[i], expected[i]);
    }
  }
}

TEST_CASE("sweep: a timed solver gives the plain sweep's solutions, with seconds and attachment",
          "[sweep]") {
  // TimedSolver hands the solver the solution a timed seed holds, and usable_as_seed reads it:
  // the same continuation, bit for bit; attach sees each solution with its speed and seconds.
  const viscoroll::testing::PaperScene paper;
  const viscoroll::LineSolverD solver = paper.solver(3);
  const std::vector<double> speeds = log_speeds(0.05, 20, 10);
  SweepOptions options;
  options.chunk = 4;
  options.threads = 2;
  const auto plain = viscoroll::sweep(solver, paper.scene(0), speeds, options);
  const auto attach = [](const viscoroll::LineSolverD::Solution&, double speed, double seconds) {
    return std::pair{speed, seconds};
  };
  const viscoroll::TimedSolver<viscoroll::LineSolverD, decltype(attach)> timed{solver, attach};
  const auto got = viscoroll::sweep(timed, paper.scene(0), speeds, options);
  REQUIRE(got.size() == speeds.size());
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    INFO("speed " << speeds[i]);
    require_same_solution(got[i].solution, plain[i]);
    CHECK(viscoroll::usable_as_seed(got[i]) == viscoroll::usable_as_seed(plain[i]));
    CHECK(got[i].seconds > 0);
    CHECK(got[i].extra.first == speeds[i]);
    CHECK(got[i].extra.second == got[i].seconds);
  }
}

TEST_CASE("sweep: a solver without seeds is solved speed by speed", "[sweep]") {
  const viscoroll::PlaneSolverD solver(viscoroll::StandardLinearSolid<double>(1, 0.5, 9, 1));
  const viscoroll::PlaneScene<double> scene{1, 1, 0};
  const std::vector<double> speeds = log_speeds(0.01, 100, 7);
  SweepOptions options;
  options.chunk = 2;
  options.threads = 2;
  const auto got = viscoroll::sweep(solver, scene, speeds, options);
  REQUIRE(got.size() == speeds.size());
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const auto one = solver.solve({1, 1, speeds[i]});
    REQUIRE(same_bits(got[i].a, one.a));
    REQUIRE(same_bits(got[i].b, one.b));
    REQUIRE(same_bits(got[i].chi, one.chi));
  }
}

TEST_CASE("sweep: an invalid speed is rethrown with the library's message", "[sweep]") {
  const viscoroll::PlaneSolverD solver(viscoroll::StandardLinearSolid<double>(1, 0.5, 9, 1));
  const std::vector<double> speeds{1, 2, -3, 4, 5};
  SweepOptions options;
  options.chunk = 1;
  options.threads = 2;
  REQUIRE_THROWS_WITH(
      viscoroll::sweep(solver, viscoroll::PlaneScene<double>{1, 1, 0}, speeds, options),
      Catch::Contains("speed = -3"));
}

TEST_CASE("sweep: options name the setting and its range", "[sweep]") {
  SweepOptions options;
  options.chunk = 0;
  REQUIRE_THROWS_WITH(options.validate(),
                      Catch::Contains("chunk") && Catch::Contains("1 <= chunk"));
  options.chunk = 1;
  options.threads = 5000;
  REQUIRE_THROWS_WITH(options.validate(), Catch::Contains("threads"));
  options.threads = 0;
  REQUIRE(options.effective_threads(1) == 1);  // never more threads than chunks
  REQUIRE(options.effective_threads(0) == 1);
  const viscoroll::PlaneSolverD solver(viscoroll::StandardLinearSolid<double>(1, 0.5, 9, 1));
  REQUIRE(viscoroll::sweep(solver, viscoroll::PlaneScene<double>{1, 1, 0}, std::vector<double>{})
              .empty());
}

TEST_CASE("sweep: a stop flag stops every thread before its next solve", "[sweep]") {
  const viscoroll::PlaneSolverD solver(viscoroll::StandardLinearSolid<double>(1, 0.5, 9, 1));
  const viscoroll::PlaneScene<double> scene{1, 1, 0};
  const std::vector<double> speeds = log_speeds(0.01, 100, 200);
  for (unsigned threads : {1u, 2u, 3u}) {
    INFO("threads " << threads);
    std::atomic<bool> stop{false};
    SweepOptions options;
    options.chunk = 4;
    options.threads = threads;
    options.stop = &stop;
    // Never set: the results of a sweep without the flag, bit for bit.
    SweepOptions plain;
    plain.chunk = 4;
    plain.threads = threads;
    const auto free = viscoroll::sweep(solver, scene, speeds, plain);
    const auto flagged = viscoroll::sweep(solver, scene, speeds, options);
    REQUIRE(flagged.size() == speeds.size());
    for (std::size_t i = 0; i < speeds.size(); ++i) {
      REQUIRE(same_bits(flagged[i].a, free[i].a));
      REQUIRE(same_bits(flagged[i].chi, free[i].chi));
    }
    // Set after the 10th solve (from the progress callback, under the sweep's lock): each other
    // thread finishes at most the solve it is in.
    std::size_t solved = 0;
    options.progress = [&](std::size_t done, std::size_t) {
      solved = done;
      if (done == 10) stop = true;
    };
    REQUIRE_THROWS_AS(viscoroll::sweep(solver, scene, speeds, options), viscoroll::SweepStopped);
    REQUIRE(solved >= 10);
    REQUIRE(solved <= 10 + (threads - 1));
  }
}

}  // namespace test_sweep
