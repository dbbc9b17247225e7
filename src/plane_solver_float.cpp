// viscoroll::compiled (docs/building.md, "Compiled mode"): one solver instantiated once,
// PlaneSolver<float, StandardLinearSolid<float>>.
// Compiled with VISCOROLL_COMPILED like its users, so that the other solvers' explicit
// instantiation declarations keep them out of this file (they have files of their own).
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_solver.hpp>

namespace viscoroll {

template class PlaneSolver<float, StandardLinearSolid<float>>;

}  // namespace viscoroll
