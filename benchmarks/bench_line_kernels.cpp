// The kernels kappa and psi of the leading-edge condition (L2) (docs/line-kernels.md), one call at
// z = 1e-3 (ascending series), 1 and 10 (trapezoidal rule) and 100 (asymptotic series).
#include <benchmark/benchmark.h>

#include <viscoroll/special/line_kernels.hpp>

namespace {

constexpr long double line_kernel_arguments[] = {1e-3L, 1.0L, 10.0L, 100.0L};

template <class Real>
void BM_line_kernel_kappa(benchmark::State& state) {
  Real z = static_cast<Real>(line_kernel_arguments[state.range(0)]);
  benchmark::DoNotOptimize(viscoroll::special::line_kernel_kappa(z));  // builds the rule once
  for (auto _ : state) {
    benchmark::DoNotOptimize(z);
    benchmark::DoNotOptimize(viscoroll::special::line_kernel_kappa(z));
  }
}

template <class Real>
void BM_line_kernel_psi(benchmark::State& state) {
  Real z = static_cast<Real>(line_kernel_arguments[state.range(0)]);
  benchmark::DoNotOptimize(viscoroll::special::line_kernel_psi(z));
  for (auto _ : state) {
    benchmark::DoNotOptimize(z);
    benchmark::DoNotOptimize(viscoroll::special::line_kernel_psi(z));
  }
}

}  // namespace

// Argument i is the index into line_kernel_arguments: z = 1e-3, 1, 10, 100.
BENCHMARK_TEMPLATE(BM_line_kernel_kappa, float)->DenseRange(0, 3);
BENCHMARK_TEMPLATE(BM_line_kernel_kappa, double)->DenseRange(0, 3);
BENCHMARK_TEMPLATE(BM_line_kernel_kappa, long double)->DenseRange(0, 3);
BENCHMARK_TEMPLATE(BM_line_kernel_psi, float)->DenseRange(0, 3);
BENCHMARK_TEMPLATE(BM_line_kernel_psi, double)->DenseRange(0, 3);
BENCHMARK_TEMPLATE(BM_line_kernel_psi, long double)->DenseRange(0, 3);
