// viscoroll: a generalised Maxwell (Prony series) half space, the multi-time generalisation of
// the standard linear solid of Panek & Kalker (1980), Eq. (1).
//
// Creep in shear under a constant stress sigma applied at t = 0:
//   e(t) = sigma / mu_D [1 + sum_k f_k (1 - exp(-t / tau_k))] H(t)                 (docs/bem.md,
//   (B9))
// Hunter's steady-state superposition that gives Eq. (2) applies term by term, so the moving-frame
// displacement is u = u_e + sum_k f_k int_0^inf e^(-eta) u_e(x + V tau_k eta, y) d eta (B10).
// One term (f_1, tau_1) is the standard linear solid (f, tau).
//
// The model provides memory_terms() (the list of (f_k, tau_k)) instead of the single
// relaxation_time() of a ConstitutiveModel, so the single-time solvers (plane, line) reject it at
// compile time rather than silently approximating it; the boundary-element solver accepts both
// (concept MemoryModel below).
#pragma once

#include <boost/math/constants/constants.hpp>
#include <concepts>
#include <string>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll {

/// One term of a Prony series: creep ratio f_k and retardation time tau_k (Eq. B9).
template <RealScalar Real>
struct PronyTerm {
  Real f;
  Real tau;
};

/// A material whose creep function is a Prony series: it provides
///   - `typename M::real_type`, a RealScalar; `static constexpr bool is_viscoelastic`;
///   - `real_type instantaneous_compliance() const`: (1 - nu) / (2 pi mu_D);
///   - `real_type creep_ratio() const`: sum_k f_k (the long-term compliance is 1 + that times the
///     instantaneous one);
///   - `memory_terms() const`: a range of PronyTerm<real_type>.
template <class M>
concept PronySeriesModel = RealScalar<typename M::real_type> && requires(const M& m) {
  { M::is_viscoelastic } -> std::convertible_to<bool>;
  { m.instantaneous_compliance() } -> std::same_as<typename M::real_type>;
  { m.creep_ratio() } -> std::same_as<typename M::real_type>;
  { m.memory_terms()[0] } -> std::convertible_to<PronyTerm<typename M::real_type>>;
};

/// Generalised Maxwell solid: instantaneous shear modulus mu_d, Poisson's ratio nu (constant),
/// creep terms (f_k >= 0, tau_k >= 0) of Eq. (B9).
template <RealScalar Real>
class GeneralizedMaxwell {
 public:
  using real_type = Real;
  static constexpr bool is_viscoelastic = true;

  /// Throws std::invalid_argument unless mu_d > 0, -1 < nu <= 0.5, every f_k >= 0 and
  /// tau_k >= 0, all finite (the parameter is named with its index, "f[2]").
  GeneralizedMaxwell(Real mu_d, Real nu, std::vector<PronyTerm<Real>> terms)
      : mu_d_(mu_d), nu_(nu), terms_(std::move(terms)) {
    detail::require_positive("mu_d", mu_d);
    detail::require_poisson_ratio(nu);
    for (std::size_t k = 0; k < terms_.size(); ++k) {
      detail::require_non_negative("f[" + std::to_string(k) + "]", terms_[k].f);
      detail::require_non_negative("tau[" + std::to_string(k) + "]", terms_[k].tau);
    }
  }

  Real mu_d() const { return mu_d_; }
  Real nu() const { return nu_; }
  const std::vector<PronyTerm<Real>>& memory_terms() const { return terms_; }

  /// sum_k f_k: the long-term compliance is (1 + sum f_k) times the instantaneous one.
  Real creep_ratio() const {
    Real s = 0;
    for (const auto& t : terms_) s += t.f;
    return s;
  }

  /// (1 - nu) / (2 pi mu_D): the factor of Eq. (3).
  Real instantaneous_compliance() const {
    return (1 - nu_) / (2 * boost::math::constants::pi<Real>() * mu_d_);
  }
  Real long_term_compliance() const { return (1 + creep_ratio()) * instantaneous_compliance(); }

  /// Eq. (B9): the creep function times mu_D, 1 + sum_k f_k (1 - exp(-t/tau_k)), t >= 0.
  Real creep(Real t) const {
    using std::exp;
    Real s = 1;
    for (const auto& term : terms_) s += term.tau > 0 ? term.f * (1 - exp(-t / term.tau)) : term.f;
    return s;
  }

 private:
  Real mu_d_, nu_;
  std::vector<PronyTerm<Real>> terms_;
};

}  // namespace viscoroll
