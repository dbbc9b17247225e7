// viscoroll: the plane problem on a spring bed in closed form (plane_substrate_solver.hpp,
// docs/plane-substrate.md (Q10)-(Q13)): the memory's modes and the solve by the edges' roots:
// members of PlaneSubstrateSolver defined out of the class.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/plane/plane_substrate_solver.hpp>

namespace viscoroll {

// (Q10)-(Q11): the spring bed's modes.
template <RealScalar Real, ConstitutiveModel Material, Substrate Body>
requires detail::PlaneSubstrateArguments<Real, Material, Body>
auto PlaneSubstrateSolver<Real, Material, Body>::bed_modes(const Problem& pr) const -> BedModes {
  const Real pi = boost::math::constants::pi<Real>();
  BedModes modes;
  // (Q10): T(q) = q l, so K = pi l delta(x) and u = 2 pi c l p.
  const Real h = body_.thickness();
  const Real l = body_.surface_factor(1 / h, pr.nu) * h;
  detail::require(l > 0 && l < std::numeric_limits<Real>::infinity(), "surface_factor(q)/q", l,
                  "0 < T(q)/q < inf for a local substrate");
  modes.kappa = 2 * pi * pr.c * l;
  modes.c1 = pr.c1;
  modes.creep = pr.creep;
  const int k_count = static_cast<int>(pr.terms.size());
  if (k_count == 0) return modes;
  Matrix m(k_count, k_count);
  Vector u(k_count), x(k_count);
  for (int k = 0; k < k_count; ++k) {
    const auto& t = pr.terms[static_cast<std::size_t>(k)];
    modes.f.push_back(t.f);
    using std::sqrt;
    u(k) = sqrt(t.f / t.length);
    x(k) = sqrt(t.f * t.length);
  }
  m = u * u.transpose();
  for (int k = 0; k < k_count; ++k) m(k, k) += 1 / pr.terms[static_cast<std::size_t>(k)].length;
  const Eigen::SelfAdjointEigenSolver<Matrix> eig(m);
  modes.lambda = eig.eigenvalues();
  modes.back = x.cwiseInverse().asDiagonal() * eig.eigenvectors();
  Vector rho(k_count);
  for (int k = 0; k < k_count; ++k)
    rho(k) = x(k) / (modes.kappa * pr.terms[static_cast<std::size_t>(k)].length);
  modes.sigma = eig.eigenvectors().transpose() * rho;
  return modes;
}

// (Q12): a spring bed, its edges by roots of the pressure and of the load.
template <RealScalar Real, ConstitutiveModel Material, Substrate Body>
requires detail::PlaneSubstrateArguments<Real, Material, Body>
auto PlaneSubstrateSolver<Real, Material, Body>::solve_bed(const Problem& pr) const -> Solution {
  using std::abs;
  using std::cbrt;
  const BedModes modes = bed_modes(pr);
  Solution s;
  s.d_absolute = true;
  int evaluations = 0;
  // (Q12): the trailing edge x1 < x2 is the first zero of p behind x2, bracketed by steps.
  const auto trailing = [&](Real x2) {
    const Real step = x2 / 128;
    Real hi = x2 - step / 1024, p_hi = modes.pressure(hi, x2);
    for (int k = 0; k < 1 << 16; ++k) {
      const Real lo = hi - step;
      const Real p_lo = modes.pressure(lo, x2);
      if (p_lo <= 0) {
        if (p_lo == 0) return lo;
        std::uintmax_t it = static_cast<std::uintmax_t>(options_.max_iterations);
        const auto r = boost::math::tools::toms748_solve(
            [&](Real x) { return modes.pressure(x, x2); }, lo, hi, p_lo, p_hi,
            boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 3), it);
        return (r.first + r.second) / 2;
      }
      hi = lo;
      p_hi = p_lo;
    }
    return hi;
  };
  const auto moments = [&](Real x1, Real x2, int refine) {
    std::array<Real, 2> out{};
    bed_quadrature(modes, x1, x2, refine, [&](Real x, Real w) {
      const Real p = modes.pressure(x, x2);
      out[0] += w * p;
      out[1] += w * x * p;
    });
    return out;
  };
  const auto load_gap = [&](Real x2) {
    ++evaluations;
    return moments(trailing(x2), x2, 0)[0] / pr.load - 1;
  };
  // Bracket: the glassy and the long-term static leading edges, (3 W kappa (1+f) / (2 C1))^(1/3).
  Real lo = cbrt(3 * pr.load * modes.kappa / (2 * pr.c1)) / 2;
  Real hi = cbrt(3 * pr.load * modes.kappa * (1 + pr.creep) / (2 * pr.c1)) * 2;
  Real g_lo = load_gap(lo), g_hi = load_gap(hi);
  for (int k = 0; k < 60 && g_lo > 0; ++k) g_lo = load_gap(lo /= 2);
  for (int k = 0; k < 60 && g_hi < 0; ++k) g_hi = load_gap(hi *= 2);
  bool root_ok = g_lo <= 0 && g_hi >= 0;
  Real x2 = hi;
  if (root_ok) {
    std::uintmax_t it = static_cast<std::uintmax_t>(options_.max_iterations);
    const auto r = boost::math::tools::toms748_solve(
        load_gap, lo, hi, g_lo, g_hi,
        boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 3), it);
    x2 = (r.first + r.second) / 2;
    root_ok = it < static_cast<std::uintmax_t>(options_.max_iterations);
  }
  const Real x1 = trailing(x2);
  const auto coarse = moments(x1, x2, 0), fine = moments(x1, x2, 1);
  s.a = (x2 - x1) / 2;
  s.b = (x2 + x1) / 2;
  s.d = pr.c1 * x2 * x2 / 2;  // (Q12): p(x2) = 0
  s.chi = pr.c1 * fine[1] / fine[0];
  s.load_residual = abs(fine[0] / pr.load - 1);
  // (Q13) for the closed form: the quadrature's change under halving its panels (rounding,
  // some eps C1 a in chi, is not included).
  s.error_chi = Real(5) / 4 * abs(s.chi - pr.c1 * coarse[1] / coarse[0]);
  s.error_a = Real(5) / 4 * abs(fine[0] - coarse[0]) / pr.load * s.a;
  s.error_d = 2 * s.error_a / s.a * s.d;
  s.iterations = evaluations;
  const auto m = modes;
  s.pressure_function = [m, x1, x2](Real x) {
    return (x > x1 && x < x2) ? std::max(Real(0), m.pressure(x, x2)) : Real(0);
  };
  // The peak: the best of the quadrature's nodes, then Brent around it.
  Real best_x = s.b, best_p = -1;
  bed_quadrature(modes, x1, x2, 1, [&](Real x, Real) {
    const Real p = modes.pressure(x, x2);
    if (p > best_p) {
      best_p = p;
      best_x = x;
    }
  });
  const Real reach = (x2 - x1) / 64;
  const auto brent = boost::math::tools::brent_find_minima(
      [&](Real x) { return -s.pressure_function(x); }, std::max(x1, best_x - reach),
      std::min(x2, best_x + reach), std::numeric_limits<Real>::digits / 2);
  s.peak_ = PressurePeak<Real>{brent.first, -brent.second};
  const Real tol = Real(options_.tolerance);
  const bool met =
      s.error_a <= tol * s.a && s.error_chi <= tol * std::max(abs(s.chi), Real(1e-6) * pr.c1 * s.a);
  s.converged = root_ok && met;
  if (!root_ok)
    detail::set_stop(s, StopCode::root_finder_failed,
                     "the root finder for the leading edge did not converge");
  else if (!met)
    detail::set_stop(s, StopCode::tolerance_not_met,
                     "the quadrature's estimated errors (a " + detail::format_value(s.error_a) +
                         ", chi " + detail::format_value(s.error_chi) + ") exceed the tolerance");
  return s;
}

}  // namespace viscoroll
