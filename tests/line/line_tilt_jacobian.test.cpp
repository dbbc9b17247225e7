// The semi-analytic Jacobians of the asymmetric line residuals (docs/theory.md section 16,
// "Status": the odd parts' columns t times the even ones', the centre's through h'(y) only) against
// central differences of the residuals, for LineResidual over one term and over a spectrum with a
// drop that is not even (h = C2 y^2/2 + theta y), at iterates with odd parts and a centre off zero.
// The tolerances are the symmetric residuals' (tests/line/line_jacobian.test.cpp,
// line_spectrum_jacobian.test.cpp): the central difference's own error.
#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/static_line_contact.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

#include "support/jacobian_check.hpp"
#include "support/three_term_spectrum.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_tilt_jacobian {

namespace {

/// h(y) = C2 y^2/2 + theta y: the paper's drop tilted (a RollerDrop that is not even).
struct TiltedDrop {
  double theta;
  template <class Problem, class Real>
  Real drop(const Problem& p, Real y) const {
    return p.c2 * y * y / 2 + theta * y;
  }
  template <class Problem, class Real>
  Real drop_slope(const Problem& p, Real y) const {
    return p.c2 * y + theta;
  }
};

using Rule = viscoroll::GaussLegendre<double, 12>;
const double c1 = 1, c2 = (std::log(20.0) - 1) / 25, theta = 0.02;

/// A contact narrower than the static one, shifted by a tenth of its length, with odd parts;
/// every unknown then moved by 0.01 sin(3k + 1).
viscoroll::LineShape<double> shape(const viscoroll::StaticLineContact<double>& slow) {
  viscoroll::LineShape<double> s{slow.a0, 0.8 * slow.l, {std::log(0.8), 0.02}, {0.2, 0.01}};
  s.alpha_odd = {0.05, -0.01};
  s.beta_odd = {0.03, 0.01};
  s.centre = -0.1 * slow.l;
  return s;
}

void move(Eigen::VectorXd& x) {
  for (int k = 0; k < x.size(); ++k) x[k] += 0.01 * std::sin(3.0 * k + 1);
}

}  // namespace

TEST_CASE("line tilt: the asymmetric residual's Jacobian against central differences",
          "[line][jacobian][profile]") {
  // The paper's scene (f = 9, a0 = 1) as tests/line/line_jacobian.test.cpp, bound 4e-7 as there
  // (its measured 1e-10 ... 1.5e-9 at these speeds, 9.5e-8 in the slow regime). Measured here
  // 2e-10 ... 6e-10.
  const double f = 9, load_compliance = 5 * c1 / 3;  // (1 + f) c P: a0 = 1, l0 = 5
  const auto slow = viscoroll::static_line_contact(c1, c2, load_compliance);
  for (const double vtau : {0.1, 1.0, 10.0}) {
    for (const int terms : {2, 4}) {
      const viscoroll::line::LineProblem<double> problem{
          c1, c2, vtau, f, slow.a0, slow.l, c1 * slow.a0 * slow.a0 * slow.l / 3};
      const viscoroll::line::LineResidual<double, Rule, viscoroll::line::ExteriorLeadingEdge,
                                          TiltedDrop>
          res(problem, terms, viscoroll::LineBasis::t_squared, 1, 0.0, TiltedDrop{theta}, true);
      REQUIRE(res.unknowns() == 4 * terms + 5);
      REQUIRE(res.equations() == res.unknowns());
      Eigen::VectorXd x = res.pack(shape(slow), slow.d * 0.64);
      move(x);
      const double worst = viscoroll_test::worst_column_error(res, x);
      CAPTURE(vtau, terms, worst);
      CHECK(worst <= 4e-7);
    }
  }
}

TEST_CASE("line tilt: the asymmetric spectrum residual's Jacobian against central differences",
          "[line][spectrum][jacobian][profile]") {
  // The three-term spectrum of tests/line/line_spectrum_jacobian.test.cpp, bound 1e-8 as there
  // (measured here 1e-10 ... 3e-10).
  for (const double v : {0.3, 1.0, 4.0}) {
    const auto slow = viscoroll::static_line_contact(c1, c2, 1.0);
    const auto problem = viscoroll_test::three_term_problem(v, c1, c2);
    for (const int terms : {2, 4}) {
      const viscoroll::line::LineResidual<double, Rule, viscoroll::line::ExteriorLeadingEdge,
                                          TiltedDrop, viscoroll::dynamic_memory_terms>
          res(problem, terms, viscoroll::LineBasis::t_squared, 1, 0.0, TiltedDrop{theta}, true);
      REQUIRE(res.unknowns() == 8 * terms + 9);
      REQUIRE(res.equations() == res.unknowns());
      viscoroll::LineSpectrumMoments<double> moments{{0.05}, {0.02}};
      moments.gamma_odd = {0.01};
      moments.kappa_odd = {-0.01};
      Eigen::VectorXd x = res.pack(shape(slow), moments, slow.d * 0.49);
      move(x);
      const double worst = viscoroll_test::worst_column_error(res, x);
      CAPTURE(v, terms, worst);
      CHECK(worst <= 1e-8);
    }
  }
}

}  // namespace test_line_tilt_jacobian
