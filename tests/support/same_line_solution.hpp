// Bitwise equality of two line solutions in what a user reads of them (converged, iterations,
// a(0), b(0), l, d, chi): for tests of paths that must give the same answer to the bit, such as a
// sweep on any number of threads or a seed set aside for the cold start. And the same five
// quantities within a bound, for paths that must land on the same root of the same equations.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <viscoroll/line/line_solver.hpp>

namespace viscoroll::testing {

/// Bitwise equality of two doubles (a NaN equal to the same NaN).
inline bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

inline void require_same_solution(const LineSolverD::Solution& x, const LineSolverD::Solution& y) {
  REQUIRE(x.converged == y.converged);
  REQUIRE(x.iterations == y.iterations);
  REQUIRE(same_bits(x.a(0.0), y.a(0.0)));
  REQUIRE(same_bits(x.b(0.0), y.b(0.0)));
  REQUIRE(same_bits(x.l(), y.l()));
  REQUIRE(same_bits(x.d, y.d));
  REQUIRE(same_bits(x.chi, y.chi));
}

/// The same root within `bound`: a(0), l, d and chi relative to the reference's, b(0) relative to
/// its a(0) (b(0) passes through zero). Any line solution type (one relaxation time or a spectrum).
template <class Solution>
void check_same_root(const Solution& x, const Solution& reference, double bound) {
  CHECK(std::abs(x.a(0) / reference.a(0) - 1) < bound);
  CHECK(std::abs(x.b(0) - reference.b(0)) / reference.a(0) < bound);
  CHECK(std::abs(x.l() / reference.l() - 1) < bound);
  CHECK(std::abs(x.d / reference.d - 1) < bound);
  CHECK(std::abs(x.chi / reference.chi - 1) < bound);
}

}  // namespace viscoroll::testing
