// viscoroll::compiled (docs/building.md, "Compiled mode"): the rolling line contact of the roller
// profiles (roller/profile.hpp) over double for the standard linear solid: the member template
// LineSolver<double, StandardLinearSolid<double>>::solve(const LineProfileScene<Profile>&, ...)
// for the ellipsoid, the crowned cylinder, the logarithmic crown and the tabulated drop.
// Compiled with VISCOROLL_COMPILED like its users (line_solver.hpp declares these instantiations).
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/roller/profile.hpp>

namespace viscoroll {

using Solver = LineSolver<double, StandardLinearSolid<double>>;
template Solver::Solution Solver::solve(const LineProfileScene<EllipsoidProfile<double>>&,
                                        const Solver::Solution*) const;
template Solver::Solution Solver::solve(const LineProfileScene<CrownedCylinder<double>>&,
                                        const Solver::Solution*) const;
template Solver::Solution Solver::solve(const LineProfileScene<LogarithmicCrown<double>>&,
                                        const Solver::Solution*) const;
template Solver::Solution Solver::solve(const LineProfileScene<TabulatedProfile<double>>&,
                                        const Solver::Solution*) const;

}  // namespace viscoroll
