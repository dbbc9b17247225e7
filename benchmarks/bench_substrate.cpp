// Solves on a layer and on the spring bed against the half space's (docs/bem.md B15-B19,
// docs/plane-substrate.md), on the paper's scene (the standard linear solid mu_D = 1, nu = 0.5,
// f = 9, tau = 1; line-contact a0 = 1) at V tau / a0 = 1.
//
// BM_substrate_bem: one complete 3-D solve (C2 = (ln 20 - 1)/25, the load of a0 = 1) on one
// thread at N = 8, 16, 32, including the solver's construction, which tabulates a body's radial
// correction D(r) (B15) once: what a user pays for one solve. Bodies: 0 the half space, 1 a
// bonded layer, 2 a frictionless layer, 3 the spring bed, each of thickness h = a0. Counters: d,
// chi, a0, the seconds of the construction, of the set-up of the grid's tables (B16, B17) and
// of the iteration.
//
// BM_substrate_plane: one plane solve per unit length (PlaneSubstrateSolver, C1 = 1, the load of
// a = 1) at the relative tolerance 1e-4 (viscoroll-solve's default on a substrate) and 1e-8 (the
// library's default), on the same four bodies, and Hunter's closed form on the half space
// (PlaneSolver, body 4) for scale. Counters: a, chi, the Chebyshev terms N.
//
//   build/release/bin/bench_substrate --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true      (one command line)
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/plane/plane_substrate_solver.hpp>

namespace {

using Sls = viscoroll::StandardLinearSolid<double>;
const Sls rubber(1.0, 0.5, 9.0, 1.0);
const double compliance = (1 - 0.5) / (2 * std::acos(-1.0));

/// The body of argument k, passed to `use` (a generic callable).
template <class Use>
void with_body(int k, Use&& use) {
  switch (k) {
    case 0:
      return use(viscoroll::HalfSpace<double>{});
    case 1:
      return use(viscoroll::Layer<double>(1.0));
    case 2:
      return use(viscoroll::Layer<double>(1.0, viscoroll::LayerBase::frictionless));
    default:
      return use(viscoroll::SpringBed<double>(1.0));
  }
}

void BM_substrate_bem(benchmark::State& state) {
  viscoroll::BemOptions o;
  o.grid = static_cast<int>(state.range(1));
  o.threads = 1;
  const viscoroll::BemScene<double> scene{.c1 = 1.0,
                                          .c2 = (std::log(20.0) - 1) / 25,
                                          .load = 5.0 / (3 * (1 + 9.0) * compliance),
                                          .speed = 1.0};
  viscoroll::BemSolution<double> s;
  double construct = 0;
  for (auto _ : state) {
    with_body(static_cast<int>(state.range(0)), [&](const auto& body) {
      const auto t0 = std::chrono::steady_clock::now();
      const viscoroll::BemSolver<double, Sls> solver(rubber, o, body);
      construct = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      s = solver.solve(scene);
    });
    benchmark::DoNotOptimize(s.pressure.data());
    benchmark::ClobberMemory();
  }
  state.counters["d"] = s.d;
  state.counters["chi"] = s.chi;
  state.counters["a0"] = s.a0;
  state.counters["converged"] = s.converged;
  state.counters["construct_s"] = construct;
  state.counters["setup_s"] = s.seconds_setup;
  state.counters["solve_s"] = s.seconds_solve;
}

void BM_substrate_plane(benchmark::State& state) {
  const int body = static_cast<int>(state.range(0));
  viscoroll::PlaneSubstrateOptions o;
  o.tolerance = state.range(1) == 0 ? 1e-4 : 1e-8;
  // The load of a = 1 on the half space with the long-term compliance (Eq. 29 at V = 0).
  const viscoroll::PlaneScene<double> scene{
      .c1 = 1.0, .load = 1.0 / (4 * (1 + 9.0) * compliance), .speed = 1.0};
  double a = 0, chi = 0, terms = 0, converged = 0;
  for (auto _ : state) {
    if (body == 4) {
      const auto s = viscoroll::PlaneSolver(rubber).solve(scene);
      a = s.a, chi = s.chi, converged = s.converged;
    } else {
      with_body(body, [&](const auto& b) {
        const auto s = viscoroll::PlaneSubstrateSolver(rubber, b, o).solve(scene);
        a = s.a, chi = s.chi, terms = s.terms, converged = s.converged;
      });
    }
    benchmark::DoNotOptimize(&chi);
    benchmark::ClobberMemory();
  }
  state.counters["a"] = a;
  state.counters["chi"] = chi;
  state.counters["terms"] = terms;
  state.counters["converged"] = converged;
}

}  // namespace

// Arguments: body (0 half space, 1 bonded layer, 2 frictionless layer, 3 spring bed), N.
BENCHMARK(BM_substrate_bem)
    ->ArgsProduct({{0, 1, 2, 3}, {8, 16, 32}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// Arguments: body (0-3 as above, 4 Hunter's closed form), tolerance (0: 1e-4, 1: 1e-8).
BENCHMARK(BM_substrate_plane)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1}})
    ->Args({4, 0})
    ->Unit(benchmark::kMillisecond);
