// What the rolling friction costs (docs/cli.md, "Output"): the rolling-resistance force, the power
// and the energy per revolution of one solution, shared by viscoroll-solve and the Python
// bindings so that every record of every method derives them the same way.
#pragma once

#include <boost/math/constants/constants.hpp>

namespace viscoroll::cli {

/// The scene's numbers behind the derived fields: the load W (total, N; the plane method's per
/// unit length, N/m), the speed V and the roller's rolling radius R (a scene file's `radius`,
/// else 1/c1: the roller's section in the rolling plane is the circle of curvature c1 that steady
/// rolling needs, docs/rollers.md's C1 = 1/R).
struct Duty {
  double load = 0, speed = 0, radius = 0;
};

/// The fields that follow chi in every record: with chi = F/W the rolling-friction coefficient
/// (Eq. 51/54, docs/paper.md),
///   rolling_resistance     F = chi W         (N; N/m for the plane method),
///   power_loss             P = chi W V       (W; W/m),
///   energy_per_revolution  E = chi W 2 pi R  (J; J/m),
/// each evaluated left to right as written. `Record` is a sequence of (key, value) fields built
/// from braces.
template <class Record>
Record engineering_fields(double chi, const Duty& duty) {
  const double two_pi = boost::math::constants::two_pi<double>();
  return {{"rolling_resistance", chi * duty.load},
          {"power_loss", chi * duty.load * duty.speed},
          {"energy_per_revolution", chi * duty.load * two_pi * duty.radius}};
}

}  // namespace viscoroll::cli
