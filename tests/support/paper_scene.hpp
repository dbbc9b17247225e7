// The paper's 3-D scene for line-solver tests (Panek & Kalker 1980, Section 7): f = 9, nu = 0.5,
// tau = 1, C1 = 1, C2/C1 = (ln 20 - 1)/25, and the load whose static long-term contact has
// a0 = 1 (so that l0 = 5 a0).
#pragma once

#include <cmath>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>

namespace viscoroll::testing {

struct PaperScene {
  StandardLinearSolid<double> material{1, 0.5, 9, 1};
  LineScene<double> scene(double vtau) const {
    const double load = 5.0 / (3 * 10 * material.instantaneous_compliance());
    return {1, (std::log(20.0) - 1) / 25, load, vtau};
  }
  /// The line solver of this material at N = terms, every other option the default.
  LineSolverD solver(int terms) const {
    LineOptions options;
    options.terms = terms;
    return LineSolverD(material, options);
  }
};

}  // namespace viscoroll::testing
