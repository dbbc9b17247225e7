// viscoroll: a substrate's influence coefficients for the boundary-element solver (docs/bem.md,
// B15-B18).
//
// A body whose surface factor T(q) (core/concepts.hpp, Substrate) tends to 1 at short waves
// responds to a point load as the half space plus a smooth radial correction,
//   G(r) = c [1/r + D(r)],   D(r) = int_0^inf (T(q) - 1) J0(q r) dq                    (B15)
// (the inverse Hankel transform of (H1) less the half space's 1/r). D is analytic within about
// a thickness of the real axis and tends to (T(0) - 1)/r beyond a few thicknesses: on a rigid
// base (T(0) = 0) it cancels the half space's 1/r, and the body's kernel decays exponentially.
// The solver adds D's cell integrals and their memory integrals (B3) to the half space's (B16),
// (B17). A local bed (T = q l) sinks under its own cell only (B18).
#pragma once

#include <algorithm>
#include <array>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>
#include <viscoroll/bem/rectangle_influence.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

namespace viscoroll {
namespace bem {

/// A function on [lo, lo + panels width] as Chebyshev series of 16 terms on equal panels: the
/// tables of (B15) and (B17). `fill(f)` samples f at each panel's Chebyshev points of the first
/// kind and forms the coefficients (the discrete cosine transform); `operator()(s)` sums a
/// panel's series by Clenshaw's recurrence.
template <RealScalar W>
class ChebyshevPanels {
 public:
  /// The Chebyshev terms per panel.
  static constexpr int terms = 16;

  /// Tabulates f on [lo, lo + panels width] in panels of the given width.
  template <class F>
  void fill(W lo, W width, int panels, F&& f) {
    const W pi = boost::math::constants::pi<W>();
    lo_ = lo;
    width_ = width;
    coefficients_.assign(static_cast<std::size_t>(panels), {});
    std::array<W, terms> values{};
    for (int k = 0; k < panels; ++k) {
      for (int j = 0; j < terms; ++j)
        values[static_cast<std::size_t>(j)] =
            f(lo + width * (W(k) + (std::cos(pi * (W(j) + W(0.5)) / W(terms)) + 1) / 2));
      auto& c = coefficients_[static_cast<std::size_t>(k)];
      for (int n = 0; n < terms; ++n) {
        W sum = 0;
        for (int j = 0; j < terms; ++j)
          sum += values[static_cast<std::size_t>(j)] *
                 std::cos(pi * W(n) * (W(j) + W(0.5)) / W(terms));
        c[static_cast<std::size_t>(n)] = (n == 0 ? W(1) : W(2)) * sum / W(terms);
      }
    }
  }

  /// Whether nothing is tabulated yet.
  bool empty() const { return coefficients_.empty(); }
  /// The table's lower end.
  W lo() const { return lo_; }
  /// The table's upper end.
  W hi() const { return lo_ + width_ * W(coefficients_.size()); }

  /// The tabulated function at s, lo() <= s <= hi().
  W operator()(W s) const {
    const auto p = std::min(static_cast<std::size_t>((s - lo_) / width_), coefficients_.size() - 1);
    const auto& c = coefficients_[p];
    const W t = 2 * (s - lo_ - width_ * W(p)) / width_ - 1, t2 = 2 * t;
    W b1 = 0, b2 = 0;
    for (int n = terms - 1; n >= 1; --n) {
      const W b = c[static_cast<std::size_t>(n)] + t2 * b1 - b2;
      b2 = b1;
      b1 = b;
    }
    return c[0] + t * b1 - b2;
  }

 private:
  W lo_ = 0, width_ = 1;
  std::vector<std::array<W, terms>> coefficients_;
};

/// J0 by Boost's rational approximations for order 0 (bessel_j0.hpp), 18 times faster here than
/// the generic cyl_bessel_j, which promotes double to long double and dispatches on the order.
template <RealScalar W>
W j0(W x) {
  return boost::math::detail::bessel_j0(x);
}

/// (B15) in units of the thickness h: d(rho) = h D(rho h) = int_0^inf (T(x/h) - 1) J0(x rho) dx,
/// tabulated once per body on panels of half a thickness by Chebyshev series of 16 terms (D is
/// analytic for |Im rho| < 1, so each panel's series converges as 7.9^-n), out to the reach
/// rho_max beyond which d = (T(0) - 1)/rho to 4096 eps relative to 1/rho.
///   - RadialCorrection(t, t0): t(x) = T(x/h) (x = q h), t0 = T(0);
///   - operator()(rho): d(rho) for rho >= 0;
///   - direct(rho): the Hankel quadrature itself (below);
///   - reach(): rho_max; far_factor(): T(0) - 1.
template <RealScalar W>
class RadialCorrection {
 public:
  /// t(x) = T(x/h) (x = q h) and t0 = T(0).
  RadialCorrection(std::function<W(W)> t, W t0) : t_(std::move(t)), t0_(t0) {
    const W eps = std::numeric_limits<W>::epsilon();
    // x_max: T - 1 below eps/64 at two consecutive integers (the concept: |T - 1| decays at
    // least as e^-x).
    int below = 0;
    for (int x = 1; x <= 400 && below < 2; ++x) {
      const W v = t_(W(x)) - 1;
      if (!(std::abs(static_cast<double>(v)) < 1e300))
        detail::require(false, "surface_factor(q)", t_(W(x)), "finite at every q");
      below = std::abs(v) <= eps / 64 ? below + 1 : 0;
      x_max_ = W(x);
    }
    detail::require(below >= 2, "surface_factor(400/thickness) - 1", t_(W(400)) - 1,
                    "|T(q) - 1| <= eps/64 by q = 400/thickness (it must decay as e^(-q h))");
    // The reach: the first multiple of 2 from 4 on where d is its far field to 4096 eps at two
    // consecutive points.
    const W tol = 4096 * eps;
    int ok = 0;
    W rho = 4;
    for (; rho <= 4000 && ok < 2; rho += 2) {
      prepare(level(rho));
      ok = std::abs(direct(rho) - (t0_ - 1) / rho) * rho <= tol ? ok + 1 : 0;
    }
    detail::require(ok >= 2, "the substrate kernel's reach", rho,
                    "a body's kernel must reach its far field (T(0) - 1)/r within 4000 thickness");
    rho_max_ = rho;
    // Chebyshev series of d on panels of half a thickness.
    const int panels = static_cast<int>(std::ceil(static_cast<double>(rho_max_ / width)));
    table_.fill(W(0), width, panels, [&](W r) { return direct(r); });
  }

  /// d(rho), rho >= 0: the panel's series by Clenshaw's recurrence, or the far field.
  W operator()(W rho) const {
    if (rho >= rho_max_) return (t0_ - 1) / rho;
    return table_(rho);
  }

  /// (B15) by quadrature: 16-point Gauss-Legendre on panels of 2^-k in x up to x_max, the
  /// largest not over 1 nor 10/rho (J0(x rho) turns by at most 10 radians on one: the rule's
  /// error is below (5/2)^32/32! ~ 1e-23; T - 1 is analytic about a unit from the axis: 3.7^-32).
  W direct(W rho) const {
    const int k = level(rho);
    if (static_cast<std::size_t>(k) < levels_.size()) {
      W s = 0;
      for (const auto& [x, w] : levels_[static_cast<std::size_t>(k)]) s += w * j0(x * rho);
      return s;
    }
    W s = 0;
    for (const auto& [x, w] : nodes_of(k)) s += w * (t_(x) - 1) * j0(x * rho);
    return s;
  }

  /// rho_max, beyond which d = (T(0) - 1)/rho.
  W reach() const { return rho_max_; }
  /// T(0) - 1.
  W far_factor() const { return t0_ - 1; }

 private:
  /// The panel level of rho: panels of 2^-k, k the least with 2^-k <= min(1, 10/rho).
  static int level(W rho) {
    int k = 0;
    while (std::ldexp(W(1), -k) * rho > 10) ++k;
    return k;
  }

  /// The nodes and weights of level k on [0, x_max].
  std::vector<std::pair<W, W>> nodes_of(int k) const {
    const W w = std::ldexp(W(1), -k);
    const int panels = static_cast<int>(std::ceil(static_cast<double>(x_max_ / w)));
    const auto& gx = GaussLegendre<W, 16>::nodes();
    const auto& gw = GaussLegendre<W, 16>::weights();
    std::vector<std::pair<W, W>> out;
    for (int p = 0; p < panels; ++p)
      for (std::size_t i = 0; i < 16; ++i)
        out.emplace_back(w * (W(p) + W(0.5)) + w / 2 * gx[i], w / 2 * gw[i]);
    return out;
  }

  /// Levels up to k with their weights times T - 1, evaluated once.
  void prepare(int k) {
    while (static_cast<int>(levels_.size()) <= k) {
      auto nodes = nodes_of(static_cast<int>(levels_.size()));
      for (auto& [x, w] : nodes) w *= t_(x) - 1;
      levels_.push_back(std::move(nodes));
    }
  }

  static constexpr W width = W(0.5);
  std::vector<std::vector<std::pair<W, W>>> levels_;
  std::function<W(W)> t_;
  W t0_;
  W x_max_ = 0, rho_max_ = 0;
  ChebyshevPanels<W> table_;
};

/// What the solver knows of a substrate: its kind, its surface factor T at x = q h, its thickness
/// h (the caller's units) and, for a body, the radial correction (B15); for a local bed its
/// length l = T(q)/q.
template <RealScalar W>
struct SubstrateKernel {
  /// What the substrate is.
  SubstrateKind kind = SubstrateKind::half_space;
  /// h, the thickness (+inf for the half space).
  W thickness = std::numeric_limits<W>::infinity();
  std::function<W(W)> factor;  ///< T(x/h), x = q h
  W local_length = 0;          ///< l of T = q l (a local bed)
  /// A body's radial correction (B15); null for the half space and a local bed.
  std::shared_ptr<const RadialCorrection<W>> radial;

  /// T at the wavenumber q in units where the thickness is h_units.
  W surface_factor(W q, W h_units) const {
    if (kind == SubstrateKind::half_space) return W(1);
    return factor(q * h_units);
  }
};

/// The kernel of `substrate` for Poisson's ratio nu, in the coefficient type W.
template <RealScalar W, Substrate S>
SubstrateKernel<W> substrate_kernel(const S& substrate, W nu) {
  SubstrateKernel<W> k;
  k.kind = S::kind;
  if (k.kind == SubstrateKind::half_space) return k;
  using R = typename S::real_type;
  const W h = W(substrate.thickness());
  detail::require(h > 0 && h < std::numeric_limits<W>::infinity(), "thickness", h,
                  "0 < thickness < inf for a layer or a bed");
  k.thickness = h;
  k.factor = [substrate, nu, h](W x) { return W(substrate.surface_factor(R(x / h), R(nu))); };
  if (k.kind == SubstrateKind::local) {
    // T = q l: l = T(1/h) h, checked against T(2/h) (a local bed is linear in q).
    k.local_length = k.factor(W(1)) * h;
    detail::require(k.local_length > 0, "surface_factor(q)/q of a local bed", k.local_length / h,
                    "> 0");
    return k;
  }
  const W t0 = k.factor(W(0));
  detail::require(t0 >= 0 && t0 < std::numeric_limits<W>::infinity(), "surface_factor(0)", t0,
                  "0 <= T(0) < inf for a body");
  k.radial = std::make_shared<const RadialCorrection<W>>(k.factor, t0);
  return k;
}

/// The rule of the cell integrals of D (B16): subpanels at most h/2 wide, each with the fewest
/// points of 2, 4, 8 whose Bernstein bound (D analytic within h of the axis: ellipse parameter
/// 4 h/w for a subpanel of width w) is below eps. Nodes are offsets from the cell centre, the
/// weights sum to the cell's width.
template <RealScalar W>
std::vector<std::array<W, 2>> cell_rule(W width, W h) {
  using std::log;
  const W eps = std::numeric_limits<W>::epsilon();
  const int sub = std::max(1, static_cast<int>(std::ceil(static_cast<double>(2 * width / h))));
  const W w = width / W(sub);
  const W q = 2 * h / w, rho = q + std::sqrt(q * q - 1);
  const double needed = static_cast<double>(-log(eps) / (2 * log(rho)));
  std::vector<std::array<W, 2>> out;
  const auto add = [&](const auto& nodes, const auto& weights) {
    for (int s = 0; s < sub; ++s) {
      const W mid = -width / 2 + w * (W(s) + W(0.5));
      for (std::size_t i = 0; i < nodes.size(); ++i)
        out.push_back({mid + w / 2 * W(nodes[i]), w / 2 * W(weights[i])});
    }
  };
  if (needed <= 2)
    add(GaussLegendre<W, 2>::nodes(), GaussLegendre<W, 2>::weights());
  else if (needed <= 4)
    add(GaussLegendre<W, 4>::nodes(), GaussLegendre<W, 4>::weights());
  else
    add(GaussLegendre<W, 8>::nodes(), GaussLegendre<W, 8>::weights());
  return out;
}

/// (B16), (B17): the body's correction to one row (offset Y = y) of the half space's table, in
/// the solver's units (thickness h), for the cells hx x hy of a table of offsets i hx, |i| <= m.
/// The row's cell integral k(s) = int int_cell D(s - x', y - y') dx' dy' is tabulated once per
/// row, where the cell is within D's reach, on panels of h/2 by Chebyshev series of 16 terms (k is
/// analytic within h of the axis, as D: 7.9^-16); beyond the reach k is T(0) - 1 times the half
/// space's coefficient (B1), exactly. Every memory term's steps and tail then integrate k.
///   - elastic(hs): k at the offsets, from the half space's Love row hs beyond the reach;
///   - memory(L, hs): the memory integral (B3) of k for the memory length L > 0, from the half
///     space's memory row hs of the same L where every point of a step lies beyond the reach.
template <RealScalar W>
class BodyCorrection {
 public:
  /// `longest`: the longest memory length of the terms to come (0: none, and no table).
  BodyCorrection(const RadialCorrection<W>& d, W h, W hx, W hy, int m, W y, W longest)
      : d_(d),
        h_(h),
        hx_(hx),
        hy_(hy),
        y_(y),
        m_(m),
        reach_(d.reach() * h),
        dy_(std::max(W(0), std::abs(y) - hy / 2)),
        xs_(cell_rule(hx, h)),
        ys_(cell_rule(hy, h)) {
    using std::log;
    using std::sqrt;
    // The whole row beyond the reach, or no memory term: no table (elastic() integrates each
    // offset once).
    if (dy_ >= reach_ || !(longest > 0)) return;
    // k is far for |s| >= s_far; the table covers what the steps and tails reach, [lo, hi] with
    // lo = max(-s_far, -x_m - hx), hi = min(s_far, x_m + hx + longest u_max).
    const W s_far = sqrt(reach_ * reach_ - dy_ * dy_) + hx / 2;
    const W u_max = -log(std::numeric_limits<W>::epsilon()) + 6;
    const W top = std::min(s_far, W(m) * hx + hx + longest * u_max);
    const W lo = std::max(-s_far, -W(m) * hx - hx);
    const W width = h / 2;
    const int panels =
        std::max(1, static_cast<int>(std::ceil(static_cast<double>((top - lo) / width))));
    table_.fill(lo, width, panels, [&](W s) { return cell(s); });
  }

  /// D at (s, y), the caller's units.
  W kernel(W s, W y) const {
    using std::sqrt;
    return d_(sqrt(s * s + y * y) / h_) / h_;
  }

  /// int int_cell D(x - x', y - y') dx' dy' by the rule (B16), at the row's y.
  W cell(W x) const {
    W s = 0;
    for (const auto& b : ys_) {
      W row = 0;
      for (const auto& a : xs_) row += a[1] * kernel(x - a[0], y_ - b[0]);
      s += b[1] * row;
    }
    return s;
  }

  /// k(s): T(0) - 1 times Love's coefficient beyond the reach, the table within it, the rule
  /// itself where there is no table.
  W k(W s) const {
    const W dx = std::max(W(0), std::abs(s) - hx_ / 2);
    if (far(dx)) return d_.far_factor() * rectangle_influence(s, y_, hx_, hy_);
    if (table_.empty() || !(s >= table_.lo() && s <= table_.hi())) return cell(s);
    return table_(s);
  }

  /// k at the offsets i hx, from the half space's Love row hs beyond the reach.
  std::vector<W> elastic(const std::vector<W>& hs) const {
    std::vector<W> out(hs.size());
    for (int i = -m_; i <= m_; ++i) {
      const W x = W(i) * hx_, dx = std::max(W(0), std::abs(x) - hx_ / 2);
      const auto q = static_cast<std::size_t>(i + m_);
      out[q] = far(dx) ? d_.far_factor() * hs[q] : k(x);
    }
    return out;
  }

  /// The memory integral (B3) of k for the memory length L > 0 (hs: the half space's row).
  std::vector<W> memory(W length, const std::vector<W>& hs) const {
    using std::exp;
    using std::log;
    const W L = length, eps = std::numeric_limits<W>::epsilon();
    const W u_max = -log(eps) + 6;  // as memory_row: the weight beyond is below eps/400
    const W decay = exp(-hx_ / L), end = std::min(hx_, L * u_max);
    std::vector<W> out(hs.size());
    const auto at = [&](int i) -> W& { return out[static_cast<std::size_t>(i + m_)]; };
    const auto hs_at = [&](int i) { return hs[static_cast<std::size_t>(i + m_)]; };
    // Steps whose points and sources all lie beyond the reach take the half space's step times
    // T(0) - 1: M(X_i) - e^(-hx/L) M(X_{i+1}) is the step integral (B4).
    const auto step_far = [&](W x) {
      const W lo = x - hx_ / 2, hi = x + end + hx_ / 2;
      return far(lo > 0 ? lo : (hi < 0 ? -hi : W(0)));
    };
    // The last offset: beyond the reach, every point ahead of it is (the half space's value
    // times T(0) - 1); otherwise the tail (B17).
    at(m_) = step_far(W(m_) * hx_) ? d_.far_factor() * hs_at(m_) : tail(W(m_) * hx_, L, u_max);
    for (int i = m_ - 1; i >= -m_; --i) {
      const W x = W(i) * hx_;
      const W step = step_far(x) ? d_.far_factor() * (hs_at(i) - decay * hs_at(i + 1))
                                 : step_integral(x, L, end);
      at(i) = decay * at(i + 1) + step;
    }
    return out;
  }

 private:
  bool far(W dx) const { return dx * dx + dy_ * dy_ >= reach_ * reach_; }

  /// (1/L) int_a^b e^(-t/L) k(x0 + t) dt by 16-point Gauss-Legendre.
  W panel(W x0, W L, W a, W b) const {
    using std::exp;
    const auto& gx = GaussLegendre<W, 16>::nodes();
    const auto& gw = GaussLegendre<W, 16>::weights();
    const W half = (b - a) / 2, mid = (a + b) / 2;
    W s = 0;
    for (std::size_t q = 0; q < 16; ++q) {
      const W t = mid + half * gx[q];
      s += gw[q] * exp(-t / L) * k(x0 + t);
    }
    return s * half / L;
  }

  /// The step (B4) of the correction: panels at most h (k is analytic within h of the axis:
  /// 16 points err by 3.7^-32) and 8 L (the weight's, as memory_row's) wide.
  W step_integral(W x0, W L, W end) const {
    const W w = std::min(h_, 8 * L);
    W s = 0;
    for (W a = 0; a < end; a += w) s += panel(x0, L, a, std::min(end, a + w));
    return s;
  }

  /// (B17) at the last offset: (1/L) int_0^inf e^(-t/L) k(x_m + t) dt, on panels at most 8 L
  /// wide, h within the reach and half the distance from the origin beyond it, to L u_max.
  W tail(W x0, W L, W u_max) const {
    using std::sqrt;
    W s = 0;
    const W end = L * u_max;
    for (W a = 0; a < end;) {
      const W x = x0 + a, r = sqrt(x * x + y_ * y_);
      const W w = std::min(8 * L, r < reach_ + hx_ + h_ ? h_ : std::max(h_, r / 2));
      const W b = std::min(end, a + w);
      s += panel(x0, L, a, b);
      a = b;
    }
    return s;
  }

  const RadialCorrection<W>& d_;
  W h_, hx_, hy_, y_;
  int m_;
  W reach_, dy_;
  std::vector<std::array<W, 2>> xs_, ys_;
  ChebyshevPanels<W> table_;
};

/// (B18): a local bed's row Y = j hy of the table (before the compliance c), T = q l: the cell's
/// own displacement 2 pi l under unit pressure, and its memory integral (B3) for L > 0,
/// int_0^inf e^(-eta) 1[|X + L eta| < hx/2] d eta: 1 - e^(-hx/(2L)) at X = 0,
/// e^(-(|X| - hx/2)/L) (1 - e^(-hx/L)) behind the cell (X < 0), 0 ahead of it.
template <RealScalar W>
std::vector<W> local_row(int m, int j, W hx, W l, W length) {
  using std::exp;
  using std::expm1;
  const W pi = boost::math::constants::pi<W>();
  std::vector<W> out(static_cast<std::size_t>(2 * m + 1), W(0));
  if (j != 0) return out;
  const W k = 2 * pi * l;
  if (!(length > 0)) {
    out[static_cast<std::size_t>(m)] = k;
    return out;
  }
  out[static_cast<std::size_t>(m)] = -k * expm1(-hx / (2 * length));
  for (int i = -1; i >= -m; --i) {
    const W x = -W(i) * hx;
    out[static_cast<std::size_t>(i + m)] = -k * exp(-(x - hx / 2) / length) * expm1(-hx / length);
  }
  return out;
}

}  // namespace bem
}  // namespace viscoroll
