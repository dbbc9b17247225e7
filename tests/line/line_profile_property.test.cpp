// A property of LineSolver::solve(LineProfileScene) over random tilted crowned rollers (docs/
// validation.md, "Tilted rollers"): every solve ends converged with a contact (d, l, a at the
// centre positive, chi finite and not negative, the centre finite) or not converged with a
// reason; nothing else (no exception for valid input, no non-finite number called converged).
// Flat parts 0 ... 20 and crown radii 5 ... 55 (C1 = 1), tilts up to +-0.01, loads 0.03 ... 3 of
// (1 + f) c P, speeds V tau 1e-3 ... 1e3 or 0, on the standard linear solid (f = 3) and on the
// two-term spectrum of validation.md, N = 8 and 6. VISCOROLL_PROPERTY_CASES sets the count
// (default 120).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_profile_property {

using viscoroll::CrownedCylinder;
using viscoroll::LineProfileScene;
using viscoroll::Tilted;
using Roller = Tilted<CrownedCylinder<double>>;

namespace {

int cases() {
  const char* text = std::getenv("VISCOROLL_PROPERTY_CASES");
  return text != nullptr ? std::atoi(text) : 120;
}

/// Checks one solve's outcome; returns whether it converged.
template <class Solver>
bool check(const Solver& solver, const Roller& roller, double load, double speed,
           const std::string& where) {
  const auto s = solver.solve(LineProfileScene<Roller>{roller, load, speed});
  INFO(where << ": " << s.reason);
  CHECK(s.warning_codes.size() == s.warnings.size());
  if (!s.converged) {
    CHECK_FALSE(s.reason.empty());
    CHECK(s.code != viscoroll::StopCode::converged);
    return false;
  }
  CHECK(std::isfinite(s.d));
  CHECK(s.d > 0);
  CHECK(s.l() > 0);
  CHECK(std::isfinite(s.shape.centre));
  CHECK(s.a(s.shape.centre) > 0);
  CHECK(std::isfinite(s.chi));
  CHECK(s.chi >= 0);
  return true;
}

}  // namespace

TEST_CASE("line profile property: random tilted crowned rollers end in a contact or a reason",
          "[line][profile][slow]") {
  std::mt19937_64 random(21);
  std::uniform_real_distribution<double> u(0, 1);
  const viscoroll::StandardLinearSolid<double> solid(1.0, 0.5, 3.0, 1.0);
  const viscoroll::PronyCreep<double> spectrum(1.0, 0.5, {{3.0, 0.05}, {6.0, 5.0}});
  viscoroll::LineOptions options;
  options.terms = 8;
  const viscoroll::LineSolverD one(solid, options);
  options.terms = 6;
  const viscoroll::LineSolver<double, viscoroll::PronyCreep<double>> many(spectrum, options);
  int converged = 0;
  const int n = cases();
  for (int i = 0; i < n; ++i) {
    const double flat = u(random) < 0.3 ? 0.0 : 20 * u(random), crown = 5 + 50 * u(random);
    const double load =
        0.3 * std::pow(10.0, -1 + 2 * u(random)) / (4 * solid.instantaneous_compliance());
    const double speed = u(random) < 0.1 ? 0.0 : std::pow(10.0, -3 + 6 * u(random));
    const double tilt = (u(random) - 0.5) * 0.02 * u(random);
    const Roller roller(CrownedCylinder<double>(1.0, flat, crown), tilt);
    const std::string where = "case " + std::to_string(i) + ": flat " + std::to_string(flat) +
                              ", crown " + std::to_string(crown) + ", load " +
                              std::to_string(load) + ", speed " + std::to_string(speed) +
                              ", tilt " + std::to_string(tilt);
    converged += u(random) < 0.3 ? check(many, roller, load, speed, "spectrum " + where)
                                 : check(one, roller, load, speed, where);
  }
  // Most converge (293 of 300 with another seed, docs/validation.md); a few end with a reason.
  CHECK(converged > n * 9 / 10);
}

}  // namespace test_line_profile_property
