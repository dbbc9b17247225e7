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

#include <string>
#include <viscoroll/special/bessel_ratio.hpp>
#include <viscoroll/special/struve_neumann.hpp>

namespace {

/// The method a Bessel function uses at x (bessel_ratio.hpp): Boost below x_T, Hankel's
/// expansion (DLMF 10.40.1-2) from x_T on; I2/I0 sums its power series below 4.
template <class Real>
std::string bessel_method(Real x, bool i2_series) {
  if (i2_series && x < viscoroll::detail::bessel_i2_series_limit<Real>()) return "power series";
  if (x < viscoroll::detail::bessel_asymptotic_threshold<Real>()) return "Boost";
  return "Hankel expansion";
}

/// The method H_0 - Y_0 uses at x (struve_neumann.hpp): series (DLMF 11.2.1, 10.8.2) for
/// x <= 1, Gauss-Legendre on the Laplace integral (DLMF 11.5.2) below x_S, asymptotic series
/// (DLMF 11.6.1) from x_S on.
template <class Real>
std::string struve_method(Real x) {
  if (x <= viscoroll::detail::struve_series_limit<Real>()) return "power series";
  if (x < viscoroll::detail::struve_asymptotic_threshold<Real>()) return "Gauss-Legendre";
  return "asymptotic series";
}

#define VISCOROLL_SPECIAL_FUNCTOR(Name, function, method) \
  struct Name {                                           \
    template <class Real>                                 \
    static Real eval(Real x) {                            \
      return viscoroll::special::function(x);             \
    }                                                     \
    template <class Real>                                 \
    static std::string method_at(Real x) {                \
      return method;                                      \
    }                                                     \
  };

VISCOROLL_SPECIAL_FUNCTOR(I1OverI0, bessel_i1_over_i0, bessel_method(x, false))
VISCOROLL_SPECIAL_FUNCTOR(I2OverI0, bessel_i2_over_i0, bessel_method(x, true))
VISCOROLL_SPECIAL_FUNCTOR(K1OverK0, bessel_k1_over_k0, bessel_method(x, false))
VISCOROLL_SPECIAL_FUNCTOR(I0Scaled, bessel_i0_scaled, bessel_method(x, false))
VISCOROLL_SPECIAL_FUNCTOR(I1Scaled, bessel_i1_scaled, bessel_method(x, false))
VISCOROLL_SPECIAL_FUNCTOR(K0Scaled, bessel_k0_scaled, bessel_method(x, false))
VISCOROLL_SPECIAL_FUNCTOR(K1Scaled, bessel_k1_scaled, bessel_method(x, false))
VISCOROLL_SPECIAL_FUNCTOR(StruveH0MinusY0, struve_h0_minus_y0, struve_method(x))

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
  state.SetLabel("x = " + std::to_string(static_cast<double>(x)).substr(0, 6) + ": " +
                 Function::method_at(x));
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
