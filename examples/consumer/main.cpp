// Consumes the installed viscoroll package: find_package(viscoroll) + viscoroll::viscoroll.
// Solves the plane rolling problem once and checks the result against its own invariants, so
// the install_and_consume test fails if the installed headers do not work.
#include <cmath>
#include <iostream>
#include <viscoroll/viscoroll.hpp>

int main() {
  const viscoroll::PlaneSolverD solver(viscoroll::StandardLinearSolid<double>(1.0, 0.3, 9.0, 1.0));
  const auto s = solver.solve({.c1 = 1.0, .load = 1.0, .speed = 1.0});
  const auto peak = s.peak();
  std::cout << "a = " << s.a << ", b = " << s.b << ", chi = " << s.chi
            << ", pmax = " << peak.pressure << " at x = " << peak.x << '\n';
  // The contact lies between the glassy and the long-term Hertz widths, ahead of the axis.
  const bool ok = s.converged && s.a < s.a_long_term && s.a > s.a_long_term / std::sqrt(10.0) &&
                  s.b > 0 && s.chi > 0 && peak.pressure > 0;
  return ok ? 0 : 1;
}
