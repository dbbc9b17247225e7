// Tests of viscoroll/line/line_operators.hpp: the finite part, the near-field operator (24)/(34),
// the extended operator (41) and its x-derivative, on LineOperators' panels and on the line
// residual's node set (LineNodeRule); and of viscoroll/line/paper_leading_edge.hpp: both forms of
// the right side of (44), and the Bessel term of (42)/(44). Truth: closed forms derived below,
// identities of the paper, and mpmath references (script in docs/line-operators.md).
#include <boost/math/special_functions/bessel.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <stdexcept>
#include <vector>
#include <viscoroll/line/line_node_rule.hpp>
#include <viscoroll/line/line_operators.hpp>
#include <viscoroll/line/paper_leading_edge.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_operators {

namespace {

using viscoroll::line::LineOperators;
using viscoroll::line::PaperLeadingEdgeOperators;

template <class Real>
Real parse(const char* s) {
  return static_cast<Real>(std::strtold(s, nullptr));
}

template <class Real>
Real eps() {
  return std::numeric_limits<Real>::epsilon();
}

// Closed form of the finite part of a monomial (derived by hand, checked with sympy):
// (y'^n - y^n)/(y' - y) = sum_{k<n} y'^k y^(n-1-k), so
//   FP[y'^n](y) = sum_{k=0}^{n-1} y^(n-1-k) (l^(k+1) + (-l)^(k+1) - 2 y^(k+1)) / (k + 1).
// Examples: FP[1] = 0, FP[y'] = -2y, FP[y'^2] = l^2 - 3y^2
// (so FP[1 - y'^2/l^2] = (3y^2 - l^2)/l^2), FP[y'^3] = l^2 y - (11/3) y^3.
template <class Real>
Real monomial_fp(int n, Real l, Real y) {
  Real sum = 0;
  for (int k = 0; k < n; ++k) {
    const Real ends = std::pow(l, Real(k + 1)) + std::pow(-l, Real(k + 1));
    sum += std::pow(y, Real(n - 1 - k)) * (ends - 2 * std::pow(y, Real(k + 1))) / Real(k + 1);
  }
  return sum;
}

// Q(t) = (1 - t^2)(1 + t^2/3), t = y/l: the test profile of docs/theory.md section 3.
template <class Real>
Real q_profile(Real y) {
  return (1 - y * y) * (1 + y * y / 3);
}

// mpmath references at l = 1 (40 digits, quad with breakpoints at y and y +- x 2^k; script
// tools in docs/line-operators.md): I[Q, x](y) of Eq. (41) and dI/dx.
struct ExtendedRef {
  const char *x, *y;
  const char *value, *derivative;
};
const ExtendedRef extended_refs[] = {
    {"1e-6", "0", "0.552961027796563057326810303694", "0.000019344876984685533893628382955"},
    {"1e-6", "0.37", "0.539106512670294490048077779827", "0.0000261807865613946123244822079296"},
    {"1e-6", "-0.9", "1.36169505582394872637391792626", "0.0000479469683123108185605930971617"},
    {"1e-3", "0", "0.552966428386505087836986407774", "0.0101345300951530252735163997625"},
    {"1e-3", "0.37", "0.539113576768419396345480955893", "0.0131877542601376171387673339897"},
    {"1e-3", "-0.9", "1.36170437697353041151414976745", "0.0163558648687544295752288214989"},
    {"0.1", "0", "0.576211745847949825388663711351", "0.397512351058859691037695633084"},
    {"0.1", "0.37", "0.566417553992804940384526645332", "0.452015978270881785852847148265"},
    {"0.1", "-0.9", "1.35676716716618771209138104453", "-0.212836374288462081008734553235"},
    {"1", "0", "1.30502825724625686584448744625", "0.879577633300085959609181050784"},
    {"1", "0.37", "1.25788777098391697924637409487", "0.77662867174052286104727514296"},
    {"1", "-0.9", "1.06613541227381455773237148774", "-0.190050754536351685450051064252"},
    {"10", "0", "4.74724053280295059521855443553", "0.185823239766595498543046436338"},
    {"10", "0.37", "4.29807624219587133360901579903", "0.166349159669293421037778858495"},
    {"10", "-0.9", "1.25273080090698203179946092721", "0.0342516280295574796832819646249"},
};

// FP[exp](y) at l = 1 (mpmath quad on [-1, y, 1], 40 digits).
struct FpRef {
  const char* y;
  const char* value;
};
const FpRef fp_exp_refs[] = {{"0", "0.521302552157350760576332978707"},
                             {"0.37", "-0.389049855369232067940884384526"},
                             {"-0.9", "1.33236520586904787781375402841"},
                             {"0.999", "-3.57865479869419842487839214344"}};

// Right side of (44), literal form, for Q = q_profile at l = 1 (mpmath, 40 digits; H0 - Y0 by
// struveh - bessely at 120 digits for z <= 200, DLMF 11.6.1 beyond; quad with breakpoints at
// y +- V 2^k). The literal form cancels ~log10|ln V| digits, harmless at 40 digits.
struct KernelRef {
  const char *vtau, *y;
  const char* value;
};
const KernelRef kernel_refs[] = {
    {"1e-3", "0", "-0.00000957079259714107516559284020331"},
    {"1e-3", "0.37", "-0.0000123925069552480846626235512036"},
    {"1e-3", "-0.9", "-0.0000144241568817454061763707627459"},
    {"0.1", "0", "-0.0338482988071698119145182527837"},
    {"0.1", "0.37", "-0.0375262086366309129106936845775"},
    {"0.1", "-0.9", "0.0141564426182689063060084480856"},
    {"10", "0", "-3.42951735959589394116884539362"},
    {"10", "0.37", "-3.08376121781301827802335839232"},
    {"10", "-0.9", "0.126890619773135287594137044402"},
    {"1e-4", "0", "-0.000000126409371694080139952028235906"},
    {"1e-4", "0.37", "-0.000000167235389331116552052926248795"},
    {"1e-4", "-0.9", "-0.000000249524780821992219815220196485"},
};

}  // namespace

TEMPLATE_TEST_CASE("line: finite part against closed forms", "[line]", float, double, long double) {
  using Real = TestType;
  using Ops = LineOperators<Real, viscoroll::GaussLegendre<Real, 16>>;
  // Rounding of F(y') - F(y) at a node at distance s costs eps |F| / s; summed with the weights
  // of the graded 16-point panels ([0, d/4] innermost) this is eps sup|F| sum_j w_j / s_j, and
  // sum_j w_j / s_j <= 2 ln(l / s_min) + 2 <= 24 for the smallest node distance
  // s_min ~ 1.3e-3 (l - |y|)/4 used below. Polynomials of degree <= 31 are integrated exactly by
  // the rule, so rounding is all there is.
  const Real condition = 24;

  SECTION("static profile 1 - y^2/l^2: FP = (3 y^2 - l^2) / l^2") {
    for (Real l : {Real(1), Real(2.5), Real(1e-3)}) {
      const Ops ops(l);
      const Real a0sq = Real(0.04);
      const auto f = [&](Real y) { return a0sq * (1 - (y / l) * (y / l)); };
      for (Real t : {Real(0), Real(0.3), Real(-0.77), Real(0.999)}) {
        const Real y = t * l;
        const Real exact = a0sq * (3 * y * y - l * l) / (l * l);
        CHECK(std::abs(ops.finite_part(f, y) - exact) <= 4 * eps<Real>() * condition * a0sq);
      }
    }
  }
  SECTION("degree-7 polynomial against the monomial closed form") {
    const Real l = Real(1.5);
    const Ops ops(l);
    const Real c[] = {Real(0.5),   Real(-1),  Real(0.25), Real(2),
                      Real(-0.75), Real(0.3), Real(0.1),  Real(-0.05)};
    const auto f = [&](Real y) {
      Real v = 0;
      for (int n = 7; n >= 0; --n) v = v * y + c[n];
      return v;
    };
    for (Real y : {Real(0), Real(0.4), Real(-1.2), Real(1.49)}) {
      Real exact = 0, scale = 0;
      for (int n = 1; n <= 7; ++n) {
        exact += c[n] * monomial_fp(n, l, y);
        scale += std::abs(c[n]) * std::pow(l, Real(n));  // bound on sup|F - c0|
      }
      CHECK(std::abs(ops.finite_part(f, y) - exact) <= 4 * eps<Real>() * condition * scale);
    }
  }
  SECTION("exp against mpmath") {
    const Ops ops(Real(1));
    for (const auto& r : fp_exp_refs) {
      const Real y = parse<Real>(r.y);
      const Real ref = parse<Real>(r.value);
      // sup|exp| = e on [-1, 1]; the 4-panel 16-point rule converges far below eps for exp.
      CHECK(std::abs(ops.finite_part([](Real t) { return std::exp(t); }, y) - ref) <=
            4 * eps<Real>() * condition * std::exp(Real(1)));
    }
  }
  SECTION("near field (24) and strip form (34) on Kalker's static solution") {
    // Static line contact (docs/paper.md, "Checked by derivation"): a^2 = a0^2 (1 - t^2),
    // F0 = C1 a^2 / 4, and (34) holds with
    // C2 = C1 (a0/l)^2 (L - 1), d = C1 a0^2 L / 2, L = ln(4 l / a0), i.e.
    //   F0 ln(16 (l^2 - y^2)/a^2) + FP[F0] = -C1 a^2/4 - C2 y^2/2 + d.
    const Real l = 2, a0 = Real(0.1), c1 = Real(3);
    const Ops ops(l);
    const Real L = std::log(4 * l / a0);
    const Real c2 = c1 * (a0 / l) * (a0 / l) * (L - 1), d = c1 * a0 * a0 * L / 2;
    const auto asq = [&](Real y) { return a0 * a0 * (1 - (y / l) * (y / l)); };
    const auto f0 = [&](Real y) { return c1 * asq(y) / 4; };
    for (Real y : {Real(0), Real(0.5), Real(-1.3), Real(1.9)}) {
      const Real rhs = -c1 * asq(y) / 4 - c2 * y * y / 2 + d;
      const Real scale = c1 * a0 * a0 * L;  // size of the terms of (34)
      CHECK(std::abs(ops.near_field_strip(f0, y, std::sqrt(asq(y))) - rhs) <=
            8 * eps<Real>() * condition * scale);
      // (24) with F = l^2 - y^2: Lambda = 3 y^2 - l^2 + (l^2 - y^2) ln 4(l^2 - y^2).
      const auto g = [&](Real t) { return l * l - t * t; };
      const Real lambda = 3 * y * y - l * l + (l * l - y * y) * std::log(4 * (l * l - y * y));
      CHECK(std::abs(ops.near_field(g, y) - lambda) <= 8 * eps<Real>() * condition * l * l * 4);
    }
  }
}

TEST_CASE("line: finite part converges with the rule's order and the end grading", "[line]") {
  // 1/(1.05 - y) has a pole 0.05 beyond the end y = l = 1. (f(y') - f(y))/(y' - y) = f(y') f(y), so
  //   FP = f(y) [int_y^1 f - int_{-1}^y f] = f(y) [ln((1.05 - y)/0.05) - ln(2.05/(1.05 - y))].
  const auto f = [](double y) { return 1 / (1.05 - y); };
  const double y = 0.37;
  const double exact = f(y) * (std::log((1.05 - y) / 0.05) - std::log(2.05 / (1.05 - y)));
  // Rounding floor: eps sup|f| sum_j w_j/s_j <= 24 eps * 20.
  const double floor = 24 * eps<double>() * 20;
  viscoroll::line::LineOperatorOptions coarse;
  coarse.end_levels = 0;  // panels [0, d/4], [d/4, d/2], [d/2, d] on each side
  const auto error = [&](auto ops) { return std::abs(ops.finite_part(f, y) - exact); };
  using viscoroll::GaussLegendre;
  const double e4 = error(LineOperators<double, GaussLegendre<double, 4>>(1, coarse));
  const double e8 = error(LineOperators<double, GaussLegendre<double, 8>>(1, coarse));
  const double e16 = error(LineOperators<double, GaussLegendre<double, 16>>(1, coarse));
  const double e32 = error(LineOperators<double, GaussLegendre<double, 32>>(1, coarse));
  const double graded = error(LineOperators<double, GaussLegendre<double, 16>>(1));
  INFO(std::setprecision(3) << "errors N=4,8,16,32: " << e4 << " " << e8 << " " << e16 << " " << e32
                            << "; N=16 with end grading " << graded);
  // Geometric convergence on the last panel [d/2, d] (pole at 0.05 / (d/4) = 0.16 half-widths
  // beyond its end: Bernstein rho ~ 1.8, error ~ rho^-2N): at least a factor 5 per doubling.
  CHECK(e8 < e4 / 5);
  CHECK(e16 < e8 / 5);
  CHECK(e32 < std::max(e16 / 5, floor));
  // The default 8 halvings toward the ends put the last panel within the pole's distance.
  CHECK(graded <= floor);
  CHECK(e16 > 100 * graded);
}

TEMPLATE_TEST_CASE("line: extended operator (41) and its x-derivative", "[line]", float, double,
                   long double) {
  using Real = TestType;
  using Ops = LineOperators<Real, viscoroll::GaussLegendre<Real, 16>>;
  const Ops ops(Real(1));
  SECTION("against mpmath for x/l from 1e-6 to 10") {
    for (const auto& r : extended_refs) {
      const Real x = parse<Real>(r.x), y = parse<Real>(r.y);
      const Real value = ops.extended(q_profile<Real>, x, y);
      const Real deriv = ops.extended_dx(q_profile<Real>, x, y);
      // Condition: the subtracted integrand is O(sup|Q'|) per unit length and the end terms are
      // O(|Q| ln(l/x)): rounding ~ eps (24 + 2 |ln x|) sup|Q|, sup|Q| = 1. The node y' = y +- s
      // itself is rounded by eps |y'| / 2, which moves Q(y') by sup|Q'| eps |y'| / 2,
      // sup|Q'| = 8/3; the kernel of I integrates to 2 ln(2l/x) against it, that of dI/dx to 2/x
      // (the intrinsic condition of dI/dx for data sampled at rounded points).
      const Real condition = 24 + 2 * std::abs(std::log(x));
      const Real condition_dx = condition + Real(8) / 3 / x;
      CHECK(std::abs(value - parse<Real>(r.value)) <= 8 * eps<Real>() * condition);
      CHECK(std::abs(deriv - parse<Real>(r.derivative)) <= 8 * eps<Real>() * condition_dx);
    }
  }
  SECTION("constant F: I = asinh((l-y)/x) + asinh((l+y)/x) + 2 ln x exactly") {
    for (Real x : {Real(1e-8), Real(0.01), Real(3)}) {
      const Real y = Real(0.25);
      const Real exact = std::asinh((1 - y) / x) + std::asinh((1 + y) / x) + 2 * std::log(x);
      // asinh(u) ~ ln 2u: the reference itself loses eps |ln x| to cancellation.
      CHECK(std::abs(ops.extended([](Real) { return Real(1); }, x, y) - exact) <=
            8 * eps<Real>() * (1 + 2 * std::abs(std::log(x))));
    }
  }
  SECTION("small-argument limit (22): I[F, x] -> Lambda[F] as x -> 0, error O(x^2 ln x)") {
    if constexpr (!std::is_same_v<Real, float>) {
      const Real y = Real(0.37);
      const Real lambda = ops.near_field(q_profile<Real>, y);
      Real previous = 1;
      for (Real x : {Real(1e-2), Real(1e-3), Real(1e-4)}) {
        const Real err = std::abs(ops.extended(q_profile<Real>, x, y) - lambda);
        CHECK(err <= 10 * x * x * (1 + std::abs(std::log(x))));
        CHECK(err < previous / 50);
        previous = err;
      }
    }
  }
}

TEMPLATE_TEST_CASE("line: the operators on the line residual's node set", "[line]", double,
                   long double) {
  // The node-set operators that LineOperators applies on its panels, here on the nodes
  // LineResidual integrates with (LineNodeRule, docs/theory.md section 7: equal panels in
  // ln(s/(len - s)) after a first panel on the scale x0, with x0 = x), against the mpmath values of
  // I and dI/dx above with the same tolerances, and the finite part against its closed form
  // (Q = 1 - 2y^2/3 - y^4/3) within 4 eps times its condition sum_j w_j / s_j times
  // sup|Q| + sup|Q'| (the rounding of Q(y') - Q(y) and of y'). l = 1, N = 4, V tau = 1, f = 9.
  using Real = TestType;
  using Rule = viscoroll::GaussLegendre<Real, 12>;
  const viscoroll::line::LineNodeRule<Real, Rule> rule(viscoroll::LineBasis::t_squared, Real(0), 4,
                                                       Real(1), Real(9));
  const viscoroll::LineShape<Real> shape{Real(1), Real(1), {Real(0)}, {Real(0)}};
  for (const auto& r : extended_refs) {
    const Real x = parse<Real>(r.x), y = parse<Real>(r.y);
    viscoroll::line::LineNodes<Real> nd;
    rule.point(shape, y, x, nd);
    const Real qy = q_profile(y);
    const auto dq = LineOperators<Real, Rule>::differences(nd, q_profile<Real>, qy);
    INFO("x = " << r.x << ", y = " << r.y);
    const Real condition = 24 + 2 * std::abs(std::log(x));
    const Real condition_dx = condition + Real(8) / 3 / x;
    CHECK(std::abs(extended(nd, dq, qy, x) - parse<Real>(r.value)) <=
          8 * eps<Real>() * condition);
    CHECK(std::abs(extended_dx(nd, dq, qy, x) - parse<Real>(r.derivative)) <=
          8 * eps<Real>() * condition_dx);
    Real fp_condition = 0;
    for (std::size_t j = 0; j < nd.dist.size(); ++j) fp_condition += nd.weight[j] / nd.dist[j];
    const Real exact = -2 * monomial_fp(2, Real(1), y) / 3 - monomial_fp(4, Real(1), y) / 3;
    CHECK(std::abs(finite_part(nd, dq) - exact) <=
          4 * eps<Real>() * fp_condition * (1 + Real(8) / 3));
  }
}

TEMPLATE_TEST_CASE("line: right side of (44), form (L2) against the literal form and mpmath",
                   "[line]", double, long double) {
  using Real = TestType;
  const PaperLeadingEdgeOperators<Real, viscoroll::GaussLegendre<Real, 16>> paper(Real(1));
  const auto& ops = paper.operators();
  SECTION("(L2) = literal (44) where (44) does not cancel, V/l = 0.1, 1, 10") {
    for (Real vtau : {Real(0.1), Real(1), Real(10)}) {
      for (Real y : {Real(0), Real(0.37), Real(-0.9)}) {
        const Real l2 = paper.kernel(q_profile<Real>, vtau, y);
        const Real literal = paper.literal(q_profile<Real>, vtau, y);
        // The literal form's terms are O(|Q| (1 + |ln V|)) and cancel to |R|: rounding
        // ~ eps * 64 * (1 + |ln V|) (condition of the finite part and of the graded log integral).
        CHECK(std::abs(l2 - literal) <= 64 * eps<Real>() * (1 + std::abs(std::log(vtau))));
      }
    }
  }
  SECTION("against mpmath at V/l = 1e-4, 1e-3, 0.1, 10") {
    for (const auto& r : kernel_refs) {
      const Real vtau = parse<Real>(r.vtau), y = parse<Real>(r.y);
      const Real ref = parse<Real>(r.value);
      const Real l2 = paper.kernel(q_profile<Real>, vtau, y);
      // (L2) has no cancellation: rounding ~ eps (condition 24 of the difference quotients plus
      // the psi end terms, O(|Q| |ln V|)).
      // (L2) has no cancellation: rounding of Q(y') - Q(y) ~ eps sup|Q| / s against the kernel
      // ~ 1/s down to the innermost node gives eps sup|Q| (24 + |ln V|) absolute (sup|Q| = 1),
      // large relative to R itself when V << l (R = O(V^2 Q'')).
      INFO(std::setprecision(3) << "V " << vtau << " y " << y << " error / eps "
                                << (l2 - ref) / eps<Real>());
      CHECK(std::abs(l2 - ref) <= 4 * eps<Real>() * (24 + std::abs(std::log(vtau))));
    }
  }
  SECTION("V/l = 1e4: (L2) tends to the V -> inf limit Lambda[Q] + 2 Q (gamma - ln V)") {
    const Real vtau = Real(1e4), y = Real(0.37);
    const Real limit = ops.near_field(q_profile<Real>, y) +
                       2 * q_profile(y) * (boost::math::constants::euler<Real>() - std::log(vtau));
    // -(pi/(2V)) int Q [H0 - Y0] ~ -(1/V) int Q (ln(2V/|s|) - gamma) = O(ln(V)/V): 1e-3 here.
    const Real l2 = paper.kernel(q_profile<Real>, vtau, y);
    const Real literal = paper.literal(q_profile<Real>, vtau, y);
    CHECK(std::abs(l2 - limit) <= 4 * std::log(vtau) / vtau);
    CHECK(std::abs(l2 - literal) <= 64 * eps<Real>() * (1 + std::abs(std::log(vtau))));
  }
}

TEMPLATE_TEST_CASE("line: Bessel term of (42) and (44) without overflow", "[line]", double,
                   long double) {
  using Real = TestType;
  struct Case {
    double c1;
    const char *a, *b, *g, *vtau, *lhs44, *term42;
  };
  // mpmath, 40 digits: C1 e^{-b/V}(a b K1(a/V) - G K0(a/V)) and the same times e^{(a+b)/V}.
  const Case cases[] = {
      {2, "0.3", "0.05", "-0.01", "0.2", "0.00981113387860564392666036553016",
       "0.0564591772724745197723430132448"},
      // e^{-b/V} = e^{999} overflows double; e^{-(a+b)/V} = e^{-1} does not.
      {1, "1", "-0.999", "0.25", "1e-3", "-0.0182157576760189958414765076154",
       "-0.0495155630823358045483472624223"},
      {1, "0.02", "0.01", "0.0003", "50", "0.497518155453540236780987238277",
       "0.497816755917993683077089355513"},
  };
  for (const auto& c : cases) {
    const Real c1 = Real(c.c1), a = parse<Real>(c.a), b = parse<Real>(c.b), g = parse<Real>(c.g),
               v = parse<Real>(c.vtau);
    const Real lhs = viscoroll::line::leading_edge_bessel_term(c1, a, b, g, v);
    const Real term = viscoroll::line::leading_edge_bessel_term_scaled(c1, a, b, g, v);
    // Scaled K to a few eps; the difference a b K1 - G K0 cancels by at most a factor 20 here,
    // and e^{-(a+b)/V} carries the rounding of (a+b)/V (relative eps (a+b)/V <= eps).
    CHECK(std::abs(lhs - parse<Real>(c.lhs44)) <=
          200 * eps<Real>() * std::abs(parse<Real>(c.lhs44)));
    CHECK(std::abs(term - parse<Real>(c.term42)) <=
          200 * eps<Real>() * std::abs(parse<Real>(c.term42)));
  }
  // Far beyond the exponent range of e^{a/V}: finite (underflows to 0 only through e^{-(a+b)/V}).
  const Real lhs =
      viscoroll::line::leading_edge_bessel_term(Real(1), Real(1), Real(0.1), Real(0.2), Real(1e-6));
  CHECK(std::isfinite(lhs));
  CHECK(lhs == Real(0));
  const Real term = viscoroll::line::leading_edge_bessel_term_scaled(Real(1), Real(1), Real(0.1),
                                                                     Real(0.2), Real(1e-6));
  CHECK(std::isfinite(term));
  CHECK(term != 0);
}

TEST_CASE("line: operators reject arguments outside their domain", "[line]") {
  using Ops = LineOperators<double, viscoroll::GaussLegendre<double, 16>>;
  CHECK_THROWS_AS(Ops(0.0), std::invalid_argument);
  const Ops ops(1.0);
  const auto one = [](double) { return 1.0; };
  CHECK_THROWS_AS(ops.finite_part(one, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(ops.extended(one, 0.0, 0.0), std::invalid_argument);
  const PaperLeadingEdgeOperators<double, viscoroll::GaussLegendre<double, 16>> paper(1.0);
  CHECK_THROWS_AS(paper.kernel(one, -1.0, 0.0), std::invalid_argument);
}

}  // namespace test_line_operators
