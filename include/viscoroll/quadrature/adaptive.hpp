// viscoroll: adaptive Gauss-Kronrod quadrature that reports failure instead of a wrong number.
//
// A thin policy around boost::math::quadrature::gauss_kronrod<Real, Points>::integrate (Boost.Math,
// quadrature/gauss_kronrod.hpp): bisection of every subinterval whose Kronrod-Gauss difference
// exceeds the tolerance, down to MaxDepth levels. Boost returns its last estimate whatever the
// error; this policy checks the accumulated error estimate against tolerance() times the L1 norm
// of the integrand and throws viscoroll::ConvergenceError when it is not met.
//
// Tolerance. tolerance() = eps^(2/3). The estimate Boost accumulates is |K - G|, the difference
// between the (2n+1)-point Kronrod and the embedded n-point Gauss results. For an integrand
// analytic on the subinterval the Kronrod error is of the order of |K - G|^(3/2) (the Kronrod rule
// has degree 3n + 1 against 2n - 1; QUADPACK's estimate (200 |K - G|)^(3/2) rests on the same
// observation: Piessens et al., QUADPACK, Springer 1983). Requiring |K - G| <= eps^(2/3)
// therefore leaves the returned Kronrod value with an error of order eps for smooth integrands,
// while a tighter request could not be met: Boost floors each local estimate at 2 eps |K|.
// For integrands with endpoint singularities the Kronrod error is of the order of |K - G| itself,
// so the guarantee is only the tolerance; such integrals should be transformed first.
#pragma once

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <cmath>
#include <limits>
#include <sstream>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/errors.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll {

/// Adaptive Gauss-Kronrod rule (Points = 15, 21, 31, 41, 51 or 61) with at most MaxDepth
/// bisection levels; satisfies QuadratureRule<AdaptiveGaussKronrod<Real>, Real>.
/// Infinite limits are mapped to finite ones as in Boost's gauss_kronrod.
template <RealScalar Real, unsigned Points = 31, unsigned MaxDepth = 15>
struct AdaptiveGaussKronrod {
  /// The scalar.
  using value_type = Real;
  /// The Kronrod rule's points.
  static constexpr unsigned points = Points;
  /// The largest number of bisection levels.
  static constexpr unsigned max_depth = MaxDepth;

  /// Relative tolerance eps^(2/3) on the Kronrod-Gauss error estimate, relative to the L1 norm
  /// of the integrand: about 2.4e-5 (float), 3.7e-11 (double), 2.3e-13 (x87 long double).
  static Real tolerance() {
    using std::cbrt;
    static const Real tol = [] {
      const Real c = cbrt(std::numeric_limits<Real>::epsilon());
      return c * c;
    }();
    return tol;
  }

  /// Integral of f over [a, b] (either limit may be infinite). a > b gives the negated integral
  /// over [b, a], a == b gives 0. Throws ConvergenceError when the error estimate after MaxDepth
  /// levels exceeds tolerance() times the L1 norm of f, or when the result is not finite;
  /// std::invalid_argument when a limit is NaN.
  template <class F>
  static Real integrate(F f, Real a, Real b) {
    detail::require(!(boost::math::isnan)(a), "AdaptiveGaussKronrod::integrate: a", a, "a not NaN");
    detail::require(!(boost::math::isnan)(b), "AdaptiveGaussKronrod::integrate: b", b, "b not NaN");
    if (a == b) return Real(0);
    if (b < a) return -integrate(f, b, a);
    Real error = 0;
    Real l1 = 0;
    const Real result =
        static_cast<Real>(boost::math::quadrature::gauss_kronrod<Real, Points>::integrate(
            f, a, b, MaxDepth, tolerance(), &error, &l1));
    if (!(error <= tolerance() * l1) || !(boost::math::isfinite)(result)) {
      std::ostringstream out;
      out << "adaptive Gauss-Kronrod (" << Points << " points, depth " << MaxDepth
          << ") did not converge on [" << detail::format_value(a) << ", " << detail::format_value(b)
          << "]: error estimate " << detail::format_value(error) << " exceeds tolerance "
          << detail::format_value(tolerance()) << " x L1 norm " << detail::format_value(l1)
          << " (result " << detail::format_value(result) << ")";
      throw ConvergenceError(out.str());
    }
    return result;
  }
};

}  // namespace viscoroll
