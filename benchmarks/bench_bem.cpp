// The boundary-element solver on the paper's scene (f = 9, 5:1, line-contact a0 = 1) at
// V tau / a0 = 1: one complete solve (influence table, its transform, active-set iteration) per
// grid N (elements per semi-axis of the static Hertz ellipse) and thread count of the table.
// Targets: on one core N = 16 under 40 ms, N = 32 under 0.2 s, N = 64 under 1 s; the
// 1,000,000-cell grid (N = 312) under 60 s with threads. Counters: d, chi, a(0), active-set and
// GMRES iterations, the solver's set-up and iteration seconds. The environment variable
// VISCOROLL_BEM_COARSE sets BemOptions::coarse_tolerance (0: every active set solved to the
// tolerance, the GMRES steps without inexact early solves). BM_bem_paper_scene_no_final_solve: the
// same without the final solve of the converged active set (BemOptions::final_tolerance = 0), the
// cost of that solve.
//
// BM_bem_apply: one application of the convolution operator u = K * p of (B6)-(B7) (the
// real-to-complex 2-D FFT of the zero-padded grid and its inverse, FFTW where the build found it,
// else Eigen's kissfft, and the product with the kernel's half spectrum), for float, double and
// long double, at N = 8, 16, 32, 64 elements per semi-axis (grid (2 ceil(1.6 N) + 1)^2 cells).
// The cost does not depend on the coefficients' values; the elastic table is used.
//
// BM_bem_setup: the influence table (B6) with its memory rows (B3)-(B5) and its transform (B7),
// the BemSolver's set-up, for the elastic material and the standard linear solid (f = 9) at
// V tau / a0 = 0, 1 and 1e12 (glassy), N = 8 and 16. Elastic and V tau = 0 need only Love's
// coefficients (B1)-(B2); V tau > 0 adds the exponential recurrence (B4)-(B5) per row, also in
// the glassy limit, where the memory term is O((a/V tau) ln(V tau/a)) of the elastic one.
// Regime 4 is a spectrum of 20 terms (PronyCreep, f_k = 0.5, tau_k log-spaced 1e-3 .. 1e3, the
// twenty-term material of plane_vs_bem_spectrum.cpp) at V = a0/tau for the spectrum's geometric
// middle, V tau_k / a0 = 1e-3 .. 1e3, on the same grid as the standard linear solid (the paper's
// load 5/(3 (1 + f) c) makes it independent of f): the target: the 20-term table within
// 5 times the one-term table (regime 2), at N = 16 and 32.
//
// BM_bem_crowned_roller: one complete solve of examples/scenes/crowned_roller.json (a cylinder
// of radius 50 mm, 50 mm flat, 50 mm crowns, 80 mm long; the standard linear solid mu_d = 2 MPa,
// f = 4, tau = 5 ms; 100 N) through bem_scene(profile, ...), at 0.1 and 1 m/s and N = 16, 24, 32
// on one thread: the grid study of docs/rollers.md converges d, chi and the edge-peak ratio to
// 0.2% from N = 24. Counters: d, chi, the largest load per unit length f0_max and its
// ratio to F0(0).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>
#include <viscoroll/bem/bem_profile.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/prony.hpp>

namespace {

void paper_scene(benchmark::State& state, bool final_solve) {
  const double f = 9, nu = 0.5, mu = 1, c = (1 - nu) / (2 * std::acos(-1.0) * mu);
  viscoroll::BemOptions o;
  o.grid = static_cast<int>(state.range(0));
  o.threads = static_cast<int>(state.range(1));
  if (const char* e = std::getenv("VISCOROLL_BEM_COARSE")) o.coarse_tolerance = std::atof(e);
  if (!final_solve) o.final_tolerance = 0;
  const viscoroll::BemSolverD solver(viscoroll::StandardLinearSolid<double>(mu, nu, f, 1.0), o);
  const viscoroll::BemScene<double> scene{
      .c1 = 1.0, .c2 = (std::log(20.0) - 1) / 25, .load = 5.0 / (3 * (1 + f) * c), .speed = 1.0};
  viscoroll::BemSolution<double> s;
  for (auto _ : state) {
    s = solver.solve(scene);
    // Not DoNotOptimize(s.chi): this library's "+m,r" constraint lets GCC garble a double lvalue.
    benchmark::DoNotOptimize(s.pressure.data());
    benchmark::ClobberMemory();
  }
  state.counters["d"] = s.d;
  state.counters["chi"] = s.chi;
  state.counters["a0"] = s.a0;
  state.counters["converged"] = s.converged;
  state.counters["active_set_iterations"] = s.iterations;
  state.counters["gmres_iterations"] = s.krylov_iterations;
  state.counters["cells"] = static_cast<double>(s.grid.size());
  state.counters["setup_s"] = s.seconds_setup;
  state.counters["solve_s"] = s.seconds_solve;
}

void BM_bem_paper_scene(benchmark::State& state) { paper_scene(state, true); }

void BM_bem_crowned_roller(benchmark::State& state) {
  viscoroll::BemOptions o;
  o.grid = static_cast<int>(state.range(0));
  o.threads = 1;
  const viscoroll::StandardLinearSolid<double> rubber(2e6, 0.5, 4.0, 0.005);
  const viscoroll::BemSolverD solver(rubber, o);
  const viscoroll::CrownedCylinder<double> roller(0.05, 0.05, 0.05, 0.08);
  const double speed = state.range(1) == 0 ? 0.1 : 1.0;
  const auto scene = viscoroll::bem_scene(roller, rubber, 100.0, speed);
  viscoroll::BemSolution<double> s;
  for (auto _ : state) {
    s = solver.solve(scene);
    benchmark::DoNotOptimize(s.pressure.data());
    benchmark::ClobberMemory();
  }
  const auto along = s.along_roller();
  state.counters["speed"] = speed;
  state.counters["d"] = s.d;
  state.counters["chi"] = s.chi;
  state.counters["converged"] = s.converged;
  state.counters["cells"] = static_cast<double>(s.grid.size());
  state.counters["f0_max"] = along.f0_max;
  state.counters["edge_peak_ratio"] = along.f0_max / along.f0_nearest(0.0);
}
/// The same without the final solve of the converged set (final_tolerance = 0): its cost.
void BM_bem_paper_scene_no_final_solve(benchmark::State& state) { paper_scene(state, false); }

/// The paper's grid for N elements per semi-axis (static Hertz ellipse of the long-term
/// compliance): the same grid BemSolver::solve uses.
template <class Real, class Material>
viscoroll::BemGrid<Real> paper_grid(const Material& material, int n, double f) {
  viscoroll::BemOptions o;
  o.grid = n;
  const double c = (1 - 0.5) / (2 * std::acos(-1.0));
  const viscoroll::BemScene<Real> scene{.c1 = Real(1),
                                        .c2 = Real((std::log(20.0) - 1) / 25),
                                        .load = Real(5.0 / (3 * (1 + f) * c)),
                                        .speed = Real(1)};
  return viscoroll::BemSolver<Real, Material>(material, o).grid_for(scene);
}

template <class Real>
void BM_bem_apply(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const viscoroll::Elastic<Real> material(Real(0.1), Real(0.5));
  const auto grid = paper_grid<Real>(material, n, 9.0);
  const viscoroll::bem::InfluenceTable<Real> table(grid, material.instantaneous_compliance(), {},
                                                   Real(0));
  const viscoroll::bem::ConvolutionOperator<Real> op(table);
  std::vector<Real> p(grid.size()), u(grid.size());
  for (std::size_t q = 0; q < p.size(); ++q) p[q] = Real(1) + Real(q % 7) / 8;
  for (auto _ : state) {
    op.apply(p, u);
    benchmark::DoNotOptimize(u.data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(std::to_string(grid.nx) + "x" + std::to_string(grid.ny) + " cells, FFT " +
                 std::to_string(op.fft_nx()) + "x" + std::to_string(op.fft_ny()));
  state.counters["cells"] = static_cast<double>(grid.size());
}

/// The twenty-term spectrum of regime 4: f_k = 0.5, tau_k = 10^(-3 + 6 k/19), k = 0 .. 19.
viscoroll::PronyCreep<double> twenty_terms() {
  std::vector<viscoroll::PronyTerm<double>> t;
  for (int k = 0; k < 20; ++k) t.push_back({0.5, std::pow(10.0, -3 + 6.0 * k / 19)});
  return viscoroll::PronyCreep<double>(1.0, 0.5, t);
}

/// Regime of BM_bem_setup: 0 elastic, 1 SLS V tau = 0, 2 SLS V tau/a0 = 1, 3 SLS V tau/a0 = 1e12,
/// 4 twenty terms, V tau_k/a0 = 1e-3 .. 1e3.
void BM_bem_setup(benchmark::State& state) {
  const int regime = static_cast<int>(state.range(0));
  const int n = static_cast<int>(state.range(1));
  const double f = 9;
  const viscoroll::StandardLinearSolid<double> sls(1.0, 0.5, f, 1.0);
  const auto grid = paper_grid<double>(sls, n, f);
  const double speed = regime == 1 ? 0.0 : regime == 3 ? 1e12 : 1.0;  // a0 = 1, tau = 1
  std::vector<viscoroll::PronyTerm<double>> terms;
  double compliance = sls.instantaneous_compliance();
  if (regime == 0) {
    const viscoroll::Elastic<double> elastic(1.0 / (1 + f), 0.5);  // the long-term modulus
    terms = viscoroll::bem::memory_terms_of(elastic);
    compliance = elastic.instantaneous_compliance();
  } else if (regime == 4) {
    const auto spectrum = twenty_terms();
    // The grid of the spectrum's own scene (f = sum f_k = 10) is the standard linear solid's.
    if (paper_grid<double>(spectrum, n, spectrum.creep_ratio()).hx != grid.hx)
      state.SkipWithError("the twenty-term scene's grid differs from the SLS one");
    terms = viscoroll::bem::memory_terms_of(spectrum);
    compliance = spectrum.instantaneous_compliance();
  } else {
    terms = viscoroll::bem::memory_terms_of(sls);
  }
  for (auto _ : state) {
    const viscoroll::bem::InfluenceTable<double> table(grid, compliance, terms, speed);
    const viscoroll::bem::ConvolutionOperator<double> op(table);
    benchmark::DoNotOptimize(&op);
    benchmark::ClobberMemory();
  }
  const char* names[] = {"Elastic", "SLS V tau/a0 = 0", "SLS V tau/a0 = 1",
                         "SLS V tau/a0 = 1e12 (glassy)", "20 terms V tau/a0 = 1e-3 .. 1e3"};
  state.SetLabel(std::string(names[regime]) + ", " + std::to_string(grid.nx) + "x" +
                 std::to_string(grid.ny) + " cells");
  state.counters["memory_terms"] = static_cast<double>(terms.size());
}

}  // namespace

BENCHMARK_TEMPLATE(BM_bem_apply, float)
    ->Arg(8)
    ->Arg(16)
    ->Arg(32)
    ->Arg(64)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_bem_apply, double)
    ->Arg(8)
    ->Arg(16)
    ->Arg(32)
    ->Arg(64)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_bem_apply, long double)
    ->Arg(8)
    ->Arg(16)
    ->Arg(32)
    ->Arg(64)
    ->Unit(benchmark::kMicrosecond);
// Arguments: regime (0 elastic, 1 V tau = 0, 2 V tau/a0 = 1, 3 V tau/a0 = 1e12, 4 twenty terms), N.
BENCHMARK(BM_bem_setup)->ArgsProduct({{0, 1, 2, 3}, {8, 16}})->Unit(benchmark::kMillisecond);
// Issue 20: twenty terms against one (regime 4 against 2) on the paper's grids N = 16 and 32.
BENCHMARK(BM_bem_setup)->Args({4, 16})->Args({2, 32})->Args({4, 32})->Unit(benchmark::kMillisecond);

// Arguments: N, threads of the influence table.
BENCHMARK(BM_bem_paper_scene)
    ->Args({8, 1})
    ->Args({12, 1})
    ->Args({16, 1})
    ->Args({24, 1})
    ->Args({32, 1})
    ->Args({64, 1})
    ->Args({16, 2})
    ->Args({32, 2})
    ->Args({64, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_bem_paper_scene_no_final_solve)
    ->Args({16, 1})
    ->Args({32, 1})
    ->Args({64, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// Arguments: N, speed (0: 0.1 m/s, 1: 1 m/s).
BENCHMARK(BM_bem_crowned_roller)
    ->ArgsProduct({{16, 24, 32}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
// The million-cell grid (N = 312: 1001 x 1001 cells), on two threads; one iteration per run.
BENCHMARK(BM_bem_paper_scene)
    ->Args({312, 2})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();
