// viscoroll::compiled (docs/building.md, "Compiled mode"): the fast setting's solver instantiated
// once, FastLineSolverD = LineSolver<double, StandardLinearSolid<double>, GaussLegendre<double,
// 6>>, and its residual LineResidual<double, GaussLegendre<double, 6>>. Compiled with
// VISCOROLL_COMPILED like its users, so that the other solvers' explicit instantiation declarations
// keep them out of this file (they have files of their own).
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

namespace viscoroll {

template class LineSolver<double, StandardLinearSolid<double>, GaussLegendre<double, 6>>;
template class line::LineResidual<double, GaussLegendre<double, 6>>;

}  // namespace viscoroll
