// LineSolver::solve for a crowned cylinder whose flat part is long beside the contact's width:
// at its middle the strip is the plane solution (Hunter's problem) at the local load per length
// (docs/theory.md (RP10).3): the line operators' end terms move it by O((x0 + V tau)^2/L_f^2),
// x0 = a + b, which bounds the difference (measured 0.05 to 0.7 of it at N = 12).
#include <catch2/catch.hpp>
#include <cmath>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/plane/plane_solver.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_profile_flat {

TEST_CASE("line profile: the middle of a long flat part is the plane solution", "[line]") {
  using Material = viscoroll::StandardLinearSolid<double>;
  const Material material(1.0, 0.5, 2.0, 1.0);
  const double c = material.instantaneous_compliance();
  viscoroll::LineOptions options;
  options.terms = 12;
  const viscoroll::LineSolver<double, Material> line(material, options);
  const viscoroll::PlaneSolver<double, Material> plane(material);
  using Scene = viscoroll::LineProfileScene<viscoroll::CrownedCylinder<double>>;
  for (const double flat : {10.0, 20.0}) {
    // Crowns of radius 20, (1 + f) c P = 0.03 L_f: a0 = 0.29 (L_f = 10), 0.31 (L_f = 20).
    const viscoroll::CrownedCylinder<double> roller(1.0, flat, 20.0);
    const double load = 0.03 * flat / (3 * c);
    const double a0 = line.solve(Scene{roller, load, 0.0}).a(0.0);
    for (const double v : {0.3, 1.0, 3.0}) {
      const auto s = line.solve(Scene{roller, load, v * a0});
      REQUIRE(s.converged);
      const double w = s.functions(0.0).f0 / (s.compliance * (1 + s.f));  // load per length
      const auto p = plane.solve({.c1 = 1.0, .load = w, .speed = v * a0});
      REQUIRE(p.converged);
      const double bound = std::pow((p.a + p.b + v * a0) / flat, 2);
      INFO("L_f = " << flat << ", V tau/a0 = " << v << ", (x0 + V tau)^2/L_f^2 = " << bound);
      CHECK(std::abs(s.a(0.0) - p.a) < bound * p.a);
      CHECK(std::abs(s.b(0.0) - p.b) < bound * p.a);
    }
  }
}

}  // namespace test_line_profile_flat
