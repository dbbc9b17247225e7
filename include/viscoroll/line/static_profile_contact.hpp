// viscoroll: the static (elastic, V tau = 0) line contact of a roller of any profile.
//
// Panek & Kalker (1980), Eqs. (33), (34), (47) at V tau = 0 for a drop h(y) in place of
// C2 y^2/2 and a contact [y_-, y_+] that need not be symmetric (docs/theory.md, "Line contact for
// any roller profile (static)"): with b = 0, G = 0 and F0 = C1 a^2/4,
//   (G1)  FP[F0](y) + F0(y) ln[16 (y_+ - y)(y - y_-)/a^2] + C1 a^2/4 + h(y) - d = 0,
//   (G2)  int_{y_-}^{y_+} F0 dy = compliance * load,
// the log term being (34)'s 16 (l^2 - y^2) = 16 (l - y)(l + y) with the distances to the ends.
// The half width is
//   (G3)  a(y) = a_ref sqrt(omega(t)) exp(g(t)),  g = sum_{k<N} alpha_k T_k(t),
//         t = (2y - y_+ - y_-)/(y_+ - y_-),  omega = (1 + e^2)(1 - t^2)/(1 - t^2 + e^2),
// a square root at both ends as in (48), no parity, and an end layer e (omega = 1 - t^2 for
// e = +inf, which makes alpha = 0 Kalker's ellipse; a small e is a flat contact with short ends),
// chosen once from the sliced starting guess. The unknowns alpha_k, ln l (l the half length), the
// centre c = (y_+ + y_-)/2 and d meet (G1) at the N + 2 roots of T_{N+2}(t) and (G2): a square
// system, solved by Newton's method with an analytic Jacobian and backtracking.
//
// In t, F0 = (C1 a_ref^2/4) omega(t) exp(2 g(t)) is analytic on [-1, 1], and the finite part is
// scale free, FP[F0](y) = int_{-1}^{1} (F(t') - F(t))/|t' - t| dt'
// (dy' = l dt', |y' - y| = l|t' - t|): F is interpolated at M + 1 Chebyshev-Lobatto points, and
// FP of each T_n is a polynomial in closed form (G4), so that FP at the collocation points and the
// load are fixed matrices applied to the values of F; M doubles until F's Chebyshev tail is below
// eps^(2/3).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>
#include <viscoroll/roller/profile.hpp>

namespace viscoroll {

/// The static line contact of a roller profile: the contact [y_minus, y_plus], the penetration d,
/// the half width a(y) of (G3) and the load per length F0(y) = C1 a(y)^2/4 (Eq. 33 at V tau = 0).
///
/// Members:
///   - `y_minus`, `y_plus`, `d`; `c1`, `a_ref`, `alpha` (the coefficients of (G3));
///   - `a(y)`, `f0(y)`: zero outside the contact;
///   - `y`, `a_nodes`, `f0_nodes`: a(y), F0(y) at the M + 1 Chebyshev-Lobatto points of the
///     contact (ends included, where both are 0), from y_minus to y_plus;
///   - `converged` (the residual of (G1), (G2) is below `tolerance`), `reason` when it is not,
///     `residual` (the largest, (G1) in units of C1 a_ref^2, (G2) relative), `iterations`, `points`
///     (M);
///   - `warnings`: the contact reaches the roller's body end (outside the theory: the result is
///     then not converged), or is not slender (l/max a < 3).
/// omega(t) of (G3) with end layer e: 1 - t^2 for e = +inf, else (1 + e^2)(1 - t^2)/(1 - t^2 +
/// e^2), which rises from the ends over 1 - t^2 ~ e^2 to 1 (a flat contact with short ends).
template <RealScalar Real>
Real static_profile_weight(Real e, Real t) {
  const Real w = (1 - t) * (1 + t);
  if (!(e < std::numeric_limits<Real>::infinity())) return w;
  return (1 + e * e) * w / (w + e * e);
}

template <RealScalar Real>
struct StaticProfileContact {
  Real y_minus, y_plus, d;
  Real c1, a_ref;
  Real epsilon = std::numeric_limits<Real>::infinity();  ///< the end layer of (G3), +inf: none
  std::vector<Real> alpha;
  std::vector<Real> y, a_nodes, f0_nodes;
  bool converged = false;
  std::string reason;
  StopCode code = StopCode::converged;  ///< `reason` as a code (core/outcome.hpp)
  std::vector<std::string> warnings;
  std::vector<WarningCode> warning_codes;  ///< the warnings' codes, index for index
  Real residual = std::numeric_limits<Real>::quiet_NaN();
  int iterations = 0;
  int points = 0;
  /// the smallest spacing of the collocation points in units of the local a(y) (NaN if not
  /// converged); a warning below 1
  Real spacing = std::numeric_limits<Real>::quiet_NaN();

  Real half_length() const { return (y_plus - y_minus) / 2; }
  Real centre() const { return (y_plus + y_minus) / 2; }
  /// t of (G3) for y in the contact.
  Real t(Real yy) const { return (2 * yy - y_plus - y_minus) / (y_plus - y_minus); }
  /// a(y), Eq. (G3); 0 outside (y_minus, y_plus).
  Real a(Real yy) const {
    using std::exp;
    using std::sqrt;
    if (!(yy > y_minus && yy < y_plus)) return 0;
    const Real u = t(yy);
    return a_ref * sqrt(weight(u)) * exp(series(u));
  }
  /// omega(t) of (G3): 1 - t^2 for epsilon = +inf, else (1 + e^2)(1 - t^2)/(1 - t^2 + e^2).
  Real weight(Real u) const { return static_profile_weight(epsilon, u); }
  /// F0(y) = C1 a^2/4 (Eq. 33 at V tau = 0).
  Real f0(Real yy) const {
    const Real h = a(yy);
    return c1 * h * h / 4;
  }
  /// sum alpha_k T_k(u) (Clenshaw).
  Real series(Real u) const {
    Real b1 = 0, b2 = 0;
    for (int k = int(alpha.size()) - 1; k >= 1; --k) {
      const Real b0 = 2 * u * b1 - b2 + alpha[k];
      b2 = b1;
      b1 = b0;
    }
    return alpha.empty() ? Real(0) : Real(u * b1 - b2 + alpha[0]);
  }
};

namespace detail {

/// int_{-1}^{1} T_n = (1 + (-1)^n)/(1 - n^2) (0 for odd n).
template <class Real>
Real chebyshev_integral(int n) {
  return n % 2 == 1 ? Real(0) : Real(2) / Real(1 - n * n);
}

/// FP[T_n](t) = int_{-1}^{1} (T_n(t') - T_n(t))/|t' - t| dt' for n = 0..m (docs/theory.md, (G4)):
/// from T_{n+1}(t') = 2 t' T_n(t') - T_{n-1}(t'),
///   P_{n+1} = 2 t P_n - P_{n-1} + 2 [J_n(1) - 2 J_n(t)],  J_n(t) = int_{-1}^{t} T_n,
/// P_0 = 0, P_1 = -2t; J_0 = t + 1, J_1 = (t^2 - 1)/2,
/// J_n = T_{n+1}/(2(n+1)) - T_{n-1}/(2(n-1)) - (-1)^n/(n^2 - 1) (n >= 2), J_n(1) = int T_n.
template <class Real>
void finite_part_chebyshev(Real t, int m, std::vector<Real>& p) {
  p.assign(m + 1, Real(0));
  std::vector<Real> T(m + 2);
  T[0] = 1;
  T[1] = t;
  for (int n = 1; n <= m; ++n) T[n + 1] = 2 * t * T[n] - T[n - 1];
  const auto j_at = [&](int n) -> Real {  // J_n(t)
    if (n == 0) return t + 1;
    if (n == 1) return (t * t - 1) / 2;
    const Real sign = n % 2 == 0 ? Real(1) : Real(-1);
    return T[n + 1] / (2 * (n + 1)) - T[n - 1] / (2 * (n - 1)) - sign / Real(n * n - 1);
  };
  if (m >= 1) p[1] = -2 * t;
  for (int n = 1; n < m; ++n)
    p[n + 1] = 2 * t * p[n] - p[n - 1] + 2 * (chebyshev_integral<Real>(n) - 2 * j_at(n));
}

/// The discretisation of (G1), (G2) at N terms and M + 1 interpolation points, in t: fixed
/// matrices (they depend on N and M only).
template <class Real>
struct StaticProfileMatrices {
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  int n, m;
  Vector tc;    ///< collocation points, the roots of T_{N+2}
  Vector xl;    ///< interpolation points cos(pi j/M), j = 0..M
  Matrix fp;    ///< FP at tc from the values at xl, (N + 2) x (M + 1)
  Vector q;     ///< int_{-1}^{1} from the values at xl (Clenshaw-Curtis)
  Matrix tail;  ///< the last two Chebyshev coefficients from the values at xl, 2 x (M + 1)
  Matrix tx;    ///< T_k(xl_j), (M + 1) x N
  Matrix tt;    ///< T_k(tc_i), (N + 2) x N

  StaticProfileMatrices(int terms, int m_points) : n(terms), m(m_points) {
    using std::cos;
    const Real pi = boost::math::constants::pi<Real>();
    const int nc = n + 2;
    tc.resize(nc);
    for (int i = 0; i < nc; ++i) tc[i] = cos(pi * Real(2 * i + 1) / Real(2 * nc));
    xl.resize(m + 1);
    for (int j = 0; j <= m; ++j) xl[j] = cos(pi * Real(j) / Real(m));
    // Values -> Chebyshev coefficients (DCT-I): c_k = (2/M) sum'' F_j cos(pi k j/M), c_0, c_M
    // halved.
    Matrix coef(m + 1, m + 1);
    for (int k = 0; k <= m; ++k)
      for (int j = 0; j <= m; ++j) {
        Real w = Real(2) / Real(m) * cos(pi * Real((long long)k * j % (2 * m)) / Real(m));
        if (j == 0 || j == m) w /= 2;
        if (k == 0 || k == m) w /= 2;
        coef(k, j) = w;
      }
    Matrix p(nc, m + 1);
    std::vector<Real> row;
    for (int i = 0; i < nc; ++i) {
      finite_part_chebyshev(tc[i], m, row);
      for (int k = 0; k <= m; ++k) p(i, k) = row[k];
    }
    fp = p * coef;
    Vector integral(m + 1);
    for (int k = 0; k <= m; ++k) integral[k] = chebyshev_integral<Real>(k);
    q = coef.transpose() * integral;
    tail = coef.bottomRows(2);
    tx = chebyshev_table(xl, n);
    tt = chebyshev_table(tc, n);
  }

  static Matrix chebyshev_table(const Vector& u, int n) {
    Matrix t(u.size(), n);
    for (Eigen::Index i = 0; i < u.size(); ++i) {
      Real a = 1, b = u[i];
      for (int k = 0; k < n; ++k) {
        t(i, k) = a;
        const Real c = 2 * u[i] * b - a;
        a = b;
        b = c;
      }
    }
    return t;
  }
};

}  // namespace detail

/// The static line contact of `profile` under compliance_load = (1 - nu)/(2 pi mu) * P > 0 (Eq.
/// (47)), with N = terms coefficients in (G3) (1 <= terms <= 64; the default 12 keeps the points
/// more than a half width apart for contacts 15 or more half widths long, docs/theory.md (G5)).
/// Throws std::invalid_argument naming the parameter; a Newton iteration that does not converge, or
/// a contact that reaches the roller's body end, is returned with converged == false, the reason
/// and (for the end) a warning.
template <RollerProfile P>
StaticProfileContact<typename P::real_type> static_profile_contact(
    const P& profile, typename P::real_type compliance_load, int terms = 12) {
  using Real = typename P::real_type;
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  using std::abs;
  using std::cbrt;
  using std::exp;
  using std::log;
  using std::sqrt;
  detail::require_positive("compliance * load", compliance_load);
  detail::require(terms >= 1 && terms <= 64, "terms", terms, "1 <= terms <= 64");
  const Real c1 = profile.c1();
  detail::require_positive("c1", c1);
  const Real ymin = profile.y_min(), ymax = profile.y_max();
  detail::require(ymin < ymax, "y_min", ymin, "y_min < y_max");
  const Real eps = std::numeric_limits<Real>::epsilon();
  const auto text = [](Real x) { return detail::format_value(x); };
  const auto inside = [&](Real y) { return y > ymin && y < ymax; };

  StaticProfileContact<Real> out{};
  out.c1 = c1;
  const auto fail = [&](StopCode code, std::string why) {
    out.converged = false;
    out.code = code;
    out.reason = std::move(why);
    return out;
  };

  // ---- The starting guess: slicing, F0 = (D - (h - h_min))/kappa, kappa = ln(16 l^2/a^2) + 1,
  // (G1) without its finite part (docs/theory.md, "Line contact for any roller profile").
  // A length scale: the ellipsoid's a0^3 rho = 3 compliance load / C1.
  const Real len0 = cbrt(compliance_load / c1);
  Real y0 = (boost::math::isfinite)(ymin) && (boost::math::isfinite)(ymax) ? (ymin + ymax) / 2
            : inside(Real(0))                                              ? Real(0)
            : (boost::math::isfinite)(ymin)                                ? ymin + len0
                                                                           : ymax - len0;
  const auto clamp_in = [&](Real y) {
    // Keeps y strictly inside the body (by a relative 1e-9 of the step scale).
    const Real margin = 1e-9 * (abs(y) + len0);
    return std::min(std::max(y, Real(ymin + margin)), Real(ymax - margin));
  };
  // The lowest point y* of h: walk downhill with doubling steps, then bisect the slope's sign.
  Real ystar = y0;
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
  const Real hmin = profile.drop(ystar);
  // The ends of {h - h_min < D} (clipped at the body's ends; `clipped` says so).
  const auto edge = [&](Real level, Real dir, bool& clipped) {
    Real lo = ystar, step = len0 / 64, hi = ystar;
    clipped = false;
    for (int k = 0; k < 400; ++k) {
      hi = clamp_in(ystar + dir * step);
      if (profile.drop(hi) - hmin >= level) break;
      if (hi != ystar + dir * step) {
        clipped = true;
        return hi;
      }
      lo = hi;
      step *= 2;
    }
    for (int k = 0; k < 200 && abs(hi - lo) > 4 * eps * (abs(lo) + len0); ++k) {
      const Real mid = (lo + hi) / 2;
      (profile.drop(mid) - hmin < level ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
  };
  Real kappa = 10, level = c1 * len0 * len0, e_minus = 0, e_plus = 0, f0max = 0;
  bool clip_minus = false, clip_plus = false;
  const auto slice_load = [&](Real lev) {
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
  };
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
  const Real a_ref = sqrt(4 * f0max / c1);
  const Real l_ref = (e_plus - e_minus) / 2;
  out.a_ref = a_ref;

  const Real scale = c1 * a_ref * a_ref;  // of (G1)
  const Real log16 = log(16 * l_ref * l_ref / (a_ref * a_ref));

  // ---- Unknowns x: alpha_0..alpha_{N-1}, lambda = ln(l/l_ref), gamma = c/l_ref,
  // delta = d/(C1 a_ref^2).
  const int n = terms, nc = n + 2, nu = n + 3;
  Vector x = Vector::Zero(nu);
  Real epsilon = std::numeric_limits<Real>::infinity();
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
        const Real v = log(sliced(u) / static_profile_weight(ee, u));
        s1 += v;
        s2 += v * v;
      }
      const Real misfit = s2 / nf - (s1 / nf) * (s1 / nf);
      if (misfit < best * Real(0.9)) best = misfit, epsilon = ee;
    }
    std::vector<Real> g(n);
    for (int j = 0; j < n; ++j) {
      const Real u = cos(pi * Real(2 * j + 1) / Real(2 * n));
      g[j] = log(4 * sliced(u) / (c1 * a_ref * a_ref * static_profile_weight(epsilon, u))) / 2;
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
  // omega of (G3) and ln((1 - t^2)/omega) (0 for e = +inf), at the points of a discretisation.
  const auto weight = [&](Real t) { return static_profile_weight(epsilon, t); };
  const auto log_ratio = [&](Real t) {
    return epsilon < std::numeric_limits<Real>::infinity()
               ? Real(log(((1 - t) * (1 + t) + epsilon * epsilon) / (1 + epsilon * epsilon)))
               : Real(0);
  };

  // ---- Residual and Jacobian of (G1) at tc (scaled by C1 a_ref^2) and (G2) (relative).
  int m = std::max(4 * n, 32);
  std::string end_note;
  const auto evaluate = [&](const detail::StaticProfileMatrices<Real>& mat, const Vector& xv,
                            Vector& r, Matrix* jac, Real* tail) -> bool {
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
    if (tail != nullptr) {
      const Vector tc2 = mat.tail * fx;
      *tail = std::max(abs(tc2[0]), abs(tc2[1])) / fx.cwiseAbs().maxCoeff();
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
  };

  // ---- Newton's method with backtracking, at M + 1 points; M doubles while F's Chebyshev tail
  // is above eps^(2/3).
  const Real tolerance = 64 * eps * (1 + abs(log16));
  // F's last two Chebyshev coefficients at M + 1 points, relative: eps^(2/3) (4e-11 in double)
  // bounds the quadrature error of FP and (G2) far below the discretisation's.
  const Real tail_tolerance = cbrt(eps * eps);
  Vector r(nc + 1), rt(nc + 1);
  Matrix jac(nc + 1, nu);
  int iterations = 0;
  bool converged = false, blocked = false;
  Real rnorm = std::numeric_limits<Real>::infinity(), tail = 0;
  for (; m <= 1024; m *= 2) {
    const detail::StaticProfileMatrices<Real> mat(n, m);
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

  // ---- The result.
  const Real l = l_ref * exp(x[n]), c = l_ref * x[n + 1];
  out.y_minus = c - l;
  out.y_plus = c + l;
  out.d = x[n + 2] * scale;
  out.alpha.assign(x.data(), x.data() + n);
  {
    const detail::StaticProfileMatrices<Real> mat(n, std::min(m, 1024));
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
      return fail(StopCode::contact_reaches_body_end, "the contact reaches the roller's body end");
    }
    // A contact not much longer than wide is outside the line theory, which needs l >> a: its
    // equations may then have no root; say so (the line solver's slenderness warning is l/a < 3).
    const Real slenderness = l / a_ref;
    return fail(StopCode::tolerance_not_met,
                "Newton's method stopped at residual " + text(rnorm) + " above the tolerance " +
                    text(tolerance) + (m > 1024 ? " (F0 not resolved by 1025 points)" : "") +
                    (slenderness < 3
                         ? "; the contact found is not slender (half length " + text(l) + ", " +
                               text(slenderness) + " times the half width): outside the line theory"
                         : std::string()));
  }
  if (tail > tail_tolerance)
    return fail(StopCode::under_resolved,
                "F0 is not resolved by 1025 interpolation points (Chebyshev tail " + text(tail) +
                    "): lower the terms");
  out.converged = true;
  {
    // The resolution: the collocation points' spacing against the local half width (docs/
    // theory.md, (G5): (G1) is not elliptic on scales below ~ 3 a, so a finer discretisation
    // resolves what the line theory does not describe).
    const detail::StaticProfileMatrices<Real> mat(n, 8);
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
  return out;
}

}  // namespace viscoroll
