// viscoroll: N-point Gauss-Legendre quadrature for any N >= 1 and any real scalar.
//
// The nodes are the zeros of the Legendre polynomial P_N and the weights are
//   w_j = 2 / ((1 - x_j^2) P_N'(x_j)^2)                                    A&S 25.4.29
// P_N is evaluated by the three-term recurrence
//   (k + 1) P_{k+1}(x) = (2k + 1) x P_k(x) - k P_{k-1}(x)                   A&S 22.7.10
// and each zero is polished by Newton's method from Tricomi's asymptotic estimate
//   x_k ~ (1 - 1/(8N^2) + 1/(8N^3)) cos(pi (4k - 1) / (4N + 2))
// (F. G. Tricomi 1950; N. Hale & A. Townsend, SIAM J. Sci. Comput. 35 (2013) A652).
// Zeros above 1/2 are iterated for y = 1 - x with the recurrence rewritten in differences, so that
// 1 - |x_j| (complements()) keeps full relative precision near the ends of the interval.
// The rule is computed once per (Real, N), on first use, in a function-local static (thread-safe
// by C++ static initialisation). For float and double the work is done in long double and
// rounded, so that each node and weight is within about half an ulp of its exact value.
#pragma once

#include <array>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <limits>
#include <type_traits>
#include <viscoroll/core/concepts.hpp>

namespace viscoroll {

namespace detail {

/// The type in which rules and tables for Real are computed before rounding to Real: long double
/// for built-in types it is wider than, Real itself otherwise (boost::multiprecision types).
template <class Real>
using wider_real_t =
    std::conditional_t<std::is_floating_point_v<Real> && (std::numeric_limits<long double>::digits >
                                                          std::numeric_limits<Real>::digits),
                       long double, Real>;

template <class Real, int N>
struct GaussLegendreRule {
  std::array<Real, N> nodes;        // ascending on [-1, 1], exactly antisymmetric
  std::array<Real, N> weights;      // symmetric, summing to 2
  std::array<Real, N> complements;  // 1 - |nodes[j]| to full relative precision
};

/// P_N(x) and P_N'(x) by the recurrence A&S 22.7.10 and the derivative identity A&S 22.8.5,
/// (1 - x^2) P_N' = N (P_{N-1} - x P_N).
template <class W>
void legendre_and_derivative(int n, const W& x, W& p, W& dp) {
  W p_prev = 1;
  p = x;
  for (int k = 1; k < n; ++k) {
    W p_next = (W(2 * k + 1) * x * p - W(k) * p_prev) / W(k + 1);
    p_prev = p;
    p = p_next;
  }
  dp = W(n) * (p_prev - x * p) / (1 - x * x);
}

/// P_N(1 - y) and P_N'(1 - y) for small y, carried as differences D_k = P_k - P_{k-1}:
///   D_{k+1} = (k D_k - (2k + 1) y P_k) / (k + 1)
/// (A&S 22.7.10 with x = 1 - y, rearranged so that no O(1) terms cancel). A zero y_j found from
/// this form has full relative precision, which 1 - x_j, rounded from x_j near 1, has not.
template <class W>
void legendre_and_derivative_near_one(int n, const W& y, W& p, W& dp) {
  W d = -y;
  p = 1 - y;
  for (int k = 1; k < n; ++k) {
    d = (W(k) * d - W(2 * k + 1) * y * p) / W(k + 1);
    p += d;
  }
  dp = W(n) * (y * p - d) / (y * (2 - y));  // A&S 22.8.5 with P_{N-1} - x P_N = y P_N - D_N
}

template <class Real, int N>
GaussLegendreRule<Real, N> compute_gauss_legendre() {
  using W = wider_real_t<Real>;
  using std::abs;
  using std::cos;
  const W pi = boost::math::constants::pi<W>();
  const W eps = std::numeric_limits<W>::epsilon();
  const W n = W(N);
  GaussLegendreRule<Real, N> rule{};
  for (int k = 1; k <= N / 2; ++k) {
    // Tricomi's estimate of the k-th largest zero.
    const W guess =
        (1 - 1 / (8 * n * n) + 1 / (8 * n * n * n)) * cos(pi * W(4 * k - 1) / W(4 * N + 2));
    // Zeros above 1/2 are found as y = 1 - x, the others as x. Newton converges quadratically;
    // iterate until the step is at rounding level, then once more from the converged iterate.
    const bool near_one = guess > W(0.5);
    W z = near_one ? W(1 - guess) : guess;
    W p, dp;
    bool converged = false;
    for (int iteration = 0; iteration < 100; ++iteration) {
      if (near_one)
        legendre_and_derivative_near_one(N, z, p, dp);
      else
        legendre_and_derivative(N, z, p, dp);
      const W step = near_one ? W(-p / dp) : W(p / dp);
      z -= step;
      if (converged) break;
      if (abs(step) <= 2 * eps * abs(z)) converged = true;
    }
    const W x = near_one ? W(1 - z) : z;
    const W y = near_one ? z : W(1 - z);
    if (near_one)
      legendre_and_derivative_near_one(N, y, p, dp);
    else
      legendre_and_derivative(N, x, p, dp);
    const W w = 2 / (y * (2 - y) * dp * dp);  // A&S 25.4.29, 1 - x^2 = y (2 - y)
    rule.nodes[N - k] = static_cast<Real>(x);
    rule.nodes[k - 1] = -static_cast<Real>(x);
    rule.weights[N - k] = rule.weights[k - 1] = static_cast<Real>(w);
    rule.complements[N - k] = rule.complements[k - 1] = static_cast<Real>(y);
  }
  if (N % 2 == 1) {
    // The middle zero is exactly 0; P_N'(0) = N P_{N-1}(0).
    W p, dp;
    legendre_and_derivative(N, W(0), p, dp);
    rule.nodes[N / 2] = Real(0);
    rule.weights[N / 2] = static_cast<Real>(2 / (dp * dp));
    rule.complements[N / 2] = Real(1);
  }
  return rule;
}

}  // namespace detail

/// N-point Gauss-Legendre rule: exact for polynomials of degree 2N - 1 (up to rounding).
/// Stateless, as Boost's gauss<Real, N>; satisfies QuadratureRule<GaussLegendre<Real, N>, Real>.
template <RealScalar Real, int N>
requires(N >= 1) struct GaussLegendre {
  /// The scalar.
  using value_type = Real;
  /// N, the rule's points.
  static constexpr int points = N;

  /// Nodes on [-1, 1], ascending.
  static const std::array<Real, N>& nodes() { return rule().nodes; }
  /// Weights on [-1, 1]; they sum to 2.
  static const std::array<Real, N>& weights() { return rule().weights; }
  /// 1 - |nodes()[j]| to full relative precision (for rules mapped to [0, c] whose integrand is
  /// concentrated at 0, where the shifted nodes 1 + x_j would otherwise lose digits).
  static const std::array<Real, N>& complements() { return rule().complements; }

  /// Integral of f over [a, b]; a > b gives the negated integral over [b, a], a == b gives 0.
  template <class F>
  static Real integrate(F f, Real a, Real b) {
    const auto& r = rule();
    const Real half = (b - a) / 2;
    const Real mid = (a + b) / 2;
    Real sum = 0;
    for (int j = 0; j < N; ++j)
      sum += r.weights[j] * static_cast<Real>(f(Real(mid + half * r.nodes[j])));
    return sum * half;
  }

 private:
  static const detail::GaussLegendreRule<Real, N>& rule() {
    static const detail::GaussLegendreRule<Real, N> r = detail::compute_gauss_legendre<Real, N>();
    return r;
  }
};

}  // namespace viscoroll
