// One evaluation of the line solver's least-squares residual (LineResidual::operator()) at the
// paper's scene: f = 9, a 5:1 static contact (C2/C1 = (ln 20 - 1)/25, a0 = 1), V tau / a0 = 1,
// for `terms` N = 2, 4, 8, 16 (N + 1 collocation points; 2N + 3 equations). Each evaluation
// assembles (34) (finite part of F0, Eqs. (22)-(24)), the leading-edge condition (L6) of
// docs/theory.md section 4 (the extended operator (26), (41) and its eta-integral, the Bessel
// terms of (42)) at every collocation point, and the load (47), with G, F0, Q from (36), (33),
// (46) at every quadrature node. The unknowns are the converged N = 4 solution, re-expanded to
// N terms. BM_line_jacobian: the residual with its semi-analytic Jacobian (theory.md section 6),
// which the Levenberg-Marquardt iteration takes at its start and when Broyden's update fails.
// Counters: equations, unknowns, max |r| at the point (to show where it was evaluated).
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <utility>
#include <viscoroll/viscoroll.hpp>

namespace {

template <class Real>
viscoroll::LineScene<Real> paper_scene(Real f, Real c) {
  using std::log;
  return {.c1 = Real(1),
          .c2 = (log(Real(20)) - 1) / 25,
          .load = 5 / (3 * (1 + f) * c),
          .speed = Real(1)};
}

template <class Real>
viscoroll::StandardLinearSolid<Real> paper_material() {
  return {Real(1), Real(0.5), Real(9), Real(1)};  // mu_D, nu, f, tau; speed 1: V tau = 1
}

/// The converged N = 4 line solution of the paper's scene, computed once per scalar type.
template <class Real>
const viscoroll::LineSolution<Real, viscoroll::GaussLegendre<Real, 12>>& reference_solution() {
  static const auto solution = [] {
    viscoroll::LineOptions options;
    options.terms = 4;
    const auto material = paper_material<Real>();
    return viscoroll::LineSolver<Real, viscoroll::StandardLinearSolid<Real>>(material, options)
        .solve(paper_scene(Real(9), material.instantaneous_compliance()));
  }();
  return solution;
}

/// The residual assembly of the paper's scene at `terms` and the converged N = 4 solution
/// re-expanded to it.
template <class Real>
struct ResidualAtSolution {
  using Residual = viscoroll::line::LineResidual<Real, viscoroll::GaussLegendre<Real, 12>>;
  Residual residual;
  typename Residual::Vector x;

  static ResidualAtSolution make(int terms) {
    viscoroll::LineOptions options;
    options.terms = terms;
    const auto material = paper_material<Real>();
    const viscoroll::LineSolver<Real, viscoroll::StandardLinearSolid<Real>> solver(material,
                                                                                   options);
    auto residual = solver.residual(paper_scene(Real(9), material.instantaneous_compliance()));
    const auto& start = reference_solution<Real>();
    auto x = residual.pack(start.shape, start.d);
    return {std::move(residual), std::move(x)};
  }
};

template <class Real>
void BM_line_residual(benchmark::State& state) {
  const int terms = static_cast<int>(state.range(0));
  const auto [residual, x] = ResidualAtSolution<Real>::make(terms);
  typename ResidualAtSolution<Real>::Residual::Vector r(residual.equations());
  bool ok = residual(x, r);
  for (auto _ : state) {
    ok = residual(x, r);
    benchmark::DoNotOptimize(r.data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(ok ? "exterior form (L6), at the N = 4 solution" : "residual undefined");
  state.counters["terms"] = terms;
  state.counters["equations"] = residual.equations();
  state.counters["unknowns"] = residual.unknowns();
  state.counters["max_abs_r"] = static_cast<double>(r.cwiseAbs().maxCoeff());
}

/// The residual and its semi-analytic Jacobian (LineResidual::jacobian) at the same point.
template <class Real>
void BM_line_jacobian(benchmark::State& state) {
  const int terms = static_cast<int>(state.range(0));
  const auto [residual, x] = ResidualAtSolution<Real>::make(terms);
  typename ResidualAtSolution<Real>::Residual::Vector r(residual.equations());
  typename ResidualAtSolution<Real>::Residual::Matrix jac(residual.equations(),
                                                          residual.unknowns());
  bool ok = residual.jacobian(x, r, jac);
  for (auto _ : state) {
    ok = residual.jacobian(x, r, jac);
    benchmark::DoNotOptimize(jac.data());
    benchmark::ClobberMemory();
  }
  state.SetLabel(ok ? "residual and semi-analytic Jacobian" : "Jacobian undefined");
  state.counters["terms"] = terms;
  state.counters["unknowns"] = residual.unknowns();
}

}  // namespace

BENCHMARK_TEMPLATE(BM_line_jacobian, double)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_line_residual, float)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_line_residual, double)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_line_residual, long double)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->Unit(benchmark::kMillisecond);
