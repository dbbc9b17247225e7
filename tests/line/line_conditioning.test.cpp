// Tests of the continuation in N of the line solver, the re-expansion of a LineShape in another
// variable (line_shape.hpp), and the symbol of the near-field operator of (34) that makes the line
// equations ill-conditioned at wavelengths ~ 2.8 a (docs/theory.md section 5).
#include <array>
#include <boost/math/constants/constants.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/line/line_operators.hpp>
#include <viscoroll/line/line_shape.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_conditioning {

namespace {

using viscoroll::LineBasis;
using viscoroll::LineShape;

/// Ci(x) = -(cos x / x^2) sum_k (-1)^k (2k + 1)! / x^(2k) at sin x = 0 (x = 2 pi m, x >= 20), the
/// asymptotic series summed to its smallest term (error below e^-x).
double ci_at_multiple_of_2pi(double x) {
  double term = 1 / (x * x), sum = 0;
  for (int k = 0; k < 30; ++k) {
    const double next = -term * (2 * k + 2) * (2 * k + 3) / (x * x);
    sum += term;
    if (std::abs(next) >= std::abs(term)) break;
    term = next;
  }
  return -std::cos(x) * sum;
}

}  // namespace

TEST_CASE("line theory: the near-field operator of (34) has the symbol 2 ln(4 e^-gamma/(k a))",
          "[line]") {
  // docs/theory.md (T1): for F = cos(k y) on (-l, l), at y = 0,
  //   FP[F](0) + F(0) ln(16 l^2 / a^2) = 2 ln(4 e^-gamma / (k a)) + 2 Ci(k l),
  // so that, away from the ends, the linearised (34) multiplies a mode of wavenumber k by
  // 2 ln(4 e^-gamma/(k a)), which vanishes at k a = 4 e^-gamma = 2.2459 and is negative beyond.
  const double gamma = boost::math::constants::euler<double>();
  for (const int m : {4, 8}) {
    for (const double k : {0.5, 2.0, 4.0}) {
      const double l = 2 * boost::math::constants::pi<double>() * m / k;
      const viscoroll::line::LineOperators<double, viscoroll::GaussLegendre<double, 24>> ops(l);
      const auto f = [k](double y) { return std::cos(k * y); };
      for (const double a : {0.3, 1.0}) {
        const double got = ops.near_field_strip(f, 0.0, a);
        const double want =
            2 * std::log(4 * std::exp(-gamma) / (k * a)) + 2 * ci_at_multiple_of_2pi(k * l);
        INFO("m = " << m << ", k = " << k << ", a = " << a << ": " << got << " vs " << want);
        // The finite part of an oscillatory F over m periods by graded 24-point panels: measured
        // agreement 1e-12 or better; 1e-9 allows for the panel error at k l = 2 pi 8.
        CHECK(std::abs(got - want) <= 1e-9 * (1 + std::abs(want)));
      }
    }
  }
  // The zero: at k a = 4 e^-gamma the symbol (without the end term) is zero to rounding.
  CHECK(std::abs(2 * std::log(4 * std::exp(-gamma) / (4 * std::exp(-gamma)))) <= 1e-15);
}

TEMPLATE_TEST_CASE("line shape: re-expansion keeps a(y) and b(y)", "[line]", double, long double) {
  using Real = TestType;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const LineShape<Real> shape{Real(1),
                              Real(4.5),
                              {Real(-0.5), Real(0.02), Real(-0.003)},
                              {Real(0.3), Real(-0.05), Real(0.004), Real(0.001)},
                              LineBasis::t_squared};
  // Into the same variable with more terms: the same polynomials, to rounding.
  const auto more = shape.reexpanded(LineBasis::t_squared, 7);
  REQUIRE(more.alpha.size() == 7);
  REQUIRE(more.beta.size() == 8);
  for (int i = 0; i <= 20; ++i) {
    const Real y = shape.l * Real(i) / 20 * Real(0.999);
    CHECK(std::abs(more.a(y) - shape.a(y)) <= 64 * eps);
    CHECK(std::abs(more.b(y) - shape.b(y)) <= 64 * eps);
  }
  CHECK(std::abs(more.alpha[5]) <= 64 * eps);
  // Into s = sqrt(1 - t^2): a polynomial in 1 - 2 s^2 is a polynomial of degree 2 N in s, exact
  // with 2 N + 1 terms.
  const auto in_s = shape.reexpanded(LineBasis::s, 7);
  for (int i = 0; i <= 20; ++i) {
    const Real y = shape.l * Real(i) / 20 * Real(0.999);
    CHECK(std::abs(in_s.a(y) - shape.a(y)) <= 256 * eps);
    CHECK(std::abs(in_s.b(y) - shape.b(y)) <= 256 * eps);
  }
}

TEST_CASE("line solver: continuation in N stays on the smooth branch", "[line][slow]") {
  // Without continuation a cold start at terms = 10 landed on another root of the discrete
  // equations at V tau = a0 (a(0) = 0.684 a0, l = 4.18 a0, with a(y) oscillating at a wavelength
  // ~ 2.8 a: docs/theory.md section 5). With continuation in N, terms = 10 and 16 agree to the
  // self-convergence of the branch (measured 7e-5 in a(0), 4e-4 in l, 6e-7 in d).
  const double f = 9, c1 = 1, c2 = (std::log(20.0) - 1) / 25;
  const viscoroll::StandardLinearSolid<double> rubber(1, 0.5, f, 1);
  const double load = c1 * 5 / (3 * (1 + f) * rubber.instantaneous_compliance());  // a0 = 1, l0 = 5
  const viscoroll::LineScene<double> scene{c1, c2, load, 1.0};
  viscoroll::LineOptions coarse, fine;
  coarse.terms = 10;
  fine.terms = 16;
  const auto s10 = viscoroll::LineSolverD(rubber, coarse).solve(scene);
  const auto s16 = viscoroll::LineSolverD(rubber, fine).solve(scene);
  REQUIRE(s10.converged);
  REQUIRE(s16.converged);
  CHECK(std::abs(s10.a(0) / s16.a(0) - 1) <= 2e-4);
  CHECK(std::abs(s10.l() / s16.l() - 1) <= 1e-3);
  CHECK(std::abs(s10.d / s16.d - 1) <= 5e-6);
  // The profile is smooth: a(y) decreases monotonically from the centre line.
  for (int i = 1; i <= 40; ++i) {
    const double y0 = s16.l() * (i - 1) / 40, y1 = s16.l() * i / 40;
    CHECK(s16.a(y1) <= s16.a(y0) + 1e-12);
  }
}

TEMPLATE_TEST_CASE("line solver: self-convergence to 1e-6 at V tau = a0 in the variable s",
                   "[line][slow]", double, long double) {
  // docs/validation.md, "Line solver: self-convergence": in the variable
  // s = sqrt(1 - t^2) the successive changes of a(0), b(0), l, d, chi fall from N = 16 -> 32 to
  // 32 -> 48; in double the last is at most 9.7e-7 (l), 8.9e-7 (a(0)), 2.2e-7 (b(0)), 7e-10
  // (d, chi), the 1e-6. Long double takes the same iteration to its own rounding; its
  // values agree with double's to the discretisation's conditioning (smallest singular value of
  // the scaled Jacobian ~5e-4: 1e-16 residuals move the unknowns by 1e-12 or less).
  using Real = TestType;
  const Real f = 9, c1 = 1, c2 = (std::log(Real(20)) - 1) / 25;
  const viscoroll::StandardLinearSolid<Real> rubber(1, Real(0.5), f, 1);
  const Real load = c1 * 5 / (3 * (1 + f) * rubber.instantaneous_compliance());
  const viscoroll::LineScene<Real> scene{c1, c2, load, Real(1)};
  std::array<std::array<Real, 5>, 3> values{};
  const int terms[] = {16, 32, 48};
  for (int k = 0; k < 3; ++k) {
    viscoroll::LineOptions options;
    options.terms = terms[k];
    options.basis = LineBasis::s;
    const auto s =
        viscoroll::LineSolver<Real, viscoroll::StandardLinearSolid<Real>>(rubber, options)
            .solve(scene);
    INFO("N = " << terms[k] << ": " << s.reason);
    REQUIRE(s.converged);
    values[k] = {s.a(Real(0)), s.b(Real(0)), s.l(), s.d, s.chi};
  }
  for (int q = 0; q < 5; ++q) {
    using std::abs;
    const Real first = abs(values[1][q] / values[0][q] - 1);
    const Real last = abs(values[2][q] / values[1][q] - 1);
    INFO("quantity " << q << ": change 16 -> 32 " << double(first) << ", 32 -> 48 "
                     << double(last));
    CHECK(last <= Real(1e-6));
    CHECK(last <= first);
  }
}

}  // namespace test_line_conditioning
