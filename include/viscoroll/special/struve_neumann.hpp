// viscoroll: H_0(x) - Y_0(x), the Struve function minus the Neumann function of order zero.
//
// Panek & Kalker (1980), Eq. (44), integrate Q(y') [H_0 - Y_0](|y - y'| / (V tau)) over the contact
// length (line/paper_leading_edge.hpp, opt-in: viscoroll.hpp does not include either); the
// argument runs from 0 (a logarithmic singularity, since -Y_0 ~ (2/pi) ln(2/x)) to 2l / (V tau),
// which is large for slow relaxation. Boost.Math has no Struve function, and
// neither H_0 nor Y_0 alone is of use at large x: both are O(x^{-1/2}) and oscillate, while their
// difference is positive, monotone and O(1/x).
//
// Three methods, each used only where it loses no digits (justification and measured accuracy in
// docs/special-functions.md):
//   0 < x <= 1:           the power series of H_0 (DLMF 11.2.1) and of Y_0 (DLMF 10.8.2); H_0 > 0
//   and
//                         -Y_0 > 0 for x < 0.89, so the difference adds magnitudes.
//   1 < x < x_S:          (2/pi) int_0^U exp(-x sinh u) du (DLMF 11.5.2 with t = sinh u) by an
//                         N-point Gauss-Legendre rule, N = digits + digits/16 + 8, fixed nodes:
//                         a sum of positive terms.
//   x >= x_S:             the asymptotic series (DLMF 11.6.1), whose smallest term is ~e^{-x}:
//                         x_S = ceil(-ln eps) + 2 (18 float, 39 double, 46 long double, 118 at 50
//                         digits).
//
// References: M. Abramowitz & I. A. Stegun, Handbook of Mathematical Functions (1964), ch. 12;
// NIST Digital Library of Mathematical Functions (DLMF), ch. 11.
#pragma once

#include <viscoroll/core/concepts.hpp>
#include <viscoroll/special/detail/struve_neumann_detail.hpp>

namespace viscoroll::special {

/// H_0(x) - Y_0(x) (Struve minus Neumann, A&S ch. 12) for x > 0 (+inf allowed), to a few eps
/// relative over the whole range: (2/pi)(ln(2/x) - gamma) near 0, 2/(pi x) for large x.
template <RealScalar Real>
Real struve_h0_minus_y0(Real x) {
  detail::require_argument("struve_h0_minus_y0", x, false);
  if (x <= detail::struve_series_limit<Real>()) return detail::struve_h0_minus_y0_series(x);
  if (x < detail::struve_asymptotic_threshold<Real>())
    return detail::struve_h0_minus_y0_quadrature(x);
  return detail::struve_h0_minus_y0_asymptotic(x);
}

}  // namespace viscoroll::special
