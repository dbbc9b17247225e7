// viscoroll: the plane problem on a body by spectral collocation (plane_substrate_solver.hpp,
// docs/plane-substrate.md (Q5)-(Q9), (Q13)): the collocation system with the substrate's Fourier
// rows, the pressure of a level, a level's root in the half width a and the refinement over
// levels: members of PlaneSubstrateSolver defined out of the class.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/expint.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/plane/detail/memory_integrals.hpp>
#include <viscoroll/plane/detail/plane_substrate_functions.hpp>
#include <viscoroll/plane/plane_substrate_solver.hpp>
#include <viscoroll/substrate/substrate.hpp>

namespace viscoroll {

// (Q6), (Q7), (Q9): the collocation system at half width a with N terms.
template <RealScalar Real, ConstitutiveModel Material, Substrate Body>
requires detail::PlaneSubstrateArguments<Real, Material, Body>
auto PlaneSubstrateSolver<Real, Material, Body>::build(const Problem& pr, Real a, int n_terms,
                                                       bool with_d) const -> System {
  using std::cos;
  using std::exp;
  using std::sin;
  const Real pi = boost::math::constants::pi<Real>();
  const int rows = n_terms + 1;
  System sys;
  sys.slope.setZero(rows, rows);
  if (with_d) sys.displacement.setZero(rows, n_terms);
  sys.s.resize(static_cast<std::size_t>(rows));
  namespace ps = detail::plane_substrate;
  const ps::MemoryQuadrature<Real> mq{};
  std::vector<std::vector<Real>> tails(pr.terms.size());
  for (std::size_t k = 0; k < pr.terms.size(); ++k)
    tails[k] = ps::tail_integrals(pr.terms[k].length / a, n_terms, mq);
  for (int j = 0; j < rows; ++j) {
    const Real phi = Real(2 * j + 1) * pi / Real(2 * rows);
    sys.s[static_cast<std::size_t>(j)] = cos(phi);
    // (Q6): the half space's slope H_n = T_{n+1} and its memory f_k m_n(s; L_k / a).
    Real t = cos(phi), t_sin = sin(phi);
    for (int n = 0; n < n_terms; ++n) {
      sys.slope(j, n) = t;
      const Real next = t * cos(phi) - t_sin * sin(phi);
      t_sin = t_sin * cos(phi) + t * sin(phi);
      t = next;
    }
    std::vector<Real> g;
    if (with_d) {
      g = ps::log_potentials(phi, n_terms);
      for (int n = 0; n < n_terms; ++n)
        sys.displacement(j, n) = (1 + pr.creep) * g[static_cast<std::size_t>(n)] / pi;
    }
    for (std::size_t k = 0; k < pr.terms.size(); ++k) {
      const Real v = pr.terms[k].length / a;
      const auto m = ps::memory_integrals(phi, v, tails[k], mq);
      for (int n = 0; n < n_terms; ++n) {
        sys.slope(j, n) += pr.terms[k].f * m[static_cast<std::size_t>(n)];
        // (Q9): int e^-eta G_n(s + v eta) d eta = G_n(s) + pi v m_n(s).
        if (with_d) sys.displacement(j, n) += pr.terms[k].f * v * m[static_cast<std::size_t>(n)];
      }
    }
    sys.slope(j, n_terms) = Real(-1);
  }
  if constexpr (Body::kind == SubstrateKind::body) fourier_rows(pr, a, n_terms, with_d, sys);
  return sys;
}

// (Q7), (Q9): the substrate's remainder E_n, D_n subtracted from the rows.
template <RealScalar Real, ConstitutiveModel Material, Substrate Body>
requires detail::PlaneSubstrateArguments<Real, Material, Body>
void PlaneSubstrateSolver<Real, Material, Body>::fourier_rows(const Problem& pr, Real a,
                                                              int n_terms, bool with_d,
                                                              System& sys) const {
  using std::exp;
  using std::min;
  const int rows = n_terms + 1;
  const Real w_max = q_max(pr) * a;
  Real pole = std::numeric_limits<Real>::infinity();  // a / max L_k
  for (const auto& t : pr.terms) pole = min(pole, a / t.length);
  const Real width_cap = min(Real(4), a / (2 * pr.omega_scale));
  std::vector<Real> j_seq, buffer, coef(static_cast<std::size_t>(n_terms));
  Real w_lo = 0;
  while (w_lo < w_max) {
    Real width = width_cap;
    if (pole < std::numeric_limits<Real>::infinity()) width = min(width, std::max(w_lo, pole) / 2);
    const Real w_hi = min(w_max, w_lo + width);
    detail::plane_substrate::gauss_panel(w_lo, w_hi, [&](Real w, Real weight) {
      const Real q = w / a;
      const Real tm1 = body_.surface_factor(q, pr.nu) - 1;
      const Complex phi = compliance_ratio(pr, q);
      detail::plane_substrate::bessel_j_sequence(w, n_terms, j_seq, buffer);
      for (int n = 0; n < n_terms; ++n)
        coef[static_cast<std::size_t>(n)] =
            weight * tm1 * Real(n + 1) * j_seq[static_cast<std::size_t>(n + 1)] / w;
      for (int j = 0; j < rows; ++j) {
        const Complex e = phi * std::polar(Real(1), w * sys.s[static_cast<std::size_t>(j)]);
        const Complex z = Complex(0, 1) * e;                               // i Phi e^{i w s}
        const Real cycle[4] = {z.real(), z.imag(), -z.real(), -z.imag()};  // Re[(-i)^n z]
        for (int n = 0; n < n_terms; ++n)
          sys.slope(j, n) -= coef[static_cast<std::size_t>(n)] * cycle[n % 4];
        if (with_d) {
          const Real cd[4] = {e.real(), e.imag(), -e.real(), -e.imag()};
          for (int n = 0; n < n_terms; ++n)
            sys.displacement(j, n) -= coef[static_cast<std::size_t>(n)] * cd[n % 4] / w;
          sys.displacement(j, 0) -= weight * (1 - pr.t0) * (1 + pr.creep) * exp(-w) / (2 * w);
        }
      }
    });
    w_lo = w_hi;
  }
  if (with_d) {
    const Real tail = (1 - pr.t0) * (1 + pr.creep) * boost::math::expint(1, w_max) / 2;
    for (int j = 0; j < rows; ++j) sys.displacement(j, 0) -= tail;
  }
}

// (Q5): the pressure of a level, its peak and its least sampled value.
template <RealScalar Real, ConstitutiveModel Material, Substrate Body>
requires detail::PlaneSubstrateArguments<Real, Material, Body>
void PlaneSubstrateSolver<Real, Material, Body>::pressure_of(const Problem& pr, Level& l) {
  using std::cos;
  const Real pi = boost::math::constants::pi<Real>();
  const int n_terms = static_cast<int>(l.col.x.size()) - 1;
  std::vector<Real> coeffs(static_cast<std::size_t>(n_terms));
  for (int k = 0; k < n_terms; ++k)
    coeffs[static_cast<std::size_t>(k)] = pr.c1 * l.a * l.col.x(k) / (2 * pi * pr.c);
  const Real a = l.a, b = l.b;
  l.pressure = [coeffs, a, b](Real x) {
    const Real t = (x - b) / a;
    if (!(t > -1 && t < 1)) return Real(0);
    Real u_prev = 0, u = 1, sum = 0;  // (Q5): U_{-1} = 0, U_0 = 1
    for (const Real c : coeffs) {
      sum += c * u;
      const Real next = 2 * t * u - u_prev;
      u_prev = u;
      u = next;
    }
    using std::sqrt;
    return sqrt((1 - t) * (1 + t)) * sum;
  };
  const int samples = 8 * n_terms + 64;
  const auto p_theta = [&](Real theta) { return l.pressure(b + a * cos(theta)); };
  int best = 0;
  Real best_p = -std::numeric_limits<Real>::infinity();
  l.lowest = std::numeric_limits<Real>::infinity();
  for (int k = 0; k < samples; ++k) {
    const Real p = p_theta((Real(k) + Real(0.5)) * pi / Real(samples));
    if (p > best_p) {
      best_p = p;
      best = k;
    }
    l.lowest = std::min(l.lowest, p);
  }
  const Real t_lo = Real(std::max(0, best - 1)) * pi / Real(samples);
  const Real t_hi = Real(std::min(samples, best + 2)) * pi / Real(samples);
  const auto brent = boost::math::tools::brent_find_minima(
      [&](Real theta) { return -p_theta(theta); }, t_lo, t_hi, std::numeric_limits<Real>::digits);
  l.peak = PressurePeak<Real>{b + a * cos(brent.first), -brent.second};
}

// (Q8): one level of the refinement, a by TOMS 748 on the load.
template <RealScalar Real, ConstitutiveModel Material, Substrate Body>
requires detail::PlaneSubstrateArguments<Real, Material, Body>
auto PlaneSubstrateSolver<Real, Material, Body>::level(const Problem& pr, int n_terms, Real guess,
                                                       Real spread) const -> Level {
  Level out;
  const auto load_gap = [&](Real a) {
    ++out.evaluations;
    const auto col = collocate(pr, a, n_terms, false);
    return pr.c1 * a * a * col.x(0) / (4 * pr.c * pr.load) - 1;
  };
  Real lo = guess / (1 + spread), hi = guess * (1 + spread);
  Real g_lo = load_gap(lo), g_hi = load_gap(hi);
  for (int k = 0; k < 60 && !(g_lo <= 0 && g_hi >= 0); ++k) {
    if (g_lo > 0) {
      hi = lo;
      g_hi = g_lo;
      lo /= 2;
      g_lo = load_gap(lo);
    } else {
      lo = hi;
      g_lo = g_hi;
      hi *= 2;
      g_hi = load_gap(hi);
    }
  }
  Real a = hi;
  out.root_ok = false;
  if (g_lo <= 0 && g_hi >= 0) {
    if (g_lo == 0 || g_hi == 0) {
      a = g_lo == 0 ? lo : hi;
      out.root_ok = true;
    } else {
      std::uintmax_t iterations = static_cast<std::uintmax_t>(options_.max_iterations);
      const auto r = boost::math::tools::toms748_solve(
          load_gap, lo, hi, g_lo, g_hi,
          boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 3),
          iterations);
      a = (r.first + r.second) / 2;
      out.root_ok = iterations < static_cast<std::uintmax_t>(options_.max_iterations);
    }
  }
  out.a = a;
  out.col = collocate(pr, a, n_terms, true);
  const Vector& x = out.col.x;
  out.b = x(n_terms) * a;
  out.chi = pr.c1 * (out.b + a * x(1) / (2 * x(0)));  // Eq. (51) with (Q5)
  // (Q9): d = u(x_j) + C1 x_j^2 / 2, averaged over the collocation points.
  const Vector u = -pr.c1 * a * a * (out.col.sys.displacement * x.head(n_terms));
  Real d = 0;
  for (int j = 0; j <= n_terms; ++j) {
    const Real xj = out.b + a * out.col.sys.s[static_cast<std::size_t>(j)];
    d += u(j) + pr.c1 * xj * xj / 2;
  }
  out.d = d / Real(n_terms + 1);
  pressure_of(pr, out);
  return out;
}

// A body: levels of N terms doubled until the estimates (Q13) meet the tolerance.
template <RealScalar Real, ConstitutiveModel Material, Substrate Body>
requires detail::PlaneSubstrateArguments<Real, Material, Body>
auto PlaneSubstrateSolver<Real, Material, Body>::solve_body(const Problem& pr) const -> Solution {
  using std::abs;
  using std::max;
  using std::sqrt;
  const Real tol = Real(options_.tolerance);
  Solution s;
  s.d_absolute = Body::kind == SubstrateKind::body && pr.t0 == 0;
  std::vector<Level> levels;
  // The first bracket starts at the half space's width or, on a thin body, at 4 thicknesses
  // (the Fourier rows cost in proportion to a / thickness; the search doubles from there).
  Real guess = std::min(pr.a0 / sqrt(sqrt(1 + pr.creep)), 4 * pr.omega_scale);
  // [guess / (1 + spread), guess (1 + spread)]: first the glassy to long-term range.
  Real spread = sqrt(1 + pr.creep) - 1 + Real(1) / 64;
  int n = options_.initial_terms;
  bool met = false;
  for (; n <= options_.max_terms; n *= 2) {
    levels.push_back(level(pr, n, guess, spread));
    s.iterations += levels.back().evaluations;
    guess = levels.back().a;
    // The next bracket: four times the last change of a (at least 1e-12 of it).
    spread =
        levels.size() < 2
            ? Real(1) / 256
            : std::max(Real(4) * abs(guess - levels[levels.size() - 2].a) / guess, Real(1e-12));
    if (levels.size() < 2) continue;
    const Level& now = levels.back();
    const Level& before = levels[levels.size() - 2];
    // (Q13) = theory.md (E2), (E3): (5/4) of the last change, or of half the change before it
    // when that is larger (either can be small by coincidence, never both).
    const Level* earlier = levels.size() >= 3 ? &levels[levels.size() - 3] : nullptr;
    const auto estimate = [&](auto member) {
      Real e = abs(member(now) - member(before));
      if (earlier) e = max(e, abs(member(before) - member(*earlier)) / 2);
      return Real(5) / 4 * e;
    };
    s.error_a = estimate([](const Level& l) { return l.a; });
    s.error_d = estimate([](const Level& l) { return l.d; });
    s.error_chi = estimate([](const Level& l) { return l.chi; });
    s.error_peak = estimate([](const Level& l) { return l.peak.pressure; });
    const Real d_scale = max(abs(now.d), pr.c1 * now.a * now.a / 2);
    const Real chi_scale = max(abs(now.chi), Real(1e-6) * pr.c1 * now.a);
    if (s.error_a <= tol * now.a && s.error_d <= tol * d_scale && s.error_chi <= tol * chi_scale) {
      met = true;
      break;
    }
  }
  const Level& last = levels.back();
  s.a = last.a;
  s.b = last.b;
  s.d = last.d;
  s.chi = last.chi;
  s.terms = static_cast<int>(last.col.x.size()) - 1;
  s.load_residual = abs(pr.c1 * s.a * s.a * last.col.x(0) / (4 * pr.c * pr.load) - 1);
  s.pressure_function = last.pressure;
  s.peak_ = last.peak;
  const Real lowest = last.lowest;
  // Converged: every level's root, the tolerance (Q13), and a pressure that is nowhere
  // negative beyond the tolerance (else the contact is not one interval with square-root edges).
  bool roots = true;
  for (const auto& l : levels) roots = roots && l.root_ok;
  s.converged = met && roots && lowest >= -tol * s.peak_.pressure;
  if (!roots)
    detail::set_stop(s, StopCode::root_finder_failed,
                     "the root finder for the half width a did not converge");
  else if (!met)
    detail::set_stop(
        s, StopCode::tolerance_not_met,
        "the estimated errors (a " + detail::format_value(s.error_a) + ", d " +
            detail::format_value(s.error_d) + ", chi " + detail::format_value(s.error_chi) +
            ") exceed the tolerance at max_terms = " + std::to_string(options_.max_terms));
  else if (!s.converged)
    detail::set_stop(s, StopCode::not_a_contact,
                     "the pressure is negative (" + detail::format_value(lowest) +
                         "): the contact is not one interval with square-root edges");
  return s;
}

}  // namespace viscoroll
