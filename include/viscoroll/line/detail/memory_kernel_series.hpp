// viscoroll: the memory kernel of the leading-edge condition (L6) far from the collocation point,
// as a series in 1/s^2 (docs/theory.md section 8).
//
// The kernel (exterior_right in line_operators.hpp, (L6)) is
//   K(s) = V int_0^inf e^-t x_t (x_t^2 + s^2)^(-3/2) dt,   x_t = x0 + V t,
// summed at every s-node over the t-nodes (one division and one square root per pair). For
// s >> x_t it is a series in 1/s^2: (1 + u)^(-3/2) = sum_n c_n u^n, c_n = binom(-3/2, n), u =
// (x_t/s)^2, integrated term by term with the moments m_j = V int_0^inf e^-t x_t^j dt. With
// R = x0 + V, alpha = x0/R, beta = V/R and e_j = int_0^inf e^-t (alpha + beta t)^j dt, so that
// m_j = V R^j e_j, integration by parts gives e_0 = 1, e_j = alpha^j + j beta e_{j-1} (positive
// terms only), and
//   K(s)          = (V R/s^3) sum_{n<M} c_n e_{2n+1} z^n,          z = (R/s)^2,
//   dK/dx0        = (V/s^3)   sum_{n<M} c_n (2n + 1) e_{2n} z^n,    (dm_j/dx0 = j m_{j-1}),
//   s dK/ds       = -(V R/s^3) sum_{n<M} c_n (2n + 3) e_{2n+1} z^n.
// (1 + u)^(-3/2) is completely monotone on u >= 0, so its Taylor remainder after M terms lies
// between 0 and the next term for every u >= 0 (not only u < 1): |K - K_M| <= |c_M| m_{2M+1}
// s^(-2M-3) at every s, with no condition on the t-range. With K >= (m_1 - (3/2) m_3/s^2)/s^3 (the
// remainder after two terms), the relative error is below eps/16 (or tol/16 for a stated
// tolerance tol > eps) wherever
//   |c_M| e_{2M+1} z^M <= (eps/32) e_1   and   (3/2) e_3 z <= e_1/2,
// i.e. for s >= threshold(). Below it the caller sums the t-nodes.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace viscoroll::detail {

template <class Real>
class MemoryKernelSeries {
 public:
  /// Terms of the series: at V << x0 (alpha ~ 1, e_j ~ 1) the threshold is ~2.3 R.
  static constexpr int kTerms = 24;

  /// tolerance: the relative accuracy tol/16 instead of eps/16 (0, the default: eps).
  MemoryKernelSeries(Real x0, Real v, Real tolerance = Real(0)) : v_(v), r_(x0 + v) {
    using std::abs;
    using std::pow;
    using std::sqrt;
    const Real alpha = x0 / r_, beta = v / r_;
    std::array<Real, 2 * kTerms + 2> e{};
    e[0] = 1;
    Real alpha_j = 1;
    for (int j = 1; j < 2 * kTerms + 2; ++j) {
      alpha_j *= alpha;
      e[j] = alpha_j + Real(j) * beta * e[j - 1];
    }
    Real c = 1;  // c_n = binom(-3/2, n) = c_{n-1} (-3/2 - n + 1)/n
    for (int n = 0; n < kTerms; ++n) {
      if (n > 0) c *= -(Real(2 * n + 1) / Real(2 * n));
      value_[n] = c * e[2 * n + 1];
      slope_x0_[n] = c * Real(2 * n + 1) * e[2 * n];
      slope_s_[n] = -c * Real(2 * n + 3) * e[2 * n + 1];
    }
    const Real c_next = -c * (Real(2 * kTerms + 1) / Real(2 * kTerms));
    const Real eps = std::max(tolerance, std::numeric_limits<Real>::epsilon());
    // z at which the first omitted term is eps/32 of the first, and the second half of it.
    const Real z_tail =
        pow(eps / 32 * e[1] / (abs(c_next) * e[2 * kTerms + 1]), Real(1) / Real(kTerms));
    const Real z_two = e[1] / (3 * e[3]);
    const Real z_max = std::min(z_tail, z_two);
    threshold_ = z_max > 0 ? Real(r_ / sqrt(z_max)) : std::numeric_limits<Real>::infinity();
  }

  /// The smallest s at which the series is within tol/16 of K(s) (+inf if nowhere; tol = eps by
  /// default).
  Real threshold() const { return threshold_; }

  /// K(s), s >= threshold().
  Real value(Real s) const {
    const Real q = r_ / s, z = q * q;
    return v_ * q * q * q / (r_ * r_) * horner(value_, z);
  }

  /// K(s), dK/dx0 and s dK/ds, s >= threshold().
  void evaluate(Real s, Real& k, Real& k_x0, Real& s_k_s) const {
    const Real q = r_ / s, z = q * q;
    const Real scale = v_ * q * q * q / (r_ * r_);  // V R/s^3
    k = scale * horner(value_, z);
    k_x0 = scale / r_ * horner(slope_x0_, z);
    s_k_s = scale * horner(slope_s_, z);
  }

 private:
  static Real horner(const std::array<Real, kTerms>& a, Real z) {
    Real sum = a[kTerms - 1];
    for (int n = kTerms - 2; n >= 0; --n) sum = sum * z + a[n];
    return sum;
  }

  Real v_, r_;
  std::array<Real, kTerms> value_{}, slope_x0_{}, slope_s_{};
  Real threshold_;
};

}  // namespace viscoroll::detail
