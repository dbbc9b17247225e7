// Two independent solutions of the static elastic crowned roller: the exact BEM on the
// profile (bem_profile.hpp) and the line theory's static contact for any profile
// (line/static_profile_contact.hpp, docs/theory.md section 15). They share nothing but the
// profile. Measured at grid N = 16 (docs/validation.md, "Crowned rollers"): d to 0.3%, the ends
// to 1.2%, F0(0) to 0.7%, the edge peak's ratio f0_max/F0(0) to 1.7% (N = 32 moves the BEM's by
// up to 2.4%, 0.4% and 0.3%); the tolerances below are those figures with that change as margin.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <viscoroll/bem/bem_profile.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/line/static_profile_contact.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_bem_profile_static {

namespace {

using viscoroll::CrownedCylinder;

void check_static_crowned(double flat_length) {
  const viscoroll::Elastic<double> elastic(1.0, 0.5);
  const double c = elastic.instantaneous_compliance(), load = 0.3 / c;
  const CrownedCylinder<double> roller(1.0, flat_length, 20.0);
  const auto line = viscoroll::static_profile_contact(roller, c * load);
  REQUIRE(line.converged);
  viscoroll::BemOptions options;
  options.grid = 16;
  const auto s = viscoroll::BemSolver(elastic, options)
                     .solve(viscoroll::bem_scene(roller, elastic, load, 0.0));
  REQUIRE(s.converged);
  const auto along = s.along_roller();
  const auto centre =
      static_cast<std::size_t>(std::find(along.y.begin(), along.y.end(), 0.0) - along.y.begin());
  REQUIRE(centre < along.y.size());
  // The line theory's F0 is c times the load per length (Eq. 47: int F0 dy = c P).
  const double f0_centre = c * along.f0[centre];
  double line_peak = 0;
  for (int k = 0; k <= 2000; ++k)
    line_peak =
        std::max(line_peak, line.f0(line.y_minus + (line.y_plus - line.y_minus) * k / 2000));
  INFO("L_f = " << flat_length << ": d " << line.d << " / " << s.d << ", y+ " << line.y_plus
                << " / " << along.y_plus << ", F0(0) " << line.f0(0.0) << " / " << f0_centre
                << ", peak ratio " << line_peak / line.f0(0.0) << " / "
                << along.f0_max / along.f0[centre]);
  CHECK(s.d == Approx(line.d).epsilon(0.005));
  CHECK(along.y_plus == Approx(line.y_plus).epsilon(0.015));
  CHECK(along.y_minus == Approx(line.y_minus).epsilon(0.015));
  CHECK(f0_centre == Approx(line.f0(0.0)).epsilon(0.015));
  CHECK(along.f0_max / along.f0[centre] == Approx(line_peak / line.f0(0.0)).epsilon(0.03));
}

}  // namespace

TEST_CASE("bem profile: the static crowned roller, BEM against the line theory", "[bem]") {
  for (const double flat_length : {0.0, 10.0, 20.0}) check_static_crowned(flat_length);
}

}  // namespace test_bem_profile_static
