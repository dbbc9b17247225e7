// Tests of the convolution operator (docs/bem.md B6-B7): the FFT apply against the direct sum,
// the table's symmetry (even in y; not even in x when rolling), and the Prony-series memory
// (B10) reducing to the standard linear solid.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <vector>
#include <viscoroll/bem/influence_operator.hpp>
#include <viscoroll/material/generalized_maxwell.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_influence_operator {

using viscoroll::BemGrid;
using viscoroll::GeneralizedMaxwell;
using viscoroll::PronyTerm;
using viscoroll::StandardLinearSolid;
using namespace viscoroll::bem;

TEMPLATE_TEST_CASE("bem: FFT apply equals the direct sum", "[bem]", float, double, long double) {
  using Real = TestType;
  const BemGrid<Real> grid{9, 7, Real(0.1), Real(0.4)};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(0, 1);
  for (const Real speed : {Real(0), Real(0.3)}) {
    const InfluenceTable<Real> table(grid, Real(0.08), {PronyTerm<Real>{Real(9), Real(1)}}, speed);
    const ConvolutionOperator<Real> op(table);
    std::vector<Real> p(grid.size()), fast(grid.size()), direct(grid.size());
    for (auto& v : p) v = Real(uni(rng));
    op.apply(p, fast);
    apply_direct(table, p, direct);
    Real scale = 0;
    for (std::size_t q = 0; q < p.size(); ++q) scale = std::max(scale, std::abs(direct[q]));
    // FFT rounding: O(eps log(n)) times the largest entry. FFTW transforms long double in long
    // double; Eigen's kissfft computes its twiddle factors in double, so there a long double
    // transform is accurate to double's eps, not its own.
    const bool fftw = std::string(transform_backend<Real>()) == "FFTW";
    const Real e = fftw ? std::numeric_limits<Real>::epsilon()
                        : std::max(std::numeric_limits<Real>::epsilon(),
                                   Real(std::numeric_limits<double>::epsilon()));
    for (std::size_t q = 0; q < p.size(); ++q)
      CHECK(std::abs(fast[q] - direct[q]) <= 200 * e * scale);
  }
}

TEST_CASE("bem: the rolling kernel is even in y and not in x", "[bem]") {
  const BemGrid<double> grid{11, 11, 0.1, 0.3};
  const InfluenceTable<double> rolling(grid, 1.0, {PronyTerm<double>{9.0, 1.0}}, 0.2);
  const InfluenceTable<double> still(grid, 1.0, {PronyTerm<double>{9.0, 1.0}}, 0.0);
  for (int j = 0; j < 5; ++j) CHECK(rolling(3, j) == rolling(3, -j));
  // Memory looks ahead (Eq. 2): a field point behind the load (offset di < 0) has already
  // passed under it and crept; one ahead of it (di > 0) has not.
  CHECK(rolling(-2, 0) > rolling(2, 0));
  CHECK(still(2, 0) == still(-2, 0));
  // V tau = 0: the long-term compliance, (1 + f) K_e.
  CHECK(still(1, 1) == Approx(10 * rectangle_influence(0.1, 0.3, 0.1, 0.3)).epsilon(1e-14));
}

TEST_CASE("bem: Prony memory terms add (B10) and one term is the standard linear solid", "[bem]") {
  const BemGrid<double> grid{7, 5, 0.1, 0.3};
  const StandardLinearSolid<double> sls(1.0, 0.3, 9.0, 2.0);
  const GeneralizedMaxwell<double> one(1.0, 0.3, {{9.0, 2.0}});
  const GeneralizedMaxwell<double> split(1.0, 0.3, {{4.0, 2.0}, {5.0, 2.0}});
  const double c = sls.instantaneous_compliance();
  REQUIRE(one.instantaneous_compliance() == c);
  REQUIRE(one.creep_ratio() == 9.0);
  const InfluenceTable<double> a(grid, c, memory_terms_of(sls), 0.7);
  const InfluenceTable<double> b(grid, c, memory_terms_of(one), 0.7);
  const InfluenceTable<double> s(grid, c, memory_terms_of(split), 0.7);
  for (int i = -6; i <= 6; ++i)
    for (int j = 0; j < 5; ++j) {
      CHECK(a(i, j) == b(i, j));
      CHECK(s(i, j) == Approx(a(i, j)).epsilon(1e-14));
    }
  // Creep function (B9): J(0) mu_D = 1, J(inf) mu_D = 1 + sum f_k.
  CHECK(split.creep(0.0) == 1.0);
  CHECK(split.creep(1e6) == Approx(10.0).epsilon(1e-15));
  CHECK_THROWS_WITH((GeneralizedMaxwell<double>(1.0, 0.3, {{1.0, 1.0}, {-1.0, 1.0}})),
                    Catch::Contains("f[1] = -1"));
  CHECK_THROWS_WITH((GeneralizedMaxwell<double>(1.0, 0.3, {{1.0, -2.0}})),
                    Catch::Contains("tau[0] = -2"));
}

TEST_CASE("bem: the table is the same for any thread count", "[bem]") {
  // Rows are independent (influence_operator.hpp); 2 and 5 threads give the serial table bit for
  // bit, with a rolling memory term (the recurrence (B4)) and the graded row dj = 0.
  const BemGrid<double> grid{13, 9, 0.1, 0.3};
  const std::vector<PronyTerm<double>> terms{{9.0, 1.0}, {3.0, 0.05}};
  const InfluenceTable<double> serial(grid, 0.08, terms, 0.7);
  for (const int threads : {2, 5, 64}) {
    const InfluenceTable<double> parallel(grid, 0.08, terms, 0.7, threads);
    for (int j = 0; j < grid.ny; ++j)
      for (int i = -(grid.nx - 1); i < grid.nx; ++i) CHECK(parallel(i, j) == serial(i, j));
  }
}

TEST_CASE("bem: operators of several grids applied on several threads", "[bem]") {
  // FFTW's plans are made once per padded size under a mutex and executed on each operator's own
  // arrays: operators built and applied concurrently on four threads (two of one grid, two of
  // others) give the serial results bit for bit; a copy shares the kernel's spectrum.
  const std::vector<BemGrid<double>> grids{
      {9, 7, 0.1, 0.4}, {9, 7, 0.1, 0.4}, {15, 11, 0.2, 0.1}, {21, 5, 0.1, 0.3}};
  const auto run = [](const BemGrid<double>& grid) {
    const InfluenceTable<double> table(grid, 0.08, {PronyTerm<double>{9.0, 1.0}}, 0.3);
    const ConvolutionOperator<double> op(table);
    const ConvolutionOperator<double> copy(op);
    std::vector<double> p(grid.size()), u(grid.size()), v(grid.size());
    for (std::size_t q = 0; q < p.size(); ++q) p[q] = 1 + double(q % 5) / 7;
    for (int k = 0; k < 20; ++k) op.apply(p, u);
    copy.apply(p, v);
    CHECK(u == v);
    return u;
  };
  std::vector<std::vector<double>> serial, parallel(grids.size());
  for (const auto& g : grids) serial.push_back(run(g));
  {
    std::vector<std::jthread> pool;
    for (std::size_t k = 0; k < grids.size(); ++k)
      pool.emplace_back([&, k] { parallel[k] = run(grids[k]); });
  }
  for (std::size_t k = 0; k < grids.size(); ++k) CHECK(parallel[k] == serial[k]);
}

}  // namespace test_influence_operator
