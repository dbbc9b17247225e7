// Relaxation and creep spectra (docs/theory.md, section 11, (R1)–(R10)).
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/next.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>
#include <viscoroll/material/generalized_maxwell.hpp>
#include <viscoroll/material/prony.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_prony {

using viscoroll::PronyCreep;
using viscoroll::PronyRelaxation;
using viscoroll::PronyTerm;
using viscoroll::RelaxationTerm;

static_assert(viscoroll::PronySeriesModel<PronyCreep<double>>);
static_assert(viscoroll::PronySeriesModel<PronyRelaxation<float>>);
static_assert(viscoroll::PronySeriesModel<viscoroll::GeneralizedMaxwell<long double>>);
// Every material is a ConstitutiveModel; a spectrum is not a SingleTimeModel (the plane and line
// solvers reject it at compile time), while the standard linear solid is one.
static_assert(viscoroll::ConstitutiveModel<PronyRelaxation<double>>);
static_assert(!viscoroll::SingleTimeModel<PronyRelaxation<double>>);
static_assert(!viscoroll::SingleTimeModel<PronyCreep<float>>);
static_assert(!viscoroll::PronySeriesModel<viscoroll::StandardLinearSolid<double>>);

namespace {

template <class T>
double ulps(T a, T b) {
  return std::abs(double(boost::math::float_distance(a, b)));
}

// 30 terms, rho_i = 10^(-8 + 20 i / 29) s (20 decades), weights varying over three decades.
template <class T>
PronyRelaxation<T> thirty_terms() {
  std::vector<RelaxationTerm<T>> terms;
  for (int i = 0; i < 30; ++i) {
    const T rho = std::pow(T(10), T(-8) + T(20) * T(i) / T(29));
    const T g = T(1e8) * std::pow(T(10), T(1.5) * std::sin(T(i)));
    terms.push_back({g, rho});
  }
  return PronyRelaxation<T>(T(1e6), T(0.49), terms);
}

}  // namespace

TEMPLATE_TEST_CASE("prony: relaxation -> creep -> relaxation round trip to a few ulps (R4)-(R8)",
                   "[material][prony]", float, double, long double) {
  using T = TestType;
  const auto m = thirty_terms<T>();
  const auto c = m.to_creep();
  const auto back = c.to_relaxation();
  REQUIRE(c.terms().size() == 30);
  REQUIRE(back.terms().size() == 30);
  // Bound: 16 ulps, |x' - x| <= 16 eps |x| (measured: <= 5 in float, double and long double).
  double worst = ulps(back.g_inf(), m.g_inf());
  for (std::size_t i = 0; i < 30; ++i) {
    worst = std::max(worst, ulps(back.terms()[i].g, m.terms()[i].g));
    worst = std::max(worst, ulps(back.terms()[i].rho, m.terms()[i].rho));
  }
  CHECK(worst <= 16);
  // And creep -> relaxation -> creep.
  const auto c2 = back.to_creep();
  double worst_creep = 0;
  for (std::size_t k = 0; k < 30; ++k) {
    worst_creep = std::max(worst_creep, ulps(c2.terms()[k].f, c.terms()[k].f));
    worst_creep = std::max(worst_creep, ulps(c2.terms()[k].tau, c.terms()[k].tau));
  }
  CHECK(worst_creep <= 16);
  CHECK(ulps(c2.mu_d(), c.mu_d()) <= 16);
  WARN("round trip over 30 terms, 20 decades, digits "
       << std::numeric_limits<T>::digits << ": relaxation " << worst << " ulps, creep "
       << worst_creep << " ulps");
}

TEMPLATE_TEST_CASE("prony: retardation times interlace the relaxation times (R6)",
                   "[material][prony]", float, double, long double) {
  using T = TestType;
  const auto m = thirty_terms<T>();
  const auto& c = m.memory_terms();
  T bound = 0;
  for (const auto& t : m.terms()) bound += t.g * t.rho;
  bound = m.terms().back().rho + bound / m.g_inf();
  for (std::size_t i = 0; i < 30; ++i) {
    CHECK(m.terms()[i].rho < c[i].tau);
    if (i + 1 < 30) CHECK(c[i].tau < m.terms()[i + 1].rho);
    CHECK(c[i].f > 0);
  }
  CHECK(c.back().tau <= bound);
  // (R6b): J_g (1 + sum f_k) = 1 / G_inf and J_g = 1 / G_g.
  const T eps = std::numeric_limits<T>::epsilon();
  const auto creep = m.to_creep();
  CHECK(creep.mu_d() == m.glassy_modulus());
  CHECK(std::abs((1 + creep.creep_ratio()) / creep.mu_d() * m.g_inf() - 1) <= 16 * eps);
  CHECK(std::abs(creep.long_term_modulus() / m.g_inf() - 1) <= 16 * eps);
  CHECK(std::abs(m.long_term_compliance() / creep.long_term_compliance() - 1) <= 16 * eps);
  CHECK(m.instantaneous_compliance() == creep.instantaneous_compliance());
}

TEMPLATE_TEST_CASE("prony: one term is the standard linear solid (R6a)", "[material][prony]", float,
                   double, long double) {
  using T = TestType;
  const T eps = std::numeric_limits<T>::epsilon();
  const T mu_d = 3, f = 9, tau = T(0.5);
  const viscoroll::StandardLinearSolid<T> sls(mu_d, T(0.3), f, tau);
  const auto creep = viscoroll::as_prony(sls);
  REQUIRE(creep.terms().size() == 1);
  const auto relax = creep.to_relaxation();
  REQUIRE(relax.terms().size() == 1);
  // G_g = mu_D, G_inf = mu_D / (1 + f), g = mu_D f / (1 + f), rho = tau / (1 + f).
  CHECK(std::abs(relax.glassy_modulus() / mu_d - 1) <= 4 * eps);
  CHECK(std::abs(relax.g_inf() / (mu_d / (1 + f)) - 1) <= 4 * eps);
  CHECK(std::abs(relax.terms()[0].g / (mu_d * f / (1 + f)) - 1) <= 8 * eps);
  CHECK(std::abs(relax.terms()[0].rho / (tau / (1 + f)) - 1) <= 8 * eps);
  // And back: f and tau of Eq. (1).
  const auto c = relax.to_creep();
  CHECK(std::abs(c.terms()[0].f / f - 1) <= 16 * eps);
  CHECK(std::abs(c.terms()[0].tau / tau - 1) <= 16 * eps);
  CHECK(relax.instantaneous_compliance() ==
        Approx(sls.instantaneous_compliance()).epsilon(8 * eps));
  CHECK(relax.long_term_compliance() == Approx(sls.long_term_compliance()).epsilon(8 * eps));
  // Elastic is the empty series.
  const auto e = viscoroll::as_prony(viscoroll::Elastic<T>(T(2), T(0.25)));
  CHECK(e.terms().empty());
  CHECK(e.to_relaxation().terms().empty());
  CHECK(e.to_relaxation().g_inf() == T(2));
}

TEMPLATE_TEST_CASE("prony: M terms with equal times are one term with the summed weight",
                   "[material][prony]", float, double, long double) {
  using T = TestType;
  const PronyRelaxation<T> split(T(1), T(0.4),
                                 {{T(1), T(2)}, {T(2), T(2)}, {T(3), T(2)}, {T(0), T(5)}});
  const PronyRelaxation<T> one(T(1), T(0.4), {{T(6), T(2)}});
  REQUIRE(split.memory_terms().size() == 1);
  CHECK(split.memory_terms()[0].f == one.memory_terms()[0].f);
  CHECK(split.memory_terms()[0].tau == one.memory_terms()[0].tau);
  const PronyCreep<T> csplit(T(1), T(0.4), {{T(0.5), T(3)}, {T(1.5), T(3)}, {T(0), T(1)}});
  const PronyCreep<T> cone(T(1), T(0.4), {{T(2), T(3)}});
  const auto a = csplit.to_relaxation(), b = cone.to_relaxation();
  REQUIRE(a.terms().size() == 1);
  CHECK(a.terms()[0].g == b.terms()[0].g);
  CHECK(a.terms()[0].rho == b.terms()[0].rho);
  CHECK(a.g_inf() == b.g_inf());
  CHECK(csplit.creep(T(1.7)) ==
        Approx(cone.creep(T(1.7))).epsilon(4 * std::numeric_limits<T>::epsilon()));
}

TEST_CASE("prony: int_0^t G(t - s) dJ(s) = 1, an independent check of the conversion (R3)",
          "[material][prony]") {
  // Five terms over four decades; J from the conversion, the convolution by adaptive quadrature
  // on panels split at the times.
  const PronyRelaxation<double> m(2e6, 0.45,
                                  {{3e8, 1e-3}, {1e8, 1e-2}, {5e7, 0.1}, {2e7, 1.0}, {1e7, 10.0}});
  const auto c = m.to_creep();
  const double jg = 1 / c.mu_d();
  auto djds = [&](double s) {  // J'(s) = J_g sum f_k / tau_k exp(-s / tau_k)
    double v = 0;
    for (const auto& t : c.terms()) v += t.f / t.tau * std::exp(-s / t.tau);
    return jg * v;
  };
  for (double t : {1e-4, 3e-3, 0.05, 0.7, 8.0, 200.0}) {
    double integral = 0;
    double a = 0;
    for (double b : {1e-4, 1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0, 1000.0}) {
      const double hi = std::min(b, t);
      if (hi > a)
        integral += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
            [&](double s) { return m.relaxation(t - s) * djds(s); }, a, hi, 15, 1e-14);
      a = std::max(a, hi);
    }
    const double total = m.relaxation(t) * jg + integral;  // the jump J(0+) = J_g at s = 0
    CHECK(total == Approx(1.0).epsilon(1e-11));
  }
  // J(t) from creep_compliance: J(0) = 1 / G_g, J(inf) = 1 / G_inf.
  CHECK(c.creep_compliance(0.0) == Approx(1 / m.glassy_modulus()).epsilon(1e-15));
  CHECK(c.creep_compliance(1e9) == Approx(1 / m.g_inf()).epsilon(1e-14));
}

TEST_CASE("prony: dynamic moduli (R10)", "[material][prony]") {
  const PronyRelaxation<double> m(1.0, 0.5, {{2.0, 0.5}});
  const double w = 3.0, u = w * 0.5;
  CHECK(m.storage_modulus(w) == Approx(1 + 2 * u * u / (1 + u * u)).epsilon(1e-15));
  CHECK(m.loss_modulus(w) == Approx(2 * u / (1 + u * u)).epsilon(1e-15));
  CHECK(m.storage_modulus(1e300) == Approx(3.0).epsilon(1e-15));
  CHECK(m.loss_modulus(1e300) >= 0);
  CHECK(m.storage_modulus(0.0) == 1.0);
}

TEST_CASE("prony: invalid parameters are named", "[material][prony][validation]") {
  using R = PronyRelaxation<double>;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(R(0.0, 0.3, {{1.0, 1.0}}),
                    Catch::Contains("g_inf = 0") && Catch::Contains("g_inf > 0"));
  CHECK_THROWS_WITH(R(-1.0, 0.3, {}), Catch::Contains("g_inf = -1"));
  CHECK_THROWS_WITH(R(1.0, 0.3, {{1.0, 1.0}, {-2.0, 1.0}}), Catch::Contains("g[1] = -2"));
  CHECK_THROWS_WITH(R(1.0, 0.3, {{1.0, 0.0}}), Catch::Contains("rho[0] = 0"));
  CHECK_THROWS_WITH(R(1.0, 0.3, {{1.0, nan}}), Catch::Contains("rho[0]"));
  CHECK_THROWS_WITH(R(1.0, 0.7, {}), Catch::Contains("nu"));
  CHECK_THROWS_WITH((PronyCreep<double>(1.0, 0.3, {{-1.0, 1.0}})), Catch::Contains("f[0] = -1"));
  CHECK_THROWS_WITH((PronyCreep<double>(1.0, 0.3, {{1.0, -1.0}})), Catch::Contains("tau[0] = -1"));
  CHECK_THROWS_WITH((PronyCreep<double>(0.0, 0.3, {})), Catch::Contains("mu_d = 0"));
  // An instantaneous creep term (tau = 0) folds into the glassy modulus.
  const auto r = PronyCreep<double>(3.0, 0.3, {{0.5, 0.0}, {1.0, 2.0}}).to_relaxation();
  CHECK(r.glassy_modulus() == Approx(2.0).epsilon(1e-15));
  CHECK(r.g_inf() == Approx(3.0 / 2.5).epsilon(1e-15));
}

}  // namespace test_prony
