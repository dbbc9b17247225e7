// The mapped composite rules of viscoroll/line/detail/graded_panels.hpp (docs/theory.md section 7)
// against closed forms, and the line residual assembled on them against the same residual on
// 40-point rules and in long double: every integral of LineResidual exact to rounding.
//
// Measured values next to the tolerances: Release build, GCC 12, x86-64.
#include <Eigen/Dense>
#include <boost/math/special_functions/expint.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>
#include <viscoroll/line/detail/graded_panels.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_mapped_panels {

namespace {

using viscoroll::GaussLegendre;

template <class Real>
Real sum_of(const std::vector<Real>& w, const std::vector<Real>& x, auto f) {
  Real sum = 0;
  for (std::size_t j = 0; j < x.size(); ++j) sum += w[j] * f(x[j]);
  return sum;
}

}  // namespace

TEMPLATE_TEST_CASE("panels: the width for a strip of analyticity", "[line][quadrature]", float,
                   double, long double) {
  using Real = TestType;
  using Q = GaussLegendre<Real, 12>;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real strip = boost::math::constants::half_pi<Real>();
  const Real width = viscoroll::detail::strip_panel_width<Q>(strip);
  // Definition: rho = exp(asinh(strip / (width/2))) satisfies rho^(-2n) = eps/4096.
  const Real rho = std::exp(std::asinh(strip / (width / 2)));
  CHECK(std::abs(std::pow(rho, Real(-24)) / (eps / 4096) - 1) < 64 * eps);
  // Wider panels for a coarser scalar and a higher order.
  CHECK(width > viscoroll::detail::strip_panel_width<GaussLegendre<Real, 8>>(strip));
  CHECK(width < viscoroll::detail::strip_panel_width<GaussLegendre<Real, 24>>(strip));
}

TEMPLATE_TEST_CASE("panels: ln(1 + t/c) nodes integrate e^-t / (1 + t/c) to rounding",
                   "[line][quadrature]", double, long double) {
  // int_0^inf e^-t / (1 + t/c) dt = c e^c E1(c) (A&S 5.1.28 with t -> c + t); its pole at t = -c
  // is the kernels' singularity at x_t = 0, in the variable w = ln(1 + t/c) at w = -infinity.
  // The rule stops at T = -ln(eps) + 8, where the tail is below eps e^-8.
  using Real = TestType;
  using Q = GaussLegendre<Real, 12>;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real top = -std::log(eps) + 8;
  for (const Real c : {Real(1e-4), Real(0.03), Real(1), Real(1) / 3 * 10}) {
    std::vector<Real> t, w;
    viscoroll::detail::append_log_mapped_nodes<Q>(t, w, top, c,
                                                  boost::math::constants::half_pi<Real>());
    const Real got = sum_of(w, t, [&](Real x) { return std::exp(-x) / (1 + x / c); });
    const Real exact = c * std::exp(c) * boost::math::expint(1, c);
    INFO("c = " << c << ": " << t.size() << " nodes, relative error " << (got / exact - 1));
    CHECK(std::abs(got / exact - 1) < 16 * eps);  // measured <= 3 eps
  }
  // A singularity at x_t = +-i s, w = ln(s/c) +- i pi/2: int_0^inf e^-t (1 + t)/((1 + t)^2 + s^2)
  // dt against the same integral on panels 4x narrower.
  for (const Real s : {Real(0.01), Real(1), Real(30)}) {
    const auto f = [&](Real x) { return std::exp(-x) * (1 + x) / ((1 + x) * (1 + x) + s * s); };
    std::vector<Real> t, w, tf, wf;
    viscoroll::detail::append_log_mapped_nodes<Q>(t, w, top, Real(1),
                                                  boost::math::constants::half_pi<Real>());
    viscoroll::detail::append_log_mapped_nodes<Q>(tf, wf, top, Real(1),
                                                  boost::math::constants::half_pi<Real>() / 4);
    const Real got = sum_of(w, t, f), fine = sum_of(wf, tf, f);
    INFO("s = " << s << ": " << t.size() << " against " << tf.size() << " nodes");
    CHECK(std::abs(got / fine - 1) < 16 * eps);
  }
}

TEMPLATE_TEST_CASE("panels: ln(s/(L - s)) nodes with mapped ends integrate to rounding",
                   "[line][quadrature]", double, long double) {
  using Real = TestType;
  using Q = GaussLegendre<Real, 12>;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real big = std::numeric_limits<Real>::max();
  SECTION("poles at s = +-i h: int_0^L ds/(s^2 + h^2) = atan(L/h)/h") {
    const Real len = 5;
    for (const Real h : {Real(1e-3), Real(0.3), Real(2), Real(40)}) {
      std::vector<Real> s, w;
      viscoroll::detail::append_logit_mapped_nodes<Q>(s, w, len, std::min(h / 2, len / 4), len / 5,
                                                      big);
      const Real got = sum_of(w, s, [&](Real x) { return 1 / (x * x + h * h); });
      const Real exact = std::atan(len / h) / h;
      INFO("h = " << h << ": " << s.size() << " nodes");
      CHECK(std::abs(got / exact - 1) < 16 * eps);
    }
  }
  SECTION("a pole delta behind the start: int_0^L ds/(s + delta) = ln((L + delta)/delta)") {
    // The mirror image of a pole of G just beyond the end (w -> -w); at the start s + delta has no
    // cancellation, so the integrand itself is exact to rounding at every node.
    const Real len = 2;
    for (const Real delta : {Real(1e-9), Real(1e-4), Real(0.1)}) {
      std::vector<Real> s, w;
      viscoroll::detail::append_logit_mapped_nodes<Q>(s, w, len, std::min(delta, len / 4), len / 5,
                                                      big);
      const Real got = sum_of(w, s, [&](Real x) { return 1 / (x + delta); });
      const Real exact = std::log((len + delta) / delta);
      INFO("delta = " << delta << ": " << s.size() << " nodes");
      CHECK(std::abs(got / exact - 1) < 16 * eps);
    }
  }
  SECTION("a pole delta beyond the end: int_0^L ds/(L + delta - s) = ln((L + delta)/delta)") {
    // delta = 2^-k, so L + delta is exact and, by Sterbenz's lemma, so is (L + delta) - s for
    // every node s >= (L + delta)/2. The nodes themselves are rounded to eps s, which moves the
    // integrand at a node by eps s/(L + delta - s)^2: that sum is part of the bound.
    const Real len = 2;
    for (const int k : {30, 13, 3}) {
      const Real delta = std::ldexp(Real(1), -k);
      std::vector<Real> s, w;
      viscoroll::detail::append_logit_mapped_nodes<Q>(s, w, len, len / 4,
                                                      std::min(delta / 4, len / 5), big);
      const Real got = sum_of(w, s, [&](Real x) { return 1 / ((len + delta) - x); });
      const Real nodes = sum_of(
          w, s, [&](Real x) { return eps * x / (((len + delta) - x) * ((len + delta) - x)); });
      const Real exact = std::log((len + delta) / delta);
      INFO("delta = " << delta << ": " << s.size() << " nodes, node rounding " << nodes / exact);
      CHECK(std::abs(got - exact) < 16 * eps * exact + nodes);
    }
  }
  SECTION("a branch point at the end: int_0^L (L - s)^(3/2) ds = (2/5) L^(5/2)") {
    // On a plain last panel the 12-point rule's error would be O(last^(5/2) / n^5); in
    // tau = sqrt((L - s)/last) the integrand is a polynomial.
    const Real len = 3;
    std::vector<Real> s, w;
    viscoroll::detail::append_logit_mapped_nodes<Q>(s, w, len, len / 4, len / 5, big);
    const Real got = sum_of(w, s, [&](Real x) { return std::pow(len - x, Real(1.5)); });
    const Real exact = Real(2) / 5 * std::pow(len, Real(2.5));
    CHECK(std::abs(got / exact - 1) < 16 * eps);
  }
}

namespace {

const viscoroll::StandardLinearSolid<double> kRubber(1, 0.5, 9, 1);

viscoroll::LineScene<double> paper_scene(double vtau) {
  const double load = 5.0 / (3 * (1 + 9) * kRubber.instantaneous_compliance());
  return {1.0, (std::log(20.0) - 1) / 25, load, vtau};
}

/// max |r_12 - r_40| and max |r_double - r_long double| at the solution (or last iterate) of the
/// paper's scene at V tau with `terms` in `basis`.
std::pair<double, double> residual_errors(double vtau, int terms, viscoroll::LineBasis basis) {
  viscoroll::LineOptions options;
  options.terms = terms;
  options.basis = basis;
  const viscoroll::LineSolverD solver(kRubber, options);
  const auto scene = paper_scene(vtau);
  const auto sol = solver.solve(scene);
  const auto res = solver.residual(scene);
  const Eigen::VectorXd x = res.pack(sol.shape, sol.d);
  Eigen::VectorXd r, r40;
  REQUIRE(res(x, r));
  const viscoroll::LineSolver<double, viscoroll::StandardLinearSolid<double>,
                              GaussLegendre<double, 40>>
      fine(kRubber, options);
  REQUIRE(fine.residual(scene)(x, r40));
  const viscoroll::StandardLinearSolid<long double> rubber_ld(1, 0.5, 9, 1);
  const viscoroll::LineSolver<long double, viscoroll::StandardLinearSolid<long double>> wide(
      rubber_ld, options);
  const viscoroll::LineScene<long double> scene_ld{1.0L, (std::log(20.0L) - 1) / 25,
                                                   static_cast<long double>(scene.load),
                                                   static_cast<long double>(vtau)};
  Eigen::Matrix<long double, Eigen::Dynamic, 1> rl;
  REQUIRE(wide.residual(scene_ld)(x.cast<long double>(), rl));
  return {(r - r40).cwiseAbs().maxCoeff(),
          static_cast<double>((r.cast<long double>() - rl).cwiseAbs().maxCoeff())};
}

}  // namespace

TEST_CASE("line: the residual's integrals are exact to rounding", "[line][quadrature]") {
  // Against the 40-point rule (its own panels) and against long double (more panels, for its
  // epsilon): the rows, sums of O(1) terms scaled to O(1), agree to rounding. Before the mapped
  // panels the 12-point rule was off by up to 9e-9 at V tau = 10 a0 (terms = 16) and by 5e-5 at
  // the last points in sqrt(1 - t^2) (terms = 32). Measured here: <= 3.6e-15 (16 eps).
  const double tol = 64 * std::numeric_limits<double>::epsilon();
  for (const int terms : {4, 8, 16}) {
    // 0.01 and 0.1: most s-nodes far from the point take the memory kernel's series in 1/s^2
    // (docs/theory.md section 8), with thresholds of their own in long double.
    for (const double vtau : {0.01, 0.1, 1.0, 3.0, 10.0, 100.0}) {
      const auto [e40, eld] = residual_errors(vtau, terms, viscoroll::LineBasis::t_squared);
      INFO("t^2, terms = " << terms << ", V tau = " << vtau << ": " << e40 << ", " << eld);
      CHECK(e40 < tol);
      CHECK(eld < tol);
    }
  }
  for (const int terms : {8, 24}) {
    const auto [e40, eld] = residual_errors(1.0, terms, viscoroll::LineBasis::s);
    INFO("sqrt(1 - t^2), terms = " << terms << ": " << e40 << ", " << eld);
    CHECK(e40 < tol);
    CHECK(eld < tol);
  }
}

}  // namespace test_mapped_panels
