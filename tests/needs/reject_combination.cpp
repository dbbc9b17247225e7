// A combination of policies that cannot work must fail to compile with the name of the concept it
// breaks (tests/CMakeLists.txt compiles this file once per case and looks for that name in the
// compiler's message). Not part of any executable.
#include <viscoroll/material/generalized_maxwell.hpp>
#include <viscoroll/material/temperature_shift.hpp>
#include <viscoroll/plane/plane_substrate_solver.hpp>
#include <viscoroll/quadrature/adaptive.hpp>
#include <viscoroll/viscoroll.hpp>

#if VISCOROLL_REJECT_CASE == 1
// A type that is not a constitutive model where the line solver needs one: ConstitutiveModel.
viscoroll::LineSolver<double, double> solver(1.0);
#elif VISCOROLL_REJECT_CASE == 2
// An adaptive rule where the line solver evaluates its kernels on fixed nodes: NodalQuadratureRule.
viscoroll::LineSolver<double, viscoroll::StandardLinearSolid<double>,
                      viscoroll::AdaptiveGaussKronrod<double>>
    solver(viscoroll::StandardLinearSolid<double>(1.0, 0.5, 9.0, 1.0));
#elif VISCOROLL_REJECT_CASE == 3
// A type that is not a constitutive model where the plane solver needs one: ConstitutiveModel.
viscoroll::PlaneSolver<double, double> solver(1.0);
#elif VISCOROLL_REJECT_CASE == 4
// A number where a scene needs a roller profile: RollerProfile.
viscoroll::LineProfileScene<double> scene{};
#elif VISCOROLL_REJECT_CASE == 5
// A number where the plane solver on a body needs a substrate: Substrate.
using Rejected =
    viscoroll::PlaneSubstrateSolver<double, viscoroll::StandardLinearSolid<double>, double>;
Rejected* solver = nullptr;
#elif VISCOROLL_REJECT_CASE == 6
// A material without time_scaled shifted to a temperature: TimeScalable.
struct NoTimes : viscoroll::StandardLinearSolid<double> {
  using viscoroll::StandardLinearSolid<double>::StandardLinearSolid;
  void time_scaled(double) const {}
};
const auto shifted = viscoroll::at_temperature(NoTimes(1.0, 0.5, 9.0, 1.0),
                                               viscoroll::WlfShift<double>(8.86, 101.6, 20.0), 0.0);
#endif
