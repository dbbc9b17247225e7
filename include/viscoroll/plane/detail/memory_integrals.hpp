// viscoroll: the memory integrals of the plane problem's Chebyshev collocation
// (docs/hunter-collocation.md, section 3; docs/plane-substrate.md (Q6)): the integrals of the
// memory weight e^-eta against the Chebyshev kernels H_n, by composite 30-point Gauss-Legendre
// panels each spanning a bounded decay and phase. Used by PlaneSubstrateSolver
// (plane/plane_substrate_solver.hpp) and by the independent collocation of the tests
// (tests/support/hunter_collocation.hpp), which checks Hunter's closed form with them.
#pragma once

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace viscoroll::detail::plane_memory {

/// Composite 30-point Gauss-Legendre: calls g(x, w) for every node of [lo, hi] split into
/// `panels` equal panels.
template <class Real, class G>
void gauss30_panels(Real lo, Real hi, std::int64_t panels, G&& g) {
  using rule = boost::math::quadrature::gauss<Real, 30>;
  const auto& x = rule::abscissa();
  const auto& w = rule::weights();
  const Real h = (hi - lo) / Real(panels);
  for (std::int64_t k = 0; k < panels; ++k) {
    const Real mid = lo + (Real(k) + Real(0.5)) * h;
    const Real half = h / 2;
    for (std::size_t i = 0; i < x.size(); ++i) {
      g(mid - half * x[i], half * w[i]);
      g(mid + half * x[i], half * w[i]);
    }
  }
}

/// Quadrature resolution. Each 30-point panel spans at most `step_exponent` of decay of the
/// weight e^{-eta} and at most `step_phase` radians of the fastest Chebyshev oscillation
/// cos((n+1) phi) (or of e^{-(n+1) theta}). With both <= 8 the Gauss-Legendre error on a
/// panel is below (8/2)^60/60! ~ 1e-46 of the integrand scale (docs/hunter-collocation.md).
template <class Real>
struct MemoryQuadrature {
  Real step_exponent = 8;
  Real step_phase = 8;
  /// The memory weight is cut where e^{-eta} < e^{-cutoff}; cutoff = -ln(eps) + 6.
  Real cutoff = -std::log(static_cast<double>(std::numeric_limits<Real>::epsilon())) + 6;
};

/// Number of sub-panels so that (n_max + 1) * width <= step_phase.
template <class Real>
std::int64_t phase_panels(Real width, int n_max, const MemoryQuadrature<Real>& q) {
  using std::ceil;
  const Real m = ceil(Real(n_max + 1) * width / q.step_phase);
  return std::max<std::int64_t>(1, static_cast<std::int64_t>(m));
}

/// J_n(v) = int_0^inf e^{-w} H_n(1 + v w) dw, n = 0..n_terms-1, with 1 + v w = cosh(theta):
/// J_n = (1/v) int_0^inf e^{-(cosh theta - 1)/v} sinh(theta) e^{-(n+1) theta} d theta.
/// The far-field part of the memory integral: int_{eta_1}^inf = e^{-eta_1} J_n(v).
template <class Real>
std::vector<Real> tail_integrals(Real v, int n_terms, const MemoryQuadrature<Real>& q = {}) {
  using std::acosh;
  using std::exp;
  using std::sinh;
  std::vector<Real> out(static_cast<std::size_t>(n_terms), Real(0));
  const auto theta_of = [v](Real e) { return acosh(1 + v * e); };
  Real e_lo = 0;
  while (e_lo < q.cutoff) {
    const Real e_hi = std::min(q.cutoff, e_lo + q.step_exponent);
    const Real t_lo = theta_of(e_lo), t_hi = theta_of(e_hi);
    gauss30_panels(t_lo, t_hi, phase_panels(t_hi - t_lo, n_terms, q), [&](Real theta, Real w) {
      const Real sh = sinh(theta / 2);
      const Real weight = w * exp(-2 * sh * sh / v) * sinh(theta) / v;
      const Real r = exp(-theta);
      Real h = r;  // H_n(cosh theta) = e^{-(n+1) theta}
      for (int n = 0; n < n_terms; ++n) {
        out[static_cast<std::size_t>(n)] += weight * h;
        h *= r;
      }
    });
    e_lo = e_hi;
  }
  return out;
}

/// Memory integrals m_n(s) = int_0^inf e^{-eta} H_n(s + v eta) d eta, n = 0..n_terms-1, at
/// s = cos(phi_s), 0 < phi_s < pi, v > 0. `tail` = tail_integrals(v, n_terms).
/// Near part (s + v eta <= 1), with s + v eta = cos(phi_s - delta):
///   (1/v) int_0^{delta_end} e^{-eta(delta)} sin(phi_s - delta) T_{n+1}(cos(phi_s - delta)) d
///   delta, eta(delta) = 2 sin(phi_s - delta/2) sin(delta/2) / v,
/// far part e^{-eta_1} J_n(v), eta_1 = (1 - s)/v, dropped when eta_1 > cutoff. The offset delta
/// (not phi) is the integration variable so that eta carries a relative, not an absolute
/// (eps phi_s / v), rounding error when v is small.
template <class Real>
std::vector<Real> memory_integrals(Real phi_s, Real v, const std::vector<Real>& tail,
                                   const MemoryQuadrature<Real>& q = {}) {
  using std::acos;
  using std::cos;
  using std::exp;
  using std::sin;
  const int n_terms = static_cast<int>(tail.size());
  std::vector<Real> out(tail.size(), Real(0));
  const Real s = cos(phi_s);
  const Real half_sin = sin(phi_s / 2);
  const Real eta_1 = 2 * half_sin * half_sin / v;  // (1 - s)/v without cancellation
  const bool reaches_edge = eta_1 <= q.cutoff;
  const Real e_max = reaches_edge ? eta_1 : q.cutoff;
  // delta where eta = e; eta is monotone in delta on [0, phi_s].
  const auto delta_of = [&](Real e) {
    if (e <= 0) return Real(0);
    if (reaches_edge && e >= eta_1) return phi_s;
    return phi_s - acos(std::min(Real(1), s + v * e));
  };
  Real e_lo = 0;
  while (e_lo < e_max) {
    const Real e_hi = std::min(e_max, e_lo + q.step_exponent);
    const Real d_lo = delta_of(e_lo), d_hi = delta_of(e_hi);
    gauss30_panels(d_lo, d_hi, phase_panels(d_hi - d_lo, n_terms, q), [&](Real delta, Real w) {
      const Real eta = 2 * sin(phi_s - delta / 2) * sin(delta / 2) / v;
      const Real phi = phi_s - delta;
      const Real cos_phi = cos(phi), sin_phi = sin(phi);
      const Real weight = w * exp(-eta) * sin_phi / v;
      // T_{n+1}(cos phi) = cos((n+1) phi) by rotation: rounding grows like n, not n^2 as
      // the three-term recurrence does near z = +-1.
      Real t = cos_phi, t_sin = sin_phi;
      for (int n = 0; n < n_terms; ++n) {
        out[static_cast<std::size_t>(n)] += weight * t;
        const Real next = t * cos_phi - t_sin * sin_phi;
        t_sin = t_sin * cos_phi + t * sin_phi;
        t = next;
      }
    });
    e_lo = e_hi;
  }
  if (reaches_edge) {
    const Real damp = exp(-eta_1);
    for (std::size_t n = 0; n < out.size(); ++n) out[n] += damp * tail[n];
  }
  return out;
}

}  // namespace viscoroll::detail::plane_memory
