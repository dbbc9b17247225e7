// The pressure reconstruction of Eq. (35) (StripPressure::pressure, GaussLegendre<Real, 24>
// panels): c p(x) = (1/V tau) int_x^{b+a} p*(x') exp(-(1+f)(x' - x)/V tau) dx' with the
// pseudo-pressure (32), on the plane solution's strip (f = 9, a0 = 1) at V tau / a0 = 0 (static:
// p = p*/(c (1+f)), Eq. (7) with V tau = 0, no quadrature or exponential), 0.01 (the leading-edge
// layer of width V tau/(1+f)), 1 and 100. Points: xi = x - b at -0.9 a (near the trailing edge),
// 0 (centre) and +0.9 a (near the leading edge); each regime and point selects one of the three
// forms of docs/theory.md section 2 (from the leading edge, interior, from the trailing edge).
// Label: V tau / a0 and the point; counter alpha = (1 + f) a / V tau (Eq. 37).
#include <benchmark/benchmark.h>

#include <string>
#include <viscoroll/plane/plane_solver.hpp>

namespace {

constexpr double strip_vtau[] = {0.0, 0.01, 1.0, 100.0};
constexpr double strip_point[] = {-0.9, 0.0, 0.9};

template <class Real>
void BM_strip_pressure(benchmark::State& state) {
  const double vtau = strip_vtau[state.range(0)];
  const double point = strip_point[state.range(1)];
  const Real f = 9;
  const viscoroll::StandardLinearSolid<Real> material(Real(1), Real(0.5), f, Real(vtau));
  const Real c = material.instantaneous_compliance();
  const auto s = viscoroll::PlaneSolver<Real, viscoroll::StandardLinearSolid<Real>>(material).solve(
      {Real(1), 1 / (4 * c * (1 + f)), Real(1)});
  Real x = s.b + Real(point) * s.a;
  for (auto _ : state) {
    benchmark::DoNotOptimize(&x);
    Real p = s.pressure(x);
    benchmark::DoNotOptimize(&p);
    benchmark::ClobberMemory();
  }
  state.SetLabel("V tau/a0 = " + std::to_string(vtau).substr(0, 4) +
                 ", xi/a = " + std::to_string(point).substr(0, 4));
  state.counters["alpha"] = vtau > 0 ? static_cast<double>((1 + f) * s.a / Real(vtau)) : 0.0;
}

}  // namespace

// Arguments: V tau index (0, 0.01, 1, 100) and point index (xi/a = -0.9, 0, 0.9).
BENCHMARK_TEMPLATE(BM_strip_pressure, float)->ArgsProduct({{0, 1, 2, 3}, {0, 1, 2}});
BENCHMARK_TEMPLATE(BM_strip_pressure, double)->ArgsProduct({{0, 1, 2, 3}, {0, 1, 2}});
BENCHMARK_TEMPLATE(BM_strip_pressure, long double)->ArgsProduct({{0, 1, 2, 3}, {0, 1, 2}});
