// viscoroll: the kernels kappa and psi of the form (L2) of the paper's leading-edge condition
// (44), used by line/paper_leading_edge.hpp (opt-in: viscoroll.hpp does not include either).
//
// docs/theory.md section 3, (L2), with g(t) = 1 - (1 + t^2)^{-1/2}:
//   kappa(z) = int_0^inf e^{-z t} g(t) dt = 1/z - (pi/2) [H0(z) - Y0(z)],
//   psi(z) = -int_0^inf e^{-z t} g(t) dt / t = ln(2z) + gamma - (pi/2) int_0^z [H0 - Y0]
//          = -int_z^inf kappa,
// H0 Struve's and Y0 Neumann's function ((pi/2)(H0 - Y0)(z) = int_0^inf e^{-zt} (1+t^2)^{-1/2} dt,
// DLMF 11.5.2). Each is evaluated without cancellation by one of three methods
// (docs/line-kernels.md derives them and gives the switch points and the measured errors):
//   z < 1/4          ascending series: DLMF 11.2.1 / A&S 12.1.3 (H0), DLMF 10.8.2 / A&S 9.1.13
//                    (Y0), and their term-by-term integrals for psi;
//   1/4 <= z < z_T   the Laplace integrals in s = z t by the trapezoidal rule after the double
//                    exponential map s = exp(tau - e^{-tau}) (Mori 1985);
//   z >= z_T         the asymptotic series (Watson's lemma, DLMF 2.3(ii)), z_T = D + 3 ln D + 2
//                    with D = -ln(epsilon).
// No intermediate result overflows for any z > 0; kappa itself does (kappa ~ 1/z) for z < 1/max,
// and kappa and psi underflow gracefully where they leave the range of Real.
//
// References: M. Abramowitz & I. A. Stegun, Handbook of Mathematical Functions (1964) [A&S];
// NIST Digital Library of Mathematical Functions, dlmf.nist.gov [DLMF]; H. Takahasi & M. Mori,
// Double exponential formulas for numerical integration, Publ. RIMS 9 (1974) 721-741; M. Mori,
// Quadrature formulas obtained by variable transformation and the DE-rule, J. Comput. Appl. Math.
// 12-13 (1985) 119-130.
#pragma once

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/errors.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll::detail {

/// D = -ln(epsilon) of Real, the number of e-foldings a result must be accurate to.
template <class Real>
Real line_kernel_digits() {
  using std::log;
  static const Real digits = -log(std::numeric_limits<Real>::epsilon());
  return digits;
}

/// Below this z the ascending series are used (docs/line-kernels.md, "Switch points").
template <class Real>
Real line_kernel_series_limit() {
  return Real(1) / 4;
}

/// From this z on the asymptotic series are used: kappa's smallest term, ~ 2 z^2 e^{-z} of the
/// first (psi's is smaller), is below epsilon / 4 with a factor ~ D to spare (docs/line-kernels.md,
/// "Switch points").
template <class Real>
Real line_kernel_asymptotic_limit() {
  using std::ceil;
  using std::log;
  static const Real limit = [] {
    const Real d = line_kernel_digits<Real>();
    return Real(ceil(d + 3 * log(d) + 2));
  }();
  return limit;
}

/// 1 - (1 + t^2)^{-1/2} = t^2 / ((1 + t^2) + sqrt(1 + t^2)), without cancellation at small t.
template <class Real>
Real line_kernel_g(Real t) {
  using std::sqrt;
  const Real q = 1 + t * t;
  return t * t / (q + sqrt(q));
}

/// (1 - (1 + t^2)^{-1/2}) / t.
template <class Real>
Real line_kernel_g_over_t(Real t) {
  using std::sqrt;
  const Real q = 1 + t * t;
  return t / (q + sqrt(q));
}

/// The trapezoidal rule in tau for int_0^inf e^{-s} f(s) ds with s = exp(tau - e^{-tau}); the
/// factor e^{-s} ds/dtau is folded into the weights, so a sum is sum_j weight_j f(node_j).
template <class Real>
struct LineKernelRule {
  std::vector<Real> node;
  std::vector<Real> weight;
};

/// Nodes per unit tau: the rule's error at z = 1/4, the nearest branch points s = +-i z of
/// the integrand, falls like e^{-4.3 n} (docs/line-kernels.md), so n = (D + 3) / 4 gives
/// about epsilon / 10.
template <class Real>
int line_kernel_rule_density() {
  using std::ceil;
  return static_cast<int>(ceil((line_kernel_digits<Real>() + 3) / 4));
}

template <class Real>
LineKernelRule<Real> make_line_kernel_rule() {
  using std::exp;
  using std::log;
  using std::sqrt;
  // The weights are formed in long double for float and double: e^{-s} amplifies a relative
  // error of s by s, and s reaches ~ D (long double and multiprecision types use their own).
  using Wide = std::conditional_t<std::is_floating_point_v<Real>, long double, Real>;
  const int n = line_kernel_rule_density<Real>();
  const Wide h = Wide(1) / Wide(n);
  const Wide eps = Wide(std::numeric_limits<Real>::epsilon());
  // Left end: int_0^{s_min} e^{-s} (1 - (1+t^2)^{-1/2}) / t ds ~ s_min^2 / (4 z) is below
  // epsilon / 16 of |psi| for z >= 1/4 (kappa's tail, ~ s_min^3, is smaller still).
  const Wide s_min = sqrt(eps) / 16;
  // Right end: int_{s_max}^inf e^{-s} s^2 ds / 2 = e^{-s_max} (s_max^2 + 2 s_max + 2) / 2 below
  // epsilon / 16 of int_0^inf e^{-s} s^2 ds / 2 = 1 (the large-z shape of kappa's integrand).
  Wide s_max = Wide(line_kernel_digits<Real>());
  for (int i = 0; i < 8; ++i) s_max = -log(eps / 8) + log(s_max * s_max + 2 * s_max + 2);
  LineKernelRule<Real> rule;
  auto add = [&](int j) {
    const Wide tau = Wide(j) * h;
    const Wide e = exp(-tau);
    Wide s = exp(tau - e);
    rule.node.push_back(Real(s));
    rule.weight.push_back(Real(h * s * (1 + e) * exp(-s)));  // h ds/dtau e^{-s}
    return s;
  };
  for (int j = 0;; ++j)
    if (add(j) >= s_max) break;
  for (int j = -1;; --j)
    if (add(j) <= s_min) break;
  return rule;
}

template <class Real>
const LineKernelRule<Real>& line_kernel_rule() {
  static const LineKernelRule<Real> rule = make_line_kernel_rule<Real>();
  return rule;
}

/// ln(z/2), also where z/2 underflows (a multiprecision z near its smallest value).
template <class Real>
Real log_half(Real z) {
  using std::log;
  const Real half = z / 2;
  if (half > 0) return log(half);
  return log(z) - boost::math::constants::ln_two<Real>();
}

/// kappa for z < 1/4: 1/z - (pi/2) H0 + (pi/2) Y0 with
///   (pi/2) H0(z) = sum_k (-1)^k z^{2k+1} / ((2k+1)!!)^2                     A&S 12.1.3,
///   (pi/2) Y0(z) = sum_k (-1)^k (z/2)^{2k} / (k!)^2 [ln(z/2) + gamma - H_k]  A&S 9.1.13,
/// H_k = 1 + 1/2 + ... + 1/k the harmonic number (H_0 = 0); Gamma(k + 3/2) = (2k+1)!! sqrt(pi)
/// / 2^{k+1} turns A&S 12.1.3 into the rational coefficients used here.
template <class Real>
Real kappa_series(Real z) {
  using std::abs;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real ell = log_half(z) + boost::math::constants::euler<Real>();
  const Real x2 = z * z / 4, z2 = z * z;
  Real bessel = 1;  // (-1)^k (z/2)^{2k} / (k!)^2
  Real struve = z;  // (-1)^k z^{2k+1} / ((2k+1)!!)^2
  Real harmonic = 0, sum = 0;
  for (int k = 0; k < 200; ++k) {
    const Real term = bessel * (ell - harmonic) - struve;
    sum += term;
    if (abs(term) <= eps / 4 * abs(sum)) return 1 / z + sum;
    bessel *= -x2 / Real((k + 1) * (k + 1));
    struve *= -z2 / Real((2 * k + 3) * (2 * k + 3));
    harmonic += Real(1) / Real(k + 1);
  }
  throw ConvergenceError("line_kernel_kappa: ascending series did not converge");
}

/// psi for z < 1/4: ln(2z) + gamma - (pi/2) int_0^z H0 + (pi/2) int_0^z Y0 (docs/theory.md
/// (L2)), the integrals term by term from A&S 12.1.3 and 9.1.13 (int_0^z s^a ln s ds =
/// z^{a+1} (ln z - 1/(a+1)) / (a+1)):
///   (pi/2) int_0^z H0 = sum_k (-1)^k z^{2k+2} / ((2k+2) ((2k+1)!!)^2),
///   (pi/2) int_0^z Y0 = z sum_k (-1)^k (z/2)^{2k} / ((k!)^2 (2k+1))
///                         [ln(z/2) + gamma - H_k - 1/(2k+1)].
template <class Real>
Real psi_series(Real z) {
  using std::abs;
  using std::log;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const auto& gamma = boost::math::constants::euler<Real>();  // a reference for multiprecision
  const Real ell = log_half(z) + gamma;
  const Real x2 = z * z / 4, z2 = z * z;
  Real bessel = 1;  // (-1)^k (z/2)^{2k} / (k!)^2
  Real struve = z;  // (-1)^k z^{2k+1} / ((2k+1)!!)^2
  Real harmonic = 0, sum = 0;
  for (int k = 0; k < 200; ++k) {
    const Real odd = Real(2 * k + 1);
    const Real term = z * (bessel / odd * (ell - harmonic - 1 / odd) - struve / (odd + 1));
    sum += term;
    if (abs(term) <= eps / 4 * abs(sum)) return (log(2 * z) + gamma) + sum;
    bessel *= -x2 / Real((k + 1) * (k + 1));
    struve *= -z2 / Real((2 * k + 3) * (2 * k + 3));
    harmonic += Real(1) / Real(k + 1);
  }
  throw ConvergenceError("line_kernel_psi: ascending series did not converge");
}

/// Watson's lemma (DLMF 2.3(ii)) on the binomial series g(t) = sum_{k>=1} c_k t^{2k},
/// c_k = -binom(-1/2, k) = (-1)^{k+1} (2k)! / (4^k (k!)^2):
///   kappa ~ sum_k c_k (2k)! / z^{2k+1},  psi ~ -sum_k c_k (2k-1)! / z^{2k},
/// with term ratios -(2k+1)^2 / z^2 and -(2k+1)^2 k / ((k+1) z^2). The series alternate and
/// envelop (1/sqrt(1 + x) is a Stieltjes function), so the first omitted term bounds the error.
template <class Real, bool Psi>
Real asymptotic_series(Real z) {
  using std::abs;
  using std::sqrt;
  const Real eps = std::numeric_limits<Real>::epsilon();
  static const Real root_max = sqrt((std::numeric_limits<Real>::max)());
  // lead = c_1 2! / z^3 (kappa) or c_1 1! / z^2 (psi) with the fewest roundings that cannot
  // overflow: 1/(z z) while z z is finite, (1/z)^2 beyond, where the results underflow anyway.
  Real r2 = 0, lead = 0;
  if (z < root_max) {
    r2 = 1 / (z * z);
    lead = r2 / z;
  } else {
    const Real r = 1 / z;
    r2 = r * r;
    lead = r2 * r;
  }
  if constexpr (Psi) lead = r2 / 2;
  // The series over lead is 1 + tail; the tail (|tail| < 9/z^2) is summed on its own, so the up
  // to ~60 small terms do not each round a sum of order 1.
  Real term = 1, tail = 0;
  for (int k = 1; k < 1000; ++k) {
    Real factor = Real(2 * k + 1) * Real(2 * k + 1);
    if constexpr (Psi) factor = factor * Real(k) / Real(k + 1);
    const Real next = -term * factor * r2;
    if (abs(next) >= abs(term)) break;  // past the smallest term: z is below the switch point
    tail += next;
    if (abs(next) <= eps / 8) {
      if constexpr (Psi) return -(lead * (1 + tail));
      return lead * (1 + tail);
    }
    term = next;
  }
  throw ConvergenceError(std::string(Psi ? "line_kernel_psi" : "line_kernel_kappa") +
                         ": asymptotic series used below its switch point");
}

/// kappa = (1/z) int_0^inf e^{-s} g(s/z) ds and psi = -(1/z) int_0^inf e^{-s} g(s/z) (z/s) ds
/// (docs/theory.md (L2) with t = s/z): positive integrands, so the sums do not cancel.
template <class Real, bool Psi>
Real laplace_rule(Real z) {
  const auto& rule = line_kernel_rule<Real>();
  // Kahan summation: the plain sum of the 30-270 terms loses up to 8 epsilon. Dividing by z
  // rather than multiplying by a rounded 1/z keeps that rounding out of every term alike.
  Real sum = 0, carry = 0;
  for (std::size_t j = 0; j < rule.node.size(); ++j) {
    const Real t = rule.node[j] / z;
    Real term = rule.weight[j];
    if constexpr (Psi)
      term *= line_kernel_g_over_t(t);
    else
      term *= line_kernel_g(t);
    term -= carry;
    const Real next = sum + term;
    carry = (next - sum) - term;
    sum = next;
  }
  if constexpr (Psi) return -(sum / z);
  return sum / z;
}

}  // namespace viscoroll::detail

namespace viscoroll::special {

/// kappa(z) = int_0^inf e^{-z t} (1 - (1 + t^2)^{-1/2}) dt = 1/z - (pi/2) [H0(z) - Y0(z)], the
/// kernel of the leading-edge condition (L2) of docs/theory.md, to a few epsilon for z > 0.
///
/// Positive and decreasing; kappa = 1/z + ln(z/2) + gamma + O(z) as z -> 0 and
/// 1/z^3 - 9/z^5 + ... as z -> inf. Throws std::invalid_argument unless z > 0.
template <RealScalar Real>
Real line_kernel_kappa(Real z) {
  detail::require(z > 0, "z", z, "z > 0");
  if (z < detail::line_kernel_series_limit<Real>()) return detail::kappa_series(z);
  if (z < detail::line_kernel_asymptotic_limit<Real>()) return detail::laplace_rule<Real, false>(z);
  return detail::asymptotic_series<Real, false>(z);
}

/// psi(z) = -int_0^inf e^{-z t} (1 - (1 + t^2)^{-1/2}) dt / t = -int_z^inf kappa, the end term of
/// the leading-edge condition (L2) of docs/theory.md, to a few epsilon for z > 0.
///
/// Negative and increasing, psi' = kappa; psi = ln(2z) + gamma + O(z ln z) as z -> 0 and
/// -1/(2 z^2) + 9/(4 z^4) - ... as z -> inf. Throws std::invalid_argument unless z > 0.
template <RealScalar Real>
Real line_kernel_psi(Real z) {
  detail::require(z > 0, "z", z, "z > 0");
  if (z < detail::line_kernel_series_limit<Real>()) return detail::psi_series(z);
  if (z < detail::line_kernel_asymptotic_limit<Real>()) return detail::laplace_rule<Real, true>(z);
  return detail::asymptotic_series<Real, true>(z);
}

}  // namespace viscoroll::special
