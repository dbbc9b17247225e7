// viscoroll::compiled (docs/building.md, "Compiled mode"): one solver instantiated once,
// BemSolver<long double, StandardLinearSolid<long double>> with its default memory-panel rule.
// Compiled with VISCOROLL_COMPILED like its users, so that the other solvers' explicit
// instantiation declarations keep them out of this file (they have files of their own).
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>

namespace viscoroll {

template class BemSolver<long double, StandardLinearSolid<long double>>;

}  // namespace viscoroll
