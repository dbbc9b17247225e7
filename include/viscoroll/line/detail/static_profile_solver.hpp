// viscoroll: the steps of the static line contact of a roller profile (static_profile_contact.hpp)
// and the state they share: the starting guess by slicing, the residual and Jacobian of (G1),
// (G2), Newton's method with backtracking as the interpolation points double, and the result with
// its verdicts (docs/theory.md, "Line contact for any roller profile (static)").
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/detail/static_profile_matrices.hpp>
#include <viscoroll/line/static_profile_solution.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>
#include <viscoroll/roller/profile.hpp>

namespace viscoroll::detail {

/// static_profile_contact's solve of (G1), (G2) for `profile` under compliance_load with N = terms
/// coefficients (validated by the caller): its steps and the state they share; `out` the result.
template <RollerProfile P>
struct StaticProfileSolver {
  using Real = typename P::real_type;                                  ///< the scalar
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;  ///< a Jacobian
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;               ///< unknowns or residuals

  /// The profile, the compliance load and the number of terms N.
  StaticProfileSolver(const P& profile_, Real compliance_load_, int terms)
      : profile(profile_),
        compliance_load(compliance_load_),
        c1(profile_.c1()),
        ymin(profile_.y_min()),
        ymax(profile_.y_max()),
        n(terms),
        nc(terms + 2),
        nu(terms + 3) {
    out.c1 = c1;
  }

  const P& profile;      ///< the roller
  Real compliance_load;  ///< (1 - nu)/(2 pi mu) P
  Real c1, ymin, ymax;   ///< C1 and the body's ends
  int n, nc, nu;         ///< N, the N + 2 collocation points, the N + 3 unknowns
  const Real eps = std::numeric_limits<Real>::epsilon();  ///< the scalar's epsilon
  StaticProfileContact<Real> out{};                       ///< the result
  /// The starting guess: the length scale, the lowest point y* and h there, slicing's level D,
  /// kappa, the sliced ends and load, and whether slicing was clipped by the body's ends.
  ///@{
  Real len0{}, ystar{}, hmin{}, kappa = 10, level{}, e_minus = 0, e_plus = 0, f0max = 0;
  bool clip_minus = false, clip_plus = false;
  ///@}
  /// The scales of (G3) and of (G1), and ln(16 l_ref^2/a_ref^2).
  ///@{
  Real a_ref{}, l_ref{}, scale{}, log16{};
  ///@}
  Real epsilon = std::numeric_limits<Real>::infinity();  ///< the end layer e of (G3)
  std::string end_note;  ///< the end that an inadmissible x passes ("y_minus", "y_plus")
  /// Newton's method: M, the tolerances of the residual and of F's Chebyshev tail, and its stop.
  ///@{
  int m = 0;
  Real tolerance{}, tail_tolerance{};
  bool converged = false, blocked = false;
  Real rnorm = std::numeric_limits<Real>::infinity(), tail = 0;
  ///@}

  /// A value for a message.
  static std::string text(Real x) { return detail::format_value(x); }
  /// Whether y is strictly inside the body.
  bool inside(Real y) const { return y > ymin && y < ymax; }
  /// Sets `out` to a stop with its code and reason; returns false.
  bool fail(StopCode code, std::string why) {
    out.converged = false;
    out.code = code;
    out.reason = std::move(why);
    return false;
  }
  /// Keeps y strictly inside the body (by a relative 1e-9 of the step scale).
  Real clamp_in(Real y) const {
    using std::abs;
    const Real margin = 1e-9 * (abs(y) + len0);
    return std::min(std::max(y, Real(ymin + margin)), Real(ymax - margin));
  }
  /// The length scale and the lowest point y* of h, and h there; false (with `out` the stop) where
  /// the lowest point is the body's end.
  bool lowest_point() {
    using std::abs;
    using std::cbrt;
    // ---- The starting guess: slicing, F0 = (D - (h - h_min))/kappa, kappa = ln(16 l^2/a^2) + 1,
    // (G1) without its finite part (docs/theory.md, "Line contact for any roller profile").
    // A length scale: the ellipsoid's a0^3 rho = 3 compliance load / C1.
    len0 = cbrt(compliance_load / c1);
    Real y0 = (boost::math::isfinite)(ymin) && (boost::math::isfinite)(ymax) ? (ymin + ymax) / 2
              : inside(Real(0))                                              ? Real(0)
              : (boost::math::isfinite)(ymin)                                ? ymin + len0
                                                                             : ymax - len0;
    // The lowest point y* of h: walk downhill with doubling steps, then bisect the slope's sign.
    ystar = y0;
    {
      const Real s0 = profile.drop_slope(y0);
      if (s0 != 0) {
        const Real dir = s0 > 0 ? Real(-1) : Real(1);
        Real lo = y0, step = len0 / 64, hi = y0;
        bool found = false;
        for (int k = 0; k < 200; ++k) {
          hi = clamp_in(y0 + dir * step);
          const Real s = profile.drop_slope(hi);
          if (!(s * dir < 0)) {  // slope no longer downhill
            found = true;
            break;
          }
          if (hi == clamp_in(y0 + dir * 2 * step)) break;  // at the body end
          lo = hi;
          step *= 2;
        }
        if (!found)
          return fail(StopCode::contact_reaches_body_end,
                      "the lowest point of the roller is its body end at y = " + text(hi) +
                          ": the contact reaches the roller's end (outside the line theory)");
        for (int k = 0; k < 200 && abs(hi - lo) > 4 * eps * (abs(lo) + len0); ++k) {
          const Real mid = (lo + hi) / 2;
          (profile.drop_slope(mid) * dir < 0 ? lo : hi) = mid;
        }
        ystar = (lo + hi) / 2;
      }
    }
    hmin = profile.drop(ystar);
    return true;
  }
  /// The ends of {h - h_min < D} (clipped at the body's ends; `clipped` says so), D = lev.
  Real edge(Real lev, Real dir, bool& clipped) const {
    using std::abs;
    Real lo = ystar, step = len0 / 64, hi = ystar;
    clipped = false;
    for (int k = 0; k < 400; ++k) {
      hi = clamp_in(ystar + dir * step);
      if (profile.drop(hi) - hmin >= lev) break;
      if (hi != ystar + dir * step) {
        clipped = true;
        return hi;
      }
      lo = hi;
      step *= 2;
    }
    for (int k = 0; k < 200 && abs(hi - lo) > 4 * eps * (abs(lo) + len0); ++k) {
      const Real mid = (lo + hi) / 2;
      (profile.drop(mid) - hmin < lev ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
  }
  /// The sliced load at the level D = lev, its ends e_minus, e_plus set.
  Real slice_load(Real lev) {
    e_minus = edge(lev, Real(-1), clip_minus);
    e_plus = edge(lev, Real(1), clip_plus);
    using Rule = GaussLegendre<Real, 16>;
    const int panels = 16;
    const Real w = (e_plus - e_minus) / panels;
    Real sum = 0;
    for (int pnl = 0; pnl < panels; ++pnl)
      for (int j = 0; j < Rule::points; ++j) {
        const Real y = e_minus + w * (pnl + (Rule::nodes()[j] + 1) / 2);
        sum += Rule::weights()[j] * std::max(Real(0), lev - (profile.drop(y) - hmin));
      }
    return sum * w / 2 / kappa;
  }
  /// Slicing's level D and kappa, the sliced ends, and the scales a_ref, l_ref of (G3) and of (G1).
  void slice() {
    using std::log;
    using std::sqrt;
    level = c1 * len0 * len0;
    for (int pass = 0; pass < 5; ++pass) {
      // The level D at which the sliced load is the target (increasing in D).
      Real lo = level, hi = level;
      while (slice_load(lo) > compliance_load) lo /= 2;
      while (slice_load(hi) < compliance_load) {
        if (clip_minus && clip_plus) break;
        hi *= 2;
      }
      for (int k = 0; k < 200 && hi - lo > 8 * eps * hi; ++k) {
        const Real mid = (lo + hi) / 2;
        (slice_load(mid) < compliance_load ? lo : hi) = mid;
      }
      level = (lo + hi) / 2;
      slice_load(level);
      f0max = level / kappa;
      const Real amax = sqrt(4 * f0max / c1), half = (e_plus - e_minus) / 2;
      kappa = std::max(Real(2), Real(log(16 * half * half / (amax * amax)) + 1));
    }
    if (clip_minus || clip_plus) {
      // Not yet a verdict (slicing overestimates the length): start a little inside the body.
      const Real half = (e_plus - e_minus) / 2, mid = (e_plus + e_minus) / 2;
      e_minus = mid - half * Real(0.9);
      e_plus = mid + half * Real(0.9);
    }
    a_ref = sqrt(4 * f0max / c1);
    l_ref = (e_plus - e_minus) / 2;
    out.a_ref = a_ref;

    scale = c1 * a_ref * a_ref;  // of (G1)
    log16 = log(16 * l_ref * l_ref / (a_ref * a_ref));
  }
  /// The unknowns' starting values from the sliced F0, and its end layer e (`epsilon`).
  Vector start() {
    using std::log;
    // ---- Unknowns x: alpha_0..alpha_{N-1}, lambda = ln(l/l_ref), gamma = c/l_ref,
    // delta = d/(C1 a_ref^2).
    Vector x = Vector::Zero(nu);
    {
      // The sliced F0 at the roots of T_N (at least 16 of them), its end layer e (the omega of
      // (G3) closest to it in ln, up to a constant, among e = +inf, 4, 2, ..., 1/32), and alpha
      // from ln(F0/omega) by interpolation at the roots of T_N (DCT-II).
      using std::cos;
      const Real pi = boost::math::constants::pi<Real>();
      const Real mid = (e_plus + e_minus) / 2;
      const auto sliced = [&](Real u) {
        const Real y = mid + l_ref * u;
        return std::max(Real(level - (profile.drop(y) - hmin)), Real(level * 1e-6)) / kappa;
      };
      const int nf = std::max(n, 16);
      Real best = std::numeric_limits<Real>::infinity();
      for (Real e = 8; e >= Real(1) / 32; e /= 2) {
        const Real ee = e == 8 ? std::numeric_limits<Real>::infinity() : e;
        Real s1 = 0, s2 = 0;
        for (int j = 0; j < nf; ++j) {
          const Real u = cos(pi * Real(2 * j + 1) / Real(2 * nf));
          const Real v = log(sliced(u) / line::static_profile_weight(ee, u));
          s1 += v;
          s2 += v * v;
        }
        const Real misfit = s2 / nf - (s1 / nf) * (s1 / nf);
        if (misfit < best * Real(0.9)) best = misfit, epsilon = ee;
      }
      std::vector<Real> g(n);
      for (int j = 0; j < n; ++j) {
        const Real u = cos(pi * Real(2 * j + 1) / Real(2 * n));
        g[j] =
            log(4 * sliced(u) / (c1 * a_ref * a_ref * line::static_profile_weight(epsilon, u))) / 2;
      }
      for (int k = 0; k < n; ++k) {
        using std::cos;
        Real s = 0;
        for (int j = 0; j < n; ++j) s += g[j] * cos(pi * Real(k) * Real(2 * j + 1) / Real(2 * n));
        x[k] = s * (k == 0 ? Real(1) : Real(2)) / Real(n);
      }
      x[n] = 0;
      x[n + 1] = mid / l_ref;
      x[n + 2] = (hmin + level) / scale;
    }
    out.epsilon = epsilon;
    return x;
  }
  // omega of (G3) and ln((1 - t^2)/omega) (0 for e = +inf), at the points of a discretisation.
  /// omega(t) of (G3) with the end layer `epsilon`.
  Real weight(Real t) const { return line::static_profile_weight(epsilon, t); }
  /// ln((1 - t^2)/omega), 0 for e = +inf.
  Real log_ratio(Real t) const {
    using std::log;
    return epsilon < std::numeric_limits<Real>::infinity()
               ? Real(log(((1 - t) * (1 + t) + epsilon * epsilon) / (1 + epsilon * epsilon)))
               : Real(0);
  }

  // ---- Residual and Jacobian of (G1) at tc (scaled by C1 a_ref^2) and (G2) (relative).
  /// The residual r of (G1), (G2) at the unknowns xv on the discretisation `mat`, its Jacobian
  /// if `jac`, F's Chebyshev tail if `tail_out`; false where xv is not admissible.
  bool evaluate(const StaticProfileMatrices<Real>& mat, const Vector& xv, Vector& r, Matrix* jac,
                Real* tail_out) {
    using std::abs;
    using std::exp;
    end_note.clear();
    const Vector alpha = xv.head(n);
    const Real lam = xv[n], l = l_ref * exp(lam), c = l_ref * xv[n + 1], dd = xv[n + 2];
    if (!inside(c - l) && c - l != ymin) {
      end_note = "y_minus";
      return false;
    }
    if (!inside(c + l) && c + l != ymax) {
      end_note = "y_plus";
      return false;
    }
    const Vector gx = mat.tx * alpha, gt = mat.tt * alpha;
    Vector fx(mat.m + 1);  // omega exp(2g) at xl: F0 / (C1 a_ref^2/4)
    for (int j = 0; j <= mat.m; ++j) fx[j] = weight(mat.xl[j]) * exp(2 * gx[j]);
    if (tail_out != nullptr) {
      const Vector tc2 = mat.tail * fx;
      *tail_out = std::max(abs(tc2[0]), abs(tc2[1])) / fx.cwiseAbs().maxCoeff();
    }
    const Vector fp = mat.fp * fx;
    const Real lg = log16 + 2 * lam;  // ln(16 l^2/a_ref^2)
    r.resize(nc + 1);
    if (jac != nullptr) jac->setZero(nc + 1, nu);
    for (int i = 0; i < nc; ++i) {
      const Real t = mat.tc[i], y = c + l * t;
      const Real ft = weight(t) * exp(2 * gt[i]), lr = log_ratio(t);
      // (G1): FP + F0 ln(16 l^2 (1 - t^2)/a^2) + C1 a^2/4 + h - d, a^2 = a_ref^2 omega e^2g.
      r[i] = (fp[i] + ft * (lg + lr - 2 * gt[i] + 1)) / 4 + (profile.drop(y) - dd * scale) / scale;
      if (jac != nullptr) {
        const Real slope = profile.drop_slope(y) / scale;
        for (int k = 0; k < n; ++k) {
          Real s = 0;
          for (int j = 0; j <= mat.m; ++j) s += mat.fp(i, j) * fx[j] * mat.tx(j, k);
          (*jac)(i, k) = (2 * s + 2 * ft * mat.tt(i, k) * (lg + lr - 2 * gt[i])) / 4;
        }
        (*jac)(i, n) = ft / 2 + slope * l * t;
        (*jac)(i, n + 1) = slope * l_ref;
        (*jac)(i, n + 2) = -1;
      }
    }
    // (G2): l int F dt (C1 a_ref^2/4) = compliance load.
    const Real factor = l * scale / 4 / compliance_load;
    r[nc] = factor * mat.q.dot(fx) - 1;
    if (jac != nullptr) {
      for (int k = 0; k < n; ++k) {
        Real s = 0;
        for (int j = 0; j <= mat.m; ++j) s += mat.q[j] * fx[j] * mat.tx(j, k);
        (*jac)(nc, k) = 2 * factor * s;
      }
      (*jac)(nc, n) = r[nc] + 1;
    }
    for (Eigen::Index i = 0; i < r.size(); ++i)
      if (!(boost::math::isfinite)(r[i])) return false;
    return jac == nullptr || jac->allFinite();
  }

  /// Newton's method with backtracking from x, M doubling while F's tail is above tolerance; false
  /// (with `out` the stop) where the start is not admissible or the Jacobian singular.
  bool newton(Vector& x) {
    using std::abs;
    using std::cbrt;
    m = std::max(4 * n, 32);
    // ---- Newton's method with backtracking, at M + 1 points; M doubles while F's Chebyshev tail
    // is above eps^(2/3).
    tolerance = 64 * eps * (1 + abs(log16));
    // F's last two Chebyshev coefficients at M + 1 points, relative: eps^(2/3) (4e-11 in double)
    // bounds the quadrature error of FP and (G2) far below the discretisation's.
    tail_tolerance = cbrt(eps * eps);
    Vector r(nc + 1), rt(nc + 1);
    Matrix jac(nc + 1, nu);
    int iterations = 0;
    converged = false, blocked = false;
    rnorm = std::numeric_limits<Real>::infinity(), tail = 0;
    for (; m <= 1024; m *= 2) {
      const StaticProfileMatrices<Real> mat(n, m);
      converged = false;
      if (!evaluate(mat, x, r, &jac, &tail))
        return fail(StopCode::outside_domain, "the starting guess is not admissible");
      rnorm = r.template lpNorm<Eigen::Infinity>();
      for (int it = 0; it < 100; ++it) {
        ++iterations;
        const Vector step = jac.colPivHouseholderQr().solve(-r);
        if (!step.allFinite())
          return fail(StopCode::singular_jacobian, "singular Jacobian of (G1), (G2)");
        Real mu = 1;
        bool accepted = false;
        blocked = false;
        for (int back = 0; back < 40; ++back, mu /= 2) {
          const Vector xt = x + mu * step;
          if (!evaluate(mat, xt, rt, nullptr, nullptr)) {
            if (!end_note.empty()) blocked = true;
            continue;
          }
          const Real tn = rt.template lpNorm<Eigen::Infinity>();
          if (tn < rnorm || (tn <= tolerance && rnorm <= tolerance)) {
            x = xt;
            accepted = true;
            break;
          }
        }
        if (!accepted) break;
        evaluate(mat, x, r, &jac, &tail);
        const Real previous = rnorm;
        rnorm = r.template lpNorm<Eigen::Infinity>();
        if (rnorm <= tolerance &&
            (mu * step.template lpNorm<Eigen::Infinity>() < 1e3 * eps || !(rnorm < previous / 2))) {
          converged = true;
          break;
        }
      }
      out.points = m;
      if (!converged || tail <= tail_tolerance) break;
    }
    out.iterations = iterations;
    out.residual = rnorm;
    return true;
  }
  /// The result at the unknowns x: the contact, its nodes and the verdicts (a stop, an
  /// under-resolved F0, the resolution and the slenderness warnings).
  void finish(const Vector& x) {
    using std::exp;
    // ---- The result.
    const Real l = l_ref * exp(x[n]), c = l_ref * x[n + 1];
    out.y_minus = c - l;
    out.y_plus = c + l;
    out.d = x[n + 2] * scale;
    out.alpha.assign(x.data(), x.data() + n);
    {
      const StaticProfileMatrices<Real> mat(n, std::min(m, 1024));
      for (int j = mat.m; j >= 0; --j) {
        const Real y = j == mat.m ? out.y_minus : j == 0 ? out.y_plus : c + l * mat.xl[j];
        out.y.push_back(y);
        out.a_nodes.push_back(out.a(y));
        out.f0_nodes.push_back(out.f0(y));
      }
    }
    if (!converged) {
      // The body end is the verdict where slicing (which overestimates the length) was clipped by
      // it, or where Newton's trial steps left the body from a contact within a quarter of its
      // half length of an end; elsewhere a blocked step is only the iteration's failure.
      const bool near_end = out.y_minus - ymin < l / 4 || ymax - out.y_plus < l / 4;
      if ((blocked && near_end) || clip_minus || clip_plus) {
        add_warning(out, WarningCode::contact_at_roller_end,
                    "the contact reaches the roller's body end (y_min = " + text(ymin) +
                        ", y_max = " + text(ymax) +
                        "): outside the line theory, no solution is returned");
        fail(StopCode::contact_reaches_body_end, "the contact reaches the roller's body end");
        return;
      }
      // A contact not much longer than wide is outside the line theory, which needs l >> a: its
      // equations may then have no root; say so (the line solver's slenderness warning is l/a < 3).
      const Real slenderness = l / a_ref;
      fail(StopCode::tolerance_not_met,
           "Newton's method stopped at residual " + text(rnorm) + " above the tolerance " +
               text(tolerance) + (m > 1024 ? " (F0 not resolved by 1025 points)" : "") +
               (slenderness < 3
                    ? "; the contact found is not slender (half length " + text(l) + ", " +
                          text(slenderness) + " times the half width): outside the line theory"
                    : std::string()));
      return;
    }
    if (tail > tail_tolerance) {
      fail(StopCode::under_resolved,
           "F0 is not resolved by 1025 interpolation points (Chebyshev tail " + text(tail) +
               "): lower the terms");
      return;
    }
    out.converged = true;
    {
      // The resolution: the collocation points' spacing against the local half width (docs/
      // theory.md, (G5): (G1) is not elliptic on scales below ~ 3 a, so a finer discretisation
      // resolves what the line theory does not describe).
      const StaticProfileMatrices<Real> mat(n, 8);
      Real worst = std::numeric_limits<Real>::infinity();
      for (int i = 0; i + 1 < nc; ++i) {
        const Real ya = c + l * mat.tc[i + 1], yb = c + l * mat.tc[i];
        worst = std::min(worst, Real((yb - ya) / out.a((ya + yb) / 2)));
      }
      out.spacing = worst;
      if (!(worst >= 1))
        add_warning(out, WarningCode::collocation_spacing,
                    "the collocation points are " + text(worst) +
                        " half widths apart somewhere (below 1): the discretisation "
                        "resolves scales below a(y), where (G1) is not elliptic (docs/"
                        "theory.md, \"Line contact for any roller profile (static)\"); "
                        "lower the terms");
    }
    Real amax = 0;
    for (const Real av : out.a_nodes) amax = std::max(amax, av);
    if (!(l >= 3 * amax))
      add_warning(out, WarningCode::short_contact,
                  "l/max a(y) = " + text(l / amax) +
                      " < 3: outside the line-contact theory's domain of validity");
  }
};

}  // namespace viscoroll::detail
