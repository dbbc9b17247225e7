// viscoroll: the policy concepts every solver is composed from.
//
// A solver is a class template Solver<Real, Material, Quadrature>. The concepts here state what
// each policy must provide; they are checked where a solver is instantiated, so a policy that
// lacks a member is rejected with a message naming the concept.
#pragma once

#include <concepts>
#include <limits>

namespace viscoroll {

/// A real scalar: float, double, long double or a boost::multiprecision floating type.
/// Constrained through std::numeric_limits, not std::floating_point, so that class types with a
/// numeric_limits specialisation qualify.
template <class T>
concept RealScalar = std::numeric_limits<T>::is_specialized && !std::numeric_limits<T>::is_integer &&
                     requires(T a, T b) {
                       { a + b } -> std::convertible_to<T>;
                       { a - b } -> std::convertible_to<T>;
                       { a * b } -> std::convertible_to<T>;
                       { a / b } -> std::convertible_to<T>;
                       { a < b } -> std::convertible_to<bool>;
                     };

/// Constitutive-model policy: the half space's material.
///
/// A model M provides
///   - `typename M::real_type`, a RealScalar;
///   - `static constexpr bool is_viscoelastic`: false lets every viscoelastic term (Bessel,
///     Struve and exponential work) compile away through `if constexpr`;
///   - `real_type instantaneous_compliance() const`: (1 - nu) / (2 pi mu_D), the factor of the
///     Boussinesq equation (3) and of the pseudo-load (7), with mu_D the instantaneous modulus;
///   - `real_type creep_ratio() const`: f of Eq. (1) (0 for an elastic model);
///   - `real_type relaxation_time() const`: tau of Eq. (1) (0 for an elastic model).
/// The long-term (rubbery) compliance is (1 + f) times the instantaneous one.
template <class M>
concept ConstitutiveModel = RealScalar<typename M::real_type> && requires(const M& m) {
  { M::is_viscoelastic } -> std::convertible_to<bool>;
  { m.instantaneous_compliance() } -> std::same_as<typename M::real_type>;
  { m.creep_ratio() } -> std::same_as<typename M::real_type>;
  { m.relaxation_time() } -> std::same_as<typename M::real_type>;
};

/// Quadrature policy: a stateless rule over Real, as Boost's gauss<Real, N>.
///
/// A rule Q provides `static Real integrate(F f, Real a, Real b)` for any callable F : Real -> Real,
/// approximating the integral of f over [a, b] (a may exceed b). Fixed rules are exact for
/// polynomials up to their degree; adaptive rules meet their documented tolerance or say so.
template <class Q, class Real>
concept QuadratureRule = RealScalar<Real> && requires(Real a, Real b) {
  { Q::integrate([](Real x) { return x; }, a, b) } -> std::convertible_to<Real>;
};


/// A fixed quadrature rule that exposes its nodes and weights on [-1, 1] (GaussLegendre<Real, N>),
/// for solvers that evaluate several kernels on one set of nodes.
template <class Q, class Real>
concept NodalQuadratureRule = QuadratureRule<Q, Real> && requires {
  { Q::nodes()[0] } -> std::convertible_to<Real>;
  { Q::weights()[0] } -> std::convertible_to<Real>;
  { Q::points } -> std::convertible_to<int>;
};

}  // namespace viscoroll
