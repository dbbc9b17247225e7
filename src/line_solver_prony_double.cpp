// viscoroll::compiled (docs/building.md, "Compiled mode"): one solver instantiated once,
// LineSolver<double, PronyRelaxation<double>>::solve (a measured rubber's spectrum) on the paper's
// ellipsoid (LineScene) and the roller profiles (solve_profile, every profile through ProfileView).
// Compiled with VISCOROLL_COMPILED like its users, so that the other solvers' explicit
// instantiation declarations keep them out of this file (they have files of their own).
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony.hpp>

namespace viscoroll {

// Its entry point only: the class's private steps are those of a single relaxation time.
using Solver = LineSolver<double, PronyRelaxation<double>>;
template Solver::Solution Solver::solve(const LineScene<double>&, const Solver::Solution*) const;
template Solver::Solution Solver::solve_profile(const LineProfileScene<ProfileView<double>>&,
                                                const Solver::Solution*) const;

}  // namespace viscoroll
