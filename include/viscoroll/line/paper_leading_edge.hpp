// viscoroll: the paper's leading-edge condition (44), opt-in: neither viscoroll.hpp nor
// line_solver.hpp includes this header, nor the Struve, kappa and psi kernels it needs.
//
// Panek & Kalker (1980), Eqs. (42)-(44); docs/theory.md section 3 for the derivation of (42)-(44)
// (with the bracket [gamma - ln V tau], docs/paper.md correction 5) and the cancellation-free form
// (L2) of (44), section 4 for why the line solver closes its equations with (L6) instead: the
// small-argument step (43) behind (44) errs by O((a/l)^2), and (44) multiplies that error by
// e^{x0/V tau} when V tau << a. Methods and measured accuracy: docs/line-operators.md.
//
//   leading_edge_kernel            the right side of (44) in the form (L2), on a node set
//   PaperLeadingEdgeOperators      (L2) and (44) as printed, for callables
//   leading_edge_bessel_term       the left side of (44)
//   leading_edge_bessel_term_scaled  the first term of the right side of (42)
//   PaperLeadingEdge               the LeadingEdgeCondition policy of LineResidual for (44)
//   PaperLineResidual              the line residual closed by (44) instead of (L6)
#pragma once

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/detail/graded_panels.hpp>
#include <viscoroll/line/line_operators.hpp>
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/line_shape.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>
#include <viscoroll/special/bessel_ratio.hpp>
#include <viscoroll/special/line_kernels.hpp>
#include <viscoroll/special/struve_neumann.hpp>

namespace viscoroll::line {

/// The right side of Eq. (44) in the cancellation-free form (L2) of docs/theory.md section 3,
///   R[Q](y) = int (Q(y') - Q(y)) V^-1 kappa(|y' - y| / V) dy' + Q(y) [psi((l - y)/V) +
///   psi((l + y)/V)],   V = V tau > 0,
/// from dq_j = Q(y'_j) - Q(y) and q = Q(y) on the nodes of nd. The integrand behaves like
/// Q' + (Q' s / V) ln s at s = 0: the nodes must be graded toward s = 0 below the scale V.
template <RealScalar Real>
Real leading_edge_kernel(const LineNodes<Real>& nd, const std::vector<Real>& dq, Real q,
                         Real vtau) {
  using special::line_kernel_kappa;
  using special::line_kernel_psi;
  Real sum = 0;
  for (std::size_t j = 0; j < dq.size(); ++j)
    sum += nd.weight[j] * dq[j] * line_kernel_kappa(Real(nd.dist[j] / vtau));
  // (L2)
  return sum / vtau +
         q * (line_kernel_psi(Real(nd.d1 / vtau)) + line_kernel_psi(Real(nd.d2 / vtau)));
}

/// Settings of PaperLeadingEdgeOperators. validate() throws std::invalid_argument on nonsense.
struct PaperLeadingEdgeOptions {
  /// The panels toward the ends (LineOperatorOptions::end_levels).
  LineOperatorOptions operators = {};
  /// Geometric levels below the kernel scale V tau for (L2), whose integrand has an s ln s term
  /// at s = 0 (Gauss-Legendre error ~ h^2 on the innermost panel of width h); < 0 selects
  /// digits/2 + 6 of the scalar type.
  int kernel_levels = -1;
  /// Geometric levels below V tau for the printed (44), whose integrand has ln s at s = 0 (error
  /// ~ h on the innermost panel); < 0 selects digits + 4 of the scalar type.
  int log_levels = -1;

  /// Throws std::invalid_argument naming the first setting out of its range.
  void validate() const {
    operators.validate();
    detail::require(kernel_levels <= 1000, "kernel_levels", kernel_levels, "<= 1000");
    detail::require(log_levels <= 1000, "log_levels", log_levels, "<= 1000");
  }
};

/// The right side of Eq. (44) for callables Q : Real -> Real smooth on [-l, l], on the graded
/// panels of LineOperators (geometric at the scale V tau). Members take |y| < l and V tau > 0 and
/// throw std::invalid_argument otherwise:
///   - `kernel(q, vtau, y)`: the form (L2) (leading_edge_kernel), accurate for V/l from 1e-4 to
///     1e4 (docs/line-operators.md);
///   - `literal(q, vtau, y)`: (44) as printed, with the bracket [gamma - ln V tau],
///     Lambda[Q](y) + 2 Q(y) (gamma - ln V) - pi/(2V) int Q(y') [H0 - Y0](|y - y'| / V) dy'.
///     Its three terms cancel to leading order as V -> 0 (lost digits ~ log10(|Q ln V| / |R|));
///     an independent check of (L2);
///   - `operators()`: the LineOperators whose panels both use.
template <RealScalar Real, class Quadrature>
requires NodalQuadratureRule<Quadrature, Real>
class PaperLeadingEdgeOperators {
 public:
  /// half_length: l > 0, the half length of the contact.
  explicit PaperLeadingEdgeOperators(Real half_length, PaperLeadingEdgeOptions options = {})
      : ops_(half_length, options.operators) {
    options.validate();
    const int digits = std::numeric_limits<Real>::digits;
    kernel_levels_ = options.kernel_levels >= 0 ? options.kernel_levels : digits / 2 + 6;
    log_levels_ = options.log_levels >= 0 ? options.log_levels : digits + 4;
  }

  /// The LineOperators whose panels both forms use.
  const LineOperators<Real, Quadrature>& operators() const { return ops_; }

  /// The right side of (44) in the form (L2) at y.
  template <class F>
  Real kernel(const F& q, Real vtau, Real y) const {
    detail::require_positive("vtau", vtau);
    const LineNodes<Real> nd = ops_.nodes(y, vtau, kernel_levels_);
    const Real qy = q(y);
    return leading_edge_kernel(nd, ops_.differences(nd, q, qy), qy, vtau);
  }

  /// The right side of (44) as printed at y (an independent check of kernel()).
  template <class F>
  Real literal(const F& q, Real vtau, Real y) const {
    using special::struve_h0_minus_y0;
    using std::log;
    detail::require_positive("vtau", vtau);
    const Real l = ops_.half_length();
    const Real lambda = ops_.near_field(q, y);  // checks |y| < l
    const auto kernel = [vtau](Real d) { return struve_h0_minus_y0(Real(d / vtau)); };
    // No subtraction here, so the node's own s is used (it may be below the spacing of y).
    const auto right = [&](Real s) { return q(Real(y + s)) * kernel(s); };
    const auto left = [&](Real s) { return q(Real(y - s)) * kernel(s); };
    const int ends = ops_.options().end_levels;
    const Real struve =
        detail::graded_integral<Quadrature>(right, Real(l - y), vtau, log_levels_, ends) +
        detail::graded_integral<Quadrature>(left, Real(l + y), vtau, log_levels_, ends);
    const Real gamma = boost::math::constants::euler<Real>();
    const Real half_pi = boost::math::constants::half_pi<Real>();
    // Eq. (44)
    return lambda + 2 * q(y) * (gamma - log(vtau)) - half_pi / vtau * struve;
  }

 private:
  LineOperators<Real, Quadrature> ops_;
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

/// The LeadingEdgeCondition of the paper: the right side of (44) in the form (L2), on the
/// panels of PaperLeadingEdgeOperators (the residual's node set is graded for the kernels of
/// (L6), not for kappa's s ln s at the scale V tau), times e^{x0/V} to the scaling of (42).
struct PaperLeadingEdge {
  /// The right side of (44) at y, (L2) times e^(x0/V tau).
  template <class Quadrature, class Real>
  static Real right(const LineProblem<Real>& p, const LineShape<Real>& s, Real y, Real x0,
                    const LineNodes<Real>&, const std::vector<Real>&, Real) {
    using std::exp;
    const PaperLeadingEdgeOperators<Real, Quadrature> paper(s.l);
    const auto q = [&](Real yp) {
      return plane::strip_functions(p.c1, s.a(yp), s.b(yp), p.vtau, p.f).q;  // Eq. (46)
    };
    return exp(x0 / p.vtau) * paper.kernel(q, p.vtau, y);
  }
};

/// The line residual closed by the paper's (44) instead of (L6): LineResidual's members without
/// `jacobian` (difference it, or iterate on it with a derivative-free method). It has no
/// solution near the physical one when V tau << a (docs/theory.md section 4).
template <RealScalar Real, class Quadrature = GaussLegendre<Real, 12>>
using PaperLineResidual = LineResidual<Real, Quadrature, PaperLeadingEdge>;

}  // namespace viscoroll::line
