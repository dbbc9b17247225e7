// The series in 1/s^2 of the memory kernel of (L6), viscoroll/line/detail/memory_kernel_series.hpp
// (docs/theory.md section 8), against the kernel's integral by exp_sinh quadrature in a wider type.
//
// Measured values next to the tolerances: Release build, GCC 12, x86-64.
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/line/detail/memory_kernel_series.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_memory_kernel_series {

namespace {

using viscoroll::detail::MemoryKernelSeries;
using Mp50 = boost::multiprecision::cpp_bin_float_50;

/// K(s), dK/dx0 and s dK/ds by exp_sinh quadrature over t in [0, inf) in the type Wide.
template <class Wide>
struct Reference {
  Wide k, k_x0, s_k_s;
};

template <class Wide>
Reference<Wide> reference(Wide x0, Wide v, Wide s) {
  using std::exp;
  using std::sqrt;
  boost::math::quadrature::exp_sinh<Wide> rule;
  const Wide s2 = s * s;
  const auto r3 = [&](Wide x) {
    const Wide h2 = x * x + s2;
    return 1 / (h2 * sqrt(h2));
  };
  Reference<Wide> out;
  // K = V int e^-t x_t (x_t^2 + s^2)^(-3/2); dK/dx0 = V int e^-t (s^2 - 2 x_t^2) (...)^(-5/2);
  // s dK/ds = -3 s^2 V int e^-t x_t (...)^(-5/2).
  out.k = rule.integrate([&](Wide t) {
    const Wide x = x0 + v * t;
    return v * exp(-t) * x * r3(x);
  });
  out.k_x0 = rule.integrate([&](Wide t) {
    const Wide x = x0 + v * t;
    return v * exp(-t) * (s2 - 2 * x * x) * r3(x) / (x * x + s2);
  });
  out.s_k_s = -3 * s2 * rule.integrate([&](Wide t) {
    const Wide x = x0 + v * t;
    return v * exp(-t) * x * r3(x) / (x * x + s2);
  });
  return out;
}

/// Largest relative error (in eps of Real) of the series' K, dK/dx0 and s dK/ds against Wide,
/// at s = threshold x {1, 1.5, 3, 30}.
template <class Real, class Wide>
void check_against(Real x0, Real v, double bound_k, double bound_slopes) {
  const MemoryKernelSeries<Real> series(x0, v);
  const Real eps = std::numeric_limits<Real>::epsilon();
  REQUIRE(std::isfinite(static_cast<double>(series.threshold())));
  for (const Real factor : {Real(1), Real(1.5), Real(3), Real(30)}) {
    const Real s = series.threshold() * factor;
    const auto ref = reference<Wide>(Wide(x0), Wide(v), Wide(s));
    Real k = 0, k_x0 = 0, s_k_s = 0;
    series.evaluate(s, k, k_x0, s_k_s);
    const auto rel = [&](Real got, const Wide& want) {
      using std::abs;
      return static_cast<double>(abs((Wide(got) - want) / want) / Wide(eps));
    };
    INFO("x0 = " << double(x0) << ", V = " << double(v) << ", s = " << double(s) << " ("
                 << double(factor) << " x threshold)");
    CHECK(rel(k, ref.k) <= bound_k);
    CHECK(series.value(s) == k);  // value() is evaluate()'s K, bit for bit
    CHECK(rel(k_x0, ref.k_x0) <= bound_slopes);
    CHECK(rel(s_k_s, ref.s_k_s) <= bound_slopes);
  }
}

}  // namespace

TEST_CASE("memory kernel series: K and its slopes against quadrature, double", "[line]") {
  // Bound on K: eps/16 of truncation (the remainder of a completely monotone function's Taylor
  // series, docs/theory.md section 8) plus Horner's rounding of terms falling at least twofold
  // (~2 eps) and the scale's (~2 eps): 4 eps. The slopes' series are truncated after the same
  // number of terms, their first omitted term relative to their first about 2M + 1 = 49 times
  // K's (<= 1.6 eps): bound 8 eps (they enter the Jacobian only). Measured (with the long double
  // case below): K <= 2.4 eps, slopes <= 3.4 eps.
  for (const double x0 : {0.05, 0.5, 2.0})
    for (const double v : {1e-3, 1e-2, 0.1, 1.0}) check_against<double, long double>(x0, v, 4, 8);
}

TEST_CASE("memory kernel series: K and its slopes against quadrature, long double", "[line]") {
  for (const long double x0 : {0.05L, 2.0L})
    for (const long double v : {1e-3L, 0.1L}) check_against<long double, Mp50>(x0, v, 4, 8);
}

TEST_CASE("memory kernel series: where it applies", "[line]") {
  // V << x0: e_j -> 1, so the threshold tends to R (32 |c_M| / eps)^(1/(2M)) (double: 2.36 R,
  // R = x0 + V), with M = 24 terms.
  const double x0 = 0.7;
  const MemoryKernelSeries<double> slow(x0, 1e-9);
  const double limit =
      std::pow(32 * 5.613758633 / std::numeric_limits<double>::epsilon(), 1.0 / 48);  // |c_24|
  INFO("threshold / R = " << slow.threshold() / (x0 + 1e-9) << ", limit " << limit);
  CHECK(std::abs(slow.threshold() / (x0 + 1e-9) / limit - 1) < 1e-3);
  // It grows with V/x0: the moments e_j grow like j! (V/R)^j.
  double last = 0;
  for (const double v : {1e-3, 1e-2, 0.1, 1.0, 10.0}) {
    const double t = MemoryKernelSeries<double>(x0, v).threshold() / (x0 + v);
    INFO("V = " << v << ": threshold / R = " << t);
    CHECK(t > last);
    last = t;
  }
  // float: at V >> x0 e_49 ~ 49! overflows; the series is then nowhere used (threshold +inf),
  // never NaN.
  const MemoryKernelSeries<float> fast(0.01f, 10.0f);
  CHECK(std::isinf(fast.threshold()));
  CHECK(std::isfinite(MemoryKernelSeries<float>(0.5f, 0.01f).threshold()));
}

}  // namespace test_memory_kernel_series
