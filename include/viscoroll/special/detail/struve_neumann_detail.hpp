// viscoroll: internals of H_0(x) - Y_0(x) (struve_neumann.hpp): the power series for x <= 1, the
// Gauss-Legendre rule for the Laplace integral on (1, x_S) and the asymptotic series beyond.
#pragma once

#include <array>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/quadrature/gauss_legendre.hpp>
#include <viscoroll/special/detail/bessel_ratio_detail.hpp>

namespace viscoroll::detail {

/// Upper end of the power-series range of H_0 - Y_0.
template <class Real>
Real struve_series_limit() {
  return Real(1);
}

/// x_S = ceil(-ln eps) + 2: from here on the asymptotic series is within eps/8 (its error is
/// below the first omitted term, DLMF 11.6(i), and the smallest term is about e^{-x} relative).
template <class Real>
const Real& struve_asymptotic_threshold() {
  using std::ceil;
  using std::log;
  static const Real threshold = ceil(-log(std::numeric_limits<Real>::epsilon())) + 2;
  return threshold;
}

/// H_0(x) - Y_0(x) = (2/pi) [h(x) + L J_0(x) - S(x)] for 0 < x <= 1, where q = x^2/4 and
///   h   = sum_k (-1)^k x^{2k+1} / ((2k+1)!!)^2 = (pi/2) H_0    DLMF 11.2.1 (A&S 12.1.3)
///   J_0 = sum_k (-q)^k / (k!)^2                                  DLMF 10.2.2
///   S   = sum_{k>=1} (-1)^{k+1} H_k q^k / (k!)^2                 DLMF 10.8.2 (A&S 9.1.13)
/// with (pi/2) Y_0 = -L J_0 + S, L = -(ln(x/2) + gamma) and H_k the harmonic numbers.
/// Every series falls by at least x^2/9 per term at once. h > 0 and L J_0 > 0 for x < 1.12, and
/// S < q: the final sum cancels by at most a factor 1.6 (at x = 1).
template <class Real>
Real struve_h0_minus_y0_series(const Real& x) {
  using std::abs;
  using std::log;
  const Real x2 = x * x;
  const Real q = x2 / 4;
  const Real tolerance = std::numeric_limits<Real>::epsilon() / 16;
  Real h_term = x, h = x;
  Real j_term = 1, j0 = 1;
  Real s_term = -1, s = 0, harmonic = 0;  // after step k: s_term = (-1)^{k+1} q^k / (k!)^2
  for (int k = 1; k < 4 * std::numeric_limits<Real>::digits; ++k) {
    h_term *= -x2 / Real((2 * k + 1) * (2 * k + 1));
    j_term *= -q / Real(k * k);
    s_term *= -q / Real(k * k);
    harmonic += Real(1) / Real(k);
    h += h_term;
    j0 += j_term;
    s += harmonic * s_term;
    // |s_term| = |j_term|; the next terms of S carry the factor H_{k+1} < 1 + H_k.
    if ((1 + harmonic) * abs(j_term) <= tolerance * abs(j0) && abs(h_term) <= tolerance * abs(h))
      break;
  }
  // ln(x/2) as ln x - ln 2: x/2 underflows for the smallest subnormal x.
  const Real log_term =
      boost::math::constants::ln_two<Real>() - log(x) - boost::math::constants::euler<Real>();
  return boost::math::constants::two_div_pi<Real>() * (h + log_term * j0 - s);
}

/// H_0(x) - Y_0(x) ~ (2/(pi x)) sum_k (-1)^k ((2k-1)!!)^2 / x^{2k}, DLMF 11.6.1 (A&S 12.1.29) with
/// nu = 0; the remainder is below the first omitted term and of the same sign (DLMF 11.6(i)).
template <class Real>
Real struve_h0_minus_y0_asymptotic(const Real& x) {
  using std::abs;
  const Real inv_x2 = 1 / (x * x);
  const Real tolerance = std::numeric_limits<Real>::epsilon() / 16;
  Real term = 1;
  Real tail = 0;  // summed apart from the leading 1, as in hankel_tail
  for (int k = 1; k < 4 * std::numeric_limits<Real>::digits; ++k) {
    const Real next = -term * Real((2 * k - 1) * (2 * k - 1)) * inv_x2;
    if (abs(next) >= abs(term)) break;
    term = next;
    tail += term;
    if (abs(term) <= tolerance * abs(1 + tail)) break;
  }
  return boost::math::constants::two_div_pi<Real>() * (1 + tail) / x;
}

/// Number of Gauss-Legendre nodes for the integral range: the rule's error on [1, x_S] is below
/// eps/1000 with this many (measured against mpmath for 24, 53, 64 and 168 bits).
template <class Real>
constexpr int struve_quadrature_points() {
  constexpr int digits = std::numeric_limits<Real>::digits;
  return digits + digits / 16 + 8;
}

/// The Gauss-Legendre rule for (2/pi) int_0^U exp(-x sinh u) du, U = asinh((-ln eps + 3) / x_0)
/// with x_0 = struve_series_limit(): stored as weights c_j (including U/2 and 2/pi) and
/// s_j = sinh(u_j), ascending, computed in wider_real_t<Real> and rounded.
template <class Real>
struct StruveQuadratureTable {
  static constexpr int points = struve_quadrature_points<Real>();
  std::array<Real, points> weight;
  std::array<Real, points> sinh_node;
  /// Nodes with x sinh(u_j) above this contribute less than eps/64 of the result in total.
  Real cutoff;

  StruveQuadratureTable() {
    using W = wider_real_t<Real>;
    using std::asinh;
    using std::log;
    using std::sinh;
    const W log_inv_eps = -log(W(std::numeric_limits<Real>::epsilon()));
    const W upper = asinh((log_inv_eps + 3) / W(struve_series_limit<Real>()));
    const auto& t = GaussLegendre<W, points>::nodes();
    const auto& w = GaussLegendre<W, points>::weights();
    const auto& complement = GaussLegendre<W, points>::complements();
    const W scale = boost::math::constants::two_div_pi<W>() * upper / 2;
    for (int j = 0; j < points; ++j) {
      // u_j = U (1 + t_j) / 2. For large x the integrand lives within ~1/x of u = 0, where the
      // result is as accurate as the nodes relative to their own size: 1 + t_j for t_j near -1
      // is taken from the complement 1 - |t_j|, not formed by cancellation.
      const W one_plus_t = t[j] < 0 ? complement[j] : W(1 + t[j]);
      weight[j] = static_cast<Real>(scale * w[j]);
      sinh_node[j] = static_cast<Real>(sinh(upper * one_plus_t / 2));
    }
    // Tail sum <= (2/pi) U e^{-cutoff}; f >= 2/(pi x_S) on the range: require the ratio <= eps/64.
    cutoff =
        static_cast<Real>(log_inv_eps + log(64 * upper * W(struve_asymptotic_threshold<Real>())));
  }
};

template <class Real>
Real struve_h0_minus_y0_quadrature(const Real& x) {
  using std::exp;
  static const StruveQuadratureTable<Real> table;
  Real sum = 0;
  Real compensation = 0;
  for (int j = 0; j < table.points; ++j) {
    const Real exponent = x * table.sinh_node[j];
    if (exponent > table.cutoff) break;  // the nodes ascend, so every later term is smaller still
    compensated_add(sum, compensation, Real(table.weight[j] * exp(-exponent)));
  }
  return sum + compensation;
}

}  // namespace viscoroll::detail
