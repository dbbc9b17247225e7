// Consumes the installed viscoroll package: find_package(viscoroll) + viscoroll::viscoroll.
#include <iostream>
#include <viscoroll/material/standard_linear_solid.hpp>

int main() {
  const viscoroll::StandardLinearSolid<double> material(1.0, 0.3, 9.0, 1.0);
  std::cout << "long-term compliance: " << material.long_term_compliance() << '\n';
  return 0;
}
