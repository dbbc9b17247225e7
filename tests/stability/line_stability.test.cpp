// Stability matrix of the line solver in float, double and long double (docs/stability.md);
// the scenes and checks are described in line_stability_support.hpp. cpp_bin_float_50:
// line_stability_multiprecision.test.cpp.
#include <catch2/catch.hpp>

#include "line_stability_support.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_stability {

TEMPLATE_TEST_CASE("stability: line solver closed forms over l0/a0 x f x speed",
                   "[stability][line]", float, double, long double) {
  closed_form_matrix<TestType>();
}

TEST_CASE("stability: line solver, one iterated cell", "[stability][line]") {
  const auto o = check_iterated<double>({1.0, 9.0, 5.0}, 2);
  CHECK(o.converged);  // measured: 7 iterations, residual 4.5e-16
}

TEST_CASE("stability: line solver matrix, V tau/a0 x f x l0/a0", "[stability][line][slow]") {
  // Along each axis from the paper's cell (V tau = a0, f = 9, l0/a0 = 5), then the corners.
  const std::vector<Cell<double>> cells{
      {1e-4, 9, 5},   {1e-2, 9, 5},  {1, 9, 5},       {1e2, 9, 5},      {1e4, 9, 5},
      {1, 1e-2, 5},   {1, 1e4, 5},   {1, 9, 3},       {1, 9, 1000},     {1e-4, 1e4, 5},
      {1e-2, 1e4, 5}, {1e4, 1e4, 5}, {1e-4, 9, 1000}, {1e4, 9, 1000},   {1, 1e4, 1000},
      {1e-2, 9, 3},   {1e4, 9, 3},   {1e-4, 9, 3},    {1e4, 1e4, 1000}, {1e-4, 1e4, 1000}};
  for (const auto& cell : cells) check_iterated<double>(cell, 4);
}

TEST_CASE("stability: line solver in float and long double", "[stability][line][slow]") {
  for (const Cell<double> c :
       {Cell<double>{1, 9, 5}, Cell<double>{1e-2, 9, 5}, Cell<double>{1e4, 9, 5},
        Cell<double>{1, 1e4, 5}, Cell<double>{1, 9, 1000}}) {
    const auto ref = check_iterated<double>(c, 4);
    const auto fl = check_iterated<float>({c.v, c.f, c.rho}, 4);
    compare_with_double(fl, ref, "line float " + c.name());
    if (c.v == 1 && c.rho == 5) {
      const auto ld = check_iterated<long double>({c.v, c.f, c.rho}, 4);
      compare_with_double(ld, ref, "line long double " + c.name());
    }
  }
}

}  // namespace test_line_stability
