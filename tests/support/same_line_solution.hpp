// Bitwise equality of two line solutions in what a user reads of them (converged, iterations,
// a(0), b(0), l, d, chi): for tests of paths that must give the same answer to the bit, such as a
// sweep on any number of threads or a seed set aside for the cold start.
#pragma once

#include <catch2/catch.hpp>
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

}  // namespace viscoroll::testing
