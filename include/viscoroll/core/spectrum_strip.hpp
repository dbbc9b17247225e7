// viscoroll: the strip of a material with a discrete spectrum (M retardation times), in closed
// form given its half width: the generalisation of Eqs. (32)-(37) derived in docs/theory.md,
// section 12 ((S1)-(S10)).
//
// With lambda_k = V tau_k the retardation lengths and mu_i = V rho_i the relaxation lengths (the
// zeros of the creep function's transform, interlacing: mu_1 < lambda_1 < mu_2 < ... < lambda_M),
// the pseudo-pressure is (S4)
//   p* = C1/(2 pi) [ (a^2 - xi^2) + Pi_h(D) + (Pi_g(D) - b) xi ] / sqrt(a^2 - xi^2)
// (finite parts; D = d/dxi acting on 1/sqrt and xi/sqrt), Pi_h, Pi_g polynomials of degree M - 1
// with Pi_g(0) = Lambda_1 = sum lambda_k. The unknowns are their values at the relaxation rates,
// u_i = Pi_h(1/mu_i), w_i = Pi_g(1/mu_i), and b; the equations are the trailing-edge condition
// of each relaxation length (S6), the leading-edge condition of each retardation length (S7) and
// Pi_g(0) = Lambda_1, a linear system of order 2M + 1. The pressure is a weighted sum of M
// one-term strips (S9), each an instance of StripPressure.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/material/detail/prony_spectrum.hpp>
#include <viscoroll/special/bessel_ratio.hpp>

namespace viscoroll {

namespace plane {

/// The lengths of a spectrum at one speed, in one unit of length: retardation lengths
/// lambda_k = V tau_k and relaxation lengths mu_i = V rho_i, both ascending and interlacing
/// (mu_1 < lambda_1 < mu_2 < ... < lambda_M), and the creep ratio F = sum f_k.
template <RealScalar Real>
struct SpectrumLengths {
  /// lambda_k = V tau_k, ascending.
  std::vector<Real> retardation;
  /// mu_i = V rho_i, ascending.
  std::vector<Real> relaxation;
  /// F = sum f_k.
  Real creep_ratio{};
};

/// The closed-form strip of a spectrum at half width a (S5)-(S8), lengths in the caller's unit:
/// u_i = A_i Pi_h(1/mu_i) (a length squared) and w_i = A_i (Pi_g(1/mu_i) - b), the odd
/// coefficient of the term's (32) (a length), the offset
/// b, G0 = Pi_h(0) (the G of Eq. (33): F0 = C1 (a^2/4 + G0/2)) and Pi_h'(0) (a length cubed, in
/// the first moment (S8)), and the weights A_i of the pressure's partial fractions (S9).
template <RealScalar Real>
struct SpectrumStrip {
  /// u_i, w_i and the weights A_i, one per relaxation length.
  ///@{
  std::vector<Real> u, w, weight;
  ///@}
  /// The offset b and G0 = Pi_h(0).
  ///@{
  Real b{}, g0{};
  ///@}
  /// Pi_g'(0) + e_2, e_2 = sum_{j<k} lambda_j lambda_k (a length squared): the constant that the
  /// memory adds to the line equation (34) of a spectrum, docs/theory.md (S13).
  Real pig1{};
  Real centroid{};  ///< int (x - b) p dx / int p dx, the pressure's centroid ahead of the centre
                    ///< (S10)
  Real residual{};  ///< max |X r - rhs| / (|X| |r| + |rhs|) of the linear solve (S5)
};

/// The derivatives of a SpectrumStrip's b, g0, pig1 and centroid in the right sides right[k] of
/// its leading-edge conditions (S12) (M values each; exact, as the solve (S5) is linear in them)
/// and in the half width a at fixed right sides (`*_a`, central differences with step
/// eps^(1/3) a: relative error about eps^(2/3)). The line solver's Jacobian (docs/theory.md
/// (S17)).
template <RealScalar Real>
struct SpectrumStripSlopes {
  /// d/d right[k] of b, g0, pig1 and centroid (M values each).
  ///@{
  std::vector<Real> b, g0, pig1, centroid;
  ///@}
  /// d/da of b, g0, pig1 and centroid at fixed right sides.
  ///@{
  Real b_a{}, g0_a{}, pig1_a{}, centroid_a{};
  ///@}
};

}  // namespace plane

namespace detail {

/// (S10) M_i / pi = int (xi - mu_i) phi_i(xi) / sqrt(1 - xi^2) dxi / pi in units of a (a = 1):
/// phi_i = even (1 - xi^2) + odd xi + g, alpha = 1/mu_i. With (S6) it equals
/// even e1/alpha - odd e1 + g e0, e1 = I1(alpha)/alpha - 1/2, e0 = (I0(alpha) - 1)/alpha, which
/// is summed by its series for alpha <= 1 (the direct form cancels as mu_i grows); else
/// odd/2 - mu_i (even/2 + g).
template <class Real>
Real spectrum_term_moment(Real even, Real odd, Real g, Real alpha, Real mu) {
  if (alpha > 1) return odd / 2 - mu * (even / 2 + g);
  // e1 = (1/2) sum_{j>=1} (alpha/2)^{2j} / (j! (j+1)!),
  // e0 = (1/alpha) sum_{j>=1} (alpha/2)^{2j} / (j!)^2.
  const Real q = alpha * alpha / 4;
  Real t1 = 1, t0 = 1, e1 = 0, e0 = 0;  // t1 = q^j/(j!(j+1)!), t0 = q^j/(j!)^2
  for (int j = 1; j <= 40; ++j) {
    t1 *= q / Real(j * (j + 1));
    t0 *= q / Real(j * j);
    e1 += t1;
    e0 += t0;
    if (t0 <= std::numeric_limits<Real>::epsilon() * e0 / 4) break;
  }
  e1 /= 2;
  // e0/alpha^0: e0 = (sum)/alpha; e1/alpha: both divide a series starting at alpha^2 by alpha.
  return even * (e1 / alpha) - odd * e1 + g * (e0 / alpha);
}

/// Solves X x = rhs for `columns` right sides at once (row-major X, n x n; rhs row-major n x
/// columns), by Gaussian elimination with partial pivoting, in place: the solutions in rhs.
/// Small dense systems only (n = 2M + 1).
template <class Real>
void solve_dense(std::vector<Real>& X, std::vector<Real>& rhs, std::size_t n, std::size_t columns) {
  using std::abs;
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (abs(X[r * n + c]) > abs(X[pivot * n + c])) pivot = r;
    if (pivot != c) {
      for (std::size_t k = 0; k < n; ++k) std::swap(X[c * n + k], X[pivot * n + k]);
      for (std::size_t j = 0; j < columns; ++j)
        std::swap(rhs[c * columns + j], rhs[pivot * columns + j]);
    }
    const Real d = X[c * n + c];
    for (std::size_t r = c + 1; r < n; ++r) {
      const Real factor = X[r * n + c] / d;
      if (factor == 0) continue;
      for (std::size_t k = c; k < n; ++k) X[r * n + k] -= factor * X[c * n + k];
      for (std::size_t j = 0; j < columns; ++j)
        rhs[r * columns + j] -= factor * rhs[c * columns + j];
    }
  }
  for (std::size_t c = n; c-- > 0;) {
    for (std::size_t j = 0; j < columns; ++j) {
      Real sum = rhs[c * columns + j];
      for (std::size_t k = c + 1; k < n; ++k) sum -= X[c * n + k] * rhs[k * columns + j];
      rhs[c * columns + j] = sum / X[c * n + c];
    }
  }
}

/// The same for one right side.
template <class Real>
void solve_dense(std::vector<Real>& X, std::vector<Real>& rhs, std::size_t n) {
  solve_dense(X, rhs, n, std::size_t(1));
}

}  // namespace detail

namespace plane {

/// Solves (S5)-(S7) at half width a > 0. Every length of `lengths` and a in one unit; the
/// unknowns are formed in units of a and returned in the caller's. With `right` (M values, the
/// line solver's), the leading-edge condition of retardation length lambda_k is the line form
/// (S12) of docs/theory.md, A_k = Psi_k right[k] with A_k = C1 e^z_k [a (b + lambda_k -
/// Pi_g(1/lambda_k)) K1(z_k) - Pi_h(1/lambda_k) K0(z_k)], z_k = a/lambda_k,
/// Psi_k = prod_i (1 - mu_i/lambda_k), instead of the plane's A_k = 0; c1 is C1 in the same units
/// (used only with `right`). With `slopes` (and `right`), also the derivatives of the result in
/// the right sides and in a (SpectrumStripSlopes).
template <RealScalar Real>
SpectrumStrip<Real> spectrum_strip(Real a, const SpectrumLengths<Real>& lengths,
                                   const std::vector<Real>* right = nullptr, Real c1 = Real(1),
                                   SpectrumStripSlopes<Real>* slopes = nullptr) {
  using std::abs;
  const auto& mu = lengths.relaxation;
  const auto& lambda = lengths.retardation;
  const std::size_t m = mu.size(), n = 2 * m + 1;
  std::vector<Real> X(n * n, Real(0)), rhs(n, Real(0));
  // d rhs[m + k] / d right[k] (S12), for the slopes.
  std::vector<Real> right_factor(right != nullptr ? m : 0);
  const auto at = [&X, n](std::size_t r, std::size_t c) -> Real& { return X[r * n + c]; };
  // (S9) A_i = prod_{j != i} mu_i / (mu_i - mu_j) = l_i(0), the weights of the partial fractions.
  std::vector<Real> weight(m);
  for (std::size_t i = 0; i < m; ++i) {
    Real w = 1;
    for (std::size_t j = 0; j < m; ++j)
      if (j != i) w *= mu[i] / (mu[i] - mu[j]);
    weight[i] = w;
  }
  // (S5) The glassy part of Pi_g, exact: omega_i = A_i N(1/mu_i), N(z) = (1 - prod_k (1 -
  // lambda_k z))/z - Lambda_1, which makes every leading-edge condition (S7) hold with b = 0 and
  // Pi_h = 0. With P_i = prod_k (1 - lambda_k/mu_i), A_i (Lambda_1 - mu_i) + omega_i =
  // -A_i mu_i P_i. The product A_i P_i is formed pairwise (S5a),
  //   A_i P_i = ((mu_i - lambda_i)/mu_i) prod_{j != i} (mu_i - lambda_j)/(mu_i - mu_j),
  // each factor of order one by the interlacing (no cancellation, no overflow), where A_i and P_i
  // apart would overflow and underflow for a spectrum over many decades (a factor
  // lambda_k/mu_i per slower term).
  std::vector<Real> weighted(m);
  for (std::size_t i = 0; i < m; ++i) {
    Real p = (mu[i] - lambda[i]) / mu[i];
    for (std::size_t j = 0; j < m; ++j)
      if (j != i) p *= (mu[i] - lambda[j]) / (mu[i] - mu[j]);
    weighted[i] = p;
  }
  // Unknowns U_i = A_i u_i / a^2, W_i = (A_i (w_i - Lambda_1) - omega_i) / a, b / a.
  for (std::size_t i = 0; i < m; ++i) {
    // (S6) trailing edge of relaxation length mu_i, times A_i / I0(a/mu_i):
    //   U_i - r_i W_i + r_i A_i b = -r_i A_i mu_i P_i,  r_i = I1/I0(a / mu_i).
    const Real mu_i = mu[i] / a;
    const Real r = special::bessel_i1_over_i0(1 / mu_i);
    at(i, i) = 1;
    at(i, m + i) = -r;
    at(i, 2 * m) = r * weight[i];
    rhs[i] = -r * mu_i * weighted[i];
  }
  for (std::size_t k = 0; k < m; ++k) {
    // (S7) leading edge of retardation length lambda_k, over K0(a/lambda_k) (1 + s_k) Psi_k:
    //   sum_i c_ki (U_i + s_k W_i) - (s_k / Psi_k) b = 0,
    //   c_ki = lambda_k / (lambda_k - mu_i),  Psi_k = prod_j (1 - mu_j / lambda_k),
    //   s_k = K1/K0(a/lambda_k).
    const Real lam = lambda[k] / a;
    const Real s = special::bessel_k1_over_k0(1 / lam);
    const Real row = 1 / (1 + s);
    Real inv_psi = 1;
    for (std::size_t j = 0; j < m; ++j) inv_psi *= lambda[k] / (lambda[k] - mu[j]);
    for (std::size_t i = 0; i < m; ++i) {
      const Real c = lambda[k] / (lambda[k] - mu[i]);
      at(m + k, i) = c * row;
      at(m + k, m + i) = s * c * row;
    }
    at(m + k, 2 * m) = -s * inv_psi * row;
    // (S12): the row (without its 1/(1 + s_k)) is -A_k / (C1 a^2 e^z K0(z) Psi_k), and
    // A_k = Psi_k right[k].
    if (right != nullptr) {
      const Real scale =
          c1 * a * a * (special::bessel_k0_scaled(1 / lam) + special::bessel_k1_scaled(1 / lam));
      right_factor[k] = -1 / scale;
      rhs[m + k] = -(*right)[k] / scale;
    }
  }
  // Pi_g(0) = sum_i A_i w_i = Lambda_1 (S4), with sum_i A_i = 1 and sum_i omega_i = N(0) = 0:
  // sum_i W_i = 0.
  for (std::size_t i = 0; i < m; ++i) at(2 * m, m + i) = 1;
  rhs[2 * m] = 0;
  const std::vector<Real> X0 = X, rhs0 = rhs;
  detail::solve_dense(X, rhs, n);
  const std::vector<Real>& x = rhs;

  SpectrumStrip<Real> out;
  out.u.resize(m);
  out.w.resize(m);
  out.weight = weight;
  Real g0 = 0, moment = 0, pig1 = 0;
  const Real b = x[2 * m];
  for (std::size_t i = 0; i < m; ++i) {
    // The term's (32): even = A_i, odd = A_i (w_i - b) = A_i mu_i (1 - P_i) - A_i b + W_i, g = U_i
    // (S9).
    const Real odd = (mu[i] / a) * (weight[i] - weighted[i]) - weight[i] * b + x[m + i];
    out.u[i] = x[i] * a * a;
    out.w[i] = odd * a;
    g0 += x[i];                // G0 = Pi_h(0) = sum_i A_i u_i (S8)
    pig1 += mu[i] * x[m + i];  // (S13): Pi_g'(0) + e_2 = a sum_i mu_i W_i (W_i in units of a)
    moment += detail::spectrum_term_moment(weight[i], odd, x[i], a / mu[i], mu[i] / a);
  }
  out.b = b * a;
  out.g0 = g0 * a * a;
  out.pig1 = pig1 * a;
  // (S10): int (x - b) p dx / int p dx = sum_i M_i / (pi (1/2 + G0/a^2)), in units of a.
  out.centroid = (moment / (Real(1) / 2 + g0)) * a;
  // Relative residual of the solve, in the (row-scaled) system.
  Real worst = 0, row_max = 0, x_max = 0, rhs_max = 0;
  for (std::size_t r = 0; r < n; ++r) {
    Real sum = -rhs0[r], row_sum = 0;
    for (std::size_t c = 0; c < n; ++c) {
      sum += X0[r * n + c] * x[c];
      row_sum += abs(X0[r * n + c]);
    }
    worst = std::max(worst, abs(sum));
    row_max = std::max(row_max, row_sum);
    rhs_max = std::max(rhs_max, abs(rhs0[r]));
  }
  for (const Real& v : x) x_max = std::max(x_max, abs(v));
  out.residual = worst / (row_max * x_max + rhs_max);
  if (slopes != nullptr && right != nullptr) {
    // In the right sides: the system's solution for the columns d rhs / d right[k], and the
    // outputs linearised: b' = a x'_b, G0' = a^2 sum U_i', pig1' = a sum mu_i W_i', odd_i' =
    // W_i' - A_i x'_b, and the centroid's quotient (S10) differentiated.
    std::vector<Real> cols(n * m, Real(0));
    for (std::size_t k = 0; k < m; ++k) cols[(m + k) * m + k] = right_factor[k];
    std::vector<Real> X1 = X0;
    detail::solve_dense(X1, cols, n, m);
    const Real half_g = Real(1) / 2 + g0;
    for (auto* v : {&slopes->b, &slopes->g0, &slopes->pig1, &slopes->centroid})
      v->assign(m, Real(0));
    for (std::size_t k = 0; k < m; ++k) {
      const auto z = [&](std::size_t row) { return cols[row * m + k]; };
      Real dg = 0, dpig = 0, dmoment = 0;
      for (std::size_t i = 0; i < m; ++i) {
        dg += z(i);
        dpig += mu[i] * z(m + i);
        const Real dodd = z(m + i) - weight[i] * z(2 * m);
        dmoment += detail::spectrum_term_moment(Real(0), dodd, z(i), a / mu[i], mu[i] / a);
      }
      slopes->b[k] = z(2 * m) * a;
      slopes->g0[k] = dg * a * a;
      slopes->pig1[k] = dpig * a;
      slopes->centroid[k] = a * (dmoment * half_g - moment * dg) / (half_g * half_g);
    }
    // In a at fixed right sides: central differences (every coefficient of the system depends on
    // a through the Bessel ratios).
    using std::cbrt;
    const Real h = cbrt(std::numeric_limits<Real>::epsilon()) * a;
    const SpectrumStrip<Real> up = spectrum_strip(a + h, lengths, right, c1);
    const SpectrumStrip<Real> down = spectrum_strip(a - h, lengths, right, c1);
    slopes->b_a = (up.b - down.b) / (2 * h);
    slopes->g0_a = (up.g0 - down.g0) / (2 * h);
    slopes->pig1_a = (up.pig1 - down.pig1) / (2 * h);
    slopes->centroid_a = (up.centroid - down.centroid) / (2 * h);
  }
  return out;
}

}  // namespace plane

/// The pressure across a plane strip of any material: a weighted sum of one-term strips (S9),
/// p = sum_i A_i p_i, p_i the one-term strip of relaxation length mu_i with G = u_i and odd
/// coefficient w_i - b, each a StripPressure. A material with at most one memory term active
/// has a single strip, the paper's (32), (35) (Hertz's with none): every member then is that
/// StripPressure's, digit for digit.
template <RealScalar Real, class Quadrature>
requires QuadratureRule<Quadrature, Real>
class PlaneStrip {
 public:
  /// No strip: pressure 0 everywhere (a default-constructed solution's; no solver returns one).
  PlaneStrip() = default;
  /// The strip of one memory term, or Hertz's (32), (35).
  explicit PlaneStrip(StripPressure<Real, Quadrature> one)
      : units_{}, a_(one.half_width()), b_(one.offset()), one_(std::move(one)) {}
  /// The strip of a spectrum (S9), all arguments in `units` (StripUnits) as StripPressure's.
  PlaneStrip(plane::StripUnits units, Real c1, Real a, const plane::SpectrumStrip<Real>& strip,
             const plane::SpectrumLengths<Real>& lengths, Real compliance)
      : units_(units), a_(a), b_(strip.b), layer_(lengths.relaxation), spectrum_(true) {
    const Real creep = lengths.creep_ratio;
    for (std::size_t i = 0; i < strip.u.size(); ++i)
      terms_.emplace_back(units, c1, a, strip.b, strip.u[i], (1 + creep) * lengths.relaxation[i],
                          creep, compliance, strip.weight[i], strip.w[i]);
  }

  /// One-term strips summed: 1 for the paper's strip or Hertz's, M for a spectrum's (S9).
  std::size_t terms() const { return spectrum_ ? terms_.size() : one_ ? 1 : 0; }
  /// The one-term strip (requires terms() == 1): the paper's (32), (35).
  const StripPressure<Real, Quadrature>& single() const {
    return spectrum_ ? terms_.front() : *one_;
  }

  /// a, the strip's half width (caller's units).
  Real half_width() const { return length(a_); }
  /// b, the offset of its centre ahead of the axis.
  Real offset() const { return length(b_); }
  /// b + a, the leading edge.
  Real leading_edge() const { return length(b_ + a_); }
  /// b - a, the trailing edge.
  Real trailing_edge() const { return length(b_ - a_); }

  /// (35), (S9): the contact pressure at x (caller's units); zero outside the strip.
  Real pressure(Real x) const {
    if (!spectrum_) return one_ ? one_->pressure(x) : Real(0);
    Real p = 0;
    for (const auto& t : terms_) p += t.pressure(x);
    return p;
  }
  /// dp/dx, the sum of the terms' slopes (each from its own Eq. (7)).
  Real pressure_slope(Real x) const {
    if (!spectrum_) return one_ ? one_->pressure_slope(x) : Real(0);
    Real s = 0;
    for (const auto& t : terms_) s += t.pressure_slope(x);
    return s;
  }
  /// Eq. (32): the pseudo-pressure at x, for the strip of one term (a spectrum's (S4) is not
  /// the sum of its terms'): throws std::logic_error for a spectrum's strip.
  Real pseudo_pressure(Real x) const {
    if (spectrum_)
      throw std::logic_error(
          "viscoroll: PlaneStrip::pseudo_pressure is the one-term strip's (32); a spectrum's "
          "strip gives pressure(x) (S9)");
    return one_ ? one_->pseudo_pressure(x) : Real(0);
  }

  /// The largest pressure and where it sits (a spectrum's: samples clustered at the ends and
  /// through each relaxation layer at the leading edge, then the root of the slope).
  PressurePeak<Real> peak() const { return peak_between(trailing_edge(), leading_edge()); }
  /// The largest pressure on [lo, hi] (clipped to the strip) and where it sits.
  PressurePeak<Real> peak_between(Real lo, Real hi) const {
    if (!spectrum_) return one_ ? one_->peak_between(lo, hi) : PressurePeak<Real>{Real(0), Real(0)};
    std::vector<Real> layers;
    for (const Real l : layer_)
      if (l < a_) layers.push_back(length(l));
    using std::max;
    using std::min;
    return detail::strip_peak(
        max(lo, trailing_edge()), min(hi, leading_edge()), leading_edge(), layers,
        [this](Real x) { return pressure(x); }, [this](Real x) { return pressure_slope(x); }, true);
  }

 private:
  /// x in the strip's units to the caller's (the strip of one term keeps a and b in the
  /// caller's: its units_ are 2^0).
  Real length(Real x) const { return detail::times_power_of_two(x, units_.length); }

  plane::StripUnits units_{};
  Real a_{}, b_{};
  std::vector<Real> layer_;
  std::optional<StripPressure<Real, Quadrature>> one_;  // the strip of one term (no allocation)
  std::vector<StripPressure<Real, Quadrature>> terms_;  // a spectrum's (S9)
  bool spectrum_ = false;
};

}  // namespace viscoroll
