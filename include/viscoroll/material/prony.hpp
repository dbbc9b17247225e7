// viscoroll: a linear viscoelastic solid with a discrete spectrum (Prony series), in its
// relaxation and its creep form, and the exact conversion between them (docs/theory.md,
// section 11; docs/materials.md).
//
// Relaxation form (R1): G(t) = G_inf + sum_i g_i exp(-t / rho_i),  G_inf > 0, g_i >= 0, rho_i > 0.
// Creep form (R2):      J(t) = J_g [1 + sum_k f_k (1 - exp(-t / tau_k))],  J_g = 1 / G_g,
//                       G_g = G_inf + sum_i g_i (the glassy modulus, mu_D of Eq. 1).
// One creep term (f, tau) is the standard linear solid of Eq. (1); its relaxation form is
// G_inf = mu_D / (1 + f), g = mu_D f / (1 + f), rho = tau / (1 + f) (R6a).
// Poisson's ratio nu is constant. The solvers use the creep form (the memory terms of Hunter's
// superposition, docs/bem.md (B9), (B10)): both classes model ConstitutiveModel with a run-time
// spectrum (PronySeriesModel).
#pragma once

#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/material/detail/prony_spectrum.hpp>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>

namespace viscoroll {

/// One term of the relaxation form (R1): modulus g_i (Pa) and relaxation time rho_i (s).
template <RealScalar Real>
struct RelaxationTerm {
  /// g_i, the term's modulus (Pa), >= 0.
  Real g;
  /// rho_i, its relaxation time (s), > 0.
  Real rho;
};

/// A ConstitutiveModel whose spectrum is a run-time list of terms (PronyCreep, PronyRelaxation).
template <class M>
concept PronySeriesModel = ConstitutiveModel<M> && M::memory_term_count == dynamic_memory_terms;

namespace detail {
template <class Real>
Real sum_creep_ratios(const std::vector<PronyTerm<Real>>& terms) {
  Real s = 0;  // non-negative terms: no cancellation
  for (const auto& t : terms) s += t.f;
  return s;
}
/// (R10): the factors (u^2 / (1 + u^2), u / (1 + u^2)) of one term at u = omega rho, written so
/// that neither overflows for u up to the largest finite value.
template <class Real>
std::pair<Real, Real> maxwell_factors(Real u) {
  if (u <= 1) return {u * u / (1 + u * u), u / (1 + u * u)};
  const Real v = 1 / u;
  return {1 / (1 + v * v), v / (1 + v * v)};
}
}  // namespace detail

template <RealScalar Real>
class PronyRelaxation;

/// The creep (retardation) form (R2): glassy shear modulus mu_d = G_g = 1 / J_g, Poisson's ratio
/// nu, terms (f_k >= 0, tau_k >= 0). `GeneralizedMaxwell` is this class.
template <RealScalar Real>
class PronyCreep {
 public:
  /// The scalar.
  using real_type = Real;
  /// True: the solvers keep the viscoelastic terms.
  static constexpr bool is_viscoelastic = true;
  /// A run-time number of memory terms.
  static constexpr int memory_term_count = dynamic_memory_terms;

  /// Throws std::invalid_argument unless mu_d > 0, -1 < nu <= 0.5, every f_k >= 0 and
  /// tau_k >= 0, all finite (the parameter is named with its index, "f[2]").
  PronyCreep(Real mu_d, Real nu, std::vector<PronyTerm<Real>> terms)
      : mu_d_(mu_d), nu_(nu), terms_(std::move(terms)) {
    detail::require_positive("mu_d", mu_d);
    detail::require_poisson_ratio(nu);
    for (std::size_t k = 0; k < terms_.size(); ++k) {
      detail::require_non_negative("f[" + std::to_string(k) + "]", terms_[k].f);
      detail::require_non_negative("tau[" + std::to_string(k) + "]", terms_[k].tau);
    }
    detail::require_finite("sum of f", creep_ratio(), "sum of f finite");
  }

  /// mu_D = G_g, the glassy shear modulus.
  Real mu_d() const { return mu_d_; }
  /// nu, Poisson's ratio.
  Real nu() const { return nu_; }
  /// The terms as given (not sorted, not merged).
  const std::vector<PronyTerm<Real>>& memory_terms() const { return terms_; }
  /// The same terms as memory_terms().
  const std::vector<PronyTerm<Real>>& terms() const { return terms_; }
  /// The material with every retardation time times `a` (> 0): (R13), the TimeScalable concept
  /// behind at_temperature.
  PronyCreep time_scaled(Real a) const {
    std::vector<PronyTerm<Real>> scaled = terms_;
    for (auto& t : scaled) t.tau *= a;
    return PronyCreep(mu_d_, nu_, std::move(scaled));
  }

  /// sum_k f_k: the long-term compliance is (1 + sum f_k) times the instantaneous one (R6b).
  Real creep_ratio() const { return detail::sum_creep_ratios(terms_); }

  /// (1 - nu) / (2 pi mu_D): the factor of Eq. (3).
  Real instantaneous_compliance() const {
    return (1 - nu_) / (2 * boost::math::constants::pi<Real>() * mu_d_);
  }
  /// (1 + sum f_k) (1 - nu) / (2 pi mu_D), the compliance under a load held for long (R6b).
  Real long_term_compliance() const { return (1 + creep_ratio()) * instantaneous_compliance(); }
  /// G_inf = mu_d / (1 + sum f_k) (R6b).
  Real long_term_modulus() const { return mu_d_ / (1 + creep_ratio()); }

  /// (R2) times mu_D: 1 + sum_k f_k (1 - exp(-t/tau_k)), t >= 0 (1 - exp by expm1: no
  /// cancellation at t << tau_k). Named `creep` as in docs/bem.md (B9).
  Real creep(Real t) const {
    using std::expm1;
    Real s = 1;
    for (const auto& term : terms_) s += term.tau > 0 ? term.f * -expm1(-t / term.tau) : term.f;
    return s;
  }
  /// (R2): the shear creep compliance J(t) (1/Pa).
  Real creep_compliance(Real t) const { return creep(t) / mu_d_; }

  /// The relaxation form (R7), (R8): zeros of Psi interlacing the retardation times, weights from
  /// the residues. Terms with f_k = 0 are dropped, equal tau_k merged (their f add); a term with
  /// tau_k = 0 is an instantaneous compliance and is folded into the glassy modulus
  /// (mu_d / (1 + f_k), the other f scaled by 1 / (1 + f_k)). The result's terms are sorted by
  /// time.
  PronyRelaxation<Real> to_relaxation() const;

 private:
  Real mu_d_, nu_;
  std::vector<PronyTerm<Real>> terms_;
};

/// The relaxation form (R1): long-term shear modulus g_inf = G_inf > 0 (a solid: rolling needs
/// it), Poisson's ratio nu, terms (g_i >= 0, rho_i > 0). It models ConstitutiveModel through its
/// creep form, computed on construction ((R4), (R5)): memory_terms() are the retardation terms.
template <RealScalar Real>
class PronyRelaxation {
 public:
  /// The scalar.
  using real_type = Real;
  /// True: the solvers keep the viscoelastic terms.
  static constexpr bool is_viscoelastic = true;
  /// A run-time number of memory terms.
  static constexpr int memory_term_count = dynamic_memory_terms;

  /// Throws std::invalid_argument unless g_inf > 0, -1 < nu <= 0.5, every g_i >= 0 and
  /// rho_i > 0, all finite (named with the index, "g[3]", "rho[0]").
  PronyRelaxation(Real g_inf, Real nu, std::vector<RelaxationTerm<Real>> terms)
      : g_inf_(g_inf), nu_(nu), terms_(std::move(terms)) {
    detail::require_positive("g_inf", g_inf);
    detail::require_poisson_ratio(nu);
    Real gg = g_inf_;
    for (std::size_t i = 0; i < terms_.size(); ++i) {
      detail::require_non_negative("g[" + std::to_string(i) + "]", terms_[i].g);
      detail::require_positive("rho[" + std::to_string(i) + "]", terms_[i].rho);
      gg += terms_[i].g;
    }
    detail::require_finite("glassy modulus g_inf + sum g", gg, "g_inf + sum g finite");
    glassy_ = gg;
    std::vector<detail::SpectrumTerm<Real>> s;
    s.reserve(terms_.size());
    for (const auto& t : terms_) s.push_back({t.g, t.rho});
    for (const auto& t :
         detail::convert_spectrum(detail::merge_spectrum(std::move(s)),
                                  detail::SpectrumDirection::relaxation_to_creep, g_inf_, glassy_))
      creep_terms_.push_back(PronyTerm<Real>{t.w, t.q});
  }

  /// G_inf, the long-term (rubbery) shear modulus.
  Real g_inf() const { return g_inf_; }
  /// nu, Poisson's ratio.
  Real nu() const { return nu_; }
  /// The relaxation terms as given (not sorted, not merged).
  const std::vector<RelaxationTerm<Real>>& terms() const { return terms_; }
  /// The material with every relaxation time times `a` (> 0): (R13), the TimeScalable concept
  /// behind at_temperature.
  PronyRelaxation time_scaled(Real a) const {
    std::vector<RelaxationTerm<Real>> scaled = terms_;
    for (auto& t : scaled) t.rho *= a;
    return PronyRelaxation(g_inf_, nu_, std::move(scaled));
  }
  /// G_g = G_inf + sum g_i, the instantaneous modulus (mu_D of Eq. 1).
  Real glassy_modulus() const { return glassy_; }
  /// mu_D = G_g, the glassy modulus (as glassy_modulus()).
  Real mu_d() const { return glassy_; }

  /// (R1): G(t) (Pa), t >= 0. Every term is positive: no cancellation.
  Real relaxation(Real t) const {
    using std::exp;
    Real s = g_inf_;
    for (const auto& term : terms_) s += term.g * exp(-t / term.rho);
    return s;
  }
  /// (R10): storage modulus G'(omega) = G_inf + sum g_i (w rho_i)^2 / (1 + (w rho_i)^2), omega in
  /// rad/s.
  Real storage_modulus(Real omega) const {
    Real s = g_inf_;
    for (const auto& term : terms_) s += term.g * detail::maxwell_factors(omega * term.rho).first;
    return s;
  }
  /// (R10): loss modulus G''(omega) = sum g_i w rho_i / (1 + (w rho_i)^2), omega in rad/s.
  Real loss_modulus(Real omega) const {
    Real s = 0;
    for (const auto& term : terms_) s += term.g * detail::maxwell_factors(omega * term.rho).second;
    return s;
  }

  /// The creep form (R4), (R5): zeros of Phi interlacing the relaxation times (R6), weights from
  /// the residues; terms with g_i = 0 dropped, equal rho_i merged; sorted by time.
  PronyCreep<Real> to_creep() const { return PronyCreep<Real>(glassy_, nu_, creep_terms_); }

  // ConstitutiveModel, through the creep form.
  /// The creep form's terms (f_k, tau_k), sorted by time.
  const std::vector<PronyTerm<Real>>& memory_terms() const { return creep_terms_; }
  /// sum_k f_k of the creep form: G_g / G_inf - 1.
  Real creep_ratio() const { return detail::sum_creep_ratios(creep_terms_); }
  /// (1 - nu) / (2 pi G_g): the factor of Eq. (3).
  Real instantaneous_compliance() const {
    return (1 - nu_) / (2 * boost::math::constants::pi<Real>() * glassy_);
  }
  /// (1 - nu) / (2 pi G_inf) (R6b).
  Real long_term_compliance() const {
    return (1 - nu_) / (2 * boost::math::constants::pi<Real>() * g_inf_);
  }

 private:
  Real g_inf_, nu_;
  std::vector<RelaxationTerm<Real>> terms_;
  Real glassy_{};
  std::vector<PronyTerm<Real>> creep_terms_;
};

template <RealScalar Real>
PronyRelaxation<Real> PronyCreep<Real>::to_relaxation() const {
  Real instantaneous = 0;  // sum of the f_k with tau_k = 0
  std::vector<detail::SpectrumTerm<Real>> s;
  for (const auto& t : terms_) {
    if (t.tau > 0)
      s.push_back({t.f, t.tau});
    else
      instantaneous += t.f;
  }
  const Real glassy = mu_d_ / (1 + instantaneous);
  if (instantaneous > 0)
    for (auto& t : s) t.w /= 1 + instantaneous;
  s = detail::merge_spectrum(std::move(s));
  Real sum_f = 0;
  for (const auto& t : s) sum_f += t.w;
  // (R8): G_inf = G_g / (1 + sum f_k); the converter does not use it for creep -> relaxation.
  const Real g_inf = glassy / (1 + sum_f);
  std::vector<RelaxationTerm<Real>> out;
  for (const auto& t :
       detail::convert_spectrum(s, detail::SpectrumDirection::creep_to_relaxation, g_inf, glassy))
    out.push_back(RelaxationTerm<Real>{t.w, t.q});
  return PronyRelaxation<Real>(g_inf, nu_, std::move(out));
}

/// The standard linear solid of Eq. (1) as a one-term creep series (f, tau); no term if f = 0.
template <RealScalar Real>
PronyCreep<Real> as_prony(const StandardLinearSolid<Real>& m) {
  std::vector<PronyTerm<Real>> terms;
  if (m.creep_ratio() > 0) terms.push_back({m.creep_ratio(), m.relaxation_time()});
  return PronyCreep<Real>(m.mu_d(), m.nu(), std::move(terms));
}

/// An elastic solid as the empty creep series.
template <RealScalar Real>
PronyCreep<Real> as_prony(const Elastic<Real>& m) {
  return PronyCreep<Real>(m.mu_d(), m.nu(), {});
}

}  // namespace viscoroll
