// The line theory's domain of validity: line_domain_warnings on shapes whose a(y) is
// known in closed form (line_shape.hpp: a = a_ref sqrt(1 - t^2) exp(sum alpha_k T_k(2 t^2 - 1))).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <viscoroll/line/line_solver.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_domain {

TEST_CASE("line domain: slender static shapes carry no warning, short ones do",
          "[line][validate]") {
  using viscoroll::LineShape;
  // Static shape (alpha = 0): a = sqrt(1 - t^2), largest at y = 0, so only l/a(0) decides.
  CHECK(viscoroll::line::line_domain_warnings(LineShape<double>{1.0, 3.0, {0.0}, {0.0}}).empty());
  const auto w = viscoroll::line::line_domain_warnings(LineShape<double>{1.0, 2.9, {0.0}, {0.0}});
  REQUIRE(w.size() == 1);
  CHECK(w.front().code == viscoroll::WarningCode::line_aspect);
  CHECK(w.front().text.find("l/a(0) = 2.9") != std::string::npos);
}

TEST_CASE("line domain: a(y) larger off the centre than l/3 is flagged", "[line][validate]") {
  using viscoroll::LineShape;
  // alpha = {0, 1}: a = sqrt(1 - w) e^(2 w - 1), w = t^2; a(0) = 1/e = 0.3679, and
  // d ln a / dw = -1/(2(1 - w)) + 2 = 0 at w = 3/4: a_max = e^(1/2)/2 = 0.8244 at t = 0.8660.
  const double a0 = std::exp(-1.0), a_max = std::exp(0.5) / 2;
  // l = 2: l/a(0) = 5.44 >= 3 but l/a_max = 2.43 < 3.
  const auto w =
      viscoroll::line::line_domain_warnings(LineShape<double>{1.0, 2.0, {0.0, 1.0}, {0.0}});
  REQUIRE(w.size() == 1);
  CHECK(w.front().code == viscoroll::WarningCode::line_width);
  // The sampled maximum (65 points, spacing 1/64 in t) lies within 1/128 of the peak, where
  // (ln a)'' = -(1 + t^2)/(1 - t^2)^2 + 4 = -24: within 24 (1/128)^2 / 2 = 7.3e-4 relative of
  // a_max; std::to_string prints 6 decimals. Bound: 1e-3.
  const auto at = w.front().text.find("a(y) = ");
  REQUIRE(at != std::string::npos);
  const double printed = std::stod(w.front().text.substr(at + 7));
  CHECK(std::abs(printed - a_max) <= 1e-3 * a_max);
  // l = 2.5 > 3 a_max = 2.473: no warning; and l/a(0) >= 3.
  CHECK(2.5 / a0 >= 3);
  CHECK(viscoroll::line::line_domain_warnings(LineShape<double>{1.0, 2.5, {0.0, 1.0}, {0.0}})
            .empty());
}

}  // namespace test_line_domain
