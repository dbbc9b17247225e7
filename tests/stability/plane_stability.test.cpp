// Stability matrix of the plane (Hunter) solver, docs/stability.md: V tau/a0 = 0, 1e-4 ... 1e4
// against f = 0, 1e-2 ... 1e4 in float, double and long double (the default suite), and a subset
// in cpp_bin_float_50.
//
// Every cell: every number of the solution finite; converged; (P2) a^2 + 2G = a0^2 to rounding;
// a between the glassy and the long-term Hertz widths, b >= 0, G >= 0, chi >= 0; the pressure
// finite and >= 0 on the strip, zero at both edges, and its integral (an independent graded
// Gauss-Legendre quadrature of the reconstructed p, Eq. 35) equal to the load W; a, b and chi
// against a 70-digit mpmath solution of (P5), (P4), (P7) (docs/stability.md gives the script);
// and the limits: V tau = 0 and f = 0 are Hertz with the long-term compliance exactly,
// V tau/a0 = 1e-4 is a = a0 (1 - f/(1+f) V tau/(2 a0)) to O((V tau/a0)^3), V tau/a0 = 1e4 is the
// glassy width a0 (1+f)^(-1/2) to O((a0/V tau) ln(V tau/a0)).
#include <algorithm>
#include <array>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

#include "stability_support.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_stability {

namespace {

using stability::eps;
using stability::finite;
using stability::report;
using stability::str;
using viscoroll::GaussLegendre;
using viscoroll::PlaneScene;
using viscoroll::PlaneSolver;
using viscoroll::StandardLinearSolid;

/// The 70-digit solution of (P5) (mpmath findroot, Bessel functions of mpmath), then b (P4) and
/// chi/(C1 a0) (P7), for a0 = 1: docs/stability.md, "Plane truth table".
struct Truth {
  double v, f;
  const char *a, *b, *chi;
};
// clang-format off
constexpr std::array<Truth, 20> truth{{
    {1e-4, 1e-2, "0.9999995049504968876198121292758736759913170999662179805", "0.000000495024875012162248478511927627044758166678100673992506", "0.0000009900004901483905123721330949842646711603762545349745098"},
    {1e-4, 1, "0.9999750000000546861819811523414070461502119508926716434", "0.00002499906249999780293940616835930731881342473108171319889", "0.00004999625000000878865240636215764705502573731576042823002"},
    {1e-4, 9, "0.9999550000000624352032421171072157627963986890355708239", "0.00004499876249999765679338816452298671868512011707493578073", "0.0000899950500000093734444387015719761608055325482332649397"},
    {1e-4, 1e4, "0.9999500049995625476516019794666489686325653833573769606", "0.00004999375049996015906232227538896168147579484354663466749", "0.00009998500099995937437557020587543834172570448919445684869"},
    {1e-2, 1e-2, "0.999950496887700358261347353516572563801789093924115336", "0.0000492586419666677589919582295128821006793130517362806571", "0.00009802474004114629082258666587950775906062814053673343364"},
    {1e-2, 1, "0.9975000545590222398991745772413681194617061050931130496", "0.00249062478227821349462257154951519996392788398775362583", "0.004962500874866342357001826636377715379287387709676449671"},
    {1e-2, 9, "0.9955000622112392191842661822291545255271789998809147317", "0.004487624768687866026787772461230374482878744748355921217", "0.008950500931293649313660862113866081704850918117400324046"},
    {1e-2, 1e4, "0.9950005622190797136406859914118830550262289809033841696", "0.004986999818818494137788802148255003948684634743312436825", "0.009949001031808953491302199263055917672821108201402615581"},
    {1, 1e-2, "0.9966235472799984687092496617861489554301931465169407912", "0.002363614778371774755094453560713028276061973953607662193", "0.00317541941284033385067432098302549246592260354054387861"},
    {1, 1, "0.8034026936165959006762756405896240587779163997917224744", "0.1449396281773697536744095606537164620724250347725393564", "0.1968433798601559963282382291641394071892119339107041743"},
    {1, 9, "0.6009187545590024355807314019928189172211401205221164872", "0.317425992079259584106041330985432623478997851672747781", "0.4639057526761912860348269316985858363877273662440789319"},
    {1, 1e4, "0.5503175165809490873248075683507800388420152080227578637", "0.3664348258104701702176353322353941735744706545691292033", "0.5582096490685120843048332044206575312820823389548820971"},
    {1e2, 1e-2, "0.9950384164507662758757209137925910664412775115442871407", "0.0002339740237106511686687027481983926149366436790845989171", "0.0002463471893705460759745382504940880860067565548348980983"},
    {1e2, 1, "0.7071559974896407414592089249919035640655592132971590573", "0.01266920388152797791646335852606806946096783777050752318", "0.01329419866042275167070047007420701440913112007421555993"},
    {1e2, 9, "0.3162873503601387715677854230378429096130816451973483626", "0.02642473931417950402855155516285202347957317380823217071", "0.02755006927096098415784433170884248564070070904265615714"},
    {1e2, 1e4, "0.01065910033920674766600521555046795809503516076742010967", "0.04630695569280036646895238778065278320672598291271178814", "0.0476643363664092797562254959620350092846529378418605337"},
    {1e4, 1e-2, "0.9950371904460333130740451087057512975131882627628302113", "0.000004619429252390811331232683199243423921868688076047632022", "0.000004743191622763251566662024038486783155712750893274009208"},
    {1e4, 1, "0.7071067901781577115975835853020087165728540923539646961", "0.0002418211369634892045334113938567701574882852970331335955", "0.0002480711369582808670316768128526838897239119110360563005"},
    {1e4, 9, "0.3162277752505372635126998039350149598987251820919038039", "0.000471490397879576567360788185133237589562832231465045327", "0.0004827403984166919890052668024342795473034696329759051051"},
    {1e4, 1e4, "0.009999562882938964514147462509891248183672390968125460766", "0.0006965046379800463025280098141108080273766773958921332121", "0.0007090034931112497453602768804956577157327478703268738"},
}};
// clang-format on

template <class Real>
Real parse(const char* s) {
  if constexpr (std::numeric_limits<Real>::digits > 64)
    return Real(s);
  else
    return static_cast<Real>(std::stold(s));
}

/// The parameter in Real exactly as the truth table has it: 1e-4 and 1e-2 as 1/10000 and 1/100
/// (their double values differ from them by ~1e-17, which long double would see).
template <class Real>
Real exact(double x) {
  return x < 1 ? 1 / Real(std::round(1 / x)) : Real(x);
}

template <class Real, class Quadrature>
using Solver = PlaneSolver<Real, StandardLinearSolid<Real>, Quadrature>;

/// The scene of a0 = 1 (C1 = 1, W = 1/(4 c (1 + f))), mu_D = 1, nu = 0.3, tau = 1: speed = V
/// tau/a0.
template <class Real>
struct Cell {
  Real v, f;
  StandardLinearSolid<Real> material() const { return {Real(1), Real(0.3), f, Real(1)}; }
  Real load() const { return 1 / (4 * material().instantaneous_compliance() * (1 + f)); }
};

/// int p dx over the strip by 24-point Gauss-Legendre on panels graded by 4 towards both edges
/// (p ~ sqrt of the distance there; each panel [s, 4s] converges as 3^-48) down to eps a, and at
/// most 4 delta wide within (ln(1/eps) + 10) delta of the leading edge, delta = V tau/(1+f) the
/// width of the leading-edge layer. Also the smallest p at the nodes.
template <class Real, class Solution>
std::array<Real, 2> pressure_integral(const Solution& s, Real delta) {
  using std::log;
  const Real lo = s.b - s.a, hi = s.b + s.a, a = s.a;
  std::vector<Real> cuts{lo, hi, s.b};
  for (Real h = a / 4; h > a * eps<Real>(); h /= 4) {
    cuts.push_back(lo + h);
    cuts.push_back(hi - h);
  }
  for (int k = 1; k < 8; ++k) cuts.push_back(lo + Real(k) * a / 4);
  if (delta > 0) {
    const Real reach = (log(1 / eps<Real>()) + 10) * delta;
    for (Real u = 4 * delta; u < std::min(reach, 2 * a); u += 4 * delta) cuts.push_back(hi - u);
  }
  std::sort(cuts.begin(), cuts.end());
  Real sum = 0, pmin = 0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (!(cuts[k + 1] > cuts[k])) continue;
    sum += GaussLegendre<Real, 24>::integrate(
        [&](Real x) {
          const Real p = s.pressure(x);
          if (!(p >= pmin)) pmin = p;  // also catches NaN
          return p;
        },
        cuts[k], cuts[k + 1]);
  }
  return {sum, pmin};
}

/// The checks of one cell; `quadrature` false skips the load integral (multiprecision: its
/// ~10^4 pressure evaluations would take minutes).
template <class Real, class Quadrature>
void check_cell(const Cell<Real>& cell, const Truth* t, bool quadrature) {
  using std::abs;
  using std::log;
  using std::sqrt;
  const Real e = eps<Real>();
  const Solver<Real, Quadrature> solver(cell.material());
  const Real W = cell.load();
  const auto s = solver.solve(PlaneScene<Real>{Real(1), W, cell.v});
  const std::string name =
      "plane " + stability::type_name<Real>() + " v=" + str(cell.v) + " f=" + str(cell.f);
  INFO(name << ": a = " << s.a << ", b = " << s.b << ", chi = " << s.chi << ", residual "
            << s.residual << ", iterations " << s.iterations);
  for (const Real& x : {s.a, s.b, s.g, s.a_long_term, s.f0, s.q, s.chi, s.residual})
    REQUIRE(finite(x));
  REQUIRE(s.converged);
  // The glassy and long-term widths bracket the root (P5); b, G, chi are sums of non-negative
  // terms (P4), (P7).
  const Real a_glassy = 1 / sqrt(1 + cell.f);
  CHECK(abs(s.a_long_term - 1) <= 4 * e);
  CHECK(s.a >= a_glassy * (1 - 4 * e));
  CHECK(s.a <= 1 + 4 * e);
  CHECK(s.b >= 0);
  CHECK(s.g >= 0);
  CHECK(s.chi >= 0);
  // (P2), F0 = C1 (a^2/4 + G/2) = C1 a0^2/4: a^2 and 2G are each <= 1 and rounded once or twice.
  const Real p2 = abs(s.a * s.a + 2 * s.g - 1);
  CHECK(p2 <= 8 * e);
  // Conditioning of (P5) in A: h(A) = A^2 + 2 f/(1+f) v A R - 1 is evaluated to a few eps of its
  // largest term (1), and h'(A) >= 2 A (both terms increase), so A is found to about
  // 2 eps / (2 A) absolute, i.e. eps / A^2 <= (1 + f) eps relative. b and chi inherit it
  // (b, chi ~ V tau R: relative errors of R's Bessel ratios, <= 2 eps, and of A).
  const Real cond = 1 / (s.a * s.a);
  long double ea = 0, eb = 0, ec = 0;
  if (t != nullptr) {
    const Real ta = parse<Real>(t->a), tb = parse<Real>(t->b), tc = parse<Real>(t->chi);
    ea = static_cast<long double>(abs(s.a / ta - 1));
    eb = static_cast<long double>(abs(s.b / tb - 1));
    ec = static_cast<long double>(abs(s.chi / tc - 1));
    // 55 significant digits in the table (mpmath at 70 digits, root to 1e-65): the floor for
    // cpp_bin_float_50.
    const Real floor = Real(1e-54);
    CHECK(abs(s.a / ta - 1) <= 8 * cond * e + floor);
    CHECK(abs(s.b / tb - 1) <= 32 * cond * e + floor);
    CHECK(abs(s.chi / tc - 1) <= 32 * cond * e + floor);
  }
  // Limits.
  const Real creep = cell.f / (1 + cell.f);
  if (cell.v == 0 || cell.f == 0) {
    // Hertz with the long-term compliance, closed form: no root, no Bessel work.
    CHECK(s.iterations == 0);
    CHECK(s.a == s.a_long_term);
    CHECK(s.b == 0);
    CHECK(s.chi == 0);
  } else if (cell.v <= Real(1e-4)) {
    // (P5) expanded for V tau << a0 (r_I ~ 1 - 1/(2 alpha), r_K ~ 1 + 1/(2 beta)): the O(v^2)
    // terms cancel, A = 1 - creep v/2 + c3 v^3, c3 in [0.0018, 0.0625] for f in [1e-2, 1e4]
    // (mpmath); bound v^3/8 plus the root's rounding. b = creep V tau/2 (1 + O(v)).
    CHECK(abs(s.a - (1 - creep * cell.v / 2)) <= cell.v * cell.v * cell.v / 8 + 4 * cond * e);
    CHECK(abs(s.b / (creep * cell.v / 2) - 1) <= 2 * cell.v + 32 * cond * e);
  } else if (cell.v >= Real(1e4)) {
    // (P6): a -> a0 (1+f)^(-1/2) at O((a0/V tau) ln(V tau/a0)) (9.2e-4 here; measured <= 6.3e-6,
    // at f = 1e4).
    CHECK(abs(s.a / a_glassy - 1) <= log(cell.v) / cell.v);
  }
  // The reconstructed pressure: zero at both edges, finite and >= 0 between, its integral is W.
  CHECK(s.pressure(s.b - s.a) == 0);
  CHECK(s.pressure(s.b + s.a) == 0);
  long double load_error = 0, pmin = 0;
  if (quadrature) {
    const Real delta = cell.v > 0 && cell.f > 0 ? cell.v / (1 + cell.f) : Real(0);
    const auto q = pressure_integral(s, delta);
    REQUIRE(finite(q[0]));
    REQUIRE(finite(q[1]));
    // The pressure's scale is W / a (mean over the strip); every evaluation of (35) is accurate to
    // a few eps of its largest term (docs/theory.md section 2): 64 eps of W/a at the nodes.
    CHECK(q[1] >= -64 * e * W / s.a);
    // The panels are exact to < eps, so the integral inherits the pressure's rounding and that
    // of a, b (cond): 64 cond eps.
    CHECK(abs(q[0] / W - 1) <= 64 * cond * e);
    load_error = static_cast<long double>(abs(q[0] / W - 1));
    pmin = static_cast<long double>(q[1] / (W / s.a));
  }
  report(name + ": a/a0 = " + str(s.a) + ", error a " + str(ea) + " b " + str(eb) + " chi " +
         str(ec) + " (bound on a " + str(8 * cond * e) + "), |a^2+2G-a0^2| " + str(p2) + ", load " +
         str(load_error) + ", min p/(W/a) " + str(pmin) + ", iterations " +
         std::to_string(s.iterations));
}

template <class Real, class Quadrature = GaussLegendre<Real, 24>>
void run_matrix(bool quadrature) {
  for (const auto& t : truth)
    check_cell<Real, Quadrature>({exact<Real>(t.v), exact<Real>(t.f)}, &t, quadrature);
  // f = 0 (elastic through the standard linear solid) at every speed, and V tau = 0 at every f.
  for (const double v : {0.0, 1e-4, 1.0, 1e4})
    check_cell<Real, Quadrature>({exact<Real>(v), Real(0)}, nullptr, quadrature);
  for (const double f : {1e-2, 9.0, 1e4})
    check_cell<Real, Quadrature>({Real(0), exact<Real>(f)}, nullptr, quadrature);
}

}  // namespace

TEMPLATE_TEST_CASE("stability: plane solver, V tau/a0 1e-4..1e4 x f 0..1e4", "[stability][plane]",
                   float, double, long double) {
  run_matrix<TestType>(true);
}

TEST_CASE("stability: plane solver in cpp_bin_float_50", "[stability][plane][multiprecision]") {
  // The extremes of both axes and the paper's f at V tau = a0, 48-point panels (theory.md sec. 2);
  // the load quadrature is left to the built-in types (it would take minutes here).
  using mp = boost::multiprecision::cpp_bin_float_50;
  for (const auto& t : truth)
    if ((t.v == 1e-4 || t.v == 1e4 || t.v == 1) && (t.f == 1e-2 || t.f == 1e4 || t.f == 9))
      check_cell<mp, GaussLegendre<mp, 48>>({exact<mp>(t.v), exact<mp>(t.f)}, &t, false);
  check_cell<mp, GaussLegendre<mp, 48>>({mp(1), mp(0)}, nullptr, false);
}

}  // namespace test_plane_stability
