// The kernels and line operators of the line-contact theory, for float, double and long double.
//
// 1. kappa and psi of the paper's leading-edge condition (44) in the form (L2)
//    (docs/line-kernels.md), one call at z = 1e-3 (ascending series), 1 and 10 (trapezoidal rule)
//    and 100 (asymptotic series).
// 2. The line operators of line/line_operators.hpp (GaussLegendre<Real, 12> on graded panels, the
//    line solver's default rule), one evaluation at y = l/3 of F(y) = (1 - y^2/l^2)/4, the static
//    F0 = C1 a^2/4 of a contact with a0 = 1, C1 = 1:
//      finite part      FP[F](y) = int (F(y') - F(y)) / |y' - y| dy'          Eqs. (22)-(24)
//      near field       FP[F](y) + F(y) ln 4(l^2 - y^2)                      Eqs. (24), (25)
//      extended         I[F, x](y), Eq. (41), the F0 term of the extended approximation (26)
//      extended_dx      d/dx I[F, x](y), the F1 term of (26)
//      leading_edge     the right side of (44) in the form (L2) (kappa and psi of part 1),
//                       PaperLeadingEdgeOperators::kernel of line/paper_leading_edge.hpp
//    over short and long contacts, l / a0 = 3, 30, 1000, and, for the extended operator and (L2),
//    the kernel scale x (or V tau) / a0 = 0.01, 1, 100 (its panels are graded down to x).
#include <benchmark/benchmark.h>

#include <string>
#include <viscoroll/line/line_operators.hpp>
#include <viscoroll/line/paper_leading_edge.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>
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
  state.SetLabel("z = " + std::to_string(static_cast<double>(z)));
}

template <class Real>
void BM_line_kernel_psi(benchmark::State& state) {
  Real z = static_cast<Real>(line_kernel_arguments[state.range(0)]);
  benchmark::DoNotOptimize(viscoroll::special::line_kernel_psi(z));
  for (auto _ : state) {
    benchmark::DoNotOptimize(z);
    benchmark::DoNotOptimize(viscoroll::special::line_kernel_psi(z));
  }
  state.SetLabel("z = " + std::to_string(static_cast<double>(z)));
}

constexpr double contact_half_lengths[] = {3.0, 30.0, 1000.0};  // l / a0
constexpr double kernel_scales[] = {0.01, 1.0, 100.0};          // x / a0 or V tau / a0

enum class Operator { finite_part, near_field, extended, extended_dx, leading_edge };

template <class Real, Operator Op>
void BM_line_operator(benchmark::State& state) {
  const Real l = Real(contact_half_lengths[state.range(0)]);
  const Real x = Real(kernel_scales[state.range(1)]);
  const viscoroll::line::LineOperators<Real, viscoroll::GaussLegendre<Real, 12>> ops(l);
  const viscoroll::line::PaperLeadingEdgeOperators<Real, viscoroll::GaussLegendre<Real, 12>> paper(
      l);
  const auto F = [l](Real y) { return (1 - (y / l) * (y / l)) / 4; };
  Real y = l / 3;
  const auto evaluate = [&] {
    if constexpr (Op == Operator::finite_part) return ops.finite_part(F, y);
    if constexpr (Op == Operator::near_field) return ops.near_field(F, y);
    if constexpr (Op == Operator::extended) return ops.extended(F, x, y);
    if constexpr (Op == Operator::extended_dx) return ops.extended_dx(F, x, y);
    if constexpr (Op == Operator::leading_edge) return paper.kernel(F, x, y);
  };
  Real value = evaluate();  // builds the rules once
  for (auto _ : state) {
    benchmark::DoNotOptimize(&y);
    value = evaluate();
    benchmark::DoNotOptimize(&value);
    benchmark::ClobberMemory();
  }
  std::string label =
      "l/a0 = " + std::to_string(static_cast<int>(contact_half_lengths[state.range(0)]));
  if constexpr (Op == Operator::extended || Op == Operator::extended_dx)
    label += ", x/a0 = " + std::to_string(kernel_scales[state.range(1)]).substr(0, 5);
  if constexpr (Op == Operator::leading_edge)
    label += ", V tau/a0 = " + std::to_string(kernel_scales[state.range(1)]).substr(0, 5);
  state.SetLabel(label);
  state.counters["value"] = static_cast<double>(value);
}

template <class Real>
void BM_finite_part(benchmark::State& state) {
  BM_line_operator<Real, Operator::finite_part>(state);
}
template <class Real>
void BM_near_field(benchmark::State& state) {
  BM_line_operator<Real, Operator::near_field>(state);
}
template <class Real>
void BM_extended(benchmark::State& state) {
  BM_line_operator<Real, Operator::extended>(state);
}
template <class Real>
void BM_extended_dx(benchmark::State& state) {
  BM_line_operator<Real, Operator::extended_dx>(state);
}
template <class Real>
void BM_leading_edge_kernel(benchmark::State& state) {
  BM_line_operator<Real, Operator::leading_edge>(state);
}

}  // namespace

// Argument i is the index into line_kernel_arguments: z = 1e-3, 1, 10, 100.
BENCHMARK_TEMPLATE(BM_line_kernel_kappa, float)->DenseRange(0, 3);
BENCHMARK_TEMPLATE(BM_line_kernel_kappa, double)->DenseRange(0, 3);
BENCHMARK_TEMPLATE(BM_line_kernel_kappa, long double)->DenseRange(0, 3);
BENCHMARK_TEMPLATE(BM_line_kernel_psi, float)->DenseRange(0, 3);
BENCHMARK_TEMPLATE(BM_line_kernel_psi, double)->DenseRange(0, 3);
BENCHMARK_TEMPLATE(BM_line_kernel_psi, long double)->DenseRange(0, 3);

// Arguments: index into contact_half_lengths (l/a0 = 3, 30, 1000), index into kernel_scales
// (x/a0 or V tau/a0 = 0.01, 1, 100; the finite part and the near field do not depend on it).
BENCHMARK_TEMPLATE(BM_finite_part, float)->ArgsProduct({{0, 1, 2}, {1}});
BENCHMARK_TEMPLATE(BM_finite_part, double)->ArgsProduct({{0, 1, 2}, {1}});
BENCHMARK_TEMPLATE(BM_finite_part, long double)->ArgsProduct({{0, 1, 2}, {1}});
BENCHMARK_TEMPLATE(BM_near_field, float)->ArgsProduct({{0, 1, 2}, {1}});
BENCHMARK_TEMPLATE(BM_near_field, double)->ArgsProduct({{0, 1, 2}, {1}});
BENCHMARK_TEMPLATE(BM_near_field, long double)->ArgsProduct({{0, 1, 2}, {1}});
BENCHMARK_TEMPLATE(BM_extended, float)->ArgsProduct({{0, 1, 2}, {0, 1, 2}});
BENCHMARK_TEMPLATE(BM_extended, double)->ArgsProduct({{0, 1, 2}, {0, 1, 2}});
BENCHMARK_TEMPLATE(BM_extended, long double)->ArgsProduct({{0, 1, 2}, {0, 1, 2}});
BENCHMARK_TEMPLATE(BM_extended_dx, float)->ArgsProduct({{0, 1, 2}, {0, 1, 2}});
BENCHMARK_TEMPLATE(BM_extended_dx, double)->ArgsProduct({{0, 1, 2}, {0, 1, 2}});
BENCHMARK_TEMPLATE(BM_extended_dx, long double)->ArgsProduct({{0, 1, 2}, {0, 1, 2}});
BENCHMARK_TEMPLATE(BM_leading_edge_kernel, float)->ArgsProduct({{0, 1, 2}, {0, 1, 2}});
BENCHMARK_TEMPLATE(BM_leading_edge_kernel, double)->ArgsProduct({{0, 1, 2}, {0, 1, 2}});
BENCHMARK_TEMPLATE(BM_leading_edge_kernel, long double)->ArgsProduct({{0, 1, 2}, {0, 1, 2}});
