// viscoroll::compiled (docs/building.md, "Compiled mode"): one solver instantiated once,
// BemSolver<double, PronyRelaxation<double>> (a measured rubber's spectrum).
// Compiled with VISCOROLL_COMPILED like its users, so that the other solvers' explicit
// instantiation declarations keep them out of this file (they have files of their own).
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/material/prony.hpp>

namespace viscoroll {

template class BemSolver<double, PronyRelaxation<double>>;

}  // namespace viscoroll
