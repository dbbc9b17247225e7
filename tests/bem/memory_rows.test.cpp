// Many memory terms at once (docs/bem.md, "Many memory terms"): the rows of MemoryRows, whose
// lengths share their panels' nodes, against memory_row's one length at a time, and the influence
// table of a twenty-term spectrum against the term-by-term sum of one-term tables.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <vector>
#include <viscoroll/bem/influence_operator.hpp>
#include <viscoroll/bem/rectangle_influence.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_memory_rows {

using viscoroll::PronyTerm;
using viscoroll::bem::InfluenceTable;
using viscoroll::bem::memory_row;
using viscoroll::bem::MemoryRows;

TEST_CASE("bem: memory rows of many lengths at once are memory_row's", "[bem]") {
  // L/hx from 1/64 (the shared panels graded towards X_i) to 1e17 (near the glassy cut of
  // BemSolver), on the kinked row Y = 0 (graded to the last bit), a row inside the kink's reach
  // (hy < hx here: |Y| - hy/2 < hx) and smooth rows. The two are different panels of the same
  // integrals and differ by rounding, which the recurrence (B4) accumulates over up to 2m step
  // integrals of a few dozen nodes each: 1e-12 ~ 2m 100 eps; measured at most 4.9e-15 here (both
  // weights take the panels' offsets from X_i, so no error of m hx eps/L enters).
  const double hx = 0.1, hy = 0.06;
  const int m = 20;
  const std::vector<double> lengths{hx / 64, hx / 17,  hx / 8,   hx / 3,    hx,
                                    7 * hx,  1e2 * hx, 1e4 * hx, 1e10 * hx, 1e17 * hx};
  const MemoryRows<double> shared(m, hx, hy, lengths);
  for (const double y : {0.0, 0.06, 0.3, 3.0}) {
    const auto rows = shared(y);
    REQUIRE(rows.size() == lengths.size());
    for (std::size_t t = 0; t < lengths.size(); ++t) {
      const auto one = memory_row<double>(m, y, hx, hy, lengths[t]);
      REQUIRE(rows[t].size() == one.size());
      double largest = 0, diff = 0;
      for (std::size_t i = 0; i < one.size(); ++i) {
        largest = std::max(largest, std::abs(one[i]));
        diff = std::max(diff, std::abs(rows[t][i] - one[i]));
      }
      INFO("Y = " << y << ", L/hx = " << lengths[t] / hx);
      CHECK(diff <= 1e-12 * largest);
    }
  }
}

TEST_CASE("bem: a twenty-term table is the sum of its one-term tables", "[bem]") {
  // The spectrum of benchmarks/bench_bem.cpp (f_k = 0.5, tau_k = 1e-3 .. 1e3 log-spaced) at V = 1
  // on a 27 x 27 grid of cells 0.126 x 0.654 (the paper's grid N = 8): V tau_k/hx = 0.008 .. 8000,
  // every term on the shared nodes. Each one-term table (memory_row) holds K_e once; the sum
  // K_e + sum_k (T_k - K_e) is the twenty-term table to rounding: 1e-12 relative per coefficient
  // (measured 1.3e-14).
  const viscoroll::BemGrid<double> grid{27, 27, 0.126, 0.654};
  const double c = 0.08, speed = 1.0;
  std::vector<PronyTerm<double>> terms;
  for (int k = 0; k < 20; ++k) terms.push_back({0.5, std::pow(10.0, -3 + 6.0 * k / 19)});
  const InfluenceTable<double> all(grid, c, terms, speed);
  const InfluenceTable<double> elastic(grid, c, {}, speed);
  std::vector<InfluenceTable<double>> one;
  for (const auto& t : terms) one.emplace_back(grid, c, std::vector<PronyTerm<double>>{t}, speed);
  double worst = 0;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = -(grid.nx - 1); i < grid.nx; ++i) {
      double sum = elastic(i, j);
      for (const auto& table : one) sum += table(i, j) - elastic(i, j);
      worst = std::max(worst, std::abs(all(i, j) - sum) / std::abs(sum));
    }
  INFO("largest relative difference " << worst);
  CHECK(worst <= 1e-12);
}

TEST_CASE("bem: the row |Y| = hy/2 through the cells' corners is graded as its neighbours",
          "[bem]") {
  // At |Y| = hy/2 the row passes through the corners of the cell, where K_e has a logarithmic
  // y-derivative; the grading (B4) must be the full one of the rows inside (it read
  // log(hx/0) there before). K_e and so M_L are continuous in Y with modulus d ln(1/d): rows at
  // hy/2 (1 -+ 1e-12) differ from it by about 1e-12 * 28 relative, so 1e-10 is the bound, far
  // under what an ungraded kink leaves.
  const double hx = 0.1, hy = 0.06;
  const int m = 6;
  for (const double length : {hx / 8, hx, 10 * hx}) {
    const auto at = memory_row(m, hy / 2, hx, hy, length);
    const auto below = memory_row(m, hy / 2 * (1 - 1e-12), hx, hy, length);
    const auto above = memory_row(m, hy / 2 * (1 + 1e-12), hx, hy, length);
    const MemoryRows<double> shared(m, hx, hy, {length});
    const auto row = shared(hy / 2).front();
    for (std::size_t i = 0; i < at.size(); ++i) {
      INFO("L/hx = " << length / hx << ", i = " << int(i) - m);
      REQUIRE(std::isfinite(at[i]));
      CHECK(std::abs(at[i] - below[i]) <= 1e-10 * std::abs(at[i]));
      CHECK(std::abs(at[i] - above[i]) <= 1e-10 * std::abs(at[i]));
      CHECK(std::abs(row[i] - at[i]) <= 1e-13 * std::abs(at[i]));
    }
  }
  CHECK(viscoroll::bem::kink_grading_depth(hy / 2, hx, hy) == 53);
  CHECK(viscoroll::bem::kink_grading_depth(std::nextafter(hy / 2, 1.0), hx, hy) == 53);
  CHECK(viscoroll::bem::kink_grading_depth(hy / 2 + hx / 4, hx, hy) == 4);
  CHECK(viscoroll::bem::kink_grading_depth(hy / 2 + hx, hx, hy) == 0);
}

}  // namespace test_memory_rows
