// viscoroll::sweep (viscoroll/sweep.hpp) on the paper's scene (f = 9, nu = 0.5, a 5:1 static
// contact, the load of a long-term static a0 = 1), double, the line solver at N = `terms`:
//   BM_sweep_line/N/chunk/threads: 100 speeds V tau/a0 = 10^-3 ... 10^3, evenly spaced in log, in
//   chunks of `chunk` speeds (each chunk from a cold start, then continuation) on `threads`
//   threads. Wall time (UseRealTime), so the thread count shows. Counter not_converged: speeds
//   that did not converge (their time counts).
//   BM_sweep_line_fast/chunk/threads: the same with LineOptions::fast() (docs/performance.md, "The
//   fast setting");
//   BM_sweep_line_fast_6/chunk/threads: the same on 6-point panels (FastLineSolverD); chunk 16 is
//   the library's default (SweepOptions), chunk 1 a cold solve at every speed.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/sweep.hpp>

namespace {

const viscoroll::StandardLinearSolid<double> kRubber(1, 0.5, 9, 1);  // tau = 1: speed = V tau

template <class Solver = viscoroll::LineSolverD>
void run_sweep(benchmark::State& state, const viscoroll::LineOptions& options, std::size_t chunk,
               unsigned threads) {
  const Solver solver(kRubber, options);
  const double load = 5.0 / (3 * (1 + 9) * kRubber.instantaneous_compliance());  // a0 = 1
  const viscoroll::LineScene<double> scene{
      .c1 = 1.0, .c2 = (std::log(20.0) - 1) / 25, .load = load, .speed = 0.0};
  std::vector<double> speeds;
  for (int i = 0; i < 100; ++i) speeds.push_back(std::pow(10.0, -3 + 6.0 * i / 99));
  viscoroll::SweepOptions sweep_options;
  sweep_options.chunk = chunk;
  sweep_options.threads = threads;
  int failures = 0;
  for (auto _ : state) {
    const auto results = viscoroll::sweep(solver, scene, speeds, sweep_options);
    failures = 0;
    for (const auto& s : results) failures += s.converged ? 0 : 1;
    benchmark::DoNotOptimize(results.back().d);
  }
  state.counters["not_converged"] = failures;
}

void BM_sweep_line(benchmark::State& state) {
  viscoroll::LineOptions options;
  options.terms = static_cast<int>(state.range(0));
  run_sweep(state, options, static_cast<std::size_t>(state.range(1)),
            static_cast<unsigned>(state.range(2)));
}

void BM_sweep_line_fast(benchmark::State& state) {
  run_sweep(state, viscoroll::LineOptions::fast(), static_cast<std::size_t>(state.range(0)),
            static_cast<unsigned>(state.range(1)));
}

void BM_sweep_line_fast_6(benchmark::State& state) {
  run_sweep<viscoroll::FastLineSolverD>(state, viscoroll::LineOptions::fast(),
                                        static_cast<std::size_t>(state.range(0)),
                                        static_cast<unsigned>(state.range(1)));
}

}  // namespace

BENCHMARK(BM_sweep_line)
    ->Args({3, 100, 1})
    ->Args({3, 25, 1})
    ->Args({3, 25, 2})
    ->Args({6, 100, 1})
    ->Args({6, 25, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
BENCHMARK(BM_sweep_line_fast)
    ->Args({100, 1})
    ->Args({50, 2})
    ->Args({25, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
BENCHMARK(BM_sweep_line_fast_6)
    ->Args({100, 1})
    ->Args({50, 2})
    ->Args({16, 2})
    ->Args({1, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
