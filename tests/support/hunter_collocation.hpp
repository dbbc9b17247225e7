// Independent reference solver for the plane problem: a rigid cylinder rolling on a standard
// linear solid half space (Hunter 1961), by spectral collocation of Hunter's Eq. (2).
//
// References:
//   S. C. Hunter, "The rolling contact of a rigid cylinder with a viscoelastic half space",
//     J. Appl. Mech. 28 (1961) 611-617.
//   C. Panek & J. J. Kalker, "Three-dimensional contact of a rigid roller traversing a
//     viscoelastic half space", J. Inst. Maths Applics 26 (1980), Section 2, Eq. (2).
//   Derivation, identities and the measured convergence: docs/hunter-collocation.md.
//
// Test code only. It deliberately does NOT use the pseudo-pressure formulas (7), (32)-(36) of
// Panek & Kalker, so that it can check the library's plane solver, which is built from them.
//
// Frame moving with the cylinder, which travels towards +x; contact on [b - a, b + a];
// c = (1 - nu) / (2 pi mu_D); f = creep ratio; vt = V tau. Unknowns:
//   p(b + a s) = sqrt(1 - s^2) sum_{n<N} c_n U_n(s),
// and b; collocation of u'(x) = -C1 x at the N + 1 Chebyshev points of the first kind; the
// half width a by a scalar root find on the load  W = a (pi / 2) c_0.
#ifndef VISCOROLL_TESTS_SUPPORT_HUNTER_COLLOCATION_HPP
#define VISCOROLL_TESTS_SUPPORT_HUNTER_COLLOCATION_HPP

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>
#include <viscoroll/plane/detail/memory_integrals.hpp>

namespace viscoroll::testing {

/// Result of hunter_reference(): the steady rolling solution of the plane problem.
template <class Real>
struct HunterReference {
  Real a{};               ///< contact half width
  Real b{};               ///< offset of the contact centre ahead of the cylinder axis (towards +x)
  Real chi{};             ///< rolling friction C1 int x p dx / int p dx (x from the axis)
  Real pmax{};            ///< maximum pressure
  Real pmax_x{};          ///< where the maximum is (moving frame, from the axis)
  Real load{};            ///< a (pi/2) c_0: the load the coefficients carry (= W when converged)
  int n_terms{};          ///< N, number of Chebyshev terms
  bool converged{false};  ///< root find on a bracketed and converged, LU residual small
  std::vector<Real> coeffs;  ///< c_n: p(b + a s) = sqrt(1 - s^2) sum c_n U_n(s)
  Real residual{};           ///< max |A x - r| / (|A|_inf |x|_inf + |r|_inf) of the last solve
  Real rcond{};              ///< reciprocal condition estimate of the collocation matrix
  int root_evaluations{};    ///< number of linear solves spent on the root find for a

  /// Contact pressure at x (moving frame); zero outside [b - a, b + a].
  Real pressure(Real x) const {
    const Real s = (x - b) / a;
    if (!(s > -1 && s < 1)) return Real(0);
    Real u_prev = 0, u = 1, sum = 0;  // U_{-1} = 0, U_0 = 1
    for (const Real c : coeffs) {
      sum += c * u;
      const Real next = 2 * s * u - u_prev;
      u_prev = u;
      u = next;
    }
    using std::sqrt;
    return sqrt((1 - s) * (1 + s)) * sum;
  }
};

namespace hunter_detail {

// The memory integrals are the library's (plane/detail/memory_integrals.hpp); what this file
// adds is the collocation around them, independent of Hunter's closed form.
using viscoroll::detail::plane_memory::gauss30_panels;
using viscoroll::detail::plane_memory::memory_integrals;
using viscoroll::detail::plane_memory::phase_panels;
using viscoroll::detail::plane_memory::tail_integrals;
template <class Real>
using QuadratureSettings = viscoroll::detail::plane_memory::MemoryQuadrature<Real>;

/// Dimensionless collocation solution for a given v = vt / a:
///   sum_n gamma_n M_n(s_j) - beta = s_j,   c_n = C1 a gamma_n / (2 pi c),  b = a beta.
template <class Real>
struct Dimensionless {
  std::vector<Real> gamma;
  Real beta{};
  Real residual{};
  Real rcond{};
};

/// One memory term in the collocation's units: creep ratio f and v = V tau / a.
template <class Real>
struct MemoryTerm {
  Real f, v;
};

/// Collocation matrix A (N+1 x N+1): A(j, n) = M_n(s_j) for n < N, A(j, N) = -1, with
/// M_n(s) = H_n(s) + sum_k f_k m_n(s; v_k) (one memory integral per term of the spectrum).
template <class Real>
Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic> collocation_matrix(
    const std::vector<MemoryTerm<Real>>& terms, int n_terms,
    const QuadratureSettings<Real>& q = {}) {
  using std::cos;
  const Real pi = boost::math::constants::pi<Real>();
  const int rows = n_terms + 1;
  Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic> A(rows, rows);
  std::vector<std::vector<Real>> tails(terms.size());
  for (std::size_t k = 0; k < terms.size(); ++k)
    if (terms[k].v > 0) tails[k] = tail_integrals(terms[k].v, n_terms, q);
  for (int j = 0; j < rows; ++j) {
    const Real phi = Real(2 * j + 1) * pi / Real(2 * rows);
    const Real cos_phi = cos(phi), sin_phi = sin(phi);
    std::vector<std::vector<Real>> memory(terms.size());
    for (std::size_t k = 0; k < terms.size(); ++k)
      if (terms[k].v > 0) memory[k] = memory_integrals(phi, terms[k].v, tails[k], q);
    Real t = cos_phi, t_sin = sin_phi;  // T_{n+1}(s_j) = cos((n+1) phi_j)
    for (int n = 0; n < n_terms; ++n) {
      Real entry = t;  // M_n(s_j) = H_n(s_j) + sum_k f_k m_n, H_n = T_{n+1} on [-1, 1]
      for (std::size_t k = 0; k < terms.size(); ++k) {
        // v = 0: the memory integral is int e^{-eta} d eta H_n(s) = H_n(s).
        const Real mem = terms[k].v > 0 ? memory[k][static_cast<std::size_t>(n)] : t;
        entry += terms[k].f * mem;
      }
      A(j, n) = entry;
      const Real next = t * cos_phi - t_sin * sin_phi;
      t_sin = t_sin * cos_phi + t * sin_phi;
      t = next;
    }
    A(j, n_terms) = Real(-1);  // -beta
  }
  return A;
}

/// The single-term matrix (creep ratio f, v = V tau / a).
template <class Real>
Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic> collocation_matrix(
    Real f, Real v, int n_terms, const QuadratureSettings<Real>& q = {}) {
  return collocation_matrix(std::vector<MemoryTerm<Real>>{{f, v}}, n_terms, q);
}

template <class Real>
Dimensionless<Real> solve_dimensionless(const std::vector<MemoryTerm<Real>>& terms, int n_terms,
                                        const QuadratureSettings<Real>& q = {}) {
  using std::cos;
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  const Real pi = boost::math::constants::pi<Real>();
  const int rows = n_terms + 1;
  const Matrix A = collocation_matrix(terms, n_terms, q);
  Vector rhs(rows);
  for (int j = 0; j < rows; ++j) rhs(j) = cos(Real(2 * j + 1) * pi / Real(2 * rows));
  const Eigen::PartialPivLU<Matrix> lu(A);
  const Vector x = lu.solve(rhs);
  Dimensionless<Real> out;
  out.gamma.assign(x.data(), x.data() + n_terms);
  out.beta = x(n_terms);
  const Real scale =
      A.cwiseAbs().rowwise().sum().maxCoeff() * x.cwiseAbs().maxCoeff() + rhs.cwiseAbs().maxCoeff();
  out.residual = (A * x - rhs).cwiseAbs().maxCoeff() / scale;
  out.rcond = lu.rcond();
  return out;
}

template <class Real>
Dimensionless<Real> solve_dimensionless(Real f, Real v, int n_terms,
                                        const QuadratureSettings<Real>& q = {}) {
  return solve_dimensionless(std::vector<MemoryTerm<Real>>{{f, v}}, n_terms, q);
}

/// q(s) = sum c_n U_n(s) and D(s) = (1 - s^2) q'(s) - s q(s); dp/ds = D / sqrt(1 - s^2).
template <class Real>
std::pair<Real, Real> series_and_slope(const std::vector<Real>& c, Real s) {
  Real u_prev = 0, u = 1, du_prev = 0, du = 0, q = 0, dq = 0;
  for (const Real cn : c) {
    q += cn * u;
    dq += cn * du;
    const Real next = 2 * s * u - u_prev;
    const Real dnext = 2 * u + 2 * s * du - du_prev;
    u_prev = u;
    u = next;
    du_prev = du;
    du = dnext;
  }
  return {q, (1 - s) * (1 + s) * dq - s * q};
}

}  // namespace hunter_detail

/// Reference solution of Hunter's plane problem by collocation of Eq. (2).
/// @param compliance c = (1 - nu)/(2 pi mu_D), instantaneous
/// @param f          creep ratio (long-term compliance (1 + f) c)
/// @param vt         V tau (>= 0; 0 gives the long-term elastic solution)
/// @param c1         curvature C1 of the profile S = -C1 x^2 / 2 + d
/// @param load       W, load per unit length
/// @param n_terms    N, number of Chebyshev terms of p / sqrt(1 - s^2)
/// The same for a spectrum: memory terms (f_k, V tau_k) given as {f, v} = {f_k, V tau_k}.
template <class Real>
HunterReference<Real> hunter_reference(Real compliance,
                                       const std::vector<hunter_detail::MemoryTerm<Real>>& spectrum,
                                       Real c1, Real load, int n_terms);

template <class Real>
HunterReference<Real> hunter_reference(Real compliance, Real f, Real vt, Real c1, Real load,
                                       int n_terms) {
  if (!(f >= 0) || !(vt >= 0) || !std::isfinite(static_cast<double>(f)) ||
      !std::isfinite(static_cast<double>(vt)))
    throw std::invalid_argument("hunter_reference: need c, C1, W > 0, f, V tau >= 0, N >= 2");
  return hunter_reference(compliance, std::vector<hunter_detail::MemoryTerm<Real>>{{f, vt}}, c1,
                          load, n_terms);
}

template <class Real>
HunterReference<Real> hunter_reference(Real compliance,
                                       const std::vector<hunter_detail::MemoryTerm<Real>>& spectrum,
                                       Real c1, Real load, int n_terms) {
  using std::abs;
  using std::cos;
  using std::sqrt;
  Real f = 0;  // the creep ratio of the spectrum, sum f_k
  for (const auto& t : spectrum) {
    if (!(t.f >= 0) || !(t.v >= 0) || !std::isfinite(static_cast<double>(t.f)) ||
        !std::isfinite(static_cast<double>(t.v)))
      throw std::invalid_argument("hunter_reference: need f_k, V tau_k >= 0, finite");
    f += t.f;
  }
  if (!(compliance > 0) || !(c1 > 0) || !(load > 0) || n_terms < 2)
    throw std::invalid_argument("hunter_reference: need c, C1, W > 0, f, V tau >= 0, N >= 2");
  const Real pi = boost::math::constants::pi<Real>();
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real a_long = sqrt(4 * compliance * (1 + f) * load / c1);  // long-term Hertz half width

  HunterReference<Real> out;
  out.n_terms = n_terms;
  hunter_detail::Dimensionless<Real> last;
  Real last_ratio = -1;
  // Load condition in units of the long-term Hertz load: (a/a_L)^2 (1 + f) gamma_0 - 1 = 0.
  const auto solve_at = [&](Real ratio) {
    if (ratio != last_ratio) {
      std::vector<hunter_detail::MemoryTerm<Real>> terms;
      for (const auto& t : spectrum) terms.push_back({t.f, t.v / (ratio * a_long)});
      last = hunter_detail::solve_dimensionless(terms, n_terms);
      last_ratio = ratio;
      ++out.root_evaluations;
    }
    return last;
  };
  const auto load_gap = [&](Real ratio) {
    return ratio * ratio * (1 + f) * solve_at(ratio).gamma[0] - 1;
  };

  // Bracket: between the instantaneous and the long-term Hertz half widths; widen if needed.
  Real lo = 1 / sqrt(1 + f), hi = 1;
  Real g_lo = load_gap(lo), g_hi = load_gap(hi);
  bool bracketed = g_lo <= 0 && g_hi >= 0;
  for (int k = 0; k < 20 && !bracketed; ++k) {
    if (g_lo > 0) {
      lo /= Real(1.25);
      g_lo = load_gap(lo);
    }
    if (g_hi < 0) {
      hi *= Real(1.25);
      g_hi = load_gap(hi);
    }
    bracketed = g_lo <= 0 && g_hi >= 0;
  }
  Real ratio = hi;
  bool root_ok = false;
  if (bracketed) {
    if (g_lo == 0) {
      ratio = lo;
      root_ok = true;
    } else if (g_hi == 0) {
      ratio = hi;
      root_ok = true;
    } else {
      std::uintmax_t max_iter = 200;
      const auto bracket = boost::math::tools::toms748_solve(
          load_gap, lo, hi, g_lo, g_hi,
          boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 2), max_iter);
      ratio = (bracket.first + bracket.second) / 2;
      root_ok = max_iter < 200;
    }
  }
  const auto sol = solve_at(ratio);
  const Real a = ratio * a_long;
  const Real scale = c1 * a / (2 * pi * compliance);
  out.a = a;
  out.b = sol.beta * a;
  out.coeffs.resize(sol.gamma.size());
  for (std::size_t n = 0; n < sol.gamma.size(); ++n) out.coeffs[n] = scale * sol.gamma[n];
  out.residual = sol.residual;
  out.rcond = sol.rcond;
  out.load = a * pi / 2 * out.coeffs[0];  // int sqrt(1-s^2) U_m U_n ds = (pi/2) delta_mn
  // int x p dx = b W + a^2 (pi/4) c_1, since s = U_1(s) / 2.
  const Real c_1 = out.coeffs.size() > 1 ? out.coeffs[1] : Real(0);
  out.chi = c1 * (out.b + a * a * pi / 4 * c_1 / out.load);

  // Maximum pressure: dense samples uniform in theta (s = cos theta clusters at both edges),
  // Brent on the best sample's neighbourhood, then the root of dp/ds there.
  const int samples = 8 * n_terms + 64;
  const auto p_theta = [&](Real theta) { return out.pressure(out.b + a * cos(theta)); };
  int best = 0;
  Real best_p = -std::numeric_limits<Real>::infinity();
  for (int k = 0; k < samples; ++k) {
    const Real p = p_theta((Real(k) + Real(0.5)) * pi / Real(samples));
    if (p > best_p) {
      best_p = p;
      best = k;
    }
  }
  const Real t_lo = Real(std::max(0, best - 1)) * pi / Real(samples) + (best == 0 ? eps : 0);
  const Real t_hi =
      Real(std::min(samples, best + 2)) * pi / Real(samples) - (best == samples - 1 ? eps : 0);
  const auto brent = boost::math::tools::brent_find_minima(
      [&](Real theta) { return -p_theta(theta); }, t_lo, t_hi, std::numeric_limits<Real>::digits);
  Real s_max = cos(brent.first);
  // Polish: dp/ds changes sign across the maximum; its root is well conditioned.
  const auto slope = [&](Real s) { return hunter_detail::series_and_slope(out.coeffs, s).second; };
  const Real s_a = cos(t_hi), s_b = cos(t_lo);
  const Real d_a = slope(s_a), d_b = slope(s_b);
  Real p_max = -brent.second;
  if (d_a > 0 && d_b < 0) {
    std::uintmax_t it = 200;
    const auto r = boost::math::tools::toms748_solve(
        slope, s_a, s_b, d_a, d_b,
        boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 2), it);
    s_max = (r.first + r.second) / 2;
    p_max = out.pressure(out.b + a * s_max);
  }
  out.pmax_x = out.b + a * s_max;
  out.pmax = p_max;

  out.converged = root_ok && abs(out.load - load) <= 64 * eps * load * Real(n_terms) &&
                  out.residual <= 64 * eps * Real(n_terms);
  return out;
}

}  // namespace viscoroll::testing

#endif  // VISCOROLL_TESTS_SUPPORT_HUNTER_COLLOCATION_HPP
