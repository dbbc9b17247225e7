// viscoroll: ratios and exponentially scaled forms of the modified Bessel functions of order 0, 1.
//
// Panek & Kalker (1980) need I_1(alpha)/I_0(alpha) in G(y), Eq. (36), with alpha = (1 + f) a / (V
// tau) from Eq. (37), and e^{a/(V tau)} K_nu(a/(V tau)), nu = 0, 1, in Eqs. (42) and (44). The
// arguments are unbounded as V tau -> 0, where the unscaled functions overflow (I) or underflow (K)
// long before the ratios and scaled forms stop being O(1).
//
// Method (details, thresholds and measured accuracy in docs/special-functions.md):
//   x < x_T = ceil(-ln(eps)/2) + 2: boost::math::cyl_bessel_i / cyl_bessel_k;
//   x >= x_T: Hankel's expansions DLMF 10.40.1-2 of the scaled functions
//   (detail/bessel_ratio_detail.hpp).
// Near zero the ratios use their leading terms, I_2/I_0 its power series (no cancellation).
//
// References: M. Abramowitz & I. A. Stegun, Handbook of Mathematical Functions (1964), ch. 9;
// NIST Digital Library of Mathematical Functions (DLMF), ch. 10.
#pragma once

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <cmath>
#include <limits>
#include <type_traits>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/special/detail/bessel_ratio_detail.hpp>
#include <viscoroll/special/detail/i1_over_i0_chebyshev.hpp>

namespace viscoroll::special {

/// e^{-x} I_0(x) for x >= 0 (+inf allowed); never overflows.
template <RealScalar Real>
Real bessel_i0_scaled(Real x) {
  using std::exp;
  using std::sqrt;
  detail::require_argument("bessel_i0_scaled", x, true);
  if (x < detail::bessel_asymptotic_threshold<Real>())
    return static_cast<Real>(exp(-x) * boost::math::cyl_bessel_i(Real(0), x));
  // DLMF 10.40.1
  return (1 + detail::hankel_tail(0, x, true)) *
         boost::math::constants::one_div_root_two_pi<Real>() / sqrt(x);
}

/// e^{-x} I_1(x) for x >= 0 (+inf allowed); never overflows.
template <RealScalar Real>
Real bessel_i1_scaled(Real x) {
  using std::exp;
  using std::sqrt;
  detail::require_argument("bessel_i1_scaled", x, true);
  if (x < detail::bessel_asymptotic_threshold<Real>())
    return static_cast<Real>(exp(-x) * boost::math::cyl_bessel_i(Real(1), x));
  // DLMF 10.40.1
  return (1 + detail::hankel_tail(1, x, true)) *
         boost::math::constants::one_div_root_two_pi<Real>() / sqrt(x);
}

/// e^{x} K_0(x) for x > 0 (+inf allowed); never underflows.
template <RealScalar Real>
Real bessel_k0_scaled(Real x) {
  using std::exp;
  using std::sqrt;
  detail::require_argument("bessel_k0_scaled", x, false);
  if (x < detail::bessel_asymptotic_threshold<Real>())
    return static_cast<Real>(exp(x) * boost::math::cyl_bessel_k(Real(0), x));
  // DLMF 10.40.2
  return (1 + detail::hankel_tail(0, x, false)) * boost::math::constants::root_half_pi<Real>() /
         sqrt(x);
}

/// e^{x} K_1(x) for x > 0 (+inf allowed); never underflows (overflows to +inf only where 1/x does).
template <RealScalar Real>
Real bessel_k1_scaled(Real x) {
  using std::exp;
  using std::sqrt;
  detail::require_argument("bessel_k1_scaled", x, false);
  if (x < std::numeric_limits<Real>::epsilon()) {
    // DLMF 10.31.1 (n = 1) times e^x: 1/x + 1 + O(x ln x), relative error O(x^2 ln x).
    return 1 / x + 1;
  }
  if (x < detail::bessel_asymptotic_threshold<Real>())
    return static_cast<Real>(exp(x) * boost::math::cyl_bessel_k(Real(1), x));
  // DLMF 10.40.2
  return (1 + detail::hankel_tail(1, x, false)) * boost::math::constants::root_half_pi<Real>() /
         sqrt(x);
}

/// I_1(x) / I_0(x) for x >= 0 (+inf allowed), in [0, 1): x/2 near 0, 1 - 1/(2x) for large x.
template <RealScalar Real>
Real bessel_i1_over_i0(Real x) {
  using std::sqrt;
  detail::require_argument("bessel_i1_over_i0", x, true);
  static const Real small = sqrt(std::numeric_limits<Real>::epsilon());
  // DLMF 10.25.2: I_1/I_0 = x/2 (1 - x^2/8 + ...); the correction is below eps/8 here.
  if (x < small) return x / 2;
  if (x < detail::bessel_asymptotic_threshold<Real>())
    return static_cast<Real>(boost::math::cyl_bessel_i(Real(1), x) /
                             boost::math::cyl_bessel_i(Real(0), x));
  // DLMF 10.40.1 for both orders; the common factor e^x / sqrt(2 pi x) cancels.
  return detail::hankel_ratio(1, 0, x, true);
}

/// I_1(x) / I_0(x) as bessel_i1_over_i0, but for double
/// - below x_T = 21 from a piecewise Chebyshev interpolant of degree 13 on pieces of width 1/2
///   (detail::i1_over_i0_chebyshev; 12 ns against 54 ns for Boost's double-precision I_1 and I_0,
///   and within 1.79 eps of the exact ratio over [1.5e-8, 21) against 3.1 eps for that quotient);
/// - from x_T = 21 on as one series in 1/x, the quotient of Hankel's two sums, by Horner's rule
///   (detail::i1_over_i0_series; 18 ns against 179 ns for the two sums at x = 21, and within
///   0.3 eps of the 50-digit ratio over [21, 1e9]).
/// docs/special-functions.md. The line solver's inner loops use it, where the ratio is evaluated
/// at every quadrature node; other types forward to bessel_i1_over_i0.
template <RealScalar Real>
Real bessel_i1_over_i0_fast(Real x) {
  if constexpr (std::is_same_v<Real, double>) {
    if (x >= std::sqrt(std::numeric_limits<double>::epsilon()) &&
        x < detail::bessel_asymptotic_threshold<double>())
      return detail::i1_over_i0_chebyshev(x);
    if (x >= detail::bessel_asymptotic_threshold<double>()) return detail::i1_over_i0_series(x);
  }
  return bessel_i1_over_i0(x);
}

/// I_2(x) / I_0(x) = 1 - 2 I_1(x) / (x I_0(x)) for x >= 0 (+inf allowed), in [0, 1): x^2/8 near 0,
/// without cancellation.
template <RealScalar Real>
Real bessel_i2_over_i0(Real x) {
  detail::require_argument("bessel_i2_over_i0", x, true);
  if (x < detail::bessel_i2_series_limit<Real>()) return detail::bessel_i2_over_i0_series(x);
  // DLMF 10.29.1: I_0 - I_2 = (2/x) I_1.
  return 1 - 2 * bessel_i1_over_i0(x) / x;
}

/// I_2(x) / I_0(x) as bessel_i2_over_i0, but for double from x = 4 on as 1 - 2 r / x with
/// r = bessel_i1_over_i0_fast(x) (DLMF 10.29.1): there the subtraction amplifies r's relative
/// error (at most 1.79 eps) by at most 0.76, so the result is within 2.5 eps of the exact ratio
/// (docs/special-functions.md); below 4, and for other types, bessel_i2_over_i0 itself.
template <RealScalar Real>
Real bessel_i2_over_i0_fast(Real x) {
  if constexpr (std::is_same_v<Real, double>) {
    if (x >= detail::bessel_i2_series_limit<double>() && x <= std::numeric_limits<double>::max())
      return 1 - 2 * bessel_i1_over_i0_fast(x) / x;  // DLMF 10.29.1
  }
  return bessel_i2_over_i0(x);
}

/// K_1(x) / K_0(x) for x > 0 (+inf allowed), > 1: 1/(x (-ln(x/2) - gamma)) near 0,
/// 1 + 1/(2x) for large x.
template <RealScalar Real>
Real bessel_k1_over_k0(Real x) {
  using std::log;
  detail::require_argument("bessel_k1_over_k0", x, false);
  if (x < std::numeric_limits<Real>::epsilon()) {
    // DLMF 10.31.1-2: K_1 = 1/x (1 + O(x^2 ln x)), K_0 = -ln(x/2) - gamma + O(x^2 ln x).
    // ln(x/2) as ln x - ln 2: x/2 underflows for the smallest subnormal x.
    return 1 / (x * (boost::math::constants::ln_two<Real>() - log(x) -
                     boost::math::constants::euler<Real>()));
  }
  if (x < detail::bessel_asymptotic_threshold<Real>())
    return static_cast<Real>(boost::math::cyl_bessel_k(Real(1), x) /
                             boost::math::cyl_bessel_k(Real(0), x));
  // DLMF 10.40.2 for both orders; the common factor sqrt(pi/(2x)) e^{-x} cancels.
  return detail::hankel_ratio(1, 0, x, false);
}

}  // namespace viscoroll::special
