// kappa and psi of the leading-edge condition (L2) (docs/theory.md section 3,
// docs/line-kernels.md): mpmath references across all three ranges and on both sides of each switch
// point, continuity of the methods at the switch points, psi' = kappa, and the limits z -> 0 and z
// -> inf.
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/next.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <viscoroll/special/line_kernels.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_kernels {

namespace {

using viscoroll::special::line_kernel_kappa;
using viscoroll::special::line_kernel_psi;
using Mp50 = boost::multiprecision::cpp_bin_float_50;
namespace detail = viscoroll::detail;

/// The accuracy documented in docs/line-kernels.md, in epsilon of Real, for every range: the
/// largest error measured over 1.2e5 arguments per type and range is 2.3 epsilon (float, double,
/// long double), from the rounding of 1/z and ln(z/2) just below z = 1/4.
constexpr double accuracy = 3;

struct Reference {
  long double z;  // exact in float, hence in every type tested
  const char* kappa;
  const char* psi;
};

// mpmath 1.3, mp.dps = 60, printed to 55 digits, by two independent methods that agree to 1e-55:
//   g = lambda t: t*t/((1+t*t)+sqrt(1+t*t));  h = lambda t: t/((1+t*t)+sqrt(1+t*t))
//   z < 1:  kappa = quad(lambda t: exp(-z*t)*g(t), P),  psi = -quad(lambda t: exp(-z*t)*h(t), P),
//           P = [0, 1/z, 10/z, 100/z, inf] and the powers 100^k from 1/(100 z) to 100/z;
//   z >= 1: kappa = quad(lambda s: exp(-s)*z*z*g(s/z), [0,1,10,100,z,inf])/z**3,
//           psi = -quad(lambda s: exp(-s)*z*h(s/z), [0,1,10,100,z,inf])/z**2;
// and, with extra working digits (80 + 3 log10 z),
//   kappa = 1/z - pi/2*(struveh(0,z) - bessely(0,z)),
//   psi = log(2*z) + euler - pi/2*quad(lambda s: struveh(0,s) - bessely(0,s), [0,1,10,z]),
// or, for z >= 200, the asymptotic series summed to 1e-60 (error < e^-200).
constexpr Reference references[] = {
    {0x1.4484cp-100L, "9.999999968289231590846770156725337257775271083493543566e+29",
     "-6.780718994118881550457281226867835317167506177549735712e+1"},  // 1e-30
    {0x1.79ca1p-67L, "1.000000031734478467718626607911526139878294754420575632e+20",
     "-4.478133904615391347544951297255785055066376155676128652e+1"},  // 1e-20
    {0x1.b7cdfep-34L, "9.99999984334389975007899521412887159411596360828675148e+9",
     "-2.175548807354172507473092778956110627693698183196040542e+1"},  // 1e-10
    {0x1.4f8b58p-17L, "9.998837365920697267009933109473430360168133276816353368e+4",
     "-1.024268893338774291292761226015197316318816693789681815e+1"},  // 1e-05
    {0x1.0624dep-10L, "9.929752677613932091215713765795892640835931609483965459e+2",
     "-5.645416572455057782187987097239112703888420374273987889"},  // 0.001
    {0x1.99999ap-5L, "1.684091915403241874669274814061851586523152200224204823e+1",
     "-1.932156134051416978371642563081585266576992833979770116"},  // 0.05
    {0x1.31afeep-3L, "4.549560332420663993934402398913416605557130194307410001",
     "-1.092360496549524744647325305110601129962493790080923125"},  // 0.149261
    {0x1.ff7ceep-3L, "2.291606686901340438204598925241959978665085116957866956",
     "-7.695197793116051622327347155703440176511098855734470052e-1"},  // 0.24975
    {0x1.ffffdep-3L, "2.288423515846875978324776904887330501379500404616405588",
     "-7.689478631594938706292408023489737080080781133096621207e-1"},  // 0.25
    {0x1p-2L, "2.288420290663785634681892768354943422738396477408876778",
     "-7.689472834570516518132004186823544146485100691325870784e-1"},  // 0.25
    {0x1.00001p-2L, "2.288417255203950490549885983485279283563602981294965106",
     "-7.689467378554994197063951610502005249694054435883223803e-1"},  // 0.25
    {0x1.00418ap-2L, "2.285240744842405185514720562137631280917925110662344521",
     "-7.683755492581478322312912256734467862790298157841716184e-1"},  // 0.25025
    {0x1.682f9cp-2L, "1.401461604693270211812650902286994410218031953894169262",
     "-5.869721147925020539545120382871657061401012214392545671e-1"},  // 0.351744
    {0x1.00c5p-1L, "8.115984812271181714653884063631498199552513918713289526e-1",
     "-4.273032372345259658231894390492623120578529724994035368e-1"},  // 0.501503
    {0x1.636dd8p-1L, "4.731883380082989596987002362888244412107951006536478476e-1",
     "-3.077886531741390541759981752317145271229678409536152216e-1"},  // 0.694197
    {0x1p+0L, "2.453899742290278313373872851290135492937526730659875857e-1",
     "-2.032951275330982609110393891977550638409459397920373214e-1"},  // 1
    {0x1.94c584p+1L, "2.037811605493216693579554367145792677076363612115410556e-2",
     "-3.884970945032709928069788219026456800379961459257877598e-2"},  // 3.16228
    {0x1.67e6p+2L, "4.613937529417402292591568509530413314847647127131473656e-3",
     "-1.419988948230883333403434399366988783564956947980852174e-2"},  // 5.62341
    {0x1.4p+3L, "9.259229111029017902605308760704568217953097043339816943e-4",
     "-4.803570448164093586050958062122055405026116872340195449e-3"},  // 10
    {0x1.1c8654p+4L, "1.731167424662021746049309154048328236122418876348170341e-4",
     "-1.559708600791613077512893706385620281056283686484582329e-3"},  // 17.7828
    {0x1.afffe4p+4L, "5.019838849711999944367472169034913291748953170936983219e-5",
     "-6.817309224932758887466082949810830077853260142357841807e-4"},  // 27
    {0x1.bp+4L, "5.01982407223860601151919061459792591457790381542479027e-5",
     "-6.817295820536615243763839682269632102980645550163515003e-4"},  // 27
    {0x1.b0001cp+4L, "5.019809294823110286300139873781649320196388215772797635e-5",
     "-6.817282416179931633903163687848620939162925362893703795e-4"},  // 27
    {0x1.f9f6e4p+4L, "3.13449650800756809328516744754698404808431985301368568e-5",
     "-4.977862211434243324913524067284284121882968949785244473e-4"},  // 31.6228
    {0x1.87ffe6p+5L, "8.468349398526856300268824396019853316385129734660043625e-6",
     "-2.078593530947623402130898791312664847195023207126366154e-4"},  // 49
    {0x1.88p+5L, "8.468323750242788305416696071198223144185825130465594738e-6",
     "-2.078589331409374695673750307072596235212041017536289341e-4"},  // 49
    {0x1.88001ap+5L, "8.468298102062233585365036807440820654564363893756650461e-6",
     "-2.078585131883845220633192760695601550816826037904548899e-4"},  // 49
    {0x1.c1df8p+5L, "5.607533847413091336414813863493457645373228458265220375e-6",
     "-1.578900646616735598057917630790275055508704949434493975e-4"},  // 56.2341
    {0x1.c7ffe2p+5L, "5.38494390127090198746476623913448232423335148244972228e-6",
     "-1.536817462020319042547884653830244253995643175171701612e-4"},  // 56.9999
    {0x1.c8p+5L, "5.384927713552755714622877680081447688164862451163884277e-6",
     "-1.536814380735334030632084015038422607545331329185760011e-4"},  // 57
    {0x1.c8001ep+5L, "5.384911525899463040574577279619615145007047483361071017e-6",
     "-1.536811299459611686783898728005265384027398894627508657e-4"},  // 57.0001
    {0x1.9p+6L, "9.991022390632398017990020989867482227744009081739531737e-7",
     "-4.99775373630716482661979713557767529260732757806023864e-5"},  // 100
    {0x1.09ffeep+7L, "4.248403053062857889517538852371443436074122426127357214e-7",
     "-2.825902843187175864492868287823278079211755830758352205e-5"},  // 133
    {0x1.0ap+7L, "4.248389897468872889239629124294589820971856952716099699e-7",
     "-2.825897008902465575177942611649419717646425426663278796e-5"},  // 133
    {0x1.0a0012p+7L, "4.248376741929200025493887605891071891959404189814964707e-7",
     "-2.82589117463582170759461146567127905126548564532400353e-5"},  // 133
    {0x1.63a7e8p+7L, "1.777773675634210624720085936462229080148007078638575857e-7",
     "-1.58091393269852565489647540043143593201367283274276516e-5"},  // 177.828
    {0x1.3c3a4ep+8L, "3.161993526174171259112950086965213820672152961057291389e-8",
     "-4.999775459020761232471208576196538716408871381403729556e-6"},  // 316.228
    {0x1.f4p+9L, "9.999910002249889758929169622323605816728651125743558354e-10",
     "-4.999977500374986219642934966353838515512149809537901681e-7"},  // 1000
    {0x1.86ap+16L, "9.999999991000000022499999889750000893024989194397682615e-16",
     "-4.999999997750000003749999986218750089302499099533138044e-11"},  // 100000
    {0x1.2a05f2p+33L, "9.999999999999999999100000000000000000225e-31",
     "-4.9999999999999999997750000000000000000375e-21"},  // 1e+10
    {0x1.c6bf52p+49L, "1.000000039026689015388272848021020766726465505137468942e-45",
     "-5.000000130088962538470671112485398337156803362840154089e-31"},  // 1e+15
    {0x1.5af1d8p+66L, "9.999999398773703816605075041581397316935478983451025842e-61",
     "-4.999999799591232597351309006159017913966983175350364886e-41"},  // 1e+20
    {0x1.08b2a2p+83L, "1.000000131392953635174676185404467529233877676972173105e-75",
     "-5.000000437976502526078222392802078411379127956601161046e-51"},  // 1e+25
    {0x1.93e594p+99L, "9.999999548576026989273371934491334579281756044238091883e-91",
     "-4.999999849525341197626637881728154041690502438508085619e-61"},  // 1e+30
};

template <class Real>
Real parse(const char* text) {
  if constexpr (std::is_floating_point_v<Real>)
    return static_cast<Real>(std::strtold(text, nullptr));
  else
    return Real(text);
}

template <class Real>
Real eps() {
  return std::numeric_limits<Real>::epsilon();
}

/// Parsing a reference rounds it by 1/2 epsilon of Real, after 1/2 epsilon of long double
/// (strtold) for the built-in types.
template <class Real>
Real reference_rounding() {
  if constexpr (std::is_floating_point_v<Real>)
    return Real(0.5) + Real(0.5) * static_cast<Real>(eps<long double>() / eps<Real>());
  else
    return Real(0.5);
}

/// |value - reference| <= tolerance_eps epsilon |reference|; below the smallest normal number
/// relative accuracy becomes absolute accuracy: tolerance_eps epsilon min().
template <class Real>
bool close(Real value, Real reference, Real tolerance_eps) {
  using std::abs;
  const Real scale = std::max<Real>(abs(reference), (std::numeric_limits<Real>::min)());
  return abs(value - reference) <= tolerance_eps * eps<Real>() * scale;
}

template <class Real>
Real relative_error_in_eps(Real value, Real reference) {
  using std::abs;
  return abs(value - reference) / (abs(reference) * eps<Real>());
}

}  // namespace

TEMPLATE_TEST_CASE("line kernels: kappa and psi against mpmath", "[special][line]", float, double,
                   long double) {
  using Real = TestType;
  const Real tolerance = accuracy + reference_rounding<Real>();
  for (const auto& row : references) {
    const Real z = static_cast<Real>(row.z);
    const Real kappa = line_kernel_kappa(z), psi = line_kernel_psi(z);
    const Real kappa_ref = parse<Real>(row.kappa), psi_ref = parse<Real>(row.psi);
    INFO("z = " << z << ", kappa error " << relative_error_in_eps(kappa, kappa_ref)
                << " eps, psi error " << relative_error_in_eps(psi, psi_ref) << " eps");
    CHECK(close(kappa, kappa_ref, tolerance));
    CHECK(close(psi, psi_ref, tolerance));
  }
}

TEST_CASE("line kernels: kappa and psi against mpmath in cpp_bin_float_50", "[special][line]") {
  using Real = Mp50;
  using Wide = boost::multiprecision::cpp_bin_float_100;
  using std::abs;
  using std::log;
  const Real z_series = detail::line_kernel_series_limit<Real>();
  for (const auto& row : references) {
    const Real z(row.z);
    const Real kappa = line_kernel_kappa(z), psi = line_kernel_psi(z);
    const Real kappa_ref = parse<Real>(row.kappa), psi_ref = parse<Real>(row.psi);
    // Below z = 1/4 the series call log, which Boost.Multiprecision rounds to a few epsilon, not
    // to 1/2: its absolute errors at z/2 and 2z enter kappa and psi as they are (the series use
    // ln(z/2) in kappa and ln(2z) + z ln(z/2) in psi), measured here against 100 digits.
    Real log_kappa = 0, log_psi = 0;
    if (z < z_series) {
      const Real err_half = Real(abs(Wide(Real(log(z / 2))) - log(Wide(z) / 2)));
      const Real err_twice = Real(abs(Wide(Real(log(2 * z))) - log(2 * Wide(z))));
      log_kappa = err_half / (kappa_ref * eps<Real>());
      log_psi = (err_twice + z * err_half) / (abs(psi_ref) * eps<Real>());
    }
    INFO("z = " << z << ", kappa error " << relative_error_in_eps(kappa, kappa_ref) << " eps (log "
                << log_kappa << "), psi error " << relative_error_in_eps(psi, psi_ref)
                << " eps (log " << log_psi << ")");
    CHECK(close(kappa, kappa_ref, Real(accuracy + reference_rounding<Real>() + log_kappa)));
    CHECK(close(psi, psi_ref, Real(accuracy + reference_rounding<Real>() + log_psi)));
  }
}

namespace {

/// At each switch point both adjacent methods are evaluated at the switch point itself and must
/// agree to twice the accuracy (each is within `accuracy` of the truth); the public functions
/// just below and at the switch point must agree to that plus the change of the function over
/// one ulp, at most 3 epsilon relative (z |kappa'| / kappa <= 3 and z kappa / |psi| <= 2 since
/// 1 - (1 + t^2)^{-1/2} grows at most like t^2).
template <class Real>
void check_switch_points(Real extra_tolerance) {
  const Real z_series = detail::line_kernel_series_limit<Real>();
  const Real z_asymptotic = detail::line_kernel_asymptotic_limit<Real>();
  const Real both = 2 * accuracy + extra_tolerance;
  {
    INFO("z = 1/4, the series against the rule");
    CHECK(close(detail::kappa_series(z_series), detail::laplace_rule<Real, false>(z_series), both));
    CHECK(close(detail::psi_series(z_series), detail::laplace_rule<Real, true>(z_series), both));
  }
  {
    INFO("z = " << z_asymptotic << ", the rule against the asymptotic series");
    CHECK(close(detail::laplace_rule<Real, false>(z_asymptotic),
                detail::asymptotic_series<Real, false>(z_asymptotic), both));
    CHECK(close(detail::laplace_rule<Real, true>(z_asymptotic),
                detail::asymptotic_series<Real, true>(z_asymptotic), both));
  }
  for (const Real& z : {z_series, z_asymptotic}) {
    const Real below = boost::math::float_prior(z);
    INFO("public functions at z = " << z << " and the number below it");
    CHECK(close(line_kernel_kappa(below), line_kernel_kappa(z), Real(both + 3)));
    CHECK(close(line_kernel_psi(below), line_kernel_psi(z), Real(both + 3)));
  }
}

}  // namespace

TEMPLATE_TEST_CASE("line kernels: continuous across the switch points", "[special][line]", float,
                   double, long double) {
  check_switch_points<TestType>(TestType(0));
}

TEST_CASE("line kernels: continuous across the switch points in cpp_bin_float_50",
          "[special][line]") {
  // The series side calls log, good to about 4 epsilon in Boost.Multiprecision (see above); at
  // z = 1/4 that enters kappa with |ln(1/8)| / kappa(1/4) < 1 and psi with
  // (|ln(1/2)| + |ln(1/8)| / 4) / |psi(1/4)| < 2.
  check_switch_points<Mp50>(Mp50(2 * 4));
}

TEMPLATE_TEST_CASE("line kernels: psi' = kappa", "[special][line]", float, double, long double) {
  using Real = TestType;
  using std::abs;
  using std::cbrt;
  using std::exp2;
  using std::log2;
  using std::min;
  using std::round;
  // (psi(z + h) - psi(z - h)) / (2h) = kappa(z) + h^2/6 psi'''(xi), and psi''' = kappa'' =
  // int t^2 e^{-zt} g(t) dt <= M(z) = min(2/z^3, 12/z^5) as 0 <= g(t) <= min(1, t^2/2). With psi
  // good to a epsilon |psi|, the difference is good to h^2/6 M(z - h) + a eps |psi| / h; h is the
  // power of two nearest the step that balances the two, so z +- h and 2h are exact.
  auto bound = [](Real x) { return min<Real>(2 / (x * x * x), 12 / (x * x * x * x * x)); };
  for (const Real z : {Real(0.125), Real(0.375), Real(2), Real(8), Real(24), Real(40), Real(80)}) {
    const Real a = accuracy;
    const Real psi_scale = abs(line_kernel_psi(z / 2));  // |psi| is largest at the left end
    const Real h = exp2(round(log2(cbrt(3 * a * eps<Real>() * psi_scale / bound(z / 2)))));
    REQUIRE(h < z / 2);
    const Real difference = (line_kernel_psi(z + h) - line_kernel_psi(z - h)) / (2 * h);
    const Real kappa = line_kernel_kappa(z);
    const Real tolerance =
        h * h / 6 * bound(z - h) + a * eps<Real>() * psi_scale / h + a * eps<Real>() * kappa;
    INFO("z = " << z << ", h = " << h << ", difference " << difference << ", kappa " << kappa
                << ", tolerance " << tolerance);
    CHECK(abs(difference - kappa) <= tolerance);
  }
}

TEMPLATE_TEST_CASE("line kernels: small-z limits", "[special][line]", float, double, long double) {
  using Real = TestType;
  using std::abs;
  using std::cbrt;
  using std::log;
  const Real gamma = boost::math::constants::euler<Real>();
  // psi(z) - ln(2z) - gamma = z (ln(z/2) + gamma - 1) - z^2/2 + O(z^3 ln z) and
  // kappa(z) - 1/z - ln(z/2) - gamma = -z + O(z^2 ln z) (A&S 9.1.13, 12.1.3, 11.1.7-8): the
  // first-order terms are checked with the next order, bounded by z^2 (|ln(z/2)| + 2), as
  // tolerance, plus the rounding of the functions and of the logarithms. z = eps^{1/3} makes the
  // first-order term dominate both.
  for (const Real z : {cbrt(eps<Real>()), Real(1e-3) * cbrt(eps<Real>())}) {
    const Real ell = log(z / 2) + gamma;
    const Real next_order = z * z * (abs(ell) + 2);
    const Real psi = line_kernel_psi(z), kappa = line_kernel_kappa(z);
    const Real psi_lead = log(2 * z) + gamma;
    INFO("z = " << z);
    CHECK(abs(psi - psi_lead - z * (ell - 1)) <=
          next_order + (accuracy + 1) * eps<Real>() * (abs(psi) + abs(psi_lead)));
    CHECK(abs(kappa - 1 / z - ell + z) <=
          next_order + (accuracy + 1) * eps<Real>() * (kappa + 1 / z + abs(ell)));
  }
  // psi(z) - ln(2z) - gamma -> 0: at z = 1e-30 it is ~ 7e-29, far below epsilon |psi|.
  const Real z = Real(1e-30);
  CHECK(abs(line_kernel_psi(z) - log(2 * z) - gamma) <=
        (accuracy + 1) * eps<Real>() * abs(log(2 * z) + gamma));
}

TEMPLATE_TEST_CASE("line kernels: large-z limits", "[special][line]", float, double, long double) {
  using Real = TestType;
  using std::abs;
  // kappa z^3 = 1 - 9/z^2 + 225/z^4 - ... and -2 z^2 psi = 1 - 9/(2 z^2) + 75/z^4 - ...
  // (Watson's lemma, docs/line-kernels.md); the series alternate and envelop, so the third
  // term bounds the remainder. Forming z^3 kappa rounds three times, 2 z^2 psi twice.
  for (const Real z : {Real(100), Real(1e3), Real(1e6), Real(1e10)}) {
    const Real z2 = z * z;
    const Real kappa_scaled = line_kernel_kappa(z) * z * z * z;
    const Real psi_scaled = -2 * z2 * line_kernel_psi(z);
    INFO("z = " << z);
    CHECK(abs(kappa_scaled - (1 - 9 / z2)) <= 225 / (z2 * z2) + (accuracy + 1.5) * eps<Real>());
    CHECK(abs(psi_scaled - (1 - 9 / (2 * z2))) <= 75 / (z2 * z2) + (accuracy + 1) * eps<Real>());
  }
}

TEMPLATE_TEST_CASE("line kernels: signs, monotonicity and no overflow over [1e-30, 1e30]",
                   "[special][line]", float, double, long double) {
  using Real = TestType;
  using std::cbrt;
  using std::isfinite;
  using std::pow;
  // kappa > 0 decreasing and psi < 0 increasing (the integrands are positive); successive points
  // differ by 3.5 %, far more than the accuracy, so rounding cannot reverse the order. kappa
  // underflows (float, z > 4e12) to 0 and psi to -0 beyond the range of Real.
  const Real underflow = cbrt(1 / (std::numeric_limits<Real>::min)());
  Real previous_kappa = std::numeric_limits<Real>::infinity(), previous_psi = -previous_kappa;
  for (int i = 0; i <= 4000; ++i) {
    const Real z = pow(Real(10), Real(-30) + Real(60) * Real(i) / Real(4000));
    const Real kappa = line_kernel_kappa(z), psi = line_kernel_psi(z);
    INFO("z = " << z << ", kappa " << kappa << ", psi " << psi);
    REQUIRE(isfinite(kappa));
    REQUIRE(isfinite(psi));
    CHECK(kappa >= 0);
    CHECK(psi <= 0);
    if (z < underflow) {
      CHECK(kappa > 0);
      CHECK(kappa < previous_kappa);
      CHECK(psi < 0);
      CHECK(psi > previous_psi);
    }
    previous_kappa = kappa;
    previous_psi = psi;
  }
}

TEMPLATE_TEST_CASE("line kernels: z must be positive", "[special][line]", float, double) {
  using Real = TestType;
  for (const Real z : {Real(0), Real(-1), std::numeric_limits<Real>::quiet_NaN(),
                       -std::numeric_limits<Real>::infinity()}) {
    CHECK_THROWS_AS(line_kernel_kappa(z), std::invalid_argument);
    CHECK_THROWS_AS(line_kernel_psi(z), std::invalid_argument);
  }
  CHECK_THROWS_WITH(line_kernel_kappa(Real(-2)), Catch::Contains("z") && Catch::Contains("z > 0"));
}

}  // namespace test_line_kernels
