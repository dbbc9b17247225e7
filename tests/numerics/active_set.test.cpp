// Tests of the primal-dual active-set solver (numerics/active_set.hpp) on problems with known
// solutions, independent of the boundary-element solver: a 1-D contact of a parabolic punch on a
// dense flexibility matrix, symmetric and not, against the solution found by enumerating every
// active set with Eigen's LU; and a 3 x 3 problem on which the iteration cycles from one start and
// converges from another (found by exhaustive search over small integer problems).
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>
#include <viscoroll/numerics/active_set.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_active_set {

namespace {

using Matrix = Eigen::MatrixXd;
using Vector = Eigen::VectorXd;
using viscoroll::numerics::ActiveSetSettings;
using viscoroll::numerics::ActiveSetState;
using viscoroll::numerics::LoadEquation;

/// K p, preconditioned by a fixed approximate inverse of K (the inverse of its symmetric part,
/// of which the solver uses the rows and columns of the active set) or by nothing (an empty one).
struct DenseOperator {
  Matrix k;
  Matrix inverse;

  void apply(const std::vector<double>& p, std::vector<double>& u) const {
    const auto n = k.rows();
    Eigen::Map<Vector>(u.data(), n) = k * Eigen::Map<const Vector>(p.data(), n);
  }
  void precondition(const std::vector<double>& v, std::vector<double>& out) const {
    const auto n = k.rows();
    if (inverse.size() == 0)
      out = v;
    else
      Eigen::Map<Vector>(out.data(), n) = inverse * Eigen::Map<const Vector>(v.data(), n);
  }
};
static_assert(viscoroll::numerics::ContactOperator<DenseOperator, double>);

/// The bordered matrix of (AS1) on the active set `cells`, load row scaled by s w / P.
Matrix bordered(const Matrix& k, const std::vector<Eigen::Index>& cells,
                const LoadEquation<double>& load) {
  const auto na = static_cast<Eigen::Index>(cells.size());
  Matrix a = Matrix::Zero(na + 1, na + 1);
  for (Eigen::Index r = 0; r < na; ++r) {
    for (Eigen::Index c = 0; c < na; ++c)
      a(r, c) = k(cells[static_cast<std::size_t>(r)], cells[static_cast<std::size_t>(c)]);
    a(r, na) = -1;
    a(na, r) = load.scale * load.weight / load.total;
  }
  return a;
}

struct Reference {
  std::vector<Eigen::Index> cells;
  Vector p;
  double d;
};

/// Every active set that solves the complementarity problem: p_A >= 0 from the LU solve of
/// (AS1) and g >= 0 off A. The margin 1e-9 is far above the LU's rounding (cond ~ 1e3 times eps)
/// and far below the smallest non-zero |p_q| or |g_q| of the problems here.
std::vector<Reference> enumerate(const Matrix& k, const Vector& h,
                                 const LoadEquation<double>& load) {
  const auto n = k.rows();
  std::vector<Reference> found;
  for (long mask = 1; mask < (1L << n); ++mask) {
    std::vector<Eigen::Index> cells;
    for (Eigen::Index q = 0; q < n; ++q)
      if (mask & (1L << q)) cells.push_back(q);
    const auto na = static_cast<Eigen::Index>(cells.size());
    Vector b(na + 1);
    for (Eigen::Index r = 0; r < na; ++r) b[r] = -h[cells[static_cast<std::size_t>(r)]];
    b[na] = load.scale;
    const Vector x = bordered(k, cells, load).fullPivLu().solve(b);
    Vector p = Vector::Zero(n);
    for (Eigen::Index r = 0; r < na; ++r) p[cells[static_cast<std::size_t>(r)]] = x[r];
    const Vector g = k * p - Vector::Constant(n, x[na]) + h;
    bool ok = true;
    for (Eigen::Index q = 0; q < n; ++q)
      ok = ok && (mask & (1L << q) ? p[q] > -1e-9 : g[q] > -1e-9);
    if (ok) found.push_back({cells, p, x[na]});
  }
  return found;
}

}  // namespace

TEST_CASE("numerics: active set solves a 1-D contact as enumeration does", "[numerics]") {
  // A parabolic punch h = x^2 on 12 cells of [-1, 1] pressed with total 0.1 into a flexibility
  // matrix exp(-|x_i - x_j| / 0.5) (positive definite), and the same with the non-symmetric part
  // 0.5 sign(x_i - x_j) exp(...) of a rolling contact (the symmetric part unchanged: the
  // problem stays monotone, so its solution is unique).
  constexpr Eigen::Index n = 12;
  Vector x(n), h(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    x[i] = -1 + double(2 * i + 1) / double(n);
    h[i] = x[i] * x[i];
  }
  const LoadEquation<double> load{.weight = 2.0 / n, .total = 0.1, .scale = 1.0};
  const ActiveSetSettings<double> settings{
      .tolerance = 1e-12, .restart = 4, .max_iterations = 50, .max_krylov_iterations = 10000};
  for (const double skew : {0.0, 0.5}) {
    Matrix k(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) {
        const double s = x[i] > x[j] ? 1.0 : x[i] < x[j] ? -1.0 : 0.0;
        k(i, j) = std::exp(-std::abs(x[i] - x[j]) / 0.5) * (1 + skew * s);
      }
    const auto refs = enumerate(k, h, load);
    REQUIRE(refs.size() == 1);
    const Reference& ref = refs.front();
    // A proper contact: some cells out of it, so the iteration has work to do.
    REQUIRE(ref.cells.size() > 1);
    REQUIRE(ref.cells.size() < static_cast<std::size_t>(n));
    const Matrix a = bordered(k, ref.cells, load);
    const Eigen::JacobiSVD<Matrix> svd(a);
    const double cond = svd.singularValues()[0] / svd.singularValues()[a.rows() - 1];
    const Matrix inverse = ((k + k.transpose()) / 2).inverse();
    // Every set solved to the tolerance, or the early ones to 1e-2 only (inexact early solves:
    // the stopping test is the exact one, so the answer is the same to the same bound); the final
    // set solved once more to 1e-14, or to 1e-30, out of GMRES' reach (the solve counts, having
    // reached the tolerance).
    for (const double coarse : {0.0, 1e-2})
      for (const double final_tolerance : {0.0, 1e-14, 1e-30})
        for (const bool preconditioned : {false, true}) {
          INFO("skew " << skew << ", preconditioned " << preconditioned << ", coarse " << coarse
                       << ", final " << final_tolerance);
          // Start from every cell in contact with no pressure.
          ActiveSetState<double> state{
              .p = std::vector<double>(n, 0.0), .d = 0.0, .active = std::vector<char>(n, 1)};
          ActiveSetSettings<double> s = settings;
          s.coarse_tolerance = coarse;
          s.final_tolerance = final_tolerance;
          const auto report = viscoroll::numerics::active_set(
              DenseOperator{k, preconditioned ? inverse : Matrix()},
              std::vector<double>(h.data(), h.data() + n), load, s, state);
          CHECK(report.converged);
          CHECK(report.code == viscoroll::StopCode::converged);
          CHECK(report.iterations > 1);
          CHECK(report.krylov_iterations > settings.restart);
          Vector got(static_cast<Eigen::Index>(ref.cells.size()) + 1), want(got.size());
          for (std::size_t r = 0; r < ref.cells.size(); ++r) {
            const auto q = static_cast<std::size_t>(ref.cells[r]);
            CHECK(state.active[q]);
            got[static_cast<Eigen::Index>(r)] = state.p[q];
            want[static_cast<Eigen::Index>(r)] = ref.p[ref.cells[r]];
          }
          got[got.size() - 1] = state.d;
          want[want.size() - 1] = ref.d;
          for (Eigen::Index q = 0; q < n; ++q)
            if (ref.p[q] == 0) CHECK(state.p[static_cast<std::size_t>(q)] == 0);
          // GMRES' relative residual <= tolerance (or the final one) bounds the error by cond(A)
          // times it; the reference's LU adds cond(A) times a few eps. Unpreconditioned, GMRES(4)
          // may end the final solve above 1e-14 (a cycle that does not halve the residual): the
          // tolerance's bound.
          const double eps = std::numeric_limits<double>::epsilon();
          const double residual =
              final_tolerance == 1e-14 && preconditioned ? final_tolerance : settings.tolerance;
          CHECK((got - want).norm() <= cond * (residual + 16 * n * eps) * want.norm());
        }
  }
}

TEST_CASE("numerics: active set reports cycling, the iteration limit and an empty set",
          "[numerics]") {
  // K = [1 2 2; 2 2 1; 4 2 3], h = (2, -2, 1), sum p = 1: the only solution is p = (0, 1, 0),
  // d = 0 (g = (4, 0, 3)). From A = {0}: p0 = 1, d = 3, g1 = -3 adds cell 1; on {0, 1}, p1 = -3
  // removes it again: A = {0} repeats.
  Matrix k(3, 3);
  k << 1, 2, 2, 2, 2, 1, 4, 2, 3;
  const std::vector<double> h{2, -2, 1};
  const LoadEquation<double> load{.weight = 1.0, .total = 1.0, .scale = 1.0};
  ActiveSetSettings<double> settings{
      .tolerance = 1e-13, .restart = 4, .max_iterations = 20, .max_krylov_iterations = 100};
  const DenseOperator op{k, Matrix()};
  const auto start = [](std::vector<char> active) {
    return ActiveSetState<double>{.p = std::vector<double>(3, 0.0), .d = 0.0, .active = active};
  };

  auto cycling = start({1, 0, 0});
  const auto cycles = viscoroll::numerics::active_set(op, h, load, settings, cycling);
  CHECK_FALSE(cycles.converged);
  CHECK(cycles.code == viscoroll::StopCode::active_set_cycles);
  CHECK(cycles.iterations == 2);

  auto good = start({0, 1, 0});
  const auto converges = viscoroll::numerics::active_set(op, h, load, settings, good);
  CHECK(converges.converged);
  CHECK(converges.code == viscoroll::StopCode::converged);
  CHECK(converges.iterations == 1);
  // The 2 x 2 system [2 -1; 1 0] (condition number 5.8) solved to relative residual 1e-13.
  CHECK(good.p[0] == 0);
  CHECK(good.p[1] == Approx(1).margin(8 * settings.tolerance));
  CHECK(good.p[2] == 0);
  CHECK(good.d == Approx(0).margin(8 * settings.tolerance));

  settings.max_iterations = 1;
  auto limited = start({1, 0, 0});
  const auto limit = viscoroll::numerics::active_set(op, h, load, settings, limited);
  CHECK_FALSE(limit.converged);
  CHECK(limit.code == viscoroll::StopCode::iteration_limit);
  CHECK(limit.iterations == 1);

  settings.max_iterations = 20;
  settings.max_krylov_iterations = 1;
  auto starved = start({1, 1, 0});
  const auto krylov = viscoroll::numerics::active_set(op, h, load, settings, starved);
  CHECK_FALSE(krylov.converged);
  CHECK(krylov.code == viscoroll::StopCode::linear_solver_failed);
  CHECK(krylov.krylov_iterations == 1);

  auto empty = start({0, 0, 0});
  const auto none = viscoroll::numerics::active_set(op, h, load, settings, empty);
  CHECK_FALSE(none.converged);
  CHECK(none.code == viscoroll::StopCode::empty_contact);
  CHECK(none.iterations == 0);
}

}  // namespace test_active_set
