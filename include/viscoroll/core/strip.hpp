// viscoroll: the 2-D strip solution, shared by the plane and the line solver.
//
// Panek & Kalker (1980), Sections 5-6. A strip is the chord of the contact at one y (or the whole
// contact of the plane problem): x in [b - a, b + a], with xi = x - b (Eq. 30), rolling at V with
// one memory term (creep ratio f, relaxation time tau). Given its half width a and offset b:
//   alpha = (1 + f) a / V tau                                                         Eq. (37)
//   G = a (V tau f/(1 + f) - b) I1(alpha)/I0(alpha)    (trailing-edge condition)      Eq. (36)
//   F0 = C1 (a^2/4 + G/2) = int p* dx                                                 Eq. (33)
//   Q = (C1/2) G (1 - b/V tau)                                                        Eq. (46)
// (strip_functions); the pseudo-pressure across it (Eq. 32)
//   p*(xi) = C1 / (2 pi) [sqrt(a^2 - xi^2) + ((V tau - b) xi + G) / sqrt(a^2 - xi^2)]
// and the pressure that solves the first-order equation (7), c [(1 + f) p - V tau p'] = p*, with
// p = 0 at the leading edge (Eq. 35):
//   c p(x) = 1/(V tau) int_x^{b+a} p*(x') exp(-k (x' - x)) dx',   k = (1 + f) / (V tau)
// (StripPressure). When G satisfies (36) the same integral taken from the trailing edge
// (docs/theory.md, "Stable evaluation of Eq. (35)") is equal to it; each form is used where it
// neither overflows nor cancels. Only exponentials of non-positive arguments (or at most +1) are
// formed, so nothing overflows for any V tau; and the strip computes in units of powers of two
// in which a and C1 are of order one (StripUnits), so nothing overflows or underflows for any a
// and C1 where the pressure is representable. The strip's first moment behind the rolling
// friction (54) is strip_first_moment, in the cancellation-free form (P7).
#pragma once

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/special/bessel_ratio.hpp>

namespace viscoroll {

namespace plane {

/// alpha = (1 + f) a / V tau of Eq. (37): the strip's half width over the length V tau/(1 + f)
/// on which the pressure of Eq. (35) relaxes.
template <RealScalar Real>
Real strip_alpha(Real a, Real vtau, Real f) {
  return (1 + f) * a / vtau;  // Eq. (37)
}

/// The strip functions at one y: G of Eq. (36), F0 of Eq. (33), Q of Eq. (46).
template <RealScalar Real>
struct StripFunctions {
  /// The half width a, the offset b, G (36), F0 (33) and Q (46), in that order.
  ///@{
  Real a, b, g, f0, q;
  ///@}
};

/// G, F0 and Q for half width a > 0, offset b, V tau > 0 and creep ratio f, curvature c1, given
/// r_i = I1(alpha)/I0(alpha), alpha = (1 + f) a / V tau (for callers that need r_i as well):
///   G = {(V tau - b) a - a^2/alpha} I1(alpha)/I0(alpha)                               (36), (37)
///   F0 = C1 (a^2/4 + G/2)                                                            (33)
///   Q = (C1/2) G (1 - b / V tau)                                                      (46)
/// with (V tau - b) a - a^2/alpha = a (V tau f/(1 + f) - b).
template <RealScalar Real>
StripFunctions<Real> strip_functions_from_ratio(Real c1, Real a, Real b, Real vtau, Real f,
                                                Real r_i) {
  const Real g = a * (vtau * f / (1 + f) - b) * r_i;                             // Eq. (36)
  return {a, b, g, c1 * (a * a / 4 + g / 2), c1 * g * (vtau - b) / (2 * vtau)};  // (33), (46)
}

/// G, F0 and Q (strip_functions_from_ratio) for any a: zero beyond the ends (a <= 0).
template <RealScalar Real>
StripFunctions<Real> strip_functions(Real c1, Real a, Real b, Real vtau, Real f) {
  if (!(a > 0)) return {Real(0), b, Real(0), Real(0), Real(0)};
  return strip_functions_from_ratio(c1, a, b, vtau, f,
                                    special::bessel_i1_over_i0_fast(strip_alpha(a, vtau, f)));
}

/// The first moment of a strip's pressure in the cancellation-free form (P7) of docs/theory.md:
///   4 c (1 + f) int x p dx / C1 = 2 b G + V tau (f a^2 I2/I0 + 2 a b I1/I0) / (1 + f),
/// r_i = I1/I0(alpha), r_2 = I2/I0(alpha), alpha = (1 + f) a / V tau (every term is non-negative
/// when b, G >= 0; the paper's (54) subtracts nearly equal terms as V tau grows). Shared by the
/// plane solver (chi = C1 times this over a0^2) and, strip by strip, the line solver.
template <RealScalar Real>
Real strip_first_moment(Real a, Real b, Real g, Real vtau, Real f, Real r_i, Real r_2) {
  return 2 * b * g + vtau * (f * a * a * r_2 + 2 * a * b * r_i) / (1 + f);
}

/// True when a strip of long-term half width a0 at V tau is its glassy limit (Hertz with the
/// instantaneous compliance) to within eps: by (P6) the departures are b/a0 ~ (u/2) (ln(2
/// sqrt(1 + f)/u) - gamma) and chi/(C1 a0) ~ b/a0 + u f/(8 (1 + f)), u = a0 / V tau, while a
/// moves by O(u^2 ln u) only; u (ln(2/u) + ln(1 + f)/2 + 1) <= eps covers both (V tau >~ 40 a0 /
/// eps in double). V tau = +inf (an overflowed product) is glassy. Shared by the plane and the
/// line solver (whose strips are the plane's at leading order in a/l).
template <RealScalar Real>
bool strip_is_glassy(Real vtau, Real f, Real a0) {
  using std::log;
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real u = a0 / vtau;
  if (u == 0) return true;
  if (!(u < eps)) return false;
  // ln(2/u) as ln 2 - ln u: 2/u overflows for the smallest u.
  return u * (boost::math::constants::ln_two<Real>() - log(u) + log(1 + f) / 2 + 1) <= eps;
}

}  // namespace plane

/// Location and value of the largest pressure on a strip.
template <RealScalar Real>
struct PressurePeak {
  Real x;         ///< where the peak sits (moving frame)
  Real pressure;  ///< its value
};

namespace detail {
/// The largest value of `pressure` on [lo, hi]: samples clustered at both ends (cosine spacing)
/// and, for each length of `layers`, through the layer of that width behind `edge` (the leading
/// edge, where the low-speed peak sits, Fig. 6); then the root of `slope` between the best
/// sample's neighbours (when `has_slope`), else Brent's minimiser of -pressure.
template <class Real, class Pressure, class Slope>
PressurePeak<Real> strip_peak(Real lo, Real hi, Real edge, const std::vector<Real>& layers,
                              Pressure pressure, Slope slope, bool has_slope) {
  using std::cos;
  const Real pi = boost::math::constants::pi<Real>();
  std::vector<Real> xs;
  const int n = 96;
  const Real mid = (lo + hi) / 2, half = (hi - lo) / 2;
  for (int i = 0; i <= n; ++i) xs.push_back(mid - half * cos(pi * Real(i) / Real(n)));
  for (const Real layer : layers)
    for (Real m = Real(1) / 128; m <= 64; m *= 2)
      if (edge - m * layer > lo && edge - m * layer < hi) xs.push_back(edge - m * layer);
  std::sort(xs.begin(), xs.end());
  std::size_t best = 0;
  Real best_p = pressure(xs[0]);
  for (std::size_t i = 1; i < xs.size(); ++i) {
    const Real p = pressure(xs[i]);
    if (p > best_p) best_p = p, best = i;
  }
  if (best == 0 || best + 1 == xs.size()) return {xs[best], best_p};  // at an end of [lo, hi]
  const Real left = xs[best - 1], right = xs[best + 1];
  if (has_slope) {
    const Real s_left = slope(left), s_right = slope(right);
    if (s_left > 0 && s_right < 0) {
      std::uintmax_t iterations = 200;
      const auto root = boost::math::tools::toms748_solve(
          slope, left, right, s_left, s_right,
          boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 3),
          iterations);
      const Real x = (root.first + root.second) / 2, p = pressure(x);
      if (p >= best_p) return {x, p};
    }
  }
  const auto found =
      boost::math::tools::brent_find_minima([&pressure](Real x) { return -pressure(x); }, left,
                                            right, std::numeric_limits<Real>::digits / 2);
  if (-found.second >= best_p) return {found.first, -found.second};
  return {xs[best], best_p};
}
}  // namespace detail

namespace plane {

/// The units in which a strip is computed, powers of two: a length x is held as x 2^-length, the
/// curvature C1 as C1 2^-curvature and the compliance c as c 2^-compliance; G (a length squared)
/// as G 4^-length. Then the pseudo-pressure p* of (32) carries 2^(curvature + length), the
/// pressure p = p*/c of (35) 2^(curvature - compliance + length) and its slope
/// 2^(curvature - compliance). Every operation rounds as in the caller's units (Binary), so the
/// strip computes their bits wherever they neither overflow nor underflow, and in its own units,
/// where a and C1 are of order one, nothing does (docs/theory.md, "Scaling").
struct StripUnits {
  int length = 0;      ///< binary exponent of the unit of length
  int curvature = 0;   ///< binary exponent of the unit of C1
  int compliance = 0;  ///< binary exponent of the unit of the compliance c
};

}  // namespace plane

/// Pressure on one strip of the contact, Eqs. (32) and (35), computed in the strip's units
/// (StripUnits): x and the pressure are converted at the interface only.
///
/// Quadrature is a QuadratureRule policy applied on panels on which the exponential weight of
/// Eq. (35) falls by at most e^8; with GaussLegendre<Real, 24> each panel is exact to about 1e-39
/// relative (docs/theory.md), so the reconstruction is limited by rounding, not by the rule.
template <RealScalar Real, class Quadrature>
requires QuadratureRule<Quadrature, Real>
class StripPressure {
 public:
  /// c1: curvature C1; a, b, g: half width, offset and G(y) of the strip; vtau: V tau >= 0;
  /// f: creep ratio; compliance: (1 - nu) / (2 pi mu_D). vtau == 0 is the static strip. The
  /// units are those in which a, C1 and the compliance lie in [1, 2).
  StripPressure(Real c1, Real a, Real b, Real g, Real vtau, Real f, Real compliance)
      : units_{detail::binary(a).e, detail::binary(c1).e, detail::binary(compliance).e}, f_(f) {
    const int length = units_.length;
    c1_ = detail::times_power_of_two(c1, -units_.curvature);
    a_ = detail::times_power_of_two(a, -length);
    b_ = detail::times_power_of_two(b, -length);
    g_ = detail::times_power_of_two(g, -2 * length);
    vtau_ = detail::times_power_of_two(vtau, -length);
    c_ = detail::times_power_of_two(compliance, -units_.compliance);
    odd_ = vtau_ - b_;
  }

  /// The same strip with c1, a, b, g, vtau and compliance given in `units` (StripUnits).
  StripPressure(plane::StripUnits units, Real c1, Real a, Real b, Real g, Real vtau, Real f,
                Real compliance)
      : StripPressure(units, c1, a, b, g, vtau, f, compliance, Real(1), vtau - b) {}

  /// A strip whose pseudo-pressure (32) has the coefficients `even`, `odd` and g:
  /// p* = C1/(2 pi) [even (a^2 - xi^2) + odd xi + g] / sqrt(a^2 - xi^2), all in `units`. One
  /// relaxation term of a spectrum's strip is such a strip (docs/theory.md, (S9)); (35) holds
  /// with vtau and f, and the reconstruction from the trailing edge needs (36) in the form
  /// even a^2 I1(alpha)/alpha - odd a I1(alpha) + g I0(alpha) = 0.
  StripPressure(plane::StripUnits units, Real c1, Real a, Real b, Real g, Real vtau, Real f,
                Real compliance, Real even, Real odd)
      : units_(units),
        c1_(c1),
        a_(a),
        b_(b),
        g_(g),
        vtau_(vtau),
        f_(f),
        c_(compliance),
        odd_(odd),
        even_(even) {}

  /// a, the strip's half width (in the caller's unit of length).
  Real half_width() const { return length(a_); }
  /// b, the offset of its centre ahead of the axis.
  Real offset() const { return length(b_); }
  /// b + a, the leading edge.
  Real leading_edge() const { return length(b_ + a_); }
  /// b - a, the trailing edge.
  Real trailing_edge() const { return length(b_ - a_); }

  /// Eq. (32): the pseudo-pressure p*(x); zero outside the strip.
  Real pseudo_pressure(Real x) const {
    return detail::times_power_of_two(pseudo_in_units(in_units(x)),
                                      units_.curvature + units_.length);
  }

  /// Eq. (35): the contact pressure p(x); zero outside the strip.
  Real pressure(Real x) const {
    return detail::times_power_of_two(pressure_in_units(in_units(x)), pressure_exponent());
  }

  /// dp/dx from Eq. (7): c V tau p' = c (1 + f) p - p*; needs V tau > 0.
  Real pressure_slope(Real x) const {
    return detail::times_power_of_two(slope_in_units(in_units(x)),
                                      units_.curvature - units_.compliance);
  }

  /// The largest pressure on the strip and where it sits.
  PressurePeak<Real> peak() const { return peak_between(trailing_edge(), leading_edge()); }

  /// The largest pressure on [lo, hi] (clipped to the strip) and where it sits. The location is
  /// the root of the slope (7) to about epsilon when V tau > 0, else Brent's estimate (about
  /// sqrt(epsilon) of the width); the value is accurate to about epsilon either way. Throws
  /// std::invalid_argument if the value is beyond the largest finite number or below the
  /// smallest normal one (detail::representable).
  PressurePeak<Real> peak_between(Real lo, Real hi) const {
    const PressurePeak<Real> peak = peak_in_units(in_units(lo), in_units(hi));
    const Real value = detail::representable(
        peak.pressure, pressure_exponent(), "the pressure peak of the strip", [this] {
          return "c1 = " + detail::format_binary(c1_, units_.curvature) +
                 ", a = " + detail::format_binary(a_, units_.length) +
                 ", b = " + detail::format_binary(b_, units_.length) +
                 ", V tau = " + detail::format_binary(vtau_, units_.length) +
                 ", f = " + detail::format_value(f_) +
                 ", compliance = " + detail::format_binary(c_, units_.compliance);
        });
    return {length(peak.x), value};
  }

 private:
  static Real pi() { return boost::math::constants::pi<Real>(); }
  /// x (caller's units) in the strip's units, and back.
  Real in_units(Real x) const { return detail::times_power_of_two(x, -units_.length); }
  Real length(Real x) const { return detail::times_power_of_two(x, units_.length); }
  /// The binary exponent of the unit of pressure (StripUnits).
  int pressure_exponent() const { return units_.curvature - units_.compliance + units_.length; }

  // Eq. (32) in units, x in units.
  Real pseudo_in_units(Real x) const {
    using std::sqrt;
    const Real ahead = (b_ + a_) - x, behind = x - (b_ - a_);
    if (!(ahead > 0 && behind > 0)) return Real(0);
    const Real root = sqrt(ahead * behind);  // sqrt(a^2 - xi^2) without cancellation
    const Real xi = x - b_;
    return c1_ / (2 * pi()) * (even_ * root + (odd_ * xi + g_) / root);
  }

  // Eq. (35) in units, x in units.
  Real pressure_in_units(Real x) const {
    const Real ahead = (b_ + a_) - x, behind = x - (b_ - a_);
    if (!(ahead > 0 && behind > 0)) return Real(0);
    if (vtau_ == 0) return pseudo_in_units(x) / (c_ * (1 + f_));  // Eq. (7) with V tau = 0
    const Real alpha = plane::strip_alpha(a_, vtau_, f_);
    const Real prefactor = c1_ / (2 * pi() * c_ * vtau_);
    const Real one_minus_s = ahead / a_, one_plus_s = behind / a_;
    if (one_plus_s < 1 && alpha * one_plus_s <= 1)
      return -prefactor * from_trailing_edge(alpha, one_plus_s);
    if (alpha * one_minus_s <= cutoff()) return prefactor * near_leading_edge(alpha, one_minus_s);
    return prefactor * interior(x, ahead, behind);
  }

  // Eq. (7) in units, x in units.
  Real slope_in_units(Real x) const {
    return ((1 + f_) * pressure_in_units(x) - pseudo_in_units(x) / c_) / vtau_;
  }

  // peak_between in units.
  PressurePeak<Real> peak_in_units(Real lo, Real hi) const {
    std::vector<Real> layers;
    const Real layer = vtau_ / (1 + f_);
    if (vtau_ > 0 && layer < a_) layers.push_back(layer);
    return detail::strip_peak(
        std::max(lo, b_ - a_), std::min(hi, b_ + a_), b_ + a_, layers,
        [this](Real x) { return pressure_in_units(x); },
        [this](Real x) { return slope_in_units(x); }, vtau_ > 0);
  }

  /// Exponents beyond which exp(-u) is below epsilon / 100: the integrand is dropped there.
  static Real cutoff() {
    using std::log;
    return -log(std::numeric_limits<Real>::epsilon()) + Real(5);
  }
  /// Panel ends in the exponent u: 0, 1, 3, 7, 15, then steps of 8 up to u_max.
  template <class Body>
  static Real over_panels(Real u_max, Body body) {
    Real sum = 0, lo = 0, width = 1;
    while (lo < u_max) {
      const Real hi = std::min<Real>(lo + width, u_max);
      sum += body(lo, hi);
      lo = hi;
      width = std::min<Real>(2 * width, Real(8));
    }
    return sum;
  }

  // phi(t) = even (a^2 - t^2) + odd t + G (even = 1, odd = V tau - b for Eq. (32)), the numerator
  // of Eq. (32) over C1/(2 pi).
  Real phi_from_cos(Real cos_theta, Real sin_theta) const {
    return even_ * (a_ * a_ * sin_theta * sin_theta) + odd_ * a_ * cos_theta + g_;
  }

  /// Eq. (35) with t = a cos(theta), 0 <= theta <= theta_s: the whole remaining strip lies within
  /// the exponential's reach (alpha (1 - s) <= cutoff). Returns the integral over theta of
  /// phi(a cos theta) exp(-alpha (cos theta - s)).
  Real near_leading_edge(Real alpha, Real one_minus_s) const {
    using std::asin;
    using std::cos;
    using std::exp;
    using std::sin;
    using std::sqrt;
    const Real theta_s = 2 * asin(sqrt(one_minus_s / 2));
    // theta(u) solves alpha (cos theta - s) = u: cos theta = 1 - (1 - s - u / alpha).
    const Real u_max = alpha * one_minus_s;
    // The last panel ends at theta = 0 exactly: 1 - s - u_max/alpha is a rounding residual whose
    // square root (~1e-10 in double) would cut off a sliver of the integral.
    auto theta_of = [&](Real u) {
      const Real gap = one_minus_s - u / alpha;
      return u >= u_max || gap <= 0 ? Real(0) : 2 * asin(sqrt(gap / 2));
    };
    auto integrand = [&](Real theta) {
      // cos theta - s = 2 sin((theta_s + theta)/2) sin((theta_s - theta)/2), without cancellation
      const Real u = 2 * alpha * sin((theta_s + theta) / 2) * sin((theta_s - theta) / 2);
      return phi_from_cos(cos(theta), sin(theta)) * exp(-u);
    };
    return over_panels(u_max, [&](Real u_lo, Real u_hi) {
      return Quadrature::integrate(integrand, theta_of(u_hi), theta_of(u_lo));
    });
  }

  /// Eq. (35) in sigma = x' - x for an interior point, k (b + a - x) > cutoff: the exponential
  /// confines the integrand to sigma < cutoff / k, far from the leading edge.
  Real interior(Real x, Real ahead, Real behind) const {
    using std::exp;
    using std::sqrt;
    const Real k = (1 + f_) / vtau_;
    const Real xi = x - b_;
    auto integrand = [&](Real sigma) {
      const Real ahead_t = ahead - sigma, behind_t = behind + sigma;  // a - t, a + t
      const Real t = xi + sigma;
      return (even_ * (ahead_t * behind_t) + odd_ * t + g_) / sqrt(ahead_t * behind_t) *
             exp(-k * sigma);
    };
    return over_panels(cutoff(), [&](Real u_lo, Real u_hi) {
      return Quadrature::integrate(integrand, u_lo / k, u_hi / k);
    });
  }

  /// Eq. (35) taken from the trailing edge, valid because G satisfies Eq. (36):
  /// int_{-a}^{xi} p* exp(k (xi - t)) dt, with t = -a cos(psi), 0 <= psi <= psi_s. The exponent
  /// alpha (cos psi - cos psi_s) lies in [0, alpha (1 + s)] <= 1.
  Real from_trailing_edge(Real alpha, Real one_plus_s) const {
    using std::asin;
    using std::cos;
    using std::exp;
    using std::sin;
    using std::sqrt;
    const Real psi_s = 2 * asin(sqrt(one_plus_s / 2));
    auto integrand = [&](Real psi) {
      const Real u = 2 * alpha * sin((psi_s + psi) / 2) * sin((psi_s - psi) / 2);
      return phi_from_cos(-cos(psi), sin(psi)) * exp(u);
    };
    return Quadrature::integrate(integrand, Real(0), psi_s);
  }

  plane::StripUnits units_;
  Real c1_, a_, b_, g_, vtau_, f_, c_;  // in units_
  Real odd_;                            // the coefficient of xi in (32): V tau - b unless given
  Real even_ = 1;                       // the coefficient of a^2 - xi^2 in (32): 1 unless given
};

}  // namespace viscoroll
