// Benchmarks of viscoroll/special: the Bessel ratios and scaled functions and H_0 - Y_0, each at
// arguments that reach every method (series or Boost, Gauss-Legendre, asymptotic series) for
// float, double and long double. The argument is given in thousandths: Arg(500) is x = 0.5.
//
// Which method serves which argument (docs/special-functions.md):
//   Bessel, x_T = 10 / 21 / 24 (float / double / long double): x = 0.5, 5, 15 below x_T for double,
//   x = 30, 100 above it for every type (15 is above x_T for float only).
//   H_0 - Y_0: x = 0.5 series; 5, 15 Gauss-Legendre; 30 Gauss-Legendre except float (x_S = 18);
//   100 asymptotic.
#include <benchmark/benchmark.h>

#include <viscoroll/special/bessel_ratio.hpp>
#include <viscoroll/special/struve_neumann.hpp>

namespace {

#define VISCOROLL_SPECIAL_FUNCTOR(Name, function) \
  struct Name {                                   \
    template <class Real>                         \
    static Real eval(Real x) {                    \
      return viscoroll::special::function(x);     \
    }                                             \
  };

VISCOROLL_SPECIAL_FUNCTOR(I1OverI0, bessel_i1_over_i0)
VISCOROLL_SPECIAL_FUNCTOR(I2OverI0, bessel_i2_over_i0)
VISCOROLL_SPECIAL_FUNCTOR(K1OverK0, bessel_k1_over_k0)
VISCOROLL_SPECIAL_FUNCTOR(I0Scaled, bessel_i0_scaled)
VISCOROLL_SPECIAL_FUNCTOR(I1Scaled, bessel_i1_scaled)
VISCOROLL_SPECIAL_FUNCTOR(K0Scaled, bessel_k0_scaled)
VISCOROLL_SPECIAL_FUNCTOR(K1Scaled, bessel_k1_scaled)
VISCOROLL_SPECIAL_FUNCTOR(StruveH0MinusY0, struve_h0_minus_y0)

#undef VISCOROLL_SPECIAL_FUNCTOR

template <class Real, class Function>
void BM_special(benchmark::State& state) {
  Real x = static_cast<Real>(state.range(0)) / 1000;
  // Function-local tables (Gauss-Legendre nodes, thresholds) are built outside the timed loop.
  benchmark::DoNotOptimize(Function::eval(x));
  for (auto _ : state) {
    benchmark::DoNotOptimize(x);
    Real value = Function::eval(x);
    benchmark::DoNotOptimize(value);
  }
}

#define VISCOROLL_BENCH_SPECIAL(Function)               \
  BENCHMARK_TEMPLATE(BM_special, float, Function)       \
      ->Arg(500)                                        \
      ->Arg(5000)                                       \
      ->Arg(15000)                                      \
      ->Arg(30000)                                      \
      ->Arg(100000);                                    \
  BENCHMARK_TEMPLATE(BM_special, double, Function)      \
      ->Arg(500)                                        \
      ->Arg(5000)                                       \
      ->Arg(15000)                                      \
      ->Arg(30000)                                      \
      ->Arg(100000);                                    \
  BENCHMARK_TEMPLATE(BM_special, long double, Function) \
      ->Arg(500)                                        \
      ->Arg(5000)                                       \
      ->Arg(15000)                                      \
      ->Arg(30000)                                      \
      ->Arg(100000);

VISCOROLL_BENCH_SPECIAL(I1OverI0)
VISCOROLL_BENCH_SPECIAL(I2OverI0)
VISCOROLL_BENCH_SPECIAL(K1OverK0)
VISCOROLL_BENCH_SPECIAL(I0Scaled)
VISCOROLL_BENCH_SPECIAL(I1Scaled)
VISCOROLL_BENCH_SPECIAL(K0Scaled)
VISCOROLL_BENCH_SPECIAL(K1Scaled)
VISCOROLL_BENCH_SPECIAL(StruveH0MinusY0)

#undef VISCOROLL_BENCH_SPECIAL

}  // namespace
