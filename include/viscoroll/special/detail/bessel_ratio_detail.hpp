// viscoroll: internals of the modified Bessel functions of order 0 and 1 (bessel_ratio.hpp).
//
// Hankel's expansions for large argument (DLMF 10.40.1-2, A&S 9.7.1-2):
//   e^{-x} I_nu(x) ~ (2 pi x)^{-1/2} sum_k (-1)^k a_k(nu) / x^k
//   e^{x}  K_nu(x) ~ (pi / (2x))^{1/2} sum_k a_k(nu) / x^k
//   a_k(nu) = (4nu^2 - 1^2)(4nu^2 - 3^2)...(4nu^2 - (2k-1)^2) / (k! 8^k)     DLMF 10.17.1
// Both series diverge; their terms decrease until k ~ 2x, where the smallest is about e^{-2x}
// (for I the exponentially small companion term of DLMF 10.40.5 is of the same size). They reach
// the working precision only for x >= x_T = ceil(-ln(eps) / 2) + 2, the threshold below which
// Boost's cyl_bessel_i / cyl_bessel_k are used instead (no overflow there: e^{x_T} <= e^3/eps^0.5).
#pragma once

#include <cmath>
#include <iterator>
#include <limits>
#include <string>
#include <viscoroll/core/validate.hpp>

namespace viscoroll::detail {

/// x_T = ceil(-ln(eps) / 2) + 2: 10 (float), 21 (double), 24 (x87 long double), 60 (50 digits).
/// At x_T the truncated Hankel series is within eps/4 of the function (docs/special-functions.md).
template <class Real>
const Real& bessel_asymptotic_threshold() {
  using std::ceil;
  using std::log;
  static const Real threshold = ceil(-log(std::numeric_limits<Real>::epsilon()) / 2) + 2;
  return threshold;
}

/// Tail of Hankel's sum for order nu (0 or 1): sum_{k>=1} (-1)^k a_k(nu) / x^k for I
/// (DLMF 10.40.1) or sum_{k>=1} a_k(nu) / x^k for K (DLMF 10.40.2), truncated once a term is below
/// eps/16 of 1 + tail or (below x_T only) when the terms start to grow. Returning the tail, which
/// is O(1/x), keeps its rounding errors out of the leading 1.
template <class Real>
Real hankel_tail(int nu, const Real& x, bool modified_first_kind) {
  using std::abs;
  const int mu = 4 * nu * nu;
  const Real tolerance = std::numeric_limits<Real>::epsilon() / 16;
  const int max_terms = 2 * std::numeric_limits<Real>::digits + 64;
  Real term = 1;
  Real tail = 0;
  for (int k = 1; k <= max_terms; ++k) {
    // a_k(nu) / a_{k-1}(nu) = (mu - (2k - 1)^2) / (8k), DLMF 10.17.1.
    const int factor =
        modified_first_kind ? (2 * k - 1) * (2 * k - 1) - mu : mu - (2 * k - 1) * (2 * k - 1);
    const Real next = term * Real(factor) / (Real(8 * k) * x);
    if (abs(next) >= abs(term)) break;
    term = next;
    tail += term;
    if (abs(term) <= tolerance * abs(1 + tail)) break;
  }
  return tail;
}

/// Ratio of two Hankel sums (1 + t_num) / (1 + t_den), formed as 1 + (t_num - t_den) / (1 + t_den).
template <class Real>
Real hankel_ratio(int nu_num, int nu_den, const Real& x, bool modified_first_kind) {
  const Real tail_num = hankel_tail(nu_num, x, modified_first_kind);
  const Real tail_den = hankel_tail(nu_den, x, modified_first_kind);
  return 1 + (tail_num - tail_den) / (1 + tail_den);
}

/// Coefficients r_k of I_1(x)/I_0(x) ~ sum_k r_k x^-k, the quotient of Hankel's sums DLMF 10.40.1
/// for nu = 1 and 0 (docs/special-functions.md, "I1/I0 for large x in double"): r_0 = 1 and
/// r_k = c_k(1) - sum_{j=1..k} c_j(0) r_{k-j}, c_k(nu) = (-1)^k a_k(nu) of DLMF 10.17.1; exact
/// rationals with power-of-two denominators (r_1 = -1/2, r_2 = r_3 = -1/8, r_4 = -25/128, ...),
/// rounded to double. 25 terms reach eps/16 at x_T = 21 (test "the ratio's series ...").
inline constexpr double kI1OverI0Series[] = {
    1.0,
    -0.5,
    -0.125,
    -0.125,
    -0.1953125,
    -0.40625,
    -1.0478515625,
    -3.21875,
    -11.466461181640625,
    -46.478515625,
    -211.27614974975586,
    -1064.67822265625,
    -5892.0457146167755,
    -35528.87744140625,
    -231884.6359563172,
    -1628749.4532470703,
    -12251067.63286615,
    -98252781.81546783,
    -836956449.7799761,
    -7546911569.366995,
    -71816112232.68327,
    -719236632073.3802,
    -7562132599676.877,
    -83284339829845.66,
    -958823685326569.2,
};

/// A tier of i1_over_i0_series: the arguments from `x` on, and the terms it takes there.
struct SeriesTier {
  double x;   ///< smallest argument of the tier
  int terms;  ///< the first k with |r_k| x^-k < eps/16 there, from the exact r_k
};
inline constexpr SeriesTier kI1OverI0Tiers[] = {{1e4, 5}, {1e3, 6}, {200, 8}, {100, 10},
                                                {50, 13}, {30, 17}, {24, 21}, {21, 25}};

/// I_1(x)/I_0(x) in double for x >= 21 (x_T of double): sum_{k<K} r_k x^-k by Horner's rule, with
/// K the number of terms after which the next one, |r_K| x^-K, is below eps/16 at the tier's
/// smallest x (the terms fall monotonically there: K << 2x). 25 terms at x = 21, 5 beyond 1e4;
/// 1 at +inf. Error: eps/2 in 1 + tail, eps/16 of truncation, and the tail's own rounding times
/// |tail| <= 1/40; measured 0.29 eps at worst over [21, 1e9] (test "bessel_i1_over_i0_fast").
inline double i1_over_i0_series(double x) {
  int terms = std::end(kI1OverI0Tiers)[-1].terms;  // x_T's tier
  for (const auto& t : kI1OverI0Tiers) {
    if (x >= t.x) {
      terms = t.terms;
      break;
    }
  }
  const double z = 1 / x;
  double tail = kI1OverI0Series[terms - 1];
  for (int k = terms - 2; k >= 1; --k) tail = tail * z + kI1OverI0Series[k];
  return 1 + tail * z;  // the O(1/x) tail apart from the leading 1, as in hankel_tail
}

/// Below this argument I_2/I_0 is summed from the power series; above it 1 - 2 I_1/(x I_0) loses
/// less than the ratio's own error (the subtraction amplifies it by I_0/I_2 - 1 = 0.76 at x = 4).
template <class Real>
Real bessel_i2_series_limit() {
  return Real(4);
}

/// Neumaier's compensated summation: adds term to sum, carrying the rounding error in compensation.
template <class Real>
void compensated_add(Real& sum, Real& compensation, const Real& term) {
  using std::abs;
  const Real next = sum + term;
  compensation += abs(sum) >= abs(term) ? (sum - next) + term : (term - next) + sum;
  sum = next;
}

/// I_2(x)/I_0(x) = (q/2) B/A with A = sum q^k/(k!)^2, B = sum 2 q^k/(k!(k+2)!), q = x^2/4
/// (DLMF 10.25.2 for nu = 0 and 2): positive terms only, so no cancellation for small x.
template <class Real>
Real bessel_i2_over_i0_series(const Real& x) {
  const Real q = x * x / 4;
  const Real tolerance = std::numeric_limits<Real>::epsilon() / 16;
  Real a_term = 1, a_sum = 1, a_comp = 0;
  Real b_term = 1, b_sum = 1, b_comp = 0;
  for (int k = 1; k < 4 * std::numeric_limits<Real>::digits; ++k) {
    a_term *= q / Real(k * k);
    b_term *= q / Real(k * (k + 2));
    compensated_add(a_sum, a_comp, a_term);
    compensated_add(b_sum, b_comp, b_term);
    if (a_term <= tolerance * a_sum) break;
  }
  return (q / 2) * ((b_sum + b_comp) / (a_sum + a_comp));
}

/// Throws std::invalid_argument unless x >= 0 (zero_allowed) or x > 0; NaN is rejected, +inf is
/// accepted (the functions have finite limits there).
template <class Real>
void require_argument(const char* function, const Real& x, bool zero_allowed) {
  const bool ok = zero_allowed ? (x >= 0) : (x > 0);
  if (!ok)
    require(false, "x", x, std::string(zero_allowed ? "x >= 0" : "x > 0") + " of " + function);
}

}  // namespace viscoroll::detail
