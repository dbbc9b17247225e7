// Tests of LineResidual::jacobian for a spectrum (viscoroll/line/line_residual.hpp), the
// semi-analytic Jacobian of the spectrum's line equations (docs/theory.md (S17)), against central
// differences of the residual itself, and of spectrum_strip's slopes (SpectrumStripSlopes) against
// central differences of the strip.
//
// Scene: the paper's proportions (C1 = 1, C2/C1 = (ln 20 - 1)/25), a three-term creep spectrum
// (f, tau) = (2, 0.05), (3, 0.5), (4, 5) at speeds 0.3, 1 and 4 (every term a line term at the
// two faster speeds), the load of a long-term static contact of half width a_ref.
#include <Eigen/Core>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>
#include <viscoroll/core/spectrum_strip.hpp>
#include <viscoroll/line/detail/spectrum_memory.hpp>
#include <viscoroll/line/line_node_rule.hpp>
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/static_line_contact.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

#include "support/jacobian_check.hpp"
#include "support/three_term_spectrum.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_spectrum_jacobian {

namespace {

using Residual =
    viscoroll::line::LineResidual<double, viscoroll::GaussLegendre<double, 12>,
                                  viscoroll::line::ExteriorLeadingEdge,
                                  viscoroll::line::ParabolicDrop, viscoroll::dynamic_memory_terms>;

/// Largest relative column error of the Jacobian against central differences, at a contact
/// narrower than the static one, offset from the expansions' leading terms by `offset`.
double worst_column_error(double v, int terms, double offset) {
  const double c1 = 1, c2 = (std::log(20.0) - 1) / 25;
  const auto slow = viscoroll::static_line_contact(c1, c2, 1.0);
  const auto problem = viscoroll_test::three_term_problem(v, c1, c2);
  const Residual res(problem, terms);
  REQUIRE(res.spectrum());
  REQUIRE(res.unknowns() == 4 * terms + 5);
  const double ratio = 0.7;
  const viscoroll::LineShape<double> shape{slow.a0, slow.l * ratio, {std::log(ratio)}, {0.1}};
  const viscoroll::LineSpectrumMoments<double> moments{{0.05}, {0.02}};
  Eigen::VectorXd x = res.pack(shape, moments, slow.d * ratio * ratio);
  for (int k = 0; k < x.size(); ++k) x[k] += offset * std::sin(3.0 * k + 1);
  return viscoroll_test::worst_column_error(res, x);
}

}  // namespace

TEST_CASE("spectrum strip: slopes in the right sides and the half width", "[line][spectrum]") {
  const auto lengths = viscoroll_test::three_term_lengths(1.0);
  const std::vector<double> right{0.03, -0.02, 0.05};
  const double a = 0.8, c1 = 1.3;
  viscoroll::plane::SpectrumStripSlopes<double> slopes;
  const auto st = viscoroll::plane::spectrum_strip(a, lengths, &right, c1, &slopes);
  const auto field = [](const viscoroll::plane::SpectrumStrip<double>& s) {
    return std::vector<double>{s.b, s.g0, s.pig1, s.centroid};
  };
  const std::vector<double> base = field(st);
  // d/d right[k]: b, G0, pig1 are linear in the right sides, the centroid a quotient; central
  // differences with h = 1e-5 are exact to ~1e-10 relative.
  for (std::size_t k = 0; k < right.size(); ++k) {
    const double h = 1e-5;
    auto up = right, down = right;
    up[k] += h;
    down[k] -= h;
    const auto fu = field(viscoroll::plane::spectrum_strip(a, lengths, &up, c1));
    const auto fd = field(viscoroll::plane::spectrum_strip(a, lengths, &down, c1));
    const std::vector<double> got{slopes.b[k], slopes.g0[k], slopes.pig1[k], slopes.centroid[k]};
    for (std::size_t q = 0; q < 4; ++q) {
      const double diff = (fu[q] - fd[q]) / (2 * h);
      CAPTURE(k, q, diff, got[q]);
      CHECK(std::abs(got[q] - diff) <= 1e-8 * (std::abs(diff) + 1e-3));
    }
  }
  // d/da: the slopes' own central difference (step eps^(1/3) a) against a step of 1e-4 a with
  // Richardson's extrapolation (error O(h^4) = 1e-16 a^4).
  const double h = 1e-4 * a;
  const auto f = [&](double aa) {
    return field(viscoroll::plane::spectrum_strip(aa, lengths, &right, c1));
  };
  const auto f1 = f(a + h), f2 = f(a - h), f3 = f(a + 2 * h), f4 = f(a - 2 * h);
  const std::vector<double> got{slopes.b_a, slopes.g0_a, slopes.pig1_a, slopes.centroid_a};
  for (std::size_t q = 0; q < 4; ++q) {
    const double diff = (8 * (f1[q] - f2[q]) - (f3[q] - f4[q])) / (12 * h);
    CAPTURE(q, diff, got[q]);
    // eps^(2/3) = 4e-11 relative from the slopes' step, plus the extrapolation's rounding,
    // eps/h = 3e-12.
    CHECK(std::abs(got[q] - diff) <= 1e-9 * (std::abs(diff) + std::abs(base[q])));
  }
}

TEST_CASE("line spectrum: the semi-analytic Jacobian against central differences",
          "[line][spectrum][jacobian]") {
  // The Jacobian holds the quadrature nodes fixed in t = y/l, while the residual's panels follow
  // the leading edge; both integrate to rounding, so the difference is the central difference's
  // error and the strip's d/da step (~1e-10 of a column; 1e-8 allows a hundredfold).
  for (const double v : {0.3, 1.0, 4.0}) {
    for (const int terms : {2, 4}) {
      const double worst = worst_column_error(v, terms, 0.01);
      CAPTURE(v, terms);
      CHECK(worst <= 1e-8);  // measured 6e-11 ... 2.4e-10
    }
  }
}

TEST_CASE("line spectrum: the shared memory grid against exterior_right term by term",
          "[line][spectrum]") {
  // (S18): the right sides R_k and their slopes in x0 and ln l from one x-grid against
  // exterior_right on each term's own node set (LineNodeRule at V tau = lambda_k), for smooth
  // Q_k = F (1 - g/lambda_k) on a contact of half length 3, at a point off the centre.
  using Rule = viscoroll::line::LineNodeRule<double, viscoroll::GaussLegendre<double, 12>>;
  const viscoroll::LineShape<double> shape{0.6, 3.0, {-0.2, 0.05}, {0.1, 0.02}};
  const double y = 0.7, x0 = 0.5, mu1 = 0.02;
  const std::vector<double> lambda{0.05, 0.3, 2.0, 40.0};
  const auto big_f = [&](double yy) { return shape.one_minus_t2(yy) * (1 + 0.3 * yy); };
  const auto g = [](double yy) { return 0.1 + 0.05 * yy; };
  const auto q_of = [&](double yy, double lam) { return big_f(yy) * (1 - g(yy) / lam); };
  viscoroll::line::LineNodes<double> shared;
  Rule(viscoroll::LineBasis::t_squared, 0.0, 4, lambda[0], lambda[0] / mu1 - 1)
      .point(shape, y, x0, shared);
  std::vector<double> f0, c, q(lambda.size()), right;
  for (const double yp : shared.yp) {
    f0.push_back(big_f(yp));
    c.push_back(g(yp));
  }
  for (std::size_t k = 0; k < lambda.size(); ++k) q[k] = q_of(y, lambda[k]);
  viscoroll::detail::SpectrumMemoryWork<double> work;
  std::vector<viscoroll::line::ExteriorSlopes<double>> slopes;
  viscoroll::detail::exterior_right_terms<viscoroll::GaussLegendre<double, 12>>(
      shared, x0, lambda, f0, c, q, right, work, &slopes);
  std::vector<double> plain;
  viscoroll::detail::exterior_right_terms<viscoroll::GaussLegendre<double, 12>>(
      shared, x0, lambda, f0, c, q, plain, work);
  for (std::size_t k = 0; k < lambda.size(); ++k) {
    viscoroll::line::LineNodes<double> own;
    Rule(viscoroll::LineBasis::t_squared, 0.0, 4, lambda[k], lambda[k] / mu1 - 1)
        .point(shape, y, x0, own);
    std::vector<double> dq_own(own.yp.size());
    for (std::size_t j = 0; j < own.yp.size(); ++j) dq_own[j] = q_of(own.yp[j], lambda[k]) - q[k];
    viscoroll::line::ExteriorSlopes<double> ref;
    const double expected = viscoroll::line::exterior_right(own, dq_own, q[k], x0, lambda[k], &ref);
    CAPTURE(k, expected, right[k], ref.x0, slopes[k].x0, ref.l, slopes[k].l);
    // Both integrate to rounding: the difference is a few ulps of the terms' size, |q| ln(l/x0)
    // (measured: at most 4.1e-16 of it, 9e-16 in the ends).
    const double size = std::abs(q[k]) * std::log(shape.l / x0) + std::abs(expected);
    CHECK(std::abs(right[k] - expected) <= 16 * 2.2e-16 * size);
    CHECK(plain[k] == right[k]);  // the same operations with and without the slopes
    CHECK(std::abs(slopes[k].x0 - ref.x0) <= 16 * 2.2e-16 * (size / x0 + std::abs(ref.x0)));
    CHECK(std::abs(slopes[k].l - ref.l) <= 16 * 2.2e-16 * (size + std::abs(ref.l)));
    CHECK(std::abs(slopes[k].ends - ref.ends) <= 16 * 2.2e-16 * (1 + std::abs(ref.ends)));
  }
}

}  // namespace test_line_spectrum_jacobian
