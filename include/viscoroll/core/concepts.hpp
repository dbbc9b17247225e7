// viscoroll: the policy concepts every solver is composed from, in one place.
//
// Each solver is a class template Solver<Real, Material, Quadrature> (PlaneSolver, LineSolver,
// BemSolver): a scalar, a constitutive-model policy and a quadrature-rule policy, in that order.
// The concepts here state what each policy must provide, member by member; they are checked where
// a solver is instantiated, so a policy that lacks a member, or a combination that cannot work,
// is rejected with a message naming the concept. The scalar may be deduced from the material:
// `LineSolver solver(StandardLinearSolid<double>(...))` is a LineSolver<double, ...>.
#pragma once

#include <concepts>
#include <cstddef>
#include <limits>

namespace viscoroll {

/// A real scalar: float, double, long double or a boost::multiprecision floating type.
/// Constrained through std::numeric_limits, not std::floating_point, so that class types with a
/// numeric_limits specialisation qualify.
template <class T>
concept RealScalar =
    std::numeric_limits<T>::is_specialized && !std::numeric_limits<T>::is_integer &&
    requires(T a, T b) {
  { a + b } -> std::convertible_to<T>;
  { a - b } -> std::convertible_to<T>;
  { a* b } -> std::convertible_to<T>;
  { a / b } -> std::convertible_to<T>;
  { a < b } -> std::convertible_to<bool>;
};

/// One memory term of a solid's creep function: creep ratio f_k and retardation time tau_k of
///   J(t) = J_g [1 + sum_k f_k (1 - exp(-t / tau_k))]       (Eq. 1 for one term; theory.md (R2)).
/// At rolling speed V the term acts over the memory length V tau_k (Hunter's Eq. 2).
template <RealScalar Real>
struct PronyTerm {
  Real f;    ///< creep ratio f_k >= 0 (dimensionless)
  Real tau;  ///< retardation time tau_k >= 0
};

/// The value of `memory_term_count` of a material whose number of terms is known at run time only.
inline constexpr int dynamic_memory_terms = -1;

/// Constitutive-model policy: the half space's material, described by what the memory terms of
/// Hunter's superposition (Eq. 2) need, its instantaneous compliance and its discrete creep
/// (retardation) spectrum.
///
/// A model M provides
///   - `typename M::real_type`, a RealScalar;
///   - `static constexpr bool is_viscoelastic`: false lets every viscoelastic term (Bessel,
///     Struve and exponential work) compile away through `if constexpr`;
///   - `static constexpr int memory_term_count`: the number of memory terms when it is fixed at
///     compile time (Elastic: 0, StandardLinearSolid: 1), else `dynamic_memory_terms`;
///   - `real_type instantaneous_compliance() const`: (1 - nu) / (2 pi mu_D), the factor of the
///     Boussinesq equation (3) and of the pseudo-load (7), with mu_D the instantaneous modulus;
///   - `real_type creep_ratio() const`: sum_k f_k (f of Eq. 1 for one term; 0 for an elastic
///     model): the long-term compliance is (1 + creep_ratio()) times the instantaneous one;
///   - `memory_terms() const`: a sized, indexable range of PronyTerm<real_type>, the spectrum
///     (a std::array of memory_term_count terms when that is fixed, else a std::vector).
///
/// Models: Elastic, StandardLinearSolid (Eq. 1), PronyCreep (= GeneralizedMaxwell) and
/// PronyRelaxation (theory.md section 11), each at a temperature through at_temperature.
template <class M>
concept ConstitutiveModel = RealScalar<typename M::real_type> && requires(const M& m) {
  { M::is_viscoelastic } -> std::convertible_to<bool>;
  { M::memory_term_count } -> std::convertible_to<int>;
  { m.instantaneous_compliance() } -> std::same_as<typename M::real_type>;
  { m.creep_ratio() } -> std::same_as<typename M::real_type>;
  { m.memory_terms().size() } -> std::convertible_to<std::size_t>;
  { m.memory_terms()[0] } -> std::convertible_to<PronyTerm<typename M::real_type>>;
};

/// A constitutive model with at most one memory term, fixed at compile time (Elastic,
/// StandardLinearSolid): the plane solver's closed forms (P4)-(P7) and the paper's line theory
/// (Sections 5-7) are written for the single relaxation time of Eq. (1). A material with a
/// spectrum of several times (PronyCreep, PronyRelaxation) takes the generalisations of
/// docs/theory.md sections 12 and 14 in the plane and the line solver.
template <class M>
concept SingleTimeModel = ConstitutiveModel<M> &&
    (M::memory_term_count == 0 || M::memory_term_count == 1);

/// Quadrature policy: a stateless rule over Real, as Boost's gauss<Real, N>.
///
/// A rule Q provides `static Real integrate(F f, Real a, Real b)` for any callable F : Real ->
/// Real, approximating the integral of f over [a, b] (a may exceed b). Fixed rules are exact for
/// polynomials up to their degree; adaptive rules meet their documented tolerance or say so.
/// Models: GaussLegendre<Real, N>, AdaptiveGaussKronrod<Real, ...>.
template <class Q, class Real>
concept QuadratureRule = RealScalar<Real> && requires(Real a, Real b) {
  {
    Q::integrate([](Real x) { return x; }, a, b)
    } -> std::convertible_to<Real>;
};

/// A fixed quadrature rule that exposes its nodes and weights on [-1, 1], for solvers that
/// evaluate several kernels on one set of nodes (the line solver's graded panels, the BEM's
/// memory panels). A rule Q provides, besides `integrate`,
///   - `static constexpr int points`: the number of nodes;
///   - `Q::nodes()[i]`, `Q::weights()[i]`, i < points: the nodes on [-1, 1] and their weights.
/// Model: GaussLegendre<Real, N>. AdaptiveGaussKronrod is not one (it chooses its nodes per
/// integrand), so the line solver and the BEM reject it with this concept's name.
template <class Q, class Real>
concept NodalQuadratureRule = QuadratureRule<Q, Real> && requires {
  { Q::nodes()[0] } -> std::convertible_to<Real>;
  { Q::weights()[0] } -> std::convertible_to<Real>;
  { Q::points } -> std::convertible_to<int>;
};

/// What a substrate's surface response is made of, which decides how a solver represents it.
enum class SubstrateKind {
  half_space,  ///< the homogeneous half space: surface_factor is 1 at every q
  body,        ///< an elastic body whose surface_factor tends to 1 as q -> inf (a layer)
  local,       ///< a local (Winkler) bed: surface_factor is q times a constant length
};

/// Substrate policy: the body the roller presses, described by its surface response relative to
/// the half space's of the same material (docs/theory.md section 19). With Poisson's ratio
/// constant in time, a pressure p cos(q x) on the surface deflects it by
///   w = (1 - nu)/(mu |q|) T(|q|) p                                              (H1)
/// at every instant, with T of the geometry alone, so the material's memory (Eq. 2) and the body
/// separate: the solvers apply the material's creep to the substrate's elastic kernel.
///
/// A substrate S provides
///   - `typename S::real_type`, a RealScalar;
///   - `static constexpr SubstrateKind kind`;
///   - `real_type surface_factor(real_type q, real_type nu) const`: T(q) at the wavenumber
///     q >= 0 (1/length) for Poisson's ratio nu. For a `body`, T(q) - 1 must decay at least as
///     fast as exp(-q thickness()) as q -> inf, and T(0) >= 0 is the ratio of its long-wave
///     compliance to the half space's (0 on a rigid base); for a `local` bed T(q) = q l with
///     a constant l >= 0;
///   - `real_type thickness() const`: the length over which the body differs from a half space
///     (its layer's thickness; ignored for the half space), > 0 for a body or a bed.
///
/// Models: HalfSpace, Layer (bonded or frictionless on a rigid base), SpringBed
/// (substrate/substrate.hpp); a user's own body is one class with these members
/// (tests/seams/user_substrate.test.cpp).
template <class S>
concept Substrate = RealScalar<typename S::real_type> &&
    requires(const S& s, typename S::real_type q) {
  { S::kind } -> std::convertible_to<SubstrateKind>;
  { s.surface_factor(q, q) } -> std::convertible_to<typename S::real_type>;
  { s.thickness() } -> std::convertible_to<typename S::real_type>;
};

namespace detail {
/// The one memory term (f, tau) of a SingleTimeModel, or (0, 0) for a model without one.
template <SingleTimeModel M>
PronyTerm<typename M::real_type> single_memory_term(const M& m) {
  using Real = typename M::real_type;
  if constexpr (M::memory_term_count == 0) {
    return PronyTerm<Real>{Real(0), Real(0)};
  } else {
    return m.memory_terms()[0];
  }
}
}  // namespace detail

}  // namespace viscoroll
