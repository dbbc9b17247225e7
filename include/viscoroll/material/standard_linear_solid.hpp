// viscoroll: the standard linear solid of Panek & Kalker (1980), Eq. (1).
//
// Creep in shear under a constant stress sigma applied at t = 0:
//   e(t) = sigma / mu_D [1 + f (1 - exp(-t / tau))] H(t)                       Eq. (1)
// mu_D is the instantaneous (glassy) shear modulus, f the creep ratio, tau the relaxation time;
// the long-term (rubbery) modulus is mu_D / (1 + f). Poisson's ratio nu is constant.
#pragma once

#include <array>
#include <boost/math/constants/constants.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll {

/// Standard linear solid with a single relaxation time (Eq. 1).
template <RealScalar Real>
class StandardLinearSolid {
 public:
  /// The scalar.
  using real_type = Real;
  /// True: the solvers keep the viscoelastic terms.
  static constexpr bool is_viscoelastic = true;
  /// One memory term, (f, tau).
  static constexpr int memory_term_count = 1;

  /// Throws std::invalid_argument unless mu_d > 0, -1 < nu <= 0.5, f >= 0, tau >= 0, all finite.
  StandardLinearSolid(Real mu_d, Real nu, Real f, Real tau)
      : mu_d_(mu_d), nu_(nu), f_(f), tau_(tau) {
    detail::require_positive("mu_d", mu_d);
    detail::require_poisson_ratio(nu);
    detail::require_non_negative("f", f);
    detail::require_non_negative("tau", tau);
  }

  /// mu_D, the instantaneous (glassy) shear modulus.
  Real mu_d() const { return mu_d_; }
  /// nu, Poisson's ratio.
  Real nu() const { return nu_; }
  /// f, the creep ratio: the rubbery modulus is mu_D / (1 + f).
  Real creep_ratio() const { return f_; }
  /// tau, the relaxation time of Eq. (1).
  Real relaxation_time() const { return tau_; }
  /// The solid with tau times `a` (> 0): (R13), the TimeScalable concept behind at_temperature.
  StandardLinearSolid time_scaled(Real a) const {
    return StandardLinearSolid(mu_d_, nu_, f_, tau_ * a);
  }
  /// The spectrum of Eq. (1): the one term (f, tau).
  std::array<PronyTerm<Real>, 1> memory_terms() const { return {PronyTerm<Real>{f_, tau_}}; }

  /// (1 - nu) / (2 pi mu_D): the factor of Eqs. (3) and (7).
  Real instantaneous_compliance() const {
    return (1 - nu_) / (2 * boost::math::constants::pi<Real>() * mu_d_);
  }
  /// (1 + f) (1 - nu) / (2 pi mu_D): the compliance under a load held for t >> tau.
  Real long_term_compliance() const { return (1 + f_) * instantaneous_compliance(); }

 private:
  Real mu_d_, nu_, f_, tau_;
};

}  // namespace viscoroll
