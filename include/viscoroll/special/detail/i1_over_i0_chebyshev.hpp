// viscoroll: I_1(x)/I_0(x) in double on [0, x_T) = [0, 21) as a piecewise Chebyshev interpolant
// (bessel_i1_over_i0_fast; docs/special-functions.md, "I1/I0 in double").
//
// The ratio r(x) = I_1(x)/I_0(x) is analytic but for poles where I_0 vanishes, at x = +-i j_{0,k}
// (j_{0,1} = 2.405, DLMF 10.27.6 with 10.21). On each piece [k/2, (k + 1)/2) of width h = 1/2 a
// Chebyshev interpolant of degree n converges like rho^-n, rho the Bernstein ellipse through the
// nearest pole (rho > 14 for every piece with k >= 1); on [0, 1/2) r(x) = x g(x^2) with g
// interpolated in z = x^2 on [0, 1/4] (g is analytic but for z = -5.78, rho > 90), which keeps the
// relative accuracy as x -> 0. Degree 13 on every piece: the truncation is below 1e-17. The
// interpolant is evaluated as a polynomial in the piece's variable u in [-1, 1] by Estrin's scheme
// (four levels of multiply-adds instead of Clenshaw's thirteen: the solver's loops wait on each
// ratio, so its latency is its cost); its monomial coefficients fall like (2/rho)^k, so the sum
// loses nothing to cancellation. What is left is the rounding of the coefficients and of the sum,
// measured within 1.3 eps (test "bessel_i1_over_i0_fast"). The coefficients are computed once, at
// the first call, in long double from Boost's I_0 and I_1 at the Chebyshev points (588 pairs,
// about 0.2 ms): the Chebyshev coefficients by the discrete cosine sum, then the monomial ones.
//
// Reference: L. N. Trefethen, Approximation Theory and Approximation Practice (2013), ch. 3, 8.
#pragma once

#include <boost/math/special_functions/bessel.hpp>
#include <cmath>
#include <vector>
#include <viscoroll/special/detail/bessel_ratio_detail.hpp>

namespace viscoroll::detail {

/// The coefficients of the pieces of I_1/I_0 on [0, x_T) in double, x_T = 21.
struct I1OverI0Chebyshev {
  static constexpr int kDegree = 13;
  static_assert(kDegree == 13, "operator() spells out Estrin's scheme for degree 13");
  static constexpr int kPiecesPerUnit = 2;  // pieces of width 1/2
  int pieces = 0;                           // 2 x_T
  std::vector<double> c;  // piece k's monomial coefficients in u at c[k (kDegree + 1) + j]

  I1OverI0Chebyshev() {
    using std::cos;
    constexpr int n = kDegree + 1;
    const long double pi = 3.141592653589793238462643383279502884L;
    pieces = static_cast<int>(bessel_asymptotic_threshold<double>()) * kPiecesPerUnit;
    c.assign(static_cast<std::size_t>(pieces) * n, 0.0);
    long double f[n];
    for (int k = 0; k < pieces; ++k) {
      for (int i = 0; i < n; ++i) {
        const long double u = cos(pi * (i + 0.5L) / n);  // Chebyshev points of the first kind
        // Piece 0 in z = x^2 in [0, h^2] (f = r/x); the others in x in [k h, (k + 1) h].
        const long double x = k == 0 ? std::sqrt((u + 1) / (2.0L * kPiecesPerUnit * kPiecesPerUnit))
                                     : (k + (u + 1) / 2) / kPiecesPerUnit;
        const long double r =
            boost::math::cyl_bessel_i(1.0L, x) / boost::math::cyl_bessel_i(0.0L, x);
        f[i] = k == 0 ? r / x : r;
      }
      long double cheb[n];
      for (int j = 0; j < n; ++j) {
        long double s = 0;
        for (int i = 0; i < n; ++i) s += f[i] * cos(pi * j * (i + 0.5L) / n);
        cheb[j] = s * (j == 0 ? 1 : 2) / n;
      }
      // sum_j cheb_j T_j(u) = sum_m mono_m u^m, with T_{j+1} = 2 u T_j - T_{j-1}.
      long double t_prev[n] = {1.0L}, t_cur[n] = {0.0L, 1.0L}, mono[n] = {cheb[0]};
      for (int m = 0; m < n; ++m) mono[m] += cheb[1] * t_cur[m];
      for (int j = 2; j < n; ++j) {
        long double t_next[n];
        for (int m = 0; m < n; ++m) t_next[m] = (m > 0 ? 2 * t_cur[m - 1] : 0.0L) - t_prev[m];
        for (int m = 0; m < n; ++m) {
          t_prev[m] = t_cur[m];
          t_cur[m] = t_next[m];
          mono[m] += cheb[j] * t_cur[m];
        }
      }
      for (int m = 0; m < n; ++m)
        c[static_cast<std::size_t>(k) * n + m] = static_cast<double>(mono[m]);
    }
  }

  /// r(x) for 0 <= x < x_T: the piece's polynomial in u.
  double operator()(double x) const {
    const int k = static_cast<int>(x * kPiecesPerUnit);
    const double* a = c.data() + static_cast<std::size_t>(k) * (kDegree + 1);
    const double u = k == 0 ? 2 * kPiecesPerUnit * kPiecesPerUnit * x * x - 1
                            : 2 * (x * kPiecesPerUnit - k) - 1;
    // Estrin's scheme for degree 13 (kDegree is fixed by the static_assert above).
    const double u2 = u * u, u4 = u2 * u2, u8 = u4 * u4;
    const double q0 = (a[0] + a[1] * u) + (a[2] + a[3] * u) * u2;
    const double q1 = (a[4] + a[5] * u) + (a[6] + a[7] * u) * u2;
    const double q2 = (a[8] + a[9] * u) + (a[10] + a[11] * u) * u2;
    const double q3 = a[12] + a[13] * u;
    const double v = (q0 + q1 * u4) + (q2 + q3 * u4) * u8;
    return k == 0 ? x * v : v;
  }
};

/// The table, built at the first call (thread-safe: a function-local static).
inline const I1OverI0Chebyshev& i1_over_i0_chebyshev() {
  static const I1OverI0Chebyshev table;
  return table;
}

}  // namespace viscoroll::detail
