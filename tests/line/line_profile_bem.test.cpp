// The rolling line solver for a roller profile against the BEM on the same profile object
// (docs/validation.md, "Rolling rollers of any profile"): a crowned roller (C1 = 1, flat part 10,
// crowns of radius 20) on a standard linear solid and on a two-term spectrum, from the slow to
// the fast regime. The bounds are the line theory's errors measured there at N = 12 against the
// BEM at grid 48, with the BEM's change from grid 48 to 24 as margin: d 0.1% (+0.1%), chi 0.5%
// (+0.4%), the ends 1.3% (+1%), F0(y) 4.1% of its peak (+0.5%); a(0) 1.2% plus the BEM's own
// resolution of a row's half width, a cell (B12): 1/24 of the grid's semi-axis at grid 24.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <viscoroll/bem/bem_profile.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_profile_bem {

namespace {

using Crowned = viscoroll::CrownedCylinder<double>;

template <class Material, class LineF0>
void check_against_bem(const Material& material, double load, double speed, int terms,
                       const LineF0& line_f0) {
  const Crowned roller(1.0, 10.0, 20.0);
  viscoroll::LineOptions options;
  options.terms = terms;
  const viscoroll::LineSolver<double, Material> line(material, options);
  const auto s = line.solve(viscoroll::LineProfileScene<Crowned>{roller, load, speed});
  viscoroll::BemOptions bem_options;
  bem_options.grid = 24;
  const auto e = viscoroll::BemSolver(material, bem_options)
                     .solve(viscoroll::bem_scene(roller, material, load, speed));
  REQUIRE(s.converged);
  REQUIRE(e.converged);
  const auto along = e.along_roller();
  double worst = 0, bem_a0 = 0;
  for (std::size_t i = 0; i < along.y.size(); ++i) {
    worst = std::max(worst, std::abs(line_f0(s, along.y[i]) - along.f0[i]));
    if (along.y[i] == 0.0) bem_a0 = along.a[i];
  }
  INFO("speed " << speed << ": d " << s.d << " / " << e.d << ", chi " << s.chi << " / " << e.chi
                << ", a(0) " << s.a(0.0) << " / " << bem_a0 << ", l " << s.l() << " / "
                << along.y_plus << ", max |dF0|/F0max " << worst / along.f0_max);
  CHECK(std::abs(s.d / e.d - 1) < 0.002);
  CHECK(std::abs(s.chi / e.chi - 1) < 0.009);
  CHECK(std::abs(s.a(0.0) / bem_a0 - 1) < 0.012 + 1.0 / 24);
  CHECK(std::abs(s.l() / along.y_plus - 1) < 0.023);
  CHECK(worst < 0.046 * along.f0_max);
}

}  // namespace

TEST_CASE("line profile: a crowned roller on a standard linear solid against the BEM", "[line]") {
  const viscoroll::StandardLinearSolid<double> material(1.0, 0.5, 2.0, 1.0);
  const double c = material.instantaneous_compliance();
  const auto f0 = [](const viscoroll::LineSolverD::Solution& s, double y) {
    return std::abs(y) < s.l() ? s.functions(y).f0 / (s.compliance * (1 + s.f)) : 0.0;
  };
  // The long-term static a(0) = 0.2878: V tau/a0 = 0.1, 1, 10.
  for (const double speed : {0.02878, 0.2878, 2.878})
    check_against_bem(material, 0.3 / (3 * c), speed, 12, f0);
}

TEST_CASE("line profile: a crowned roller on a two-term spectrum against the BEM", "[line]") {
  const viscoroll::PronyCreep<double> material(1.0, 0.5, {{3.0, 0.05}, {6.0, 5.0}});
  const double c = material.instantaneous_compliance();
  // F0 carries the long-term compliance (1 + F) c of the terms solved for: both are active here.
  const auto f0 = [&](const auto& s, double y) {
    REQUIRE(s.active_terms == 2);
    return std::abs(y) < s.l() ? s.f0(y) / (10 * c) : 0.0;
  };
  for (const double speed : {0.1, 1.0, 10.0}) check_against_bem(material, 0.03 / c, speed, 12, f0);
}

}  // namespace test_line_profile_bem
