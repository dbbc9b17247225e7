// Checks of the independent plane reference solver (tests/support/hunter_collocation.hpp), a
// spectral collocation of Hunter's Eq. (2); derivation in docs/hunter-collocation.md.
#include "support/hunter_collocation.hpp"

#include <algorithm>
#include <boost/math/special_functions/bessel.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_hunter_collocation {

using viscoroll::testing::hunter_reference;
using viscoroll::testing::HunterReference;
namespace hd = viscoroll::testing::hunter_detail;

namespace {

/// A scene in units where nothing is 1: c = (1 - nu)/(2 pi mu_D), C1, W.
template <class Real>
struct Scene {
  Real c = Real(0.07);
  Real c1 = Real(2.5);
  Real load = Real(1.3);
  Real f;
  Real a_long() const { return std::sqrt(4 * c * (1 + f) * load / c1); }  // long-term Hertz
};

template <class Real>
Real pi_v() {
  return boost::math::constants::pi<Real>();
}

/// int p dx by composite Gauss-Legendre in theta, x = b + a cos(theta): the integrand
/// a p sin(theta) is analytic and periodic in theta, so this converges geometrically.
template <class Real>
Real integrated_load(const HunterReference<Real>& r) {
  Real sum = 0;
  hd::gauss30_panels<Real>(Real(0), pi_v<Real>(), 64, [&](Real t, Real w) {
    sum += w * r.a * std::sin(t) * r.pressure(r.b + r.a * std::cos(t));
  });
  return sum;
}

/// min p over samples uniform in theta (clustered at both edges in x).
template <class Real>
Real min_pressure(const HunterReference<Real>& r, int samples) {
  Real lowest = std::numeric_limits<Real>::infinity();
  for (int k = 0; k < samples; ++k) {
    const Real t = (Real(k) + Real(0.5)) * pi_v<Real>() / Real(samples);
    lowest = std::min(lowest, r.pressure(r.b + r.a * std::cos(t)));
  }
  return lowest;
}

// m_n(s) = int_0^inf e^{-eta} H_n(s + v eta) d eta at s = cos(phi), from mpmath (34 digits):
// near part quad(e^{-eta} T_{n+1}(s + v eta)) on [0, eta_1] in 40 pieces, far part with
// w = t^2, quad(2 t e^{-t^2} H_n(1 + v t^2)); script in docs/hunter-collocation.md.
struct MemoryValue {
  long double v, phi;
  int n;
  long double m;
};
constexpr MemoryValue memory_values[] = {
    {1e-4L, 0.3L, 0, 0.955436489125606019642310227568L},
    {1e-4L, 0.3L, 5, -0.225221772580020852466952028971L},
    {1e-4L, 0.3L, 40, 0.960891009293035159695663658065L},
    {1e-4L, 1.7L, 0, -0.128744494295524684087642857335L},
    {1e-4L, 1.7L, 5, -0.714688839247742669946262407127L},
    {1e-4L, 1.7L, 40, 0.836001873175679002354880364373L},
    {1e-4L, 3.0L, 0, -0.989892496600445457271572794731L},
    {1e-4L, 3.0L, 5, 0.657127669005789804525019195584L},
    {1e-4L, 3.0L, 40, -0.900516201227188375857239642831L},
    {0.05L, 0.3L, 0, 0.888507548254935003347035619697L},
    {0.05L, 0.3L, 5, 0.245410265258804427762148356561L},
    {0.05L, 0.3L, 40, -0.00695101615885771443811592577909L},
    {0.05L, 1.7L, 0, -0.0788444943402418292899812865661L},
    {0.05L, 1.7L, 5, -0.848282227481667420587084246698L},
    {0.05L, 1.7L, 40, 0.375087551612440734617936674905L},
    {0.05L, 3.0L, 0, -0.939992496600445458752854161446L},
    {0.05L, 3.0L, 5, -0.218707595698330274308933525862L},
    {0.05L, 3.0L, 40, -0.0263656980184043834671739993901L},
    {1L, 0.3L, 0, 0.390651465440757955816147389585L},
    {1L, 0.3L, 5, 0.0391721699687080521276732831924L},
    {1L, 0.3L, 40, -0.00129739156887131598492337461973L},
    {1L, 1.7L, 0, 0.342012442320157584397096381064L},
    {1L, 1.7L, 5, -0.135049777516478528880413100282L},
    {1L, 1.7L, 40, 0.0137832979516415434350631172024L},
    {1L, 3.0L, 0, -0.213648871676227709110350129907L},
    {1L, 3.0L, 5, -0.0406176421531419935643343934712L},
    {1L, 3.0L, 40, -0.00107309167781810171674814081125L},
    {300L, 0.3L, 0, 0.00904373900042917672445603971379L},
    {300L, 0.3L, 5, 0.000143730730661773796333815267227L},
    {300L, 0.3L, 40, -0.00000449893713545811188629989153349L},
    {300L, 1.7L, 0, 0.0105006860989477076495422593179L},
    {300L, 1.7L, 5, -0.000388089599367785359785101067216L},
    {300L, 1.7L, 40, 0.0000443363026070165349812779924751L},
    {300L, 3.0L, 0, 0.00886649217458224044726700437956L},
    {300L, 3.0L, 5, -0.000122851025494722485609619213757L},
    {300L, 3.0L, 40, -0.00000353561899381487157237686919283L},
};

}  // namespace

TEMPLATE_TEST_CASE("Hunter memory integrals match 34-digit quadrature", "[plane][reference]",
                   double, long double) {
  using Real = TestType;
  const Real eps = std::numeric_limits<Real>::epsilon();
  for (const auto& ref : memory_values) {
    const Real v = static_cast<Real>(ref.v), phi = static_cast<Real>(ref.phi);
    const auto tail = hd::tail_integrals<Real>(v, 41);
    const auto m = hd::memory_integrals<Real>(phi, v, tail);
    INFO("v = " << ref.v << ", s = cos(" << ref.phi << "), n = " << ref.n);
    // Rounding: the rotation for cos((n+1) phi) and the sensitivity to phi both grow like n + 1;
    // the quadrature error is below 1e-40 (docs/hunter-collocation.md).
    CHECK(std::abs(m[static_cast<std::size_t>(ref.n)] - static_cast<Real>(ref.m)) <=
          16 * Real(ref.n + 1) * eps);
  }
}

TEMPLATE_TEST_CASE("Hunter collocation matrix is unchanged by finer panels", "[plane][reference]",
                   double, long double) {
  using Real = TestType;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real f = 9;
  const int n_terms = 48;
  hd::QuadratureSettings<Real> fine;
  fine.step_exponent = 2;
  fine.step_phase = 2;
  for (const Real v : {Real(1e-4), Real(0.05), Real(1), Real(1e4)}) {
    const auto coarse_a = hd::collocation_matrix<Real>(f, v, n_terms);
    const auto fine_a = hd::collocation_matrix<Real>(f, v, n_terms, fine);
    const Real diff = (coarse_a - fine_a).cwiseAbs().maxCoeff();
    INFO("v = " << v << ": max |A(step 8) - A(step 2)| = " << diff);
    // Only rounding may differ: f times a sum of O(1) terms, cos((n+1) phi) with error ~ n eps.
    CHECK(diff <= 16 * (1 + f) * Real(n_terms + 1) * eps);
  }
}

TEMPLATE_TEST_CASE("Hunter reference: f = 0 or V tau = 0 is long-term plane Hertz",
                   "[plane][reference]", double, long double) {
  using Real = TestType;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real tol = 1000 * eps;
  struct Case {
    Real f, vt_over_al;
  };
  for (const Case cs : {Case{0, 1}, Case{0, 0}, Case{9, 0}, Case{1, 0}}) {
    Scene<Real> sc{.f = cs.f};
    const Real al = sc.a_long();
    const auto r = hunter_reference<Real>(sc.c, sc.f, cs.vt_over_al * al, sc.c1, sc.load, 12);
    INFO("f = " << cs.f << ", V tau / a_L = " << cs.vt_over_al);
    REQUIRE(r.converged);
    CHECK(std::abs(r.a - al) <= tol * al);
    CHECK(std::abs(r.b) <= tol * al);
    CHECK(std::abs(r.chi) <= tol * sc.c1 * al);
    const Real p0 = 2 * sc.load / (pi_v<Real>() * r.a);  // plane Hertz: p0 = 2 W / (pi a)
    CHECK(std::abs(r.pmax - p0) <= tol * p0);
    CHECK(std::abs(r.pmax_x) <= tol * al);
    Real worst = 0;
    for (int k = 0; k <= 200; ++k) {
      const Real x = al * (Real(-1) + Real(k) / 100);
      const Real hertz = 2 * sc.load / (pi_v<Real>() * al * al) * std::sqrt(al * al - x * x);
      worst = std::max(worst, std::abs(r.pressure(x) - hertz));
    }
    CHECK(worst <= tol * p0);
  }
}

TEMPLATE_TEST_CASE("Hunter reference: V tau >> a is instantaneous plane Hertz",
                   "[plane][reference]", double, long double) {
  using Real = TestType;
  for (const Real f : {Real(1), Real(9)}) {
    Scene<Real> sc{.f = f};
    const Real al = sc.a_long();
    const Real vt = Real(1e6) * al;
    const auto r = hunter_reference<Real>(sc.c, f, vt, sc.c1, sc.load, 16);
    REQUIRE(r.converged);
    const Real a_inst = al / std::sqrt(1 + f);
    // The memory term is f m_n with |m_n(s)| <= delta = (3 + ln(1 + v))/v, v = V tau / a:
    // |H_n| <= 1 on [s, 1] (length (1 - s)/v <= 2/v in eta) and H_n(z) <= 1/z beyond, so
    // int e^{-w}/(1 + v w) dw <= (1 + ln(1 + v))/v. The solution differs from instantaneous Hertz
    // by O(f delta) relative (observed: b/a ~ 0.4 f delta, a/a_inst - 1 ~ 4 f / v^2).
    const Real v = vt / a_inst;
    const Real tol = f * (3 + std::log1p(v)) / v;
    INFO("f = " << f << ": a/a_inst - 1 = " << r.a / a_inst - 1 << ", b/a = " << r.b / r.a
                << ", tolerance f delta = " << tol);
    CHECK(std::abs(r.a - a_inst) <= tol * a_inst);
    CHECK(std::abs(r.b) <= tol * r.a);
    CHECK(r.b > 0);  // the contact shifts forward, towards the motion
    CHECK(std::abs(r.chi) <= 2 * tol * sc.c1 * r.a);
    const Real p0 = 2 * sc.load / (pi_v<Real>() * a_inst);
    CHECK(std::abs(r.pmax - p0) <= tol * p0);
    Real worst = 0;
    for (int k = 0; k <= 200; ++k) {
      const Real x = a_inst * (Real(-1) + Real(k) / 100);
      const Real hertz =
          2 * sc.load / (pi_v<Real>() * a_inst * a_inst) * std::sqrt(a_inst * a_inst - x * x);
      worst = std::max(worst, std::abs(r.pressure(x) - hertz));
    }
    // p is sqrt-like at the edges, so a shift b of the contact moves p by up to ~ p0 sqrt(2b/a).
    CHECK(worst <= 2 * std::sqrt(tol) * p0);
  }
}

namespace {

/// Self-convergence of a, b, chi, pmax: first N of the ladder at which N and 2N agree to
/// `target` (relative), with the table as INFO. Returns -1 if none.
template <class Real>
int converged_n(Real f, Real vt_over_al, const std::vector<int>& ladder, Real target,
                std::string& table) {
  Scene<Real> sc{.f = f};
  const Real al = sc.a_long();
  std::vector<HunterReference<Real>> runs;
  for (const int n : ladder)
    runs.push_back(hunter_reference<Real>(sc.c, f, vt_over_al * al, sc.c1, sc.load, n));
  std::ostringstream out;
  out << "f = " << f << ", V tau/a_L = " << vt_over_al << "\n   N" << std::setw(16) << "a/a_L"
      << std::setw(16) << "b/a_L" << std::setw(16) << "chi/(C1 a_L)" << std::setw(16)
      << "pmax/(W/a_L)"
      << "  N->2N\n";
  int first = -1;
  bool stays = true;
  const auto rel = [](Real x, Real y) { return std::abs(x - y) / std::abs(y); };
  for (std::size_t i = 0; i < ladder.size(); ++i) {
    const auto& r = runs[i];
    out << std::setw(4) << ladder[i] << std::setprecision(10) << std::setw(16) << r.a / al
        << std::setw(16) << r.b / al << std::setw(16) << r.chi / (sc.c1 * al) << std::setw(16)
        << r.pmax / (sc.load / al);
    const auto twice = std::find(ladder.begin(), ladder.end(), 2 * ladder[i]);
    if (twice != ladder.end()) {
      const auto& q = runs[static_cast<std::size_t>(twice - ladder.begin())];
      const Real d =
          std::max({rel(r.a, q.a), rel(r.b, q.b), rel(r.chi, q.chi), rel(r.pmax, q.pmax)});
      out << std::setprecision(2) << "  " << d;
      if (d < target && first < 0) first = ladder[i];
      if (d >= target && first >= 0) stays = false;
    }
    out << (r.converged ? "" : "  (not converged)") << "\n";
  }
  table = out.str();
  return stays ? first : -1;
}

}  // namespace

TEMPLATE_TEST_CASE("Hunter reference converges (V tau/a_L = 0.1, 1, 100)", "[plane][reference]",
                   double, long double) {
  using Real = TestType;
  const std::vector<int> ladder{8, 12, 16, 24, 32, 48};
  struct Case {
    Real f, vt_over_al;
    int expected_n;  // measured, docs/hunter-collocation.md
  };
  for (const Case cs : {Case{9, 1, 16}, Case{9, 100, 8}, Case{1, Real(0.1), 24}}) {
    std::string table;
    const int n = converged_n<Real>(cs.f, cs.vt_over_al, ladder, Real(1e-6), table);
    INFO(table);
    CHECK(n > 0);
    CHECK(n <= cs.expected_n);
  }
}

TEMPLATE_TEST_CASE("Hunter reference converges (f = 9, V tau/a_L = 0.01)",
                   "[plane][reference][slow]", double, long double) {
  using Real = TestType;
  const std::vector<int> ladder{48, 72, 96, 144, 192, 288};
  std::string table;
  const int n = converged_n<Real>(9, Real(0.01), ladder, Real(1e-6), table);
  INFO(table);
  CHECK(n > 0);
  CHECK(n <= 144);
}

TEMPLATE_TEST_CASE("Hunter reference: p >= 0 and int p dx = W", "[plane][reference]", double,
                   long double) {
  using Real = TestType;
  const Real eps = std::numeric_limits<Real>::epsilon();
  struct Case {
    Real f, vt_over_al;
    int n;
  };
  for (const Case cs : {Case{1, Real(0.1), 32}, Case{9, Real(0.1), 64}, Case{9, 1, 24},
                        Case{9, 10, 16}, Case{1, 100, 16}}) {
    Scene<Real> sc{.f = cs.f};
    const Real al = sc.a_long();
    const auto r = hunter_reference<Real>(sc.c, cs.f, cs.vt_over_al * al, sc.c1, sc.load, cs.n);
    INFO("f = " << cs.f << ", V tau/a_L = " << cs.vt_over_al << ", N = " << cs.n
                << ", residual = " << r.residual << ", rcond = " << r.rcond);
    REQUIRE(r.converged);
    // Rounding of a sum of N terms of size <= pmax.
    const Real tiny = 16 * Real(cs.n) * eps * r.pmax;
    CHECK(min_pressure(r, 16 * cs.n + 1000) >= -tiny);
    // Zero outside; at the edges only the rounding of s = (x - b)/a is left, sqrt(2 eps) pmax.
    CHECK(r.pressure(r.b - r.a * (1 + 4 * eps)) == 0);
    CHECK(r.pressure(r.b + r.a * (1 + 4 * eps)) == 0);
    CHECK(std::abs(r.pressure(r.b - r.a)) <= 4 * std::sqrt(eps) * r.pmax);
    CHECK(std::abs(r.pressure(r.b + r.a)) <= 4 * std::sqrt(eps) * r.pmax);
    CHECK(std::abs(integrated_load(r) - sc.load) <= 16 * Real(cs.n) * eps * sc.load);
    CHECK(std::abs(r.load - sc.load) <= 16 * Real(cs.n) * eps * sc.load);
    // Rolling friction from the pressure by quadrature, not from the coefficients.
    Real moment = 0;
    hd::gauss30_panels<Real>(Real(0), pi_v<Real>(), 64, [&](Real t, Real w) {
      const Real x = r.b + r.a * std::cos(t);
      moment += w * r.a * std::sin(t) * x * r.pressure(x);
    });
    CHECK(std::abs(sc.c1 * moment / sc.load - r.chi) <= 16 * Real(cs.n) * eps * sc.c1 * al);
    CHECK(r.b > 0);
    CHECK(r.chi > 0);
    CHECK(r.pmax >= r.pressure(r.pmax_x - r.a * Real(1e-3)));
    CHECK(r.pmax >= r.pressure(r.pmax_x + r.a * Real(1e-3)));
  }
}

namespace {

/// int_{-1}^{1} P(t)/(sigma - t) dt (principal value for |sigma| < 1), P(t) = p(b + a t), by
/// Gauss-Legendre in theta (t = cos theta) on panels graded geometrically (to pi 2^-20) towards 0
/// and pi; for |sigma| < 1 the singularity is subtracted: + P(sigma) ln((1 + sigma)/(1 - sigma)).
/// Deliberately NOT the Chebyshev identity the solver uses.
double cauchy_integral(const HunterReference<double>& r, double sigma) {
  const double pi = pi_v<double>();
  const auto p_at = [&](double t) { return r.pressure(r.b + r.a * t); };
  const bool inside = sigma < 1;
  const double theta_s = inside ? std::acos(sigma) : 0;
  const double p_s = inside ? p_at(sigma) : 0;
  std::vector<double> cuts{0, pi};
  for (int k = 1; k <= 20; ++k) {
    cuts.push_back(pi * std::ldexp(1.0, -k));
    cuts.push_back(pi - pi * std::ldexp(1.0, -k));
  }
  std::sort(cuts.begin(), cuts.end());
  double sum = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    hd::gauss30_panels<double>(cuts[i], cuts[i + 1], 1, [&](double th, double w) {
      const double t = std::cos(th);
      // sigma - cos(theta) without cancellation
      const double gap =
          inside ? 2 * std::sin((th + theta_s) / 2) * std::sin((th - theta_s) / 2) : sigma - t;
      sum += w * std::sin(th) * (p_at(t) - p_s) / gap;
    });
  }
  if (inside) sum += p_s * std::log((1 + sigma) / (1 - sigma));
  return sum;
}

}  // namespace

TEST_CASE("Hunter reference satisfies Eq. (2) by brute-force quadrature", "[plane][reference]") {
  // u'(x) = u_e'(x) + f int_0^inf e^{-eta} u_e'(x + V tau eta) d eta, u_e' = -2 c PV int p/(x-x'),
  // evaluated between the collocation points with quadrature only (no Chebyshev identities), must
  // equal the profile slope -C1 x. Outer integral: composite Gauss-Legendre, on [0, eta_1] in
  // panels of 2 units of eta, beyond the leading edge with eta = eta_1 + t^2 (removes the sqrt
  // behaviour of u_e' there) on t in [0, 7] (e^{-49} < eps). Tolerance 1e-12 C1 a_L: measured
  // residuals are <= 1e-14 C1 a_L; the margin covers the graded inner quadrature, which resolves
  // the near-singular kernel (s + v eta just above 1) only down to panels of pi 2^-20.
  struct Case {
    double f, vt_over_al;
    int n;
    std::vector<double> sigmas;
  };
  for (const Case& cs : {Case{9, 1, 24, {-0.97, 0.013, 0.93, 0.999}}, Case{1, 0.1, 32, {0.55}}}) {
    Scene<double> sc{.f = cs.f};
    const double al = sc.a_long();
    const double vt = cs.vt_over_al * al;
    const auto r = hunter_reference<double>(sc.c, cs.f, vt, sc.c1, sc.load, cs.n);
    REQUIRE(r.converged);
    const double v = vt / r.a;
    const auto slope_e = [&](double sigma) { return -2 * sc.c * cauchy_integral(r, sigma); };
    for (const double sigma : cs.sigmas) {
      const double eta_1 = (1 - sigma) / v;
      const double eta_end = std::min(eta_1, 40.0);
      double near = 0, far = 0;
      hd::gauss30_panels<double>(
          0.0, eta_end, static_cast<std::int64_t>(std::ceil(eta_end / 2)),
          [&](double eta, double w) { near += w * std::exp(-eta) * slope_e(sigma + v * eta); });
      if (eta_1 < 40)
        hd::gauss30_panels<double>(0.0, 7.0, 8, [&](double t, double w) {
          far += w * 2 * t * std::exp(-t * t) * slope_e(1 + v * t * t);
        });
      const double u_slope = slope_e(sigma) + cs.f * (near + std::exp(-eta_1) * far);
      const double x = r.b + r.a * sigma;
      INFO("f = " << cs.f << ", V tau/a_L = " << cs.vt_over_al << ", s = " << sigma
                  << ": u'(x) = " << u_slope << ", u'(x) + C1 x = " << u_slope + sc.c1 * x);
      CHECK(std::abs(u_slope + sc.c1 * x) <= 1e-12 * sc.c1 * al);
    }
  }
}

TEMPLATE_TEST_CASE("Hunter reference obeys the plane forms of Panek-Kalker (33), (36), (46), (54)",
                   "[plane][reference]", double, long double) {
  // Not used by the solver: consequences of the pseudo-pressure route that the reference, built
  // from Eq. (2) alone, must reproduce. In the plane problem F0 = int p* dx = c (1 + f) W, and
  //   (33) G = 2 F0 / C1 - a^2 / 2,
  //   (36) G = [(V tau - b) a - a^2 / alpha] I1(alpha) / I0(alpha), alpha = (1 + f) a / (V tau),
  //   (46), (54) chi = C1 V tau [f / (1 + f) - Q / F0], Q = (C1 / 2) G (1 - b / (V tau)).
  using Real = TestType;
  const Real eps = std::numeric_limits<Real>::epsilon();
  struct Case {
    Real f, vt_over_al;
    int n;
  };
  for (const Case cs : {Case{1, Real(0.1), 32}, Case{9, Real(0.1), 64}, Case{1, 1, 16},
                        Case{9, 1, 24}, Case{9, 10, 16}}) {
    Scene<Real> sc{.f = cs.f};
    const Real al = sc.a_long(), vt = cs.vt_over_al * al;
    const auto r = hunter_reference<Real>(sc.c, cs.f, vt, sc.c1, sc.load, cs.n);
    REQUIRE(r.converged);
    const Real a = r.a, b = r.b, alpha = (1 + cs.f) * a / vt;
    const Real f0 = sc.c * (1 + cs.f) * sc.load;
    const Real g33 = 2 * f0 / sc.c1 - a * a / 2;
    const Real g36 = ((vt - b) * a - a * a / alpha) * boost::math::cyl_bessel_i(1, alpha) /
                     boost::math::cyl_bessel_i(0, alpha);
    const Real q46 = sc.c1 / 2 * g33 * (1 - b / vt);
    const Real chi54 = sc.c1 * vt * (cs.f / (1 + cs.f) - q46 / f0);
    INFO("f = " << cs.f << ", V tau/a_L = " << cs.vt_over_al << ": G(33) = " << g33
                << ", G(36) = " << g36 << ", chi = " << r.chi << ", chi(54) = " << chi54);
    // The reference is converged to rounding at these N (measured <= 50 eps); G ~ a^2 and the
    // bracket of (54) loses the factor V tau / a to cancellation.
    const Real tol = 16 * Real(cs.n) * eps;
    CHECK(std::abs(g33 - g36) <= tol * a * a);
    CHECK(std::abs(r.chi - chi54) <= tol * sc.c1 * std::max(vt, a));
  }
}

TEST_CASE("Hunter reference rejects bad input", "[plane][reference]") {
  CHECK_THROWS_AS(hunter_reference<double>(0.0, 1.0, 1.0, 1.0, 1.0, 8), std::invalid_argument);
  CHECK_THROWS_AS(hunter_reference<double>(1.0, -1.0, 1.0, 1.0, 1.0, 8), std::invalid_argument);
  CHECK_THROWS_AS(hunter_reference<double>(1.0, 1.0, -1.0, 1.0, 1.0, 8), std::invalid_argument);
  CHECK_THROWS_AS(hunter_reference<double>(1.0, 1.0, 1.0, 0.0, 1.0, 8), std::invalid_argument);
  CHECK_THROWS_AS(hunter_reference<double>(1.0, 1.0, 1.0, 1.0, 0.0, 8), std::invalid_argument);
  CHECK_THROWS_AS(hunter_reference<double>(1.0, 1.0, 1.0, 1.0, 1.0, 1), std::invalid_argument);
  CHECK_THROWS_AS(
      hunter_reference<double>(1.0, 1.0, std::numeric_limits<double>::infinity(), 1.0, 1.0, 8),
      std::invalid_argument);
}

}  // namespace test_hunter_collocation
