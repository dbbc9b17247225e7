// line_seeded_sweep: what a seeded solve of a sweep costs and which root it lands on, on the
// paper's scene (Panek & Kalker 1980, Section 7: f = 9, nu = 0.5, C2/C1 = (ln 20 - 1)/25, the
// load of a static a0 = C1 = 1, tau = 1) at the 100 speeds V tau/a0 = 10^(-3 + 6i/99) with
// LineOptions::fast() on 6-point panels (FastLineSolverD). Per speed, one line:
//   cold: LineSolver::solve(scene), the cold start (plane seed, continuation stages 2, 4, N);
//   seeded: LineSolver::solve(scene, &previous), the sweep's solve (the same stages from the
//     previous speed's seeded solution where that is a root, the rule of viscoroll::sweep,
//     viscoroll::usable_as_seed; else, and at the first speed, the cold one);
//   direct: Levenberg-Marquardt at the final N straight from the previous speed's seeded
//     solution (packed at N, no stages), then the least-squares minimisation where it stops
//     short, as the solver's last stage does;
//   predicted: the same from the secant predictor 2 x(i-1) - x(i-2) of the two previous seeded
//     solutions (even steps in ln V; from x(i-1) where x(i-2) is not a root).
// Where the previous speed is no root, the sweep solves cold, and so do direct and predicted
// here: the line says "cold start" and the cold time counts for all four.
// Columns: iterations (LM steps plus minimisation steps), residual and Jacobian evaluations
// (direct and predicted only), the best of `--repeat` wall times in ms, converged/root flags, and
// the largest relative difference over a(0), b(0), l, d and chi of each against cold and of
// direct and predicted against seeded. Summary lines at the end. The data behind
// docs/performance.md, "Sweeps", and docs/line-solver.md, "Continuation in speed".
//
// usage: line_seeded_sweep [--repeat R]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <vector>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/sweep.hpp>

namespace {

using Solver = viscoroll::FastLineSolverD;
using Solution = Solver::Solution;
using Rule = viscoroll::GaussLegendre<double, 6>;  // the fast setting's panels
using Residual = viscoroll::line::LineResidual<double, Rule>;
using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;

/// The residual with its evaluations counted.
struct Counted {
  const Residual& res;
  mutable long residuals = 0, jacobians = 0;
  int unknowns() const { return res.unknowns(); }
  int equations() const { return res.equations(); }
  bool operator()(const Vector& x, Vector& r) const {
    ++residuals;
    return res(x, r);
  }
  bool jacobian(const Vector& x, Vector& r, Matrix& j) const {
    ++jacobians;
    return res.jacobian(x, r, j);
  }
};

struct Direct {
  Solution sol;
  int iterations = 0;
  long residuals = 0, jacobians = 0;
  bool converged = false, root = false;
};

/// Levenberg-Marquardt at N from x, then the last stage's least-squares minimisation.
/// `like` supplies the fields other than the shape, d and chi (the same scene).
Direct direct(const Residual& res, Vector x, const Solution& like, int max_iterations) {
  namespace num = viscoroll::numerics;
  const Counted p{res};
  Direct out{.sol = like};
  Vector r(res.equations());
  if (!p(x, r)) return out;
  const num::LeastSquaresOptions<double> settings{.max_iterations = max_iterations};
  auto o = num::levenberg_marquardt(p, x, r, settings);
  out.iterations = o.iterations;
  if (!o.converged && !o.undefined) {
    auto minimisation = settings;
    minimisation.max_iterations = 10 * max_iterations;
    o = num::least_squares_minimum(p, x, r, minimisation);
    out.iterations += o.iterations;
    for (int turn = 0; turn < 4 && o.root_near; ++turn) {
      o = num::levenberg_marquardt(p, x, r, settings);
      out.iterations += o.iterations;
      if (o.converged || o.undefined || !o.minimum) break;
      o = num::least_squares_minimum(p, x, r, minimisation);
      out.iterations += o.iterations;
    }
    if (!o.converged && !o.undefined && r.cwiseAbs().maxCoeff() <= settings.root_tolerance)
      o.converged = true;
  }
  out.converged = o.converged && !o.undefined;
  out.root = out.converged && r.cwiseAbs().maxCoeff() <= settings.root_tolerance;
  out.residuals = p.residuals;
  out.jacobians = p.jacobians;
  out.sol.shape = res.shape(x);
  out.sol.d = res.penetration(x);
  out.sol.chi = viscoroll::detail::line_rolling_friction<Rule>(out.sol);
  return out;
}

/// Largest relative difference of a(0), b(0), l, d, chi.
double difference(const Solution& p, const Solution& q) {
  const auto rel = [](double x, double y) { return std::abs(x - y) / std::abs(x); };
  return std::max({rel(p.a(0), q.a(0)), rel(p.b(0), q.b(0)), rel(p.l(), q.l()), rel(p.d, q.d),
                   rel(p.chi, q.chi)});
}

template <class F>
double best_ms(int repeat, F&& f) {
  double best = 1e300;
  for (int k = 0; k < repeat; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(
        best,
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 3;
  for (int i = 1; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--repeat" && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else {
      std::fprintf(stderr, "usage: line_seeded_sweep [--repeat R]\n");
      return 2;
    }
  }
  const viscoroll::StandardLinearSolid<double> rubber(1, 0.5, 9, 1);
  const Solver solver(rubber, viscoroll::LineOptions::fast());
  const double load = 5.0 / (3 * (1 + 9) * rubber.instantaneous_compliance());  // a0 = 1
  const viscoroll::LineScene<double> base{
      .c1 = 1.0, .c2 = (std::log(20.0) - 1) / 25, .load = load, .speed = 0.0};
  const auto scene = [&](double v) {
    auto s = base;
    s.speed = v;
    return s;
  };
  std::vector<double> speeds;
  for (int i = 0; i < 100; ++i) speeds.push_back(std::pow(10.0, -3 + 6.0 * i / 99));
  const int max_iterations = solver.options().max_iterations;

  std::vector<Solution> seeded;
  double sum_cold = 0, sum_seeded = 0, sum_direct = 0, sum_predicted = 0;
  double worst_seeded = 0, worst_direct = 0, worst_predicted = 0;
  int other_direct = 0, other_predicted = 0, other_seeded = 0;
  std::printf(
      "# i V_tau/a0 | cold: it ms conv root | seeded: it ms conv root diff_cold | "
      "direct: it res jac ms conv root diff_cold diff_seeded | predicted: the same\n");
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const auto sc = scene(speeds[i]);
    Solution cold;
    const double t_cold = best_ms(repeat, [&] { cold = solver.solve(sc); });
    sum_cold += t_cold;
    if (i == 0 || !viscoroll::usable_as_seed(seeded.back())) {
      seeded.push_back(cold);
      sum_seeded += t_cold;
      sum_direct += t_cold;
      sum_predicted += t_cold;
      std::printf("%2zu %.4e | %3d %7.3f %d %d | cold start\n", i, speeds[i], cold.iterations,
                  t_cold, cold.converged, cold.root);
      continue;
    }
    const Solution previous = seeded.back();
    Solution s;
    const double t_seeded = best_ms(repeat, [&] { s = solver.solve(sc, &previous); });
    seeded.push_back(s);
    sum_seeded += t_seeded;
    // The residual is in the solver's units, which are the caller's for this scene (C1 = 1,
    // a0 = 1): checked by the seeded root's residual.
    const Residual res = solver.residual(sc);
    Vector r;
    if (s.root && (!res(res.pack(s.shape, s.d), r) || r.cwiseAbs().maxCoeff() > 1e-6)) {
      std::fprintf(stderr, "the solver's units are not the caller's here\n");
      return 1;
    }
    const Vector from = res.pack(previous.shape, previous.d);
    Direct d, p;
    const double t_direct = best_ms(repeat, [&] { d = direct(res, from, s, max_iterations); });
    const Vector before = i >= 2 && viscoroll::usable_as_seed(seeded[i - 2])
                              ? res.pack(seeded[i - 2].shape, seeded[i - 2].d)
                              : from;
    const Vector predictor = 2 * from - before;
    const double t_predicted =
        best_ms(repeat, [&] { p = direct(res, predictor, s, max_iterations); });
    sum_direct += t_direct;
    sum_predicted += t_predicted;
    const double ds = difference(cold, s), dd = difference(s, d.sol), dp = difference(s, p.sol);
    worst_seeded = std::max(worst_seeded, ds);
    worst_direct = std::max(worst_direct, dd);
    worst_predicted = std::max(worst_predicted, dp);
    other_seeded += ds > 1e-6;
    other_direct += dd > 1e-6;
    other_predicted += dp > 1e-6;
    std::printf(
        "%2zu %.4e | %3d %7.3f %d %d | %3d %7.3f %d %d %.1e | %3d %3ld %3ld %7.3f %d %d "
        "%.1e %.1e | %3d %3ld %3ld %7.3f %d %d %.1e %.1e\n",
        i, speeds[i], cold.iterations, t_cold, cold.converged, cold.root, s.iterations, t_seeded,
        s.converged, s.root, ds, d.iterations, d.residuals, d.jacobians, t_direct, d.converged,
        d.root, difference(cold, d.sol), dd, p.iterations, p.residuals, p.jacobians, t_predicted,
        p.converged, p.root, difference(cold, p.sol), dp);
  }
  std::printf(
      "# sum of the best times, ms: cold %.1f, seeded %.1f, direct %.1f and predicted "
      "%.1f (each with the cold starts where there is no root to seed from)\n",
      sum_cold, sum_seeded, sum_direct, sum_predicted);
  std::printf(
      "# largest difference: seeded - cold %.1e (%d speeds over 1e-6), direct - seeded "
      "%.1e (%d), predicted - seeded %.1e (%d)\n",
      worst_seeded, other_seeded, worst_direct, other_direct, worst_predicted, other_predicted);
}
