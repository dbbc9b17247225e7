// viscoroll: the result of the static line contact of a roller profile
// (static_profile_contact.hpp): StaticProfileContact, its contact, penetration and half width a(y)
// of (G3), and the weight omega(t) of (G3) (docs/theory.md, "Line contact for any roller profile
// (static)").
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/outcome.hpp>

namespace viscoroll {

namespace line {

/// omega(t) of (G3) with end layer e: 1 - t^2 for e = +inf, else (1 + e^2)(1 - t^2)/(1 - t^2 +
/// e^2), which rises from the ends over 1 - t^2 ~ e^2 to 1 (a flat contact with short ends).
template <RealScalar Real>
Real static_profile_weight(Real e, Real t) {
  const Real w = (1 - t) * (1 + t);
  if (!(e < std::numeric_limits<Real>::infinity())) return w;
  return (1 + e * e) * w / (w + e * e);
}

}  // namespace line

/// The static line contact of a roller profile: the contact [y_minus, y_plus], the penetration d,
/// the half width a(y) of (G3) and the load per length F0(y) = C1 a(y)^2/4 (Eq. 33 at V tau = 0).
///
/// Members:
///   - `y_minus`, `y_plus`, `d`; `c1`, `a_ref`, `alpha` (the coefficients of (G3));
///   - `a(y)`, `f0(y)`: zero outside the contact;
///   - `y`, `a_nodes`, `f0_nodes`: a(y), F0(y) at the M + 1 Chebyshev-Lobatto points of the
///     contact (ends included, where both are 0), from y_minus to y_plus;
///   - `converged` (the residual of (G1), (G2) is below `tolerance`), `reason` when it is not,
///     `residual` (the largest, (G1) in units of C1 a_ref^2, (G2) relative), `iterations`, `points`
///     (M);
///   - `warnings`: the contact reaches the roller's body end (outside the theory: the result is
///     then not converged), or is not slender (l/max a < 3).
template <RealScalar Real>
struct StaticProfileContact {
  /// The contact's ends and the penetration d.
  ///@{
  Real y_minus, y_plus, d;
  ///@}
  /// C1 of the roller and the scale a_ref of (G3).
  ///@{
  Real c1, a_ref;
  ///@}
  Real epsilon = std::numeric_limits<Real>::infinity();  ///< the end layer of (G3), +inf: none
  /// alpha_k, the coefficients of (G3).
  std::vector<Real> alpha;
  /// The Chebyshev-Lobatto points from y_minus to y_plus and a(y), F0(y) there.
  ///@{
  std::vector<Real> y, a_nodes, f0_nodes;
  ///@}
  /// The residual of (G1), (G2) is below the tolerance.
  bool converged = false;
  /// Why the iteration stopped short (empty when converged).
  std::string reason;
  StopCode code = StopCode::converged;  ///< `reason` as a code (core/outcome.hpp)
  /// The contact reaches the body's end, or is not slender (l/max a < 3).
  std::vector<std::string> warnings;
  std::vector<WarningCode> warning_codes;  ///< the warnings' codes, index for index
  /// The largest residual: (G1) in units of C1 a_ref^2, (G2) relative.
  Real residual = std::numeric_limits<Real>::quiet_NaN();
  /// Newton iterations.
  int iterations = 0;
  /// M: F0 is interpolated at M + 1 Chebyshev-Lobatto points.
  int points = 0;
  /// the smallest spacing of the collocation points in units of the local a(y) (NaN if not
  /// converged); a warning below 1
  Real spacing = std::numeric_limits<Real>::quiet_NaN();

  /// l = (y_plus - y_minus)/2.
  Real half_length() const { return (y_plus - y_minus) / 2; }
  /// c = (y_plus + y_minus)/2.
  Real centre() const { return (y_plus + y_minus) / 2; }
  /// t of (G3) for y in the contact.
  Real t(Real yy) const { return (2 * yy - y_plus - y_minus) / (y_plus - y_minus); }
  /// a(y), Eq. (G3); 0 outside (y_minus, y_plus).
  Real a(Real yy) const {
    using std::exp;
    using std::sqrt;
    if (!(yy > y_minus && yy < y_plus)) return 0;
    const Real u = t(yy);
    return a_ref * sqrt(weight(u)) * exp(series(u));
  }
  /// omega(t) of (G3): 1 - t^2 for epsilon = +inf, else (1 + e^2)(1 - t^2)/(1 - t^2 + e^2).
  Real weight(Real u) const { return line::static_profile_weight(epsilon, u); }
  /// F0(y) = C1 a^2/4 (Eq. 33 at V tau = 0).
  Real f0(Real yy) const {
    const Real h = a(yy);
    return c1 * h * h / 4;
  }
  /// sum alpha_k T_k(u) (Clenshaw).
  Real series(Real u) const {
    Real b1 = 0, b2 = 0;
    for (int k = int(alpha.size()) - 1; k >= 1; --k) {
      const Real b0 = 2 * u * b1 - b2 + alpha[k];
      b2 = b1;
      b1 = b0;
    }
    return alpha.empty() ? Real(0) : Real(u * b1 - b2 + alpha[0]);
  }
};

}  // namespace viscoroll
