// viscoroll: the boundary-element solver's scene for any roller profile (roller/profile.hpp).
//
// A RollerProfile gives the gap h(x, y) = C1 x^2/2 + h(y) of Eq. (27) generalised
// (docs/rollers.md); the BEM takes it as BemScene::profile. What the profile does not say is
// where the contact lies, which the grid must cover: bem_scene() estimates it (docs/bem.md,
// "Rollers of any profile", (B14)) from Hertz's contact of the long-term compliance (B8) with the
// profile's secant curvature
//   C2s(l) = [h(yc + l) + h(yc - l) - 2 h(yc)] / l^2,                                     (B14a)
// yc the lowest point of h: the half length l* is the fixed point l = b_H(C1, C2s(l)), unique
// for a convex drop (C2s grows with l, b_H falls with C2s), and exact for the ellipsoid (C2s = C2
// at every l, so its scene and grid are the ellipsoid's). The grid, centred on the roller's
// centre section y = 0, is then sized by the curvature C2g whose Hertz semi-axis is
// max(l*, (|yc| + 1.25 l*)/1.6): at the default extent 1.6 it covers the contact's estimate
// with a quarter of its length to spare on each side. A contact that still reaches the grid's
// border is reported by the solver (not converged, "increase extent").
//
// Beyond the roller's body (y outside (y_min, y_max)) there is no surface: the gap rises with
// slope 1 from the end's value (a chamfer no contact reaches at the small slopes of the theory),
// and the solver warns when the contact reaches the body's last cell (an end pressure peak
// resolved only to the grid).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <viscoroll/bem/bem_scene.hpp>
#include <viscoroll/bem/hertz.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/roller/profile.hpp>

namespace viscoroll {

namespace bem {

/// Hertz's semi-axis b along y (B8) for curvatures c1, c2 under compliance x load `cp`; +inf
/// when c2/c1 is below the Hertz solver's range (the contact is then longer than any estimate
/// needs), 0 above it.
template <RealScalar Real>
Real hertz_length(Real c1, Real c2, Real cp) {
  if (!(c2 > Real(1e-10) * c1)) return std::numeric_limits<Real>::infinity();
  if (!(c2 < Real(1e10) * c1)) return Real(0);
  return bem::hertz_contact(c1, c2, cp, Real(1)).b;
}

/// The estimate of (B14): the contact's centre yc and half length l*, and the curvature C2g that
/// sizes the grid.
template <RealScalar Real>
struct ProfileExtent {
  Real center;       ///< yc, the lowest point of h(y) within the estimate
  Real half_length;  ///< l*
  Real c2_grid;      ///< C2g
};

/// (B14) for profile `p` under long-term compliance x load `cp` (> 0).
template <RollerProfile P>
ProfileExtent<typename P::real_type> profile_extent(const P& p, typename P::real_type cp) {
  using Real = typename P::real_type;
  using std::abs;
  using std::cbrt;
  using std::sqrt;
  const Real c1 = p.c1();
  if constexpr (requires { p.c2(); }) {
    // The ellipsoid: C2s = C2 at every l, the fixed point is Hertz's b itself.
    return {Real(0), hertz_length(c1, Real(p.c2()), cp), Real(p.c2())};
  }
  // Strictly inside the body, where drop() is defined.
  const Real inside = 1 - 64 * std::numeric_limits<Real>::epsilon();
  const Real lo_end = p.y_min() * inside, hi_end = p.y_max() * inside;
  const Real round = cbrt(cp / c1);  // the size of a round contact (B8)
  // The lowest point: a golden-section search would assume one minimum; a sampled scan over the
  // body (or +-1e4 round contacts where it is unbounded) does not.
  const Real window = Real(1e4) * round;
  const Real y0 = std::max(lo_end, -window), y1 = std::min(hi_end, window);
  Real yc = 0, hc = p.drop(Real(0));
  constexpr int samples = 4096;
  for (int k = 0; k <= samples; ++k) {
    const Real y = y0 + (y1 - y0) * Real(k) / Real(samples);
    const Real h = p.drop(y);
    if (h < hc) {
      hc = h;
      yc = y;
    }
  }
  // The room on each side of yc, inside the body.
  const Real room = std::min(yc - lo_end, hi_end - yc);
  const auto secant = [&](Real l) { return (p.drop(yc + l) + p.drop(yc - l) - 2 * hc) / (l * l); };
  // g(l) = b_H(C2s(l)) - l, positive for small l, negative for large (B14a); bisection in ln l.
  const auto g = [&](Real l) { return hertz_length(c1, secant(l), cp) - l; };
  Real lo = round * Real(1e-3), hi = std::min(room, Real(1e8) * round);
  Real length;
  if (!(g(hi) < 0)) {
    length = hi;  // the contact (estimate) reaches the body's end: cover up to it
  } else {
    if (!(g(lo) > 0)) lo = std::min(lo, hi / 2);
    for (int k = 0; k < 80 && hi > lo * (1 + 8 * std::numeric_limits<Real>::epsilon()); ++k) {
      const Real mid = sqrt(lo * hi);
      (g(mid) > 0 ? lo : hi) = mid;
    }
    length = sqrt(lo * hi);
  }
  const Real target = std::max(length, (abs(yc) + Real(1.25) * length) / Real(1.6));
  Real c2g;
  if (yc == 0 && length < hi && secant(length) > Real(1e-10) * c1) {
    c2g = secant(length);  // the fixed point's own curvature: the ellipsoid's C2, exactly
  } else {
    // b_H(C2g) = target, b_H decreasing in C2g: bisection in ln C2g over Hertz's range.
    Real c_lo = Real(1e-10) * c1 * Real(1.0001), c_hi = Real(1e10) * c1 / Real(1.0001);
    if (hertz_length(c1, c_lo, cp) <= target) {
      c2g = c_lo;
    } else {
      for (int k = 0; k < 100 && c_hi > c_lo * (1 + 8 * std::numeric_limits<Real>::epsilon());
           ++k) {
        const Real mid = sqrt(c_lo * c_hi);
        (hertz_length(c1, mid, cp) > target ? c_lo : c_hi) = mid;
      }
      c2g = sqrt(c_lo * c_hi);
    }
  }
  return {yc, length, c2g};
}

}  // namespace bem

/// The BEM's scene for roller profile `profile` (any RollerProfile) on a half space of
/// `material` (any ConstitutiveModel) under total load `load` (N) at speed `speed` (m/s):
/// gap C1 x^2/2 + h(y) on the body (Eq. 27), a slope-1 chamfer beyond it, the grid sized by
/// (B14) from the long-term compliance. Throws std::invalid_argument naming the parameter for an
/// invalid load or speed.
template <RollerProfile P, ConstitutiveModel Material>
requires std::same_as<typename P::real_type, typename Material::real_type>
    BemScene<typename P::real_type> bem_scene(const P& profile, const Material& material,
                                              typename P::real_type load,
                                              typename P::real_type speed) {
  using Real = typename P::real_type;
  detail::require_positive("load", load);
  detail::require_non_negative("speed", speed);
  const Real cp = (1 + material.creep_ratio()) * material.instantaneous_compliance() * load;
  detail::require_positive("long-term compliance x load", cp);
  const auto extent = bem::profile_extent(profile, cp);
  const Real c1 = profile.c1(), y_min = profile.y_min(), y_max = profile.y_max();
  const Real inside = 1 - 64 * std::numeric_limits<Real>::epsilon();
  return BemScene<Real>{.c1 = c1,
                        .c2 = extent.c2_grid,
                        .load = load,
                        .speed = speed,
                        .profile =
                            [profile, c1, y_min, y_max, inside](Real x, Real y) {
                              const Real across = c1 * x * x / 2;
                              if (y <= y_min * inside) {
                                const Real end = y_min * inside;
                                return across + profile.drop(end) + (end - y);
                              }
                              if (y >= y_max * inside) {
                                const Real end = y_max * inside;
                                return across + profile.drop(end) + (y - end);
                              }
                              return across + profile.drop(y);
                            },
                        .y_min = y_min,
                        .y_max = y_max};
}

}  // namespace viscoroll
