// "Only what a scene needs" (docs/performance.md): one plane solve and one line solve of the
// paper's scene (f = 9; line: 5:1 static contact, C2/C1 = (ln 20 - 1)/25; a0 = 1) for an elastic
// material and for the standard linear solid at V tau = 0, at V tau / a0 = 1 and at V tau / a0 =
// 1e20 (glassy). The elastic, static and glassy scenes are closed forms (Hertz, docs/theory.md
// (P6), for the plane; Kalker's static line contact, Eqs. (33), (34), (47), (48) at V tau = 0, for
// the line) with no Bessel, Struve or exponential work; V tau / a0 = 1 solves (P5) with the Bessel
// ratios of (36)-(37) (plane) or the Levenberg-Marquardt iteration on (34), (L6), (47) (line).
// Label: the path the solver reported; counters: root-finder / Levenberg-Marquardt iterations.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/viscoroll.hpp>

namespace {

/// Regime index of the benchmark argument: the material and V tau / a0.
enum Regime : int { elastic = 0, sls_static = 1, sls_moderate = 2, sls_glassy = 3 };

const char* regime_name(int r) {
  switch (r) {
    case elastic:
      return "Elastic";
    case sls_static:
      return "SLS V tau/a0 = 0";
    case sls_moderate:
      return "SLS V tau/a0 = 1";
    default:
      return "SLS V tau/a0 = 1e20 (glassy)";
  }
}

template <class Real>
Real regime_vtau(int r) {
  return r == sls_static ? Real(0) : r == sls_moderate ? Real(1) : Real(1e20);
}

/// Plane scene with a0 = 1: mu_D = 1, nu = 0.5, c = 1/(4 pi), W = C1 / (4 c (1 + f)).
template <class Real, class Material>
void plane_solve(benchmark::State& state, const Material& material, Real f) {
  const Real c = material.instantaneous_compliance();
  const viscoroll::PlaneSolver<Real, Material> solver(material);
  const viscoroll::PlaneScene<Real> scene{
      .c1 = Real(1), .load = 1 / (4 * c * (1 + f)), .speed = Real(1)};
  auto s = solver.solve(scene);
  for (auto _ : state) {
    s = solver.solve(scene);
    benchmark::DoNotOptimize(&s);
    benchmark::ClobberMemory();
  }
  state.counters["iterations"] = s.iterations;
  state.counters["a_over_a0"] = static_cast<double>(s.a / s.a_long_term);
}

template <class Real>
void BM_plane_solve_needs(benchmark::State& state) {
  const int r = static_cast<int>(state.range(0));
  const Real f = 9;
  state.SetLabel(regime_name(r));
  if (r == elastic) {
    // The long-term modulus of the standard linear solid: the same static contact.
    plane_solve<Real>(state, viscoroll::Elastic<Real>(Real(1) / (1 + f), Real(0.5)), Real(0));
  } else {
    plane_solve<Real>(
        state, viscoroll::StandardLinearSolid<Real>(Real(1), Real(0.5), f, regime_vtau<Real>(r)),
        f);
  }
}

/// Line scene with a0 = 1 at the long-term compliance: load 5 / (3 (1 + f) c), C1 = 1.
template <class Real, class Material>
void line_solve(benchmark::State& state, const Material& material, Real f, int terms) {
  using std::log;
  const Real c = material.instantaneous_compliance();
  viscoroll::LineOptions options;
  options.terms = terms;
  const viscoroll::LineSolver<Real, Material> solver(material, options);
  const viscoroll::LineScene<Real> scene{.c1 = Real(1),
                                         .c2 = (log(Real(20)) - 1) / 25,
                                         .load = 5 / (3 * (1 + f) * c),
                                         .speed = Real(1)};
  auto s = solver.solve(scene);
  for (auto _ : state) {
    s = solver.solve(scene);
    benchmark::DoNotOptimize(&s);
    benchmark::ClobberMemory();
  }
  state.SetLabel(
      std::string(state.range(0) == elastic ? "Elastic" : regime_name(int(state.range(0)))) + ": " +
      s.reason);
  state.counters["terms"] = terms;
  state.counters["iterations"] = s.iterations;
  state.counters["converged"] = s.converged;
  state.counters["a0_over_a0_static"] = static_cast<double>(s.a(Real(0)) / s.a_long_term);
}

template <class Real>
void BM_line_solve_needs(benchmark::State& state) {
  const int r = static_cast<int>(state.range(0));
  const int terms = static_cast<int>(state.range(1));
  const Real f = 9;
  if (r == elastic) {
    line_solve<Real>(state, viscoroll::Elastic<Real>(Real(1) / (1 + f), Real(0.5)), Real(0), terms);
  } else {
    line_solve<Real>(
        state, viscoroll::StandardLinearSolid<Real>(Real(1), Real(0.5), f, regime_vtau<Real>(r)), f,
        terms);
  }
}

}  // namespace

// Argument: regime 0 Elastic, 1 SLS V tau = 0, 2 SLS V tau/a0 = 1, 3 SLS V tau/a0 = 1e20.
BENCHMARK_TEMPLATE(BM_plane_solve_needs, float)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_plane_solve_needs, double)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_plane_solve_needs, long double)
    ->DenseRange(0, 3)
    ->Unit(benchmark::kMicrosecond);
// Arguments: regime, terms (the discretisation of the rolling iteration; unused by closed forms).
BENCHMARK_TEMPLATE(BM_line_solve_needs, double)
    ->ArgsProduct({{0, 1, 2, 3}, {4}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_line_solve_needs, float)
    ->ArgsProduct({{0, 1, 2, 3}, {4}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_line_solve_needs, long double)
    ->ArgsProduct({{0, 1, 2, 3}, {4}})
    ->Unit(benchmark::kMicrosecond);
