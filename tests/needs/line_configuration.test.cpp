// The line solver's configuration, its scene (line/line_scene.hpp) and settings
// (line/line_options.hpp, with LineBasis), stands without the solver: a caller's option parser
// or configuration struct holds them without Eigen or Boost's Bessel functions (docs/reference.md).
// This file includes nothing of viscoroll but those two headers (and the probes' light
// material/standard_linear_solid.hpp, after them), so it compiles alone (not in a unity batch,
// tests/CMakeLists.txt); the line solver's own tests include Eigen and the Bessel functions, which
// the same include guards then see.
#include <viscoroll/line/line_options.hpp>
#include <viscoroll/line/line_scene.hpp>
// The probes go after the headers under test.
#include <catch2/catch.hpp>
#include <cmath>

#include "optional_parts_probe.hpp"

namespace test_line_configuration {

static_assert(!viscoroll_needs::eigen_core_included,
              "line_options.hpp or line_scene.hpp includes Eigen");
static_assert(!viscoroll_needs::boost_bessel_included,
              "line_options.hpp or line_scene.hpp includes Boost's Bessel functions");

TEST_CASE("needs: the line solver's scene and options without the solver", "[needs]") {
  CHECK_FALSE(viscoroll_needs::eigen_core_included);
  CHECK_FALSE(viscoroll_needs::boost_bessel_included);
  const viscoroll::LineOptions fast = viscoroll::LineOptions::fast();
  CHECK(fast.terms == 5);
  CHECK(fast.quadrature_tolerance == 1e-4);
  CHECK(fast.basis == viscoroll::LineBasis::t_squared);
  CHECK_NOTHROW(fast.validate());
  viscoroll::LineOptions bad;
  bad.terms = 0;
  CHECK_THROWS_WITH(bad.validate(), Catch::Contains("terms"));
  // c2 at the line theory's limit 8 e^-3 c1 has no contact.
  const double limit = viscoroll::max_line_contact_curvature_ratio<double>();
  CHECK(limit == 8 * std::exp(-3.0));
  const viscoroll::LineScene<double> scene{.c1 = 1.0, .c2 = limit, .load = 1.0, .speed = 0.0};
  CHECK_THROWS_WITH(scene.validate(), Catch::Contains("c2"));
}

}  // namespace test_line_configuration
