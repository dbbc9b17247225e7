// viscoroll: the functions of the plane problem on a substrate (plane_substrate_solver.hpp,
// docs/plane-substrate.md): composite Gauss-Legendre panels, the Bessel functions J_k(x) of all
// orders up to n, the half space's log potentials (Q6) and the exponential moments of the spring
// bed's memory (Q12).
#pragma once

#include <algorithm>
#include <array>
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>
#include <viscoroll/plane/detail/memory_integrals.hpp>

namespace viscoroll::detail::plane_substrate {

/// Composite Gauss-Legendre (20 points per panel): calls g(x, w) for every node of [lo, hi].
template <class Real, class G>
void gauss_panel(Real lo, Real hi, G&& g) {
  using rule = boost::math::quadrature::gauss<Real, 20>;
  const auto& x = rule::abscissa();
  const auto& w = rule::weights();
  const Real mid = (lo + hi) / 2, half = (hi - lo) / 2;
  for (std::size_t i = 0; i < x.size(); ++i) {
    g(mid - half * x[i], half * w[i]);
    g(mid + half * x[i], half * w[i]);
  }
}

using plane_memory::memory_integrals;
using plane_memory::MemoryQuadrature;  // (Q6): plane/detail/memory_integrals.hpp
using plane_memory::tail_integrals;

/// J_k(x), k = 0..n_max, x > 0: above x = n_max + 1 by the upward recurrence from J_0 and J_1;
/// below it by Miller's backward recurrence J_{k-1} = (2k/x) J_k - J_{k+1} normalised by
/// J_0 + 2 sum_k J_2k = 1 (A&S 9.1.27, 9.1.46), started far enough above max(n_max, x) for the
/// scalar's precision.
template <class Real>
void bessel_j_sequence(Real x, int n_max, std::vector<Real>& j, std::vector<Real>& buffer) {
  using std::abs;
  using std::ceil;
  using std::sqrt;
  j.resize(static_cast<std::size_t>(n_max + 1));
  if (x > Real(n_max + 1)) {
    // Upward recurrence from J_0, J_1: stable while k < x (A&S 9.12), O(n_max) work.
    j[0] = boost::math::cyl_bessel_j(0, x);
    if (n_max >= 1) j[1] = boost::math::cyl_bessel_j(1, x);
    for (int k = 1; k < n_max; ++k)
      j[static_cast<std::size_t>(k + 1)] =
          Real(2 * k) / x * j[static_cast<std::size_t>(k)] - j[static_cast<std::size_t>(k - 1)];
    return;
  }
  const int top = std::max(n_max, static_cast<int>(ceil(x)));
  int m = top + 24 + static_cast<int>(sqrt(Real(80 * top)));
  if (m % 2 != 0) ++m;
  buffer.assign(static_cast<std::size_t>(m + 2), Real(0));
  const Real big = sqrt(std::numeric_limits<Real>::max()) / 4;
  Real next = 0,
       current = std::numeric_limits<Real>::min() * Real(1) / std::numeric_limits<Real>::epsilon();
  buffer[static_cast<std::size_t>(m)] = current;
  for (int k = m; k >= 1; --k) {
    const Real below = Real(2 * k) / x * current - next;
    next = current;
    current = below;
    buffer[static_cast<std::size_t>(k - 1)] = below;
    if (abs(below) > big) {
      for (int i = k - 1; i <= m; ++i) buffer[static_cast<std::size_t>(i)] /= big;
      next /= big;
      current /= big;
    }
  }
  Real norm = buffer[0];
  for (int k = 2; k <= m; k += 2) norm += 2 * buffer[static_cast<std::size_t>(k)];
  for (int k = 0; k <= n_max; ++k)
    j[static_cast<std::size_t>(k)] = buffer[static_cast<std::size_t>(k)] / norm;
}

/// (Q6): G_n(s) = int_{-1}^{1} sqrt(1 - t^2) U_n(t) ln|s - t| dt for |s| <= 1:
/// (pi/2)(s^2 - 1/2 - ln 2) for n = 0, (pi/2)(T_{n+2}(s)/(n+2) - T_n(s)/n) for n >= 1.
template <class Real>
std::vector<Real> log_potentials(Real phi, int n_terms) {
  using std::cos;
  using std::log;
  const Real pi = boost::math::constants::pi<Real>();
  std::vector<Real> g(static_cast<std::size_t>(n_terms));
  const Real s = cos(phi);
  g[0] = pi / 2 * (s * s - Real(0.5) - log(Real(2)));
  for (int n = 1; n < n_terms; ++n)
    g[static_cast<std::size_t>(n)] =
        pi / 2 * (cos(Real(n + 2) * phi) / Real(n + 2) - cos(Real(n) * phi) / Real(n));
  return g;
}

/// phi_j(y) = int_0^1 u^j e^{-y u} du, j = 0, 1, 2, y >= 0: the series below y = 2, above it
/// phi_0 = -expm1(-y)/y and phi_j = (j phi_{j-1} - e^-y)/y (errors damped by j/y < 1).
template <class Real>
std::array<Real, 3> exponential_moments(Real y) {
  using std::exp;
  using std::expm1;
  std::array<Real, 3> out{};
  if (y < 2) {
    for (int j = 0; j < 3; ++j) {
      Real term = 1, sum = 0;
      for (int m = 0; m < 80; ++m) {
        const Real add = term / Real(m + j + 1);
        sum += add;
        if (std::abs(static_cast<double>(add)) <=
            static_cast<double>(std::numeric_limits<Real>::epsilon()) *
                std::abs(static_cast<double>(sum)) / 4)
          break;
        term *= -y / Real(m + 1);
      }
      out[static_cast<std::size_t>(j)] = sum;
    }
    return out;
  }
  const Real e = exp(-y);
  out[0] = -expm1(-y) / y;
  out[1] = (out[0] - e) / y;
  out[2] = (2 * out[1] - e) / y;
  return out;
}

}  // namespace viscoroll::detail::plane_substrate
