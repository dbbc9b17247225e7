// The leading-edge condition of the line solver, Eqs. (38)-(44) of Panek & Kalker (1980), checked
// against a direct numerical evaluation of (38) with the extended approximation (26).
//
// At one y, for a strip with half width a, offset b, G from (36) and V = V tau (docs/theory.md
// section 3):
//   residual_quad = u(x0) - S(x0),  u(x0) = (1/V) int_{x0}^inf e^{-(eta-x0)/V} W*(eta) d eta,
//   W*(eta) = -2 int p*(x') ln|x' - eta| dx' + I[F0, eta] - d/deta I[F1, eta]          (26), (38)
// with p* of (32), F0 = int p*, F1 = int x p* and the log potentials all by quadrature, and
// S(x0) = -C1 x0^2/2 + c, c fixed by S - V S' = W*_in at the strip centre, W*_in the near-field
// potential (25) of p* (again by quadrature). The algebra of docs/theory.md gives the identity
//   residual_quad = residual_42 := C1 e^{z}{a b K1(z) - G K0(z)}
//                    + (1/V) int_{x0}^inf e^{-(eta-x0)/V} I[Q, eta] d eta + I[F1, x0]/V -
//                    Lambda[F0]
// (Eq. (42) as "right side minus left side"; only (26) is assumed), test (i). Eq. (44) follows from
// (42) times e^{-x0/V} after the small-argument approximation I[Q, eta] ~ Lambda[Q] on (0, x0) and
// I[F1, x0] ~ Lambda[F1]:
//   e^{-x0/V} residual_42 - residual_44 = Delta := -(1/V) int_0^{x0} e^{-eta/V}(I[Q, eta] -
//   Lambda[Q]) d eta + e^{-x0/V} (I[F1, x0] - Lambda[F1]) / V,
// residual_44 = C1 e^{-b/V}{a b K1 - G K0} - R[Q]; test (ii) checks this to quadrature accuracy and
// that Delta, relative to the terms of (44), shrinks like (x0/l)^2 ln(l/x0) as a, b -> 0.
#include <boost/math/constants/constants.hpp>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <viscoroll/line/line_operators.hpp>
#include <viscoroll/line/paper_leading_edge.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>
#include <viscoroll/special/bessel_ratio.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_leading_edge_condition {

namespace {

using viscoroll::detail::graded_integral;
using viscoroll::line::LineOperators;

/// Integral of g over [0, length] on panels doubling from scale/2^levels, each at most `cap`
/// wide (so that an exponential weight varies by a bounded factor on every panel).
template <class Rule, class Real, class G>
Real capped_integral(const G& g, Real length, Real scale, int levels, Real cap) {
  Real lo = std::min(scale, length);
  for (int k = 0; k < levels; ++k) lo /= 2;
  Real sum = Rule::integrate(g, Real(0), lo), h = lo;
  while (h < length) {
    const Real next = std::min({Real(2 * h), Real(h + cap), length});
    sum += Rule::integrate(g, h, next);
    h = next;
  }
  return sum;
}

template <class Real>
struct Contact {
  Real l, a0, e1, b0, e2, vtau, c1, f;
  static Real pi() { return boost::math::constants::pi<Real>(); }

  Real t2(Real y) const { return (y / l) * (y / l); }
  Real a(Real y) const {
    const Real t = y / l;
    return a0 * std::sqrt((1 - t) * (1 + t)) * (1 + e1 * t * t);
  }
  Real b(Real y) const { return b0 * (1 + e2 * t2(y)); }
  /// Eq. (36)-(37)
  Real g(Real y) const {
    const Real ay = a(y);
    if (!(ay > 0)) return Real(0);
    const Real alpha = (1 + f) * ay / vtau;
    return ((vtau - b(y)) * ay - ay * ay / alpha) * viscoroll::special::bessel_i1_over_i0(alpha);
  }
  /// p*(x') dx' of Eq. (32) in x' = b + a cos(phi), phi in [0, pi]: (C1/2pi)(a^2 sin^2 phi +
  /// (V - b) a cos phi + G) d phi.
  Real density(Real ay, Real by, Real gy, Real phi) const {
    const Real s = std::sin(phi);
    return c1 / (2 * pi()) * (ay * ay * s * s + (vtau - by) * ay * std::cos(phi) + gy);
  }
  /// F0 (15) and F1 (16) by quadrature of p*.
  template <class Rule>
  Real moment(Real y, int order) const {
    const Real ay = a(y), by = b(y), gy = g(y);
    if (!(ay > 0)) return Real(0);
    const auto integrand = [&](Real phi) {
      const Real w = density(ay, by, gy, phi);
      return order == 0 ? w : (by + ay * std::cos(phi)) * w;
    };
    return Rule::integrate(integrand, Real(0), pi() / 2) +
           Rule::integrate(integrand, pi() / 2, pi());
  }
  /// -2 int p*(x') ln|x' - eta| dx' for eta = b + a + eps outside the strip (eps > 0):
  /// eta - x' = eps + 2 a sin^2(phi/2), nearly singular at phi = 0 on the scale sqrt(2 eps/a).
  template <class Rule>
  Real log_potential_outside(Real y, Real eps) const {
    const Real ay = a(y), by = b(y), gy = g(y);
    const auto integrand = [&](Real phi) {
      const Real s = std::sin(phi / 2);
      return density(ay, by, gy, phi) * std::log(eps + 2 * ay * s * s);
    };
    return -2 * graded_integral<Rule>(integrand, pi(), std::sqrt(2 * eps / ay), 2);
  }
  /// -2 int p*(x') ln|x' - b| dx' at the strip centre, in theta = pi/2 - phi: the odd part
  /// cancels and ln|a sin theta| is integrated on panels graded toward theta = 0.
  template <class Rule>
  Real log_potential_centre(Real y) const {
    const Real ay = a(y), gy = g(y);
    const auto integrand = [&](Real theta) {
      const Real c = std::cos(theta);
      return c1 / pi() * (ay * ay * c * c + gy) * std::log(ay * std::sin(theta));
    };
    return -2 * graded_integral<Rule>(integrand, pi() / 2, pi() / 2,
                                      std::numeric_limits<Real>::digits + 4);
  }
};

template <class Real>
struct Residuals {
  Real quad;      // u(x0) - S(x0) by quadrature of (38) with (26)
  Real eq42;      // right minus left side of (42), Bessel term in closed form
  Real eq44_l2;   // left minus right side of (44), (L2) form
  Real eq44_lit;  // the same, literal form
  Real delta;     // predicted e^{-x0/V} eq42 - eq44 (small-argument error)
  Real scale;     // size of the terms of (44): |Lambda[Q]| + 2|Q| (1 + |ln V|)
  Real scale42;   // size of the terms of (42): |Lambda[F0]| + |S(x0)|
};

template <class Real, class Rule>
Residuals<Real> residuals(const Contact<Real>& c, Real y, bool with_quadrature) {
  using std::exp;
  const LineOperators<Real, Rule> ops(c.l);
  const viscoroll::line::PaperLeadingEdgeOperators<Real, Rule> paper(c.l);
  const Real V = c.vtau, a = c.a(y), b = c.b(y), g = c.g(y), x0 = a + b;
  const auto f0 = [&](Real t) { return c.template moment<Rule>(t, 0); };
  const auto f1 = [&](Real t) { return c.template moment<Rule>(t, 1); };
  const auto q = [&](Real t) { return f0(t) - f1(t) / V; };  // Eq. (45)
  const Real lambda_f0 = ops.near_field(f0, y), lambda_f1 = ops.near_field(f1, y);
  const Real lambda_q = ops.near_field(q, y);
  const Real depth = std::numeric_limits<Real>::digits * Real(0.7) + 10;  // e^{-depth} ~ eps/1e4
  Residuals<Real> r{};

  // (42): the eta-integral of I[Q, eta] by quadrature in t = eta - x0.
  const auto iq = [&](Real t) { return exp(-t / V) * ops.extended(q, Real(x0 + t), y); };
  const Real laplace = capped_integral<Rule>(iq, depth * V, std::min(x0, V), 2, V) / V;
  r.eq42 = viscoroll::line::leading_edge_bessel_term_scaled(c.c1, a, b, g, V) + laplace +
           ops.extended(f1, x0, y) / V - lambda_f0;
  r.scale42 = std::abs(lambda_f0);

  // (44)
  const Real lhs44 = viscoroll::line::leading_edge_bessel_term(c.c1, a, b, g, V);
  r.eq44_l2 = lhs44 - paper.kernel(q, V, y);
  r.eq44_lit = lhs44 - paper.literal(q, V, y);
  r.scale = std::abs(lambda_q) + 2 * std::abs(q(y)) * (1 + std::abs(std::log(V)));
  const auto small = [&](Real eta) { return exp(-eta / V) * (ops.extended(q, eta, y) - lambda_q); };
  r.delta = -graded_integral<Rule>(small, x0, x0, 8) / V +
            exp(-x0 / V) * (ops.extended(f1, x0, y) - lambda_f1) / V;

  if (with_quadrature) {
    // (38) with (26): u(x0) in w = sqrt(eta - x0), which removes the sqrt(eta - x0) behaviour of
    // the log potential at the edge; nearest singularities at w = i sqrt(min(x0, 2a)).
    const auto wstar = [&](Real eps) {
      const Real eta = x0 + eps;
      return c.template log_potential_outside<Rule>(y, eps) + ops.extended(f0, eta, y) -
             ops.extended_dx(f1, eta, y);
    };
    const auto integrand = [&](Real w) { return 2 * w * exp(-w * w / V) * wstar(w * w); };
    const Real root_v = std::sqrt(V);
    const Real u = capped_integral<Rule>(integrand, std::sqrt(depth) * root_v,
                                         std::sqrt(std::min({x0, 2 * a, V})), 2, root_v / 2) /
                   V;
    // S - V S' = W*_in = -2 int p* ln|x' - x| + Lambda[F0] (25) inside; S = -C1 x^2/2 + const.
    const Real w_in = c.template log_potential_centre<Rule>(y) + lambda_f0;
    const Real constant = w_in + c.c1 * b * b / 2 - V * c.c1 * b;
    const Real s_x0 = -c.c1 * x0 * x0 / 2 + constant;
    r.quad = u - s_x0;
    r.scale42 += std::abs(s_x0);
  }
  return r;
}

// a0/l = 0.1, b0/a0 = 0.2, V/a0 = 0.5: a narrow contact at an intermediate speed, with a(y), b(y)
// not of the static shape (e1, e2 != 0) and G from (36) (the leading-edge condition itself need
// not hold: the identities are for any a, b, G).
template <class Real>
Contact<Real> base_contact() {
  return Contact<Real>{Real(1),    Real(0.1),  Real(0.2), Real(0.02),
                       Real(-0.3), Real(0.05), Real(2),   Real(1.5)};
}

}  // namespace

TEST_CASE("line: (42) by closed-form pieces equals quadrature of (38) with (26)", "[line]") {
  using Real = double;
  using Rule = viscoroll::GaussLegendre<Real, 16>;
  const auto start = std::chrono::steady_clock::now();
  const Contact<Real> c = base_contact<Real>();
  const Real y = Real(0.3);
  const Residuals<Real> r = residuals<Real, Rule>(c, y, true);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO(std::setprecision(17) << "residual_quad = " << r.quad << ", residual_42 = " << r.eq42
                             << ", scale = " << r.scale42 << ", time " << seconds << " s");
  // Both sides are differences of terms of size scale42 = |Lambda[F0]| + |S(x0)|; each term is
  // computed to ~ 24 eps (the condition of the subtracted line integrals) and the outer
  // quadratures converge below that (checked with 32-point rules in the [slow] test), so the
  // identity must hold to 100 eps scale42.
  CHECK(std::abs(r.quad - r.eq42) <= 100 * std::numeric_limits<Real>::epsilon() * r.scale42);
  // Not trivially zero: a, b, G do not satisfy the leading-edge condition.
  CHECK(std::abs(r.eq42) > 1e-3 * r.scale42);
}

TEST_CASE("line: (44) equals (42) times exp(-x0/V) up to the small-argument error", "[line]") {
  using Real = double;
  using Rule = viscoroll::GaussLegendre<Real, 16>;
  const Real eps = std::numeric_limits<Real>::epsilon();
  Real previous = 1;
  for (Real shrink : {Real(1), Real(0.25), Real(0.0625)}) {
    Contact<Real> c = base_contact<Real>();
    c.a0 *= shrink;
    c.b0 *= shrink;
    const Residuals<Real> r = residuals<Real, Rule>(c, Real(0.3), false);
    const Real x0 = c.a(0.3) + c.b(0.3);
    const Real e = std::exp(-x0 / c.vtau);
    INFO(std::setprecision(17) << "shrink " << shrink << ": e^{-x0/V} res42 = " << e * r.eq42
                               << ", res44 (L2) = " << r.eq44_l2 << ", literal " << r.eq44_lit
                               << ", Delta = " << r.delta
                               << ", |Delta|/scale = " << std::abs(r.delta) / r.scale);
    // The exact relation between the two, to the accuracy of the pieces (~ 24 eps scale each).
    CHECK(std::abs(e * r.eq42 - r.eq44_l2 - r.delta) <= 200 * eps * r.scale);
    // (L2) and the literal (44) agree (V/l = 0.05: (44) cancels ~ 1 digit).
    CHECK(std::abs(r.eq44_l2 - r.eq44_lit) <= 200 * eps * r.scale);
    // The small-argument error relative to the terms of (44) shrinks at least like x0^2 (a factor
    // 16 per step; 8 allows for the logarithm).
    const Real relative = std::abs(r.delta) / r.scale;
    CHECK(relative < previous / 8);
    previous = relative;
  }
}

TEST_CASE("line: (42) against quadrature of (38), other speeds, positions and rules",
          "[line][slow]") {
  using Real = double;
  const Real eps = std::numeric_limits<Real>::epsilon();
  // V/a0 from 0.1 (fast relaxation, thin leading-edge layer) to 10, and a strip near the end.
  for (Real vtau : {Real(0.01), Real(0.05), Real(1)}) {
    for (Real y : {Real(0), Real(0.9)}) {
      Contact<Real> c = base_contact<Real>();
      c.vtau = vtau;
      const Residuals<Real> r16 = residuals<Real, viscoroll::GaussLegendre<Real, 16>>(c, y, true);
      const Residuals<Real> r32 = residuals<Real, viscoroll::GaussLegendre<Real, 32>>(c, y, true);
      INFO(std::setprecision(17) << "V " << vtau << " y " << y << ": quad " << r16.quad << " (42) "
                                 << r16.eq42 << " | N=32: " << r32.quad << " " << r32.eq42
                                 << " scale " << r16.scale42);
      // Same origin as the default test; N = 32 shows the 16-point panels converged.
      CHECK(std::abs(r16.quad - r16.eq42) <= 100 * eps * r16.scale42);
      CHECK(std::abs(r32.quad - r32.eq42) <= 100 * eps * r32.scale42);
      CHECK(std::abs(r16.eq42 - r32.eq42) <= 100 * eps * r16.scale42);
    }
  }
}

TEST_CASE("line: (42) against quadrature of (38) in long double", "[line][slow]") {
  using Real = long double;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Contact<Real> c = base_contact<Real>();
  const Residuals<Real> r = residuals<Real, viscoroll::GaussLegendre<Real, 20>>(c, Real(0.3), true);
  INFO(std::setprecision(20) << "quad " << r.quad << " (42) " << r.eq42 << " scale " << r.scale42);
  CHECK(std::abs(r.quad - r.eq42) <= 100 * eps * r.scale42);
}

}  // namespace test_leading_edge_condition
