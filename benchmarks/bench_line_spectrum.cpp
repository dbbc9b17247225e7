// The line solver for a spectrum (docs/theory.md section 14) on the paper's proportions
// (C2/C1 = (ln 20 - 1)/25, C1 = 1, load 1), in double, one thread, one cold solve:
//   BM_line_spectrum/M/N/s/k/g: M terms (M = 2: (f, tau) = (3, 0.05), (6, 5); M = 20: f = 0.45,
//                             tau = 10^-3 ... 10^3 evenly in log) at speed s/10, N Chebyshev
//                             terms, integrals to 10^-k (0: to rounding); g = 1: the stage
//                             settings of LineOptions::fast() (intermediate stages to 1e-2, later
//                             ones from the damping 1e-9), g = 0: every stage to a root.
// Counters: active terms, iterations, converged (1/0), and for k > 0 or g = 1 the change from the
// solve with the integrals to rounding and every stage to a root.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony.hpp>

namespace {

viscoroll::PronyCreep<double> material(int m) {
  if (m == 2) return viscoroll::PronyCreep<double>(1.0, 0.5, {{3.0, 0.05}, {6.0, 5.0}});
  std::vector<viscoroll::PronyTerm<double>> terms;
  for (int k = 0; k < m; ++k) terms.push_back({9.0 / m, std::pow(10.0, -3 + 6.0 * k / (m - 1))});
  return viscoroll::PronyCreep<double>(1.0, 0.5, terms);
}

void BM_line_spectrum(benchmark::State& state) {
  viscoroll::LineOptions options{.terms = static_cast<int>(state.range(1))};
  // The fourth argument k: integrals to 10^-k (LineOptions::quadrature_tolerance; 0: eps).
  if (state.range(3) > 0) options.quadrature_tolerance = std::pow(10.0, -double(state.range(3)));
  if (state.range(4) == 1) {
    options.stage_tolerance = 1e-2;
    options.stage_damping = 1e-9;
  }
  const viscoroll::LineSolver<double, viscoroll::PronyCreep<double>> solver(
      material(static_cast<int>(state.range(0))), options);
  const double speed = static_cast<double>(state.range(2)) / 10;
  viscoroll::LineSolution<double, viscoroll::GaussLegendre<double, 12>> s;
  for (auto _ : state) {
    s = solver.solve({.c1 = 1.0, .c2 = (std::log(20.0) - 1) / 25, .load = 1.0, .speed = speed});
    benchmark::DoNotOptimize(s);  // the whole solution: a double alone may go through a register
  }
  state.counters["active"] = s.active_terms;
  state.counters["iterations"] = s.iterations;
  state.counters["converged"] = s.converged ? 1 : 0;
  if (state.range(3) > 0 || state.range(4) == 1) {
    // change: the largest relative difference of a(0), b(0), l, d and chi from the same solve
    // with the integrals to rounding and every stage to a root (not timed).
    options.quadrature_tolerance = 0;
    options.stage_tolerance = 0;
    options.stage_damping = 1e-3;
    const auto exact =
        viscoroll::LineSolver<double, viscoroll::PronyCreep<double>>(
            material(static_cast<int>(state.range(0))), options)
            .solve({.c1 = 1.0, .c2 = (std::log(20.0) - 1) / 25, .load = 1.0, .speed = speed});
    const double got[] = {s.a(0), s.b(0), s.l(), s.d, s.chi};
    const double want[] = {exact.a(0), exact.b(0), exact.l(), exact.d, exact.chi};
    double change = 0;
    for (int i = 0; i < 5; ++i)
      change = std::max(change, std::abs(got[i] - want[i]) / std::abs(want[i]));
    state.counters["change"] = benchmark::Counter(change);
  }
}

}  // namespace

BENCHMARK(BM_line_spectrum)
    ->Args({2, 4, 50, 0, 0})
    ->Args({20, 4, 1, 0, 0})
    ->Args({20, 4, 10, 0, 0})
    ->Args({20, 4, 1000, 0, 0})
    ->Args({20, 4, 1, 8, 0})
    ->Args({20, 4, 10, 8, 0})
    ->Args({20, 4, 1000, 8, 0})
    ->Args({20, 4, 1, 4, 0})
    ->Args({20, 4, 10, 4, 0})
    ->Args({20, 4, 1000, 4, 0})
    ->Args({20, 4, 1, 0, 1})
    ->Args({20, 4, 10, 0, 1})
    ->Args({20, 4, 1000, 0, 1})
    ->Args({20, 4, 1, 8, 1})
    ->Args({20, 4, 10, 8, 1})
    ->Args({20, 4, 1000, 8, 1})
    ->Unit(benchmark::kMillisecond);
