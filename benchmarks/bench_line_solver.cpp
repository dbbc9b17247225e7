// The line solver as a whole on the paper's scene (f = 9, nu = 0.5, a 5:1 static contact:
// C2/C1 = (ln 20 - 1)/25, the load of a long-term static a0 = 1, l0 = 5), in double, one thread:
//   BM_line_solve/N/s:  one cold solve (no seed: continuation in N from the plane seed,
//                       docs/line-solver.md) at V tau/a0 = s/1000, with `terms` = N;
//   BM_line_solve_difference_jacobian/N/s:  the same with the forward-difference Jacobian
//                       (LineJacobian::difference), the solver before the semi-analytic one;
//   BM_line_solve_tolerance/N/s/k: a cold solve as BM_line_solve with
//                       LineOptions::quadrature_tolerance = 10^-k (k = 0: the default, eps);
//   BM_line_solve_fast/s: a cold solve with LineOptions::fast() (docs/performance.md, "The fast
//                       setting") at V tau/a0 = s/1000;
//   BM_line_solve_fast_6/s: the same on 6-point Gauss-Legendre panels (FastLineSolverD);
//   BM_line_solve_fast_full_stages/s: the same with every continuation stage iterated to a root
//                       from the damping 1e-3 (fast() with stage_tolerance 0, stage_damping
//                       1e-3), for the ratio in one run;
//   BM_line_crowned_roller/N/s/k: a cold solve of the crowned roller of docs/validation.md
//                       ("Rolling rollers of any profile": C1 = 1, flat part 10, crown radius 20,
//                       f = 2, (1 + f) c P = 0.3, long-term static a0 = 0.2878) at V tau/a0 =
//                       s/1000 with `terms` = N and quadrature_tolerance = 10^-k (k = 0: eps);
//                       counters d and chi, to compare the settings' answers;
//   BM_line_tilted_roller/N/s/k: the same roller misaligned by theta = 0.003 (the asymmetric
//                       contact, docs/theory.md section 16; validation.md "Tilted rollers");
//   BM_line_sweep/N:    the figures' sweep (examples/panek_kalker): 101 speeds V tau/a0 = 10^-3 ...
//                       10^3, evenly spaced in log, each seeded with the last converged solution.
// Counters: iterations, converged (1/0) and, for the sweep, the speeds that did not converge (the
// line equations have no root near the branch at V tau/a0 ~ 1.7e-3 ... 5e-3, N = 4:
// docs/line-solver.md); each is reported, and its time counts.
#include <benchmark/benchmark.h>

#include <cmath>
#include <viscoroll/viscoroll.hpp>

namespace {

const viscoroll::StandardLinearSolid<double> kRubber(1, 0.5, 9, 1);  // tau = 1: speed = V tau

viscoroll::LineScene<double> paper_scene(double vtau) {
  const double load = 5.0 / (3 * (1 + 9) * kRubber.instantaneous_compliance());  // a0 = 1
  return {.c1 = 1.0, .c2 = (std::log(20.0) - 1) / 25, .load = load, .speed = vtau};
}

template <class Solver = viscoroll::LineSolverD>
void solve_with(benchmark::State& state, const viscoroll::LineOptions& options, double vtau) {
  const Solver solver(kRubber, options);
  typename Solver::Solution s;
  for (auto _ : state) {
    s = solver.solve(paper_scene(vtau));
    benchmark::DoNotOptimize(s);  // the whole solution: a double alone may go through a register
  }
  state.counters["vtau"] = vtau;
  state.counters["iterations"] = s.iterations;
  state.counters["converged"] = s.converged ? 1 : 0;
}

void solve_once(benchmark::State& state, viscoroll::LineJacobian jacobian) {
  viscoroll::LineOptions options;
  options.terms = static_cast<int>(state.range(0));
  options.jacobian = jacobian;
  solve_with(state, options, static_cast<double>(state.range(1)) / 1000);
}

void BM_line_solve(benchmark::State& state) {
  solve_once(state, viscoroll::LineJacobian::analytic);
}

void BM_line_solve_difference_jacobian(benchmark::State& state) {
  solve_once(state, viscoroll::LineJacobian::difference);
}

void BM_line_solve_tolerance(benchmark::State& state) {
  viscoroll::LineOptions options;
  options.terms = static_cast<int>(state.range(0));
  options.quadrature_tolerance = state.range(2) == 0 ? 0.0 : std::pow(10.0, -state.range(2));
  solve_with(state, options, static_cast<double>(state.range(1)) / 1000);
}

void BM_line_solve_fast(benchmark::State& state) {
  solve_with(state, viscoroll::LineOptions::fast(), static_cast<double>(state.range(0)) / 1000);
}

void BM_line_solve_fast_6(benchmark::State& state) {
  solve_with<viscoroll::FastLineSolverD>(state, viscoroll::LineOptions::fast(),
                                         static_cast<double>(state.range(0)) / 1000);
}

void BM_line_solve_fast_full_stages(benchmark::State& state) {
  viscoroll::LineOptions options = viscoroll::LineOptions::fast();
  options.stage_tolerance = 0;
  options.stage_damping = 1e-3;
  solve_with(state, options, static_cast<double>(state.range(0)) / 1000);
}

/// The crowned roller of BM_line_crowned_roller misaligned by `tilt` (0: the symmetric contact).
void crowned_roller(benchmark::State& state, double tilt) {
  const viscoroll::StandardLinearSolid<double> rubber(1, 0.5, 2, 1);
  viscoroll::LineOptions options;
  options.terms = static_cast<int>(state.range(0));
  options.quadrature_tolerance = state.range(2) == 0 ? 0.0 : std::pow(10.0, -state.range(2));
  const viscoroll::LineSolverD solver(rubber, options);
  using Roller = viscoroll::Tilted<viscoroll::CrownedCylinder<double>>;
  const viscoroll::LineProfileScene<Roller> scene{
      Roller(viscoroll::CrownedCylinder<double>(1.0, 10.0, 20.0), tilt),
      0.3 / (3 * rubber.instantaneous_compliance()),
      0.2878 * static_cast<double>(state.range(1)) / 1000};
  viscoroll::LineSolverD::Solution s;
  for (auto _ : state) {
    s = solver.solve(scene);
    benchmark::DoNotOptimize(s);
  }
  state.counters["iterations"] = s.iterations;
  state.counters["converged"] = s.converged ? 1 : 0;
  state.counters["d"] = s.d;
  state.counters["chi"] = s.chi;
}

void BM_line_crowned_roller(benchmark::State& state) { crowned_roller(state, 0.0); }
void BM_line_tilted_roller(benchmark::State& state) { crowned_roller(state, 0.003); }

void BM_line_sweep(benchmark::State& state) {
  viscoroll::LineOptions options;
  options.terms = static_cast<int>(state.range(0));
  const viscoroll::LineSolverD solver(kRubber, options);
  const int speeds = 101;
  int failures = 0;
  for (auto _ : state) {
    failures = 0;
    viscoroll::LineSolverD::Solution last;
    bool have = false;
    for (int i = 0; i < speeds; ++i) {
      const double vtau = std::pow(10.0, -3 + 6.0 * i / (speeds - 1));
      auto s = solver.solve(paper_scene(vtau), have ? &last : nullptr);
      if (s.converged) {
        last = std::move(s);
        have = true;
      } else {
        ++failures;
      }
    }
    benchmark::DoNotOptimize(last);
  }
  state.counters["speeds"] = speeds;
  state.counters["not_converged"] = failures;
}

}  // namespace

BENCHMARK(BM_line_solve)
    ->Args({2, 1000})
    ->Args({3, 1000})
    ->Args({6, 1000})
    ->Args({4, 100})
    ->Args({4, 1000})
    ->Args({4, 10000})
    ->Args({8, 1000})
    ->Args({16, 1000})
    ->Args({32, 1000})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_line_solve_difference_jacobian)
    ->Args({4, 100})
    ->Args({4, 1000})
    ->Args({4, 10000})
    ->Args({8, 1000})
    ->Args({16, 1000})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_line_solve_tolerance)
    ->Args({3, 1000, 0})
    ->Args({3, 1000, 8})
    ->Args({3, 1000, 4})
    ->Args({6, 1000, 0})
    ->Args({6, 1000, 8})
    ->Args({5, 1000, 0})
    ->Args({5, 1000, 4})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_line_solve_fast)->Arg(10)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_line_solve_fast_6)->Arg(10)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_line_solve_fast_full_stages)
    ->Arg(10)
    ->Arg(1000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_line_crowned_roller)
    ->ArgsProduct({{5, 8}, {100, 1000, 10000}, {0, 4}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_line_tilted_roller)
    ->ArgsProduct({{5, 8}, {100, 1000, 10000}, {0, 4}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_line_sweep)->Arg(2)->Arg(3)->Arg(4)->Unit(benchmark::kMillisecond)->Iterations(3);
