// viscoroll: the line operators of the line-contact theory: finite part, near-field operator,
// extended operator, and both sides of the leading-edge condition.
//
// Panek & Kalker (1980), Sections 4-5: Eqs. (20)-(26) (near-field and extended approximations),
// (34), (41), (42) and (44); docs/theory.md section 3 for the re-derivation of (42)-(44) and the
// cancellation-free form (L2) of (44). Methods and measured accuracy: docs/line-operators.md.
//
// Every integral over y' in [-l, l] is split at y' = y and written in s = |y' - y| on each side,
// [0, l - y] and [0, l + y]; the value F(y) is subtracted so that the integrand is bounded:
//   FP[F](y) = int (F(y') - F(y)) / |y' - y| dy'                     (smooth on each side)
//   I[F, x](y) = int (F(y') - F(y)) (x^2 + s^2)^(-1/2) dy'
//                + F(y) [ln(d1 + sqrt(d1^2 + x^2)) + ln(d2 + sqrt(d2^2 + x^2))],  d1,2 = l -+ y,
// which is Eq. (41) with asinh(d/x) + ln x = ln(d + sqrt(d^2 + x^2)): no cancellation as x -> 0.
// Panels are uniform for the smooth finite part and geometric toward s = 0 at the kernel's scale
// (x for I, V tau for (L2) and (44)), detail/graded_panels.hpp.
//
// References: J. J. Kalker, Three-dimensional elastic bodies in rolling contact (1990), ch. 1;
// C. Panek & J. J. Kalker, J. Inst. Maths Applics 26 (1980) 299-313;
// M. Abramowitz & I. A. Stegun, Handbook of Mathematical Functions (1964), ch. 9, 12.
#pragma once

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/detail/graded_panels.hpp>
#include <viscoroll/special/bessel_ratio.hpp>
#include <viscoroll/special/line_kernels.hpp>
#include <viscoroll/special/struve_neumann.hpp>

namespace viscoroll {

/// Settings of LineOperators. validate() throws std::invalid_argument on nonsense.
struct LineOperatorOptions {
  /// Halvings of the panels toward the ends y' = +-l on each side (every operator): resolves a
  /// complex singularity of F within (l - |y|) 2^-end_levels of an end (docs/line-operators.md).
  int end_levels = 16;
  /// Geometric levels below the kernel scale V tau for the (L2) kernel, whose integrand has an
  /// s ln s term at s = 0 (Gauss-Legendre error ~ h^2 on the innermost panel of width h);
  /// < 0 selects digits/2 + 6 of the scalar type.
  int kernel_levels = -1;
  /// Geometric levels below V tau for the literal (44), whose integrand has ln s at s = 0
  /// (error ~ h on the innermost panel); < 0 selects digits + 4 of the scalar type.
  int log_levels = -1;

  void validate() const {
    detail::require(end_levels >= 0 && end_levels <= 1000, "end_levels", end_levels,
                    "0 <= end_levels <= 1000");
    detail::require(kernel_levels <= 1000, "kernel_levels", kernel_levels, "<= 1000");
    detail::require(log_levels <= 1000, "log_levels", log_levels, "<= 1000");
  }
};

/// The line operators of Panek & Kalker (1980) on [-l, l] for callables F : Real -> Real that are
/// smooth on [-l, l] (they may vanish at +-l like (l^2 - y^2) times a smooth function).
///
/// Quadrature is a QuadratureRule policy (a fixed rule such as GaussLegendre<Real, 16>) applied
/// on each panel. All members take |y| < l.
template <RealScalar Real, class Quadrature>
  requires QuadratureRule<Quadrature, Real>
class LineOperators {
 public:
  using real_type = Real;

  /// half_length: l > 0, the half length of the contact.
  explicit LineOperators(Real half_length, LineOperatorOptions options = {})
      : l_(half_length), options_(options) {
    detail::require_positive("half_length", l_);
    options_.validate();
    const int digits = std::numeric_limits<Real>::digits;
    kernel_levels_ = options_.kernel_levels >= 0 ? options_.kernel_levels : digits / 2 + 6;
    log_levels_ = options_.log_levels >= 0 ? options_.log_levels : digits + 4;
  }

  Real half_length() const { return l_; }

  /// FP[F](y) = int_{-l}^{l} (F(y') - F(y)) / |y' - y| dy', the integral of Eqs. (22)-(25), (34).
  template <class F>
  Real finite_part(const F& f, Real y) const {
    check_y(y);
    const Real fy = f(y);
    const auto right = [&](Real s) { return side(f, fy, y, s, [](Real d) { return 1 / d; }); };
    const auto left = [&](Real s) { return side(f, fy, y, -s, [](Real d) { return 1 / d; }); };
    // The difference quotient is smooth: panels [0, d/4], [d/4, d/2], then halving toward the end.
    return integrate(right, Real(l_ - y), Real(l_ - y) / 2, 1) +
           integrate(left, Real(l_ + y), Real(l_ + y) / 2, 1);
  }

  /// Lambda[F](y) = FP[F](y) + F(y) ln 4(l^2 - y^2): Eq. (24), the near-field operator A_0.
  template <class F>
  Real near_field(const F& f, Real y) const {
    using std::log;
    return finite_part(f, y) + f(y) * log(4 * (l_ - y) * (l_ + y));  // Eq. (24)
  }

  /// FP[F](y) + F(y) ln[16 (l^2 - y^2) / a^2]: the left side of Eq. (34) at half width a > 0.
  template <class F>
  Real near_field_strip(const F& f, Real y, Real a) const {
    using std::log;
    detail::require_positive("a", a);
    // Eq. (34); 16 (l^2 - y^2)/a^2 as (4 (l - y)/a)(4 (l + y)/a) so that nothing overflows.
    return finite_part(f, y) + f(y) * (log(4 * (l_ - y) / a) + log(4 * (l_ + y) / a));
  }

  /// I[F, x](y) = int_{-l}^{l} F(y') (x^2 + (y - y')^2)^(-1/2) dy' + 2 F(y) ln x, Eq. (41), x > 0.
  template <class F>
  Real extended(const F& f, Real x, Real y) const {
    using std::hypot;
    using std::log;
    check_y(y);
    detail::require_positive("x", x);
    const Real fy = f(y);
    const auto kernel = [x](Real d) { return 1 / hypot(x, d); };
    const auto right = [&](Real s) { return side(f, fy, y, s, kernel); };
    const auto left = [&](Real s) { return side(f, fy, y, -s, kernel); };
    const Real d1 = l_ - y, d2 = l_ + y;
    // Eq. (20)-(21) exactly: asinh(d/x) + ln x = ln(d + sqrt(d^2 + x^2)).
    const Real ends = log(d1 + hypot(d1, x)) + log(d2 + hypot(d2, x));
    return integrate(right, d1, x, 1) +
           integrate(left, d2, x, 1) + fy * ends;
  }

  /// d/dx I[F, x](y) = -x int (F(y') - F(y)) (x^2 + s^2)^(-3/2) dy'
  ///                   + F(y) x [1/(h1 (h1 + d1)) + 1/(h2 (h2 + d2))],  h = sqrt(d^2 + x^2),
  /// the derivative of Eq. (41) (the second term is 2F/x - F (d1/h1 + d2/h2)/x without
  /// cancellation).
  template <class F>
  Real extended_dx(const F& f, Real x, Real y) const {
    using std::hypot;
    check_y(y);
    detail::require_positive("x", x);
    const Real fy = f(y);
    const auto kernel = [x](Real s) {
      const Real h = hypot(x, s);
      return x / (h * h * h);
    };
    const auto right = [&](Real s) { return side(f, fy, y, s, kernel); };
    const auto left = [&](Real s) { return side(f, fy, y, -s, kernel); };
    const Real d1 = l_ - y, d2 = l_ + y;
    const Real h1 = hypot(d1, x), h2 = hypot(d2, x);
    return -(integrate(right, d1, x, 1) +
             integrate(left, d2, x, 1)) +
           fy * x * (1 / (h1 * (h1 + d1)) + 1 / (h2 * (h2 + d2)));
  }

  /// The right side of Eq. (44) in the cancellation-free form (L2) of docs/theory.md:
  ///   R[Q](y) = int (Q(y') - Q(y)) V^-1 kappa(|y' - y| / V) dy' + Q(y) [psi((l - y)/V) +
  ///   psi((l + y)/V)], V = V tau > 0. Accurate for V/l from 1e-4 to 1e4 (docs/line-operators.md).
  template <class F>
  Real leading_edge_kernel(const F& q, Real vtau, Real y) const {
    using special::line_kernel_kappa;
    using special::line_kernel_psi;
    check_y(y);
    detail::require_positive("vtau", vtau);
    const Real qy = q(y);
    const auto kernel = [vtau](Real d) { return line_kernel_kappa(Real(d / vtau)); };
    const auto right = [&](Real s) { return side(q, qy, y, s, kernel); };
    const auto left = [&](Real s) { return side(q, qy, y, -s, kernel); };
    const Real d1 = l_ - y, d2 = l_ + y;
    // (L2)
    return (integrate(right, d1, vtau, kernel_levels_) +
            integrate(left, d2, vtau, kernel_levels_)) /
               vtau +
           qy * (line_kernel_psi(Real(d1 / vtau)) + line_kernel_psi(Real(d2 / vtau)));
  }

  /// The right side of Eq. (44) as printed, with the bracket [gamma - ln V tau] (docs/paper.md,
  /// correction 5):
  ///   Lambda[Q](y) + 2 Q(y) (gamma - ln V) - pi/(2V) int Q(y') [H0 - Y0](|y - y'| / V) dy'.
  /// Its three terms cancel to leading order as V -> 0 (lost digits ~ log10(|Q ln V| / |R|));
  /// use leading_edge_kernel there. Kept as an independent check of (L2).
  template <class F>
  Real leading_edge_literal(const F& q, Real vtau, Real y) const {
    using std::log;
    using special::struve_h0_minus_y0;
    check_y(y);
    detail::require_positive("vtau", vtau);
    const auto kernel = [vtau](Real d) { return struve_h0_minus_y0(Real(d / vtau)); };
    // No subtraction here, so the node's own s is used (it may be below the spacing of y).
    const auto right = [&](Real s) { return q(Real(y + s)) * kernel(s); };
    const auto left = [&](Real s) { return q(Real(y - s)) * kernel(s); };
    const Real struve = integrate(right, Real(l_ - y), vtau, log_levels_) +
                        integrate(left, Real(l_ + y), vtau, log_levels_);
    const Real gamma = boost::math::constants::euler<Real>();
    const Real half_pi = boost::math::constants::half_pi<Real>();
    // Eq. (44)
    return near_field(q, y) + 2 * q(y) * (gamma - log(vtau)) - half_pi / vtau * struve;
  }

 private:
  template <class G>
  Real integrate(const G& g, Real length, Real scale, int levels) const {
    return detail::graded_integral<Quadrature>(g, length, scale, levels, options_.end_levels);
  }

  /// (F(y') - F(y)) k(|y' - y|) at y' = y + s, with |y' - y| recomputed from the rounded y' so
  /// that the rounding of y + s does not enter the difference quotient (error eps |y| / s -> eps s).
  template <class F, class K>
  static Real side(const F& f, Real fy, Real y, Real s, const K& kernel) {
    using std::abs;
    const Real yp = y + s;
    const Real d = abs(Real(yp - y));
    if (d == 0) return Real(0);  // s below the spacing of y: a bounded integrand on a null set
    return (f(yp) - fy) * kernel(d);
  }

  void check_y(Real y) const {
    using std::abs;
    detail::require(abs(y) < l_, "y", y, "|y| < l");
  }

  Real l_;
  LineOperatorOptions options_;
  int kernel_levels_ = 0;
  int log_levels_ = 0;
};

/// The left side of Eq. (44): C1 e^{-b/V} {a b K1(a/V) - G K0(a/V)}, V = V tau > 0, a > 0,
/// evaluated as C1 e^{-(a+b)/V} {a b e^z K1(z) - G e^z K0(z)}, z = a/V, so that nothing overflows
/// (it underflows to 0 when (a + b)/V is beyond the exponent range).
template <RealScalar Real>
Real leading_edge_bessel_term(Real c1, Real a, Real b, Real g, Real vtau) {
  using std::exp;
  detail::require_positive("a", a);
  detail::require_positive("vtau", vtau);
  const Real z = a / vtau;
  // Eq. (44), left side
  return c1 * exp(-(a + b) / vtau) *
         (a * b * special::bessel_k1_scaled(z) - g * special::bessel_k0_scaled(z));
}

/// The Bessel term of Eq. (42): C1 e^{a/V} {a b K1(a/V) - G K0(a/V)} = C1 {a b e^z K1(z) -
/// G e^z K0(z)}, z = a/V; Eq. (44)'s left side is this times e^{-(a+b)/V}.
template <RealScalar Real>
Real leading_edge_bessel_term_scaled(Real c1, Real a, Real b, Real g, Real vtau) {
  detail::require_positive("a", a);
  detail::require_positive("vtau", vtau);
  const Real z = a / vtau;
  // Eq. (42), first term of the right side
  return c1 * (a * b * special::bessel_k1_scaled(z) - g * special::bessel_k0_scaled(z));
}

}  // namespace viscoroll
