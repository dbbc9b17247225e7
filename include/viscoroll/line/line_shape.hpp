// viscoroll: the representation of the contact zone of the line solver.
//
// Panek & Kalker (1980), Section 7, leave the parametrisation of a(y) and b(y) open. Ours, with
// t = (y - c)/l and u = 2 t^2 - 1 (c = 0 and both functions even in y for a symmetric scene):
//   a(y) = a_ref sqrt(1 - t^2) exp(sum_{k<N} alpha_k T_k(u) + t sum_{k<N} gamma_k T_k(u)),
//   b(y) = a_ref (sum_{k<=N} beta_k T_k(u) + t sum_{k<=N} delta_k T_k(u)),
// T_k the Chebyshev polynomials; the odd parts (gamma, delta: alpha_odd, beta_odd) and the centre c
// only for an asymmetric contact (a tilted roller, docs/theory.md (RP6), (RP7)), empty otherwise.
// a(c +- l) = 0 holds by construction, with the square-root end of
// the static solution (48) (alpha = beta = 0 is Kalker's static contact), and a > 0 inside for
// any coefficients. G (36), F0 (33) and Q (46) follow pointwise from the strip at each y
// (core/strip.hpp, strip_functions; docs/theory.md section 4).
#pragma once

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/line/line_basis.hpp>
#include <viscoroll/special/bessel_ratio.hpp>

namespace viscoroll {

/// a(y), b(y) of the contact and the functions of y that follow from them.
template <RealScalar Real>
struct LineShape {
  Real a_ref;               ///< scale of a and b (the long-term static half width at y = 0)
  Real l;                   ///< half length
  std::vector<Real> alpha;  ///< Chebyshev coefficients of ln(a / (a_ref sqrt(1 - t^2)))
  std::vector<Real> beta;   ///< Chebyshev coefficients of b / a_ref
  /// The expansion variable of the series alpha and beta.
  LineBasis basis = LineBasis::t_squared;
  Real scale = 0;  ///< e of LineBasis::s_mapped (unused by the other variables)
  /// The asymmetric contact's parts (empty and 0 for a symmetric one): the coefficients of the
  /// odd parts t sum gamma_k T_k(u) of ln(a/(a_ref sqrt(1 - t^2))) and t sum delta_k T_k(u) of
  /// b/a_ref, and the centre c of the contact [c - l, c + l].
  /// The odd parts' coefficients gamma_k (of ln a) and delta_k (of b/a_ref).
  ///@{
  std::vector<Real> alpha_odd{}, beta_odd{};
  ///@}
  /// c, the contact's centre along y.
  Real centre = 0;

  /// Whether the shape has an odd part or a centre (an asymmetric contact's representation).
  bool asymmetric() const { return !alpha_odd.empty() || !beta_odd.empty() || centre != 0; }

  /// The scale e of LineBasis::s_mapped for a scene: V tau/((1 + f) a_ref), the s at which the
  /// strips turn glassy ((1 + f) a/V tau = 1 with a ~ a_ref s near the ends, Eq. (37)).
  static Real mapped_scale(Real vtau, Real f, Real a_ref) { return vtau / ((1 + f) * a_ref); }

  /// The expansion variable v in [-1, 1] at w = 1 - t^2.
  static Real coordinate(LineBasis basis, Real scale, Real w) {
    using std::asinh;
    using std::sqrt;
    switch (basis) {
      case LineBasis::s:
        return 2 * sqrt(w) - 1;
      case LineBasis::s_mapped:
        if (mapped_is_identity(scale)) return 2 * sqrt(w) - 1;
        return 2 * asinh(sqrt(w) / scale) / asinh(1 / scale) - 1;
      default:
        return 1 - 2 * w;
    }
  }
  /// w = 1 - t^2 at the expansion variable v.
  static Real one_minus_t2_at(LineBasis basis, Real scale, Real v) {
    const Real h = (1 + v) / 2;
    switch (basis) {
      case LineBasis::s:
        return h * h;
      case LineBasis::s_mapped: {
        const Real s = std::min(Real(1), mapped_s(scale, h));
        return s * s;
      }
      default:
        return (1 - v) / 2;
    }
  }
  /// s = e sinh(h asinh(1/e)) of LineBasis::s_mapped at h = (1 + v)/2 in [0, 1] (h itself where
  /// the map is the identity).
  static Real mapped_s(Real scale, Real h) {
    using std::asinh;
    using std::sinh;
    return mapped_is_identity(scale) ? h : Real(scale * sinh(h * asinh(1 / scale)));
  }
  /// e sinh(h asinh(1/e)) = h (1 + O(asinh(1/e)^2)): the map is the identity to rounding once
  /// e > 1/sqrt(eps) (and is not formed there, where sinh would work at the edge of the range).
  /// An unset scale (e <= 0) is the variable s too.
  static bool mapped_is_identity(Real scale) {
    using std::sqrt;
    return !(scale > 0 && scale * sqrt(std::numeric_limits<Real>::epsilon()) < 1);
  }
  /// a / (a_ref sqrt(1 - t^2)) at the ends y = c +- l (side = +1, -1; the odd part's sign).
  Real end_factor(int side = 1) const {
    using std::exp;
    const Real u = coordinate(basis, scale, Real(0));
    const Real odd = alpha_odd.empty() ? Real(0) : Real(side * chebyshev(alpha_odd, u));
    return exp(chebyshev(alpha, u) + odd);
  }

  /// sum c_k T_k(u) by Clenshaw's recurrence.
  static Real chebyshev(const std::vector<Real>& c, Real u) {
    Real b1 = 0, b2 = 0;
    for (std::size_t k = c.size(); k-- > 1;) {
      const Real b0 = 2 * u * b1 - b2 + c[k];
      b2 = b1;
      b1 = b0;
    }
    return c.empty() ? Real(0) : u * b1 - b2 + c[0];
  }

  /// Chebyshev coefficients (m of them) of g(w(v)) interpolated at the zeros of T_m in v.
  template <class G>
  static std::vector<Real> interpolate(LineBasis to, Real scale, int m, const G& g) {
    using std::cos;
    const Real pi = boost::math::constants::pi<Real>();
    std::vector<Real> values(m), c(m, Real(0));
    for (int i = 0; i < m; ++i)
      values[i] = g(one_minus_t2_at(to, scale, cos(pi * Real(2 * i + 1) / Real(2 * m))));
    for (int k = 0; k < m; ++k) {
      Real sum = 0;
      for (int i = 0; i < m; ++i)
        sum += values[i] * cos(pi * Real(k) * Real(2 * i + 1) / Real(2 * m));
      c[k] = sum * (k == 0 ? Real(1) : Real(2)) / Real(m);
    }
    return c;
  }

  /// 1 - t^2 from y without cancellation near the ends: (l - (y - c))(l + (y - c))/l^2.
  Real one_minus_t2(Real y) const {
    const Real yc = y - centre;
    return ((l - yc) / l) * ((l + yc) / l);
  }
  /// t = (y - c)/l.
  Real t_at(Real y) const { return (y - centre) / l; }

  /// a(y) for |y - c| <= l.
  Real a(Real y) const {
    using std::exp;
    const Real w = one_minus_t2(y);
    if (alpha_odd.empty() || !(w > 0)) return a_at(w);
    return a_at(w) * exp(t_at(y) * chebyshev(alpha_odd, coordinate(basis, scale, w)));
  }
  /// a at w = 1 - t^2 in [0, 1].
  Real a_at(Real w) const {
    using std::exp;
    using std::sqrt;
    if (!(w > 0)) return Real(0);
    return a_ref * sqrt(w) * exp(chebyshev(alpha, coordinate(basis, scale, w)));
  }
  /// b at w = 1 - t^2 in [0, 1].
  Real b_at(Real w) const {
    return a_ref * chebyshev(beta, coordinate(basis, scale, w > 0 ? w : Real(0)));
  }

  /// The same a(y), b(y) (and l) expanded in `to` (with its scale) with n coefficients for ln a
  /// and n + 1 for b, by Chebyshev interpolation at the zeros of T_n and T_{n+1} in the new
  /// variable; an asymmetric shape's odd parts (functions of w too, after the factor t) alike.
  LineShape reexpanded(LineBasis to, int n, Real to_scale = 0) const {
    const auto ln_a = [&](Real w) { return chebyshev(alpha, coordinate(basis, scale, w)); };
    const auto b_over = [&](Real w) { return b_at(w) / a_ref; };
    LineShape out{a_ref,
                  l,
                  interpolate(to, to_scale, n, ln_a),
                  interpolate(to, to_scale, n + 1, b_over),
                  to,
                  to_scale};
    if (asymmetric()) {
      const auto a_odd = [&](Real w) { return chebyshev(alpha_odd, coordinate(basis, scale, w)); };
      const auto b_odd = [&](Real w) { return chebyshev(beta_odd, coordinate(basis, scale, w)); };
      out.alpha_odd = interpolate(to, to_scale, n, a_odd);
      out.beta_odd = interpolate(to, to_scale, n + 1, b_odd);
      out.centre = centre;
    }
    return out;
  }

  /// b(y) for |y - c| <= l.
  Real b(Real y) const {
    const Real w = one_minus_t2(y);
    if (beta_odd.empty()) return b_at(w);
    const Real u = coordinate(basis, scale, w > 0 ? w : Real(0));
    return b_at(w) + a_ref * t_at(y) * chebyshev(beta_odd, u);
  }
};

/// The functions gamma(y) = G0/a^2 and kappa(y)/a_ref of the spectrum's line solution,
/// Chebyshev series in u = 2 t^2 - 1, t = (y - c)/l (docs/theory.md (S14)): even, plus for an
/// asymmetric contact the odd parts t sum gamma_odd_k T_k(u), t sum kappa_odd_k T_k(u) (as
/// LineShape's; empty otherwise).
template <RealScalar Real>
struct LineSpectrumMoments {
  /// The even Chebyshev coefficients of gamma = G0/a^2 and kappa/a_ref.
  ///@{
  std::vector<Real> gamma, kappa;
  ///@}
  /// The odd parts' coefficients (empty for a symmetric contact).
  ///@{
  std::vector<Real> gamma_odd{}, kappa_odd{};
  ///@}
  /// The even part of gamma at u.
  Real gamma_at(Real u) const { return LineShape<Real>::chebyshev(gamma, u); }
  /// The even part of kappa/a_ref at u.
  Real kappa_at(Real u) const { return LineShape<Real>::chebyshev(kappa, u); }
  /// gamma and kappa/a_ref at u with their odd parts at t.
  Real gamma_at(Real u, Real t) const {
    if (gamma_odd.empty()) return gamma_at(u);
    return gamma_at(u) + t * LineShape<Real>::chebyshev(gamma_odd, u);
  }
  /// kappa/a_ref at u with its odd part at t.
  Real kappa_at(Real u, Real t) const {
    if (kappa_odd.empty()) return kappa_at(u);
    return kappa_at(u) + t * LineShape<Real>::chebyshev(kappa_odd, u);
  }
};

}  // namespace viscoroll
