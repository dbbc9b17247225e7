// One plane (Hunter) solution: a, b, G and chi (docs/theory.md (P5), (P7)); the pressure at a
// point (Eq. 35) and the peak search, separately (docs/performance.md, "1. Plane solver").
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/plane/plane_solver.hpp>

namespace {

template <class Real>
void BM_plane_solve(benchmark::State& state) {
  const Real vtau = Real(state.range(0)) / 100;  // V tau / a0 in hundredths
  const viscoroll::PlaneSolver<Real, viscoroll::StandardLinearSolid<Real>> solver(
      viscoroll::StandardLinearSolid<Real>(Real(1), Real(0.5), Real(9), vtau));
  const viscoroll::PlaneScene<Real> scene{.c1 = Real(1), .load = Real(1), .speed = Real(1)};
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve(scene).chi);
}

void BM_plane_solve_elastic(benchmark::State& state) {
  const viscoroll::PlaneSolver<double, viscoroll::Elastic<double>> solver(
      viscoroll::Elastic<double>(1.0, 0.5));
  const viscoroll::PlaneScene<double> scene{.c1 = 1.0, .load = 1.0, .speed = 1.0};
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve(scene).a);
}

template <class Real>
void BM_plane_pressure_point(benchmark::State& state) {
  const Real vtau = Real(state.range(0)) / 100;
  const auto s = viscoroll::PlaneSolver<Real, viscoroll::StandardLinearSolid<Real>>(
                     viscoroll::StandardLinearSolid<Real>(Real(1), Real(0.5), Real(9), vtau))
                     .solve({.c1 = Real(1), .load = Real(1), .speed = Real(1)});
  for (auto _ : state) benchmark::DoNotOptimize(s.pressure(s.b + s.a / 3));
}

void BM_plane_peak(benchmark::State& state) {
  const double vtau = double(state.range(0)) / 100;
  const auto s = viscoroll::PlaneSolverD(viscoroll::StandardLinearSolid<double>(1, 0.5, 9, vtau))
                     .solve({.c1 = 1.0, .load = 1.0, .speed = 1.0});
  for (auto _ : state) benchmark::DoNotOptimize(s.peak().pressure);
}

/// A spectrum of M retardation times one decade apart (1e-2 ... ) with weights 1, at V = 1 with
/// a0 ~ 0.5: the closed form of docs/theory.md, section 12.
viscoroll::PronyCreep<double> decade_spectrum(int m) {
  std::vector<viscoroll::PronyTerm<double>> terms;
  for (int k = 0; k < m; ++k) terms.push_back({1.0, std::pow(10.0, -2.0 + k)});
  return viscoroll::PronyCreep<double>(1.0, 0.5, terms);
}

void BM_plane_spectrum_solve(benchmark::State& state) {
  const viscoroll::PlaneSolver solver(decade_spectrum(int(state.range(0))));
  const viscoroll::PlaneScene<double> scene{.c1 = 1.0, .load = 0.1, .speed = 1.0};
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve(scene).chi);
}

void BM_plane_spectrum_peak(benchmark::State& state) {
  const auto s = viscoroll::PlaneSolver(decade_spectrum(int(state.range(0))))
                     .solve({.c1 = 1.0, .load = 0.1, .speed = 1.0});
  for (auto _ : state) benchmark::DoNotOptimize(s.peak().pressure);
}

}  // namespace

BENCHMARK(BM_plane_spectrum_solve)->Arg(1)->Arg(2)->Arg(5)->Arg(10)->Arg(20)->Arg(30);
BENCHMARK(BM_plane_spectrum_peak)->Arg(1)->Arg(20);
BENCHMARK_TEMPLATE(BM_plane_solve, float)->Arg(1)->Arg(100)->Arg(10000);
BENCHMARK_TEMPLATE(BM_plane_solve, double)->Arg(1)->Arg(100)->Arg(10000);
BENCHMARK_TEMPLATE(BM_plane_solve, long double)->Arg(1)->Arg(100)->Arg(10000);
BENCHMARK(BM_plane_solve_elastic);
BENCHMARK_TEMPLATE(BM_plane_pressure_point, double)->Arg(1)->Arg(100)->Arg(10000);
BENCHMARK_TEMPLATE(BM_plane_pressure_point, long double)->Arg(1)->Arg(100);
BENCHMARK(BM_plane_peak)->Arg(1)->Arg(100)->Arg(10000);
