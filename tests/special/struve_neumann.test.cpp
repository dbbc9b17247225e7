// Tests of viscoroll/special/struve_neumann.hpp: H_0(x) - Y_0(x).
#include <boost/math/special_functions/next.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <viscoroll/quadrature/gauss_legendre.hpp>
#include <viscoroll/special/struve_neumann.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_struve_neumann {

namespace {

using viscoroll::special::struve_h0_minus_y0;
using Mp50 = boost::multiprecision::cpp_bin_float_50;

// Reference values of H_0(x) - Y_0(x) at x = m 2^e (exact in float and wider), to 60 significant
// digits. Produced by mpmath 1.3:
//   mp.dps = 100; with mp.workdps(200): v = struveh(0, x) - bessely(0, x)     (x <= 200)
//   v = 2/(pi x) (1 + sum_k (-1)^k ((2k-1)!!)^2 / x^(2k)), summed to 1e-90      (x > 200,
//   DLMF 11.6.1; the series' own error there is below e^{-200}) nstr(v, 60)
// and checked against (2/pi) quad(exp(-x t)/sqrt(1 + t^2), [0, inf]) (DLMF 11.5.2) at four points.
// The points straddle every switch: the series limit 1, and x_S = 18 (float), 39 (double),
// 46 (long double), 118 (50 digits).
struct Reference {
  long m;
  int e;
  const char* value;
};
// clang-format off
const Reference references[] = {
    {1, -100, "4.42009243256390059045656303515485234172987236058440516342741e+1"},
    {1, -60, "2.65500763134268784334012954143067331265687416244501789303306e+1"},
    {1, -30, "1.33119403048606811914896137504464862979564737972045529209357e+1"},
    {1, -10, "4.48713677564154906374817022875706973409575445671626496652829"},
    {1, -2, "1.08962548494659182893057771311815751311495771409900262798298"},
    {1, -1, "7.54074648090461275312471631817009936145870005490693265125091e-1"},
    {7, -3, "5.27592024834718565882886655249095792244533430569501666844369e-1"},
    {255, -8, "4.81743523850164187075880305476768127166912961433484925226678e-1"},
    {1, 0, "4.80399662832610993003496120298838111474860304164883191400151e-1"},
    {257, -8, "4.79063420147964329358039955022707529225919677673008043226314e-1"},
    {3, -1, "3.54274541806641027634276002301529713761828730234985804865761e-1"},
    {1, 1, "2.80483176858350772955061089756181209244566480490673187644785e-1"},
    {13, -2, "1.83753297361712306522048575064170536863522647508638992173444e-1"},
    {5, 0, "1.23300809472348889967930292068067701348490504399827828655182e-1"},
    {15, -1, "8.35515105334364005278589900184463224603039376760938902032145e-2"},
    {5, 1, "6.30725164038618767140518404742039126824691676181009230658128e-2"},
    {25, -1, "5.06200526133560896008207734178829317277854927395589530006037e-2"},
    {287, -4, "3.5383568309057856956729603895646890992646933984657782021967e-2"},
    {9, 1, "3.52614323931825986237778610327648234705966525516546261750971e-2"},
    {289, -4, "3.51401344726161232795248541474745387024703800829963827124086e-2"},
    {25, 0, "2.54246121079910351284394456762250654652624703288742763527943e-2"},
    {623, -4, "1.63390645761429030887576207735860355361626060264867336708066e-2"},
    {39, 0, "1.63129142595038837505311427817125339020121067388300849376405e-2"},
    {625, -4, "1.62868474619175439351063660051795599901832881209427040242154e-2"},
    {735, -4, "1.38518501195155021701287689314351120354876991171684165482827e-2"},
    {23, 1, "1.38330473311025077393675188300375282178956469208700310417608e-2"},
    {737, -4, "1.38142954965508288336789143116137688419688348101727850465951e-2"},
    {5, 4, "7.95650549835174369752666101231644019446721964503021867570083e-3"},
    {1887, -4, "5.39755406395019484392963162752098489663213977256701606454955e-3"},
    {59, 1, "5.39469560022383875460758074420489234952483954439797883495063e-3"},
    {1889, -4, "5.39184016227765205655184748414627976593045156857285321831183e-3"},
    {125, 2, "1.27323445196031190888517227379698636247623141131914518383704e-3"},
    {1, 20, "6.07127926222803440824058141738190807098601408217234630818853e-7"},
    {1, 100, "5.02204449911484696211444887280396604621121046981063631954917e-31"},
};
// clang-format on

template <class T>
T parse(const char* text) {
  if constexpr (std::is_floating_point_v<T>)
    return static_cast<T>(std::strtold(text, nullptr));
  else
    return T(text);
}

// Tolerances in units of eps; the arguments are exact, so only evaluation error counts.
// Built-in types, 4 eps: each method ends in a sum of terms of one sign (quadrature, asymptotic
// tail) or cancelling by at most a factor 1.6 (series at x = 1), with compensated summation where
// there are many terms; the remaining error is that of one log or the exps of the terms and a few
// roundings. Measured maximum over 1482 arguments: 2.8 eps (docs/special-functions.md).
// cpp_bin_float_50, 12 eps: its own log and exp were measured at up to 9 and 3.4 eps; the measured
// maximum of this function is 5.7 eps.
template <class T>
double tolerance() {
  return std::is_same_v<T, Mp50> ? 12 : 4;
}

template <class T>
void check_references() {
  using std::abs;
  using std::ldexp;
  const T eps = std::numeric_limits<T>::epsilon();
  for (const auto& r : references) {
    const T x = ldexp(T(r.m), r.e);
    const T expected = parse<T>(r.value);
    const T computed = struve_h0_minus_y0(x);
    const double error = static_cast<double>(abs(computed - expected) / (expected * eps));
    INFO("x = " << r.m << " * 2^" << r.e << ": computed "
                << viscoroll::detail::format_value(computed) << ", expected " << r.value
                << ", error " << error << " eps");
    CHECK(error <= tolerance<T>());
  }
}

/// Both sides of a switch point agree to the sum of their tolerances; H_0 - Y_0 changes by less
/// than eps over one ulp of x there (|x f'/f| <= 1).
template <class T>
void check_continuity(const T& threshold) {
  using std::abs;
  const T a = struve_h0_minus_y0(boost::math::float_prior(threshold));
  const T b = struve_h0_minus_y0(threshold);
  const T c = struve_h0_minus_y0(boost::math::float_next(threshold));
  INFO("across x = " << viscoroll::detail::format_value(threshold) << ": "
                     << viscoroll::detail::format_value(a) << ", "
                     << viscoroll::detail::format_value(b) << ", "
                     << viscoroll::detail::format_value(c));
  const T allowed = T(2 * tolerance<T>()) * std::numeric_limits<T>::epsilon() * b;
  CHECK(abs(a - b) <= allowed);
  CHECK(abs(c - b) <= allowed);
}

}  // namespace

TEMPLATE_TEST_CASE("H0 - Y0 matches 60-digit references", "[special][struve]", float, double,
                   long double) {
  check_references<TestType>();
}

TEST_CASE("H0 - Y0 matches 60-digit references in cpp_bin_float_50",
          "[special][struve][multiprecision]") {
  check_references<Mp50>();
}

TEMPLATE_TEST_CASE("H0 - Y0 is continuous across its switch points", "[special][struve]", float,
                   double, long double, Mp50) {
  SECTION("series to quadrature") {
    check_continuity(viscoroll::detail::struve_series_limit<TestType>());
  }
  SECTION("quadrature to asymptotic series") {
    check_continuity(viscoroll::detail::struve_asymptotic_threshold<TestType>());
  }
}

TEMPLATE_TEST_CASE("H0 - Y0 switch points and node counts follow the precision",
                   "[special][struve]", float, double, long double, Mp50) {
  using T = TestType;
  // x_S = ceil(-ln eps) + 2; N = digits + digits/16 + 8 (docs/special-functions.md).
  const int x_s = std::is_same_v<T, float>    ? 18
                  : std::is_same_v<T, double> ? 39
                  : std::is_same_v<T, Mp50>   ? 118
                                              : 46;
  CHECK(viscoroll::detail::struve_asymptotic_threshold<T>() == T(x_s));
  const int digits = std::numeric_limits<T>::digits;
  CHECK(viscoroll::detail::struve_quadrature_points<T>() == digits + digits / 16 + 8);
}

TEMPLATE_TEST_CASE("H0 - Y0 agrees with an independent quadrature of its Laplace integral",
                   "[special][struve]", double, long double) {
  // DLMF 11.5.2 in the variable v = x t: (2/pi) int_0^inf e^{-v} / sqrt(x^2 + v^2) dv, summed with
  // 64-point Gauss-Legendre on [0, x], [x, 2x], [2x, 10x] and [10x, 10x + 45] (the tail beyond is
  // below e^{-55}): a second method whose pieces are smooth on the scale of their intervals (the
  // singularities at v = +-ix are an interval length away), so the rules' error is far below eps
  // and what remains is the rounding of four sums of positive terms and their exps: 16 eps.
  using T = TestType;
  using std::abs;
  using std::exp;
  using std::sqrt;
  using Rule = viscoroll::GaussLegendre<T, 64>;
  for (T x : {T(1.25), T(2), T(3.5)}) {
    auto g = [x](T v) { return exp(-v) / sqrt(x * x + v * v); };
    const T integral = Rule::integrate(g, T(0), x) + Rule::integrate(g, x, 2 * x) +
                       Rule::integrate(g, 2 * x, 10 * x) + Rule::integrate(g, 10 * x, 10 * x + 45);
    const T second_method = boost::math::constants::two_div_pi<T>() * integral;
    INFO("x = " << x);
    CHECK(abs(struve_h0_minus_y0(x) - second_method) <=
          16 * std::numeric_limits<T>::epsilon() * second_method);
  }
}

TEMPLATE_TEST_CASE("H0 - Y0 has the right limits and never overflows", "[special][struve]", float,
                   double, long double) {
  using T = TestType;
  using std::abs;
  using std::log;
  const T eps = std::numeric_limits<T>::epsilon();
  const T pi = boost::math::constants::pi<T>();
  SECTION("tiny x: (2/pi)(ln(2/x) - gamma) + (2/pi) x, DLMF 11.2.1 and 10.8.2") {
    for (T x : {T(1e-30), T(1e-25), (std::numeric_limits<T>::min)(),
                std::numeric_limits<T>::denorm_min()}) {
      // ln(2/x) as ln 2 - ln x: 2/x overflows at the subnormal end.
      const T expected =
          2 / pi *
          (boost::math::constants::ln_two<T>() - log(x) - boost::math::constants::euler<T>());
      INFO("x = " << x);
      CHECK(abs(struve_h0_minus_y0(x) - expected) <= 4 * eps * expected);
    }
  }
  SECTION("huge x: 2/(pi x) (1 - 1/x^2), DLMF 11.6.1 (the next term, 9/x^4, is below 1e-31)") {
    for (T x : {T(1e8), T(1e30), (std::numeric_limits<T>::max)() / 4}) {
      const T expected = 2 / (pi * x) * (1 - 1 / (x * x));
      INFO("x = " << x);
      CHECK(abs(struve_h0_minus_y0(x) - expected) <= 4 * eps * expected);
    }
    CHECK(struve_h0_minus_y0(std::numeric_limits<T>::infinity()) == 0);
  }
  SECTION("domain errors") {
    CHECK_THROWS_AS(struve_h0_minus_y0(T(0)), std::invalid_argument);
    CHECK_THROWS_AS(struve_h0_minus_y0(T(-1)), std::invalid_argument);
    CHECK_THROWS_WITH(struve_h0_minus_y0(std::numeric_limits<T>::quiet_NaN()),
                      Catch::Contains("struve_h0_minus_y0") && Catch::Contains("x > 0"));
  }
}

}  // namespace test_struve_neumann
