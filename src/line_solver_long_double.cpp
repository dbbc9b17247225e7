// viscoroll::compiled (docs/building.md, "Compiled mode"): one solver instantiated once,
// LineSolver<long double, StandardLinearSolid<long double>>,
// and its residual LineResidual<long double, GaussLegendre<long double, 12>>.
// Compiled with VISCOROLL_COMPILED like its users, so that the other solvers' explicit
// instantiation declarations keep them out of this file (they have files of their own).
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

namespace viscoroll {

template class LineSolver<long double, StandardLinearSolid<long double>>;
template class line::LineResidual<long double, GaussLegendre<long double, 12>>;

}  // namespace viscoroll
