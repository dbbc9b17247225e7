// viscoroll: a linear elastic half space, the material for which every viscoelastic term of
// Panek & Kalker (1980) compiles away (f = 0 in Eq. 1).
#pragma once

#include <array>
#include <boost/math/constants/constants.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll {

/// Linear elastic half space of shear modulus mu and Poisson's ratio nu.
template <RealScalar Real>
class Elastic {
 public:
  /// The scalar.
  using real_type = Real;
  /// False: every viscoelastic term compiles away.
  static constexpr bool is_viscoelastic = false;
  /// No memory term.
  static constexpr int memory_term_count = 0;

  /// Throws std::invalid_argument unless mu > 0 and -1 < nu <= 0.5, both finite.
  Elastic(Real mu, Real nu) : mu_(mu), nu_(nu) {
    detail::require_positive("mu", mu);
    detail::require_poisson_ratio(nu);
  }

  /// mu, the shear modulus (mu_D of the ConstitutiveModel interface).
  Real mu_d() const { return mu_; }
  /// nu, Poisson's ratio.
  Real nu() const { return nu_; }
  /// f = 0: no creep.
  Real creep_ratio() const { return Real(0); }
  /// tau = 0: no memory.
  Real relaxation_time() const { return Real(0); }
  /// No time to scale: the same solid (the TimeScalable concept behind at_temperature).
  Elastic time_scaled(Real /*a*/) const { return *this; }
  /// No memory: the empty spectrum.
  std::array<PronyTerm<Real>, 0> memory_terms() const { return {}; }

  /// (1 - nu) / (2 pi mu): the factor of the Boussinesq equation (3).
  Real instantaneous_compliance() const {
    return (1 - nu_) / (2 * boost::math::constants::pi<Real>() * mu_);
  }
  /// The instantaneous compliance: an elastic body does not creep.
  Real long_term_compliance() const { return instantaneous_compliance(); }

 private:
  Real mu_, nu_;
};

}  // namespace viscoroll
