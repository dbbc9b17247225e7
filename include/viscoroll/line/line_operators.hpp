// viscoroll: the line operators of the line-contact theory, on a node set: the finite part, the
// near-field operator, the extended operator and its x-derivative, and the right side of the
// leading-edge condition (L6); LineOperators applies them to callables on graded panels.
//
// Panek & Kalker (1980), Sections 4-5: Eqs. (20)-(26), (34), (41); docs/theory.md section 4 for
// (L6), section 7 for the node set of the line residual. Methods and measured accuracy:
// docs/line-operators.md. The paper's (44) is in paper_leading_edge.hpp (not included here).
//
// Every integral over y' in [-l, l] is split at y' = y and written in s = |y' - y| on each side,
// [0, l - y] and [0, l + y]; the value F(y) is subtracted so that the integrand is bounded:
//   FP[F](y) = int (F(y') - F(y)) / |y' - y| dy'                     (smooth on each side)
//   I[F, x](y) = int (F(y') - F(y)) (x^2 + s^2)^(-1/2) dy'
//                + F(y) [ln(d1 + sqrt(d1^2 + x^2)) + ln(d2 + sqrt(d2^2 + x^2))],  d1,2 = l -+ y,
// which is Eq. (41) with asinh(d/x) + ln x = ln(d + sqrt(d^2 + x^2)): no cancellation as x -> 0.
// So every operator is a sum over the nodes y'_j of one point of w_j (F(y'_j) - F(y)) k(|y'_j - y|)
// plus F(y) times end terms in closed form: the functions below take the node set (LineNodes) and
// the differences. Who builds the nodes decides the accuracy: LineResidual from the distance of the
// singularities of its integrands (docs/theory.md section 7), LineOperators on panels uniform for
// the finite part and geometric at the kernel's scale x for I (detail/graded_panels.hpp).
//
// References: J. J. Kalker, Three-dimensional elastic bodies in rolling contact (1990), ch. 1;
// C. Panek & J. J. Kalker, J. Inst. Maths Applics 26 (1980) 299-313.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/detail/graded_panels.hpp>
#include <viscoroll/line/detail/memory_kernel_series.hpp>

namespace viscoroll::line {

/// The quadrature nodes of the line integrals at one point y of (-l, l).
///
/// Members:
///   - `yp`, `dist`, `weight`: the nodes y' = y +- s of both sides, |y' - y| recomputed from the
///     rounded y' (so that the rounding of y + s, eps |y|, does not enter a difference quotient as
///     eps |y| / s), and the weights in y'. A node with |y' - y| = 0 (s below the spacing of y) is
///     left out: its integrand is bounded, on a null set.
///   - `tn`, `tw`: the nodes t of the memory integral over [0, inf) of (L6) and their weights
///     (without e^-t); empty where no memory integral is taken.
///   - `d1`, `d2`: l - y and l + y, the distances to the ends.
///   - `tolerance`: the relative accuracy the nodes were built for (0: the scalar's epsilon);
///     exterior_right's far-field series keeps to it.
///   - `add_side(y, sign, s, w)`: appends the nodes y' = y + sign s_j (sign = +1 or -1) with the
///     weights w_j.
///   - `clear()`: empties the node lists, keeping their storage, so that one LineNodes serves the
///     points of a residual evaluation in turn without allocating; `side_s`, `side_w` are the
///     builder's storage for one side's nodes (LineNodeRule::point), not part of the set.
template <RealScalar Real>
struct LineNodes {
  /// The nodes y' of both sides, their distances |y' - y| and their weights.
  ///@{
  std::vector<Real> yp, dist, weight;
  ///@}
  /// The memory integral's nodes t and weights (without e^-t).
  ///@{
  std::vector<Real> tn, tw;
  ///@}
  /// l - y and l + y, the distances to the ends.
  ///@{
  Real d1 = 0, d2 = 0;
  ///@}
  /// The relative accuracy the nodes were built for (0: the scalar's epsilon).
  Real tolerance = 0;
  /// The builder's storage for one side's nodes (not part of the set).
  ///@{
  std::vector<Real> side_s, side_w;
  ///@}

  /// Empties the node lists, keeping their storage.
  void clear() {
    yp.clear();
    dist.clear();
    weight.clear();
    tn.clear();
    tw.clear();
  }

  /// Appends the nodes y' = y + sign s_j (sign = +1 or -1) with the weights w_j.
  void add_side(Real y, int sign, const std::vector<Real>& s, const std::vector<Real>& w) {
    for (std::size_t j = 0; j < s.size(); ++j) {
      const Real node = sign > 0 ? Real(y + s[j]) : Real(y - s[j]);
      const Real d = sign > 0 ? Real(node - y) : Real(y - node);  // recomputed: rounding of node
      if (!(d > 0)) continue;
      yp.push_back(node);
      dist.push_back(d);
      weight.push_back(w[j]);
    }
  }
};

/// FP[F](y) = int_{-l}^{l} (F(y') - F(y)) / |y' - y| dy', the integral of Eqs. (22)-(25), (34),
/// from df_j = F(y'_j) - F(y) at the nodes of nd.
template <RealScalar Real>
Real finite_part(const LineNodes<Real>& nd, const std::vector<Real>& df) {
  Real fp = 0;
  for (std::size_t j = 0; j < df.size(); ++j) fp += nd.weight[j] * df[j] / nd.dist[j];
  return fp;
}

/// The factor of df_j in finite_part, w_j / |y'_j - y| (the Jacobian's, docs/theory.md section 6).
template <RealScalar Real>
Real finite_part_weight(const LineNodes<Real>& nd, std::size_t j) {
  return nd.weight[j] / nd.dist[j];
}

/// Lambda[F](y) = FP[F](y) + F(y) ln 4(l^2 - y^2), fy = F(y): Eq. (24), the near-field operator.
template <RealScalar Real>
Real near_field(const LineNodes<Real>& nd, const std::vector<Real>& df, Real fy) {
  using std::log;
  return finite_part(nd, df) + fy * log(4 * nd.d1 * nd.d2);  // Eq. (24)
}

/// FP[F](y) + F(y) ln[16 (l^2 - y^2) / a^2]: the left side of Eq. (34) at half width a > 0.
template <RealScalar Real>
Real near_field_strip(const LineNodes<Real>& nd, const std::vector<Real>& df, Real fy, Real a) {
  using std::log;
  // Eq. (34); 16 (l^2 - y^2)/a^2 as (4 (l - y)/a)(4 (l + y)/a) so that nothing overflows.
  return finite_part(nd, df) + fy * (log(4 * nd.d1 / a) + log(4 * nd.d2 / a));
}

/// I[F, x](y) = int_{-l}^{l} F(y') (x^2 + (y - y')^2)^(-1/2) dy' + 2 F(y) ln x, Eq. (41), x > 0.
template <RealScalar Real>
Real extended(const LineNodes<Real>& nd, const std::vector<Real>& df, Real fy, Real x) {
  using std::hypot;
  using std::log;
  Real sum = 0;
  for (std::size_t j = 0; j < df.size(); ++j) sum += nd.weight[j] * df[j] / hypot(x, nd.dist[j]);
  const Real d1 = nd.d1, d2 = nd.d2;
  // Eq. (20)-(21) exactly: asinh(d/x) + ln x = ln(d + sqrt(d^2 + x^2)).
  return sum + fy * (log(d1 + hypot(d1, x)) + log(d2 + hypot(d2, x)));
}

/// d/dx I[F, x](y) = -x int (F(y') - F(y)) (x^2 + s^2)^(-3/2) dy'
///                   + F(y) x [1/(h1 (h1 + d1)) + 1/(h2 (h2 + d2))],  h = sqrt(d^2 + x^2),
/// the derivative of Eq. (41) (the second term is 2F/x - F (d1/h1 + d2/h2)/x without
/// cancellation), x > 0.
template <RealScalar Real>
Real extended_dx(const LineNodes<Real>& nd, const std::vector<Real>& df, Real fy, Real x) {
  using std::hypot;
  Real sum = 0;
  for (std::size_t j = 0; j < df.size(); ++j) {
    const Real h = hypot(x, nd.dist[j]);
    sum += nd.weight[j] * df[j] * x / (h * h * h);
  }
  const Real d1 = nd.d1, d2 = nd.d2;
  const Real h1 = hypot(d1, x), h2 = hypot(d2, x);
  return -sum + fy * x * (1 / (h1 * (h1 + d1)) + 1 / (h2 * (h2 + d2)));
}

/// What the Jacobian needs of exterior_right (docs/theory.md section 6), from the same pass.
///
/// Members: `weight`, the factor of each dq_j in the result; `ends`, the factor of q; `x0` and
/// `l`, the derivatives of the result in x0 and in ln l (every distance along y stretched by l,
/// nodes fixed in t = y/l) at fixed dq and q.
template <RealScalar Real>
struct ExteriorSlopes {
  /// The factor of each dq_j in the result.
  std::vector<Real> weight;
  /// The factor of q and the derivatives in x0 and in ln l.
  ///@{
  Real ends = 0, x0 = 0, l = 0;
  ///@}
};

/// The right side of the leading-edge condition (L6) of docs/theory.md section 4,
///   (Lambda - I_x0)[Q](y) - V int_0^inf e^-t d/dx I[Q, x0 + V t](y) dt,   V = V tau > 0, x0 > 0,
/// from dq_j = Q(y'_j) - Q(y) and q = Q(y) on the nodes of nd, whose t-nodes carry the memory
/// integral. Both terms are sums over the same nodes with kernels of one sign:
///   (Lambda - I_x)[Q] = int (Q(y') - Q(y)) x^2 / (s h (s + h)) dy'
///                       - Q(y) sum_{d = l -+ y} log1p(x^2 / (2 d (h_d + d))),
///   V int e^-t dI/dx dt = int (Q(y') - Q(y)) K(s) dy'
///                         + Q(y) V int e^-t x_t sum_d 1/(h_d (h_d + d)) dt,
///   h = sqrt(x^2 + s^2), K(s) = -V int_0^inf e^-t x_t (x_t^2 + s^2)^(-3/2) dt, x_t = x0 + V t,
/// so that no term is a difference of large numbers. Far from y (s beyond ~2.4 (x0 + V) when
/// V << x0) K(s) is the series in 1/s^2 of detail/memory_kernel_series.hpp (docs/theory.md
/// section 8). With slopes, also what the Jacobian needs (ExteriorSlopes), in the same pass.
template <RealScalar Real>
Real exterior_right(const LineNodes<Real>& nd, const std::vector<Real>& dq, Real q, Real x0,
                    Real vtau, ExteriorSlopes<Real>* slopes = nullptr) {
  using std::exp;
  using std::hypot;
  using std::log1p;
  using std::sqrt;
  const Real v = vtau;
  const std::size_t nt = nd.tn.size();
  // wk: the t-weights W_k with e^-t and V; wtu2 (W u^2) only for the slopes.
  Eigen::Array<Real, Eigen::Dynamic, 1> wk(nt), uk2(nt), wu(nt), wtu2(slopes ? nt : 0), p2(nt),
      p5(slopes ? nt : 0);
  std::vector<Real> xk(nt);
  for (std::size_t k = 0; k < nt; ++k) {
    xk[k] = x0 + v * nd.tn[k];
    wk[k] = v * nd.tw[k] * exp(-nd.tn[k]);
    // In units of x0 (u = x_t/x0 >= 1, sigma = s/x0): K(s) x0^2 = -sum w u (u^2 +
    // sigma^2)^(-3/2), a square root per node instead of hypot (3x dearer), free of overflow
    // while s/x0 < 1e150.
    const Real u = xk[k] / x0;
    uk2[k] = u * u;
    wu[k] = wk[k] * u;
    if (slopes != nullptr) wtu2[k] = wk[k] * u * u;
  }
  if (slopes != nullptr) slopes->weight.resize(dq.size());
  // s-nodes beyond far.threshold() take the series in 1/s^2 instead of the t-nodes.
  const detail::MemoryKernelSeries<Real> far(x0, v, nd.tolerance);
  Real s1 = 0, s2 = 0, s_x0 = 0, s_l = 0;
  for (std::size_t j = 0; j < nd.dist.size(); ++j) {
    const Real w = nd.weight[j];
    const Real sigma = nd.dist[j] / x0, sigma2 = sigma * sigma;
    const Real hu = sqrt(1 + sigma2);                      // h / x0
    const Real k1 = w / (x0 * sigma * hu * (sigma + hu));  // x0^2/(s h (s + h)) = 1/s - 1/h
    // k2 and, for the slopes, dk2/dx0 and dk2/dln l.
    Real k2, k2_x0 = 0, k2_l = 0;
    if (nd.dist[j] >= far.threshold()) {
      // Far from the point: the series in 1/s^2 (docs/theory.md section 8), within eps/16.
      if (slopes == nullptr) {
        k2 = -w * far.value(nd.dist[j]);
      } else {
        Real kf = 0, kf_x0 = 0, kf_s = 0;
        far.evaluate(nd.dist[j], kf, kf_x0, kf_s);
        k2 = -w * kf;
        k2_x0 = -w * kf_x0;
        k2_l = k2 - w * kf_s;
      }
    } else {
      // P = (u^2 + sigma^2)^(-1/2), k2 = -w sum W u P^3 / x0^2 (W = wk): packed square roots
      // and divisions, a tree-ordered sum; one expression with and without the slopes, so that
      // the Jacobian's residual is the residual bit for bit.
      p2 = (uk2 + sigma2).rsqrt();  // P
      k2 = -w * (wu * p2.cube()).sum() / (x0 * x0);
      if (slopes != nullptr) {
        // dk2/dx0 = -w sum W (sigma^2 - 2 u^2) P^5 / x0^3,
        // dk2/dln l = k2 + 3 w sigma^2 sum W u P^5 / x0^2.
        p5 = p2.cube() * p2.square();
        k2_x0 = -w * (sigma2 * (wk * p5).sum() - 2 * (wtu2 * p5).sum()) / (x0 * x0 * x0);
        k2_l = k2 + 3 * w * sigma2 * (wu * p5).sum() / (x0 * x0);
      }
    }
    if (slopes != nullptr) {
      // dk1/dx0 = w x0/h^3, dk1/dln l = -w x0^2/h^3.
      const Real hu3 = hu * hu * hu;
      s_x0 += (w / (x0 * x0 * hu3) - k2_x0) * dq[j];
      s_l += (-w / (x0 * hu3) - k2_l) * dq[j];
      slopes->weight[j] = k1 - k2;
    }
    s1 += k1 * dq[j];
    s2 += k2 * dq[j];
  }
  const Real d1 = nd.d1, d2 = nd.d2;
  const Real h1 = hypot(x0, d1), h2 = hypot(x0, d2);
  // log1p(x0^2/(2 d (h + d))) = ln((h + d)/(2 d)).
  const Real ends_l =
      -(log1p(x0 * x0 / (2 * d1 * (h1 + d1))) + log1p(x0 * x0 / (2 * d2 * (h2 + d2))));
  Real ends_2 = 0, ends_2_x0 = 0, ends_2_l = 0;
  // g = hypot(x_t, d) as x0 sqrt(u^2 + (d/x0)^2), a square root instead of hypot (as above).
  const Real q1 = (d1 / x0) * (d1 / x0), q2 = (d2 / x0) * (d2 / x0);
  for (std::size_t k = 0; k < nt; ++k) {
    const Real g1 = x0 * sqrt(uk2[k] + q1), g2 = x0 * sqrt(uk2[k] + q2);
    const Real a1 = 1 / (g1 * (g1 + d1)), a2 = 1 / (g2 * (g2 + d2));
    ends_2 += wk[k] * xk[k] * (a1 + a2);
    if (slopes != nullptr) {
      // phi = x A, A = 1/(g (g + d)), g = hypot(x, d): dphi/dx = A - x^2 (2 g + d) A^2 / g,
      // dphi/dln l = d dphi/dd = -x d / g^3.
      const Real x2 = xk[k] * xk[k];
      ends_2_x0 +=
          wk[k] * (a1 - x2 * (2 * g1 + d1) * a1 * a1 / g1 + a2 - x2 * (2 * g2 + d2) * a2 * a2 / g2);
      ends_2_l -= wk[k] * xk[k] * (d1 / (g1 * g1 * g1) + d2 / (g2 * g2 * g2));
    }
  }
  if (slopes != nullptr) {
    slopes->ends = ends_l - ends_2;
    // d ln((h + d)/(2 d))/dx0 = x0/(h (h + d)); its derivative in ln l is -x0^2/(h (h + d)).
    const Real e1 = x0 / (h1 * (h1 + d1)), e2 = x0 / (h2 * (h2 + d2));
    slopes->x0 = s_x0 + q * (-(e1 + e2) - ends_2_x0);
    slopes->l = s_l + q * (x0 * (e1 + e2) - ends_2_l);
  }
  // (L6): (Lambda - I_x0)[Q] - V int e^-t dI/dx[Q, x0 + V t] dt
  return (s1 + q * ends_l) - (s2 + q * ends_2);
}

/// Settings of LineOperators. validate() throws std::invalid_argument on nonsense.
struct LineOperatorOptions {
  /// Halvings of the panels toward the ends y' = +-l on each side (every operator): resolves a
  /// complex singularity of F within (l - |y|) 2^-end_levels of an end (docs/line-operators.md).
  int end_levels = 16;

  /// Throws std::invalid_argument unless 0 <= end_levels <= 1000.
  void validate() const {
    detail::require(end_levels >= 0 && end_levels <= 1000, "end_levels", end_levels,
                    "0 <= end_levels <= 1000");
  }
};

/// The line operators of Panek & Kalker (1980) on [-l, l] for callables F : Real -> Real that are
/// smooth on [-l, l] (they may vanish at +-l like (l^2 - y^2) times a smooth function): each
/// operator builds the node set of its panels (nodes), samples F there (differences) and applies
/// the node-set function above of the same name.
///
/// Members:
///   - `finite_part(f, y)`, `near_field(f, y)`, `near_field_strip(f, y, a)`: FP, (24), the left
///     side of (34), on panels uniform in s;
///   - `extended(f, x, y)`, `extended_dx(f, x, y)`: (41) and its x-derivative, on panels geometric
///     at the scale x;
///   - `nodes(y, scale, levels)`: the node set of those panels; `differences(nd, f, fy)`;
///   - `half_length()`, `options()`.
///
/// Quadrature is a NodalQuadratureRule policy (a fixed rule such as GaussLegendre<Real, 16>)
/// applied on each panel. All members take |y| < l and throw std::invalid_argument otherwise.
template <RealScalar Real, class Quadrature>
requires NodalQuadratureRule<Quadrature, Real>
class LineOperators {
 public:
  /// The scalar.
  using real_type = Real;

  /// half_length: l > 0, the half length of the contact.
  explicit LineOperators(Real half_length, LineOperatorOptions options = {})
      : l_(half_length), options_(options) {
    detail::require_positive("half_length", l_);
    options_.validate();
  }

  /// l, the contact's half length.
  Real half_length() const { return l_; }
  /// The settings.
  const LineOperatorOptions& options() const { return options_; }

  /// The nodes at y on each side's panels [0, min(scale, d) 2^-levels], then doubling, and
  /// halving toward the end down to width d 2^-end_levels (d = l -+ y;
  /// detail::for_each_scaled_panel).
  LineNodes<Real> nodes(Real y, Real scale, int levels) const {
    using std::abs;
    detail::require(abs(y) < l_, "y", y, "|y| < l");
    LineNodes<Real> nd;
    nd.d1 = l_ - y;
    nd.d2 = l_ + y;
    std::vector<Real> s1, w1, s2, w2;
    detail::append_scaled_nodes<Quadrature>(s1, w1, nd.d1, scale, levels, options_.end_levels);
    detail::append_scaled_nodes<Quadrature>(s2, w2, nd.d2, scale, levels, options_.end_levels);
    const std::size_t count = s1.size() + s2.size();
    nd.yp.reserve(count);
    nd.dist.reserve(count);
    nd.weight.reserve(count);
    nd.add_side(y, 1, s1, w1);
    nd.add_side(y, -1, s2, w2);
    return nd;
  }

  /// F(y'_j) - F(y) at the nodes of nd, fy = F(y).
  template <class F>
  static std::vector<Real> differences(const LineNodes<Real>& nd, const F& f, Real fy) {
    std::vector<Real> df(nd.yp.size());
    for (std::size_t j = 0; j < df.size(); ++j) df[j] = f(nd.yp[j]) - fy;
    return df;
  }

  /// FP[F](y), the integral of Eqs. (22)-(25), (34).
  template <class F>
  Real finite_part(const F& f, Real y) const {
    const LineNodes<Real> nd = smooth_nodes(y);
    return viscoroll::line::finite_part(nd, differences(nd, f, f(y)));
  }

  /// Lambda[F](y) = FP[F](y) + F(y) ln 4(l^2 - y^2): Eq. (24), the near-field operator A_0.
  template <class F>
  Real near_field(const F& f, Real y) const {
    const LineNodes<Real> nd = smooth_nodes(y);
    const Real fy = f(y);
    return viscoroll::line::near_field(nd, differences(nd, f, fy), fy);
  }

  /// FP[F](y) + F(y) ln[16 (l^2 - y^2) / a^2]: the left side of Eq. (34) at half width a > 0.
  template <class F>
  Real near_field_strip(const F& f, Real y, Real a) const {
    detail::require_positive("a", a);
    const LineNodes<Real> nd = smooth_nodes(y);
    const Real fy = f(y);
    return viscoroll::line::near_field_strip(nd, differences(nd, f, fy), fy, a);
  }

  /// I[F, x](y), Eq. (41), x > 0.
  template <class F>
  Real extended(const F& f, Real x, Real y) const {
    detail::require_positive("x", x);
    const LineNodes<Real> nd = nodes(y, x, 1);  // poles of the kernel at s = +-i x
    const Real fy = f(y);
    return viscoroll::line::extended(nd, differences(nd, f, fy), fy, x);
  }

  /// d/dx I[F, x](y), the derivative of Eq. (41), x > 0.
  template <class F>
  Real extended_dx(const F& f, Real x, Real y) const {
    detail::require_positive("x", x);
    const LineNodes<Real> nd = nodes(y, x, 1);
    const Real fy = f(y);
    return viscoroll::line::extended_dx(nd, differences(nd, f, fy), fy, x);
  }

 private:
  /// The difference quotient of the finite part is smooth: panels [0, d/4], [d/4, d/2], then
  /// halving toward the end (a scale beyond both sides, 2 l, and two levels).
  LineNodes<Real> smooth_nodes(Real y) const { return nodes(y, Real(2 * l_), 2); }

  Real l_;
  LineOperatorOptions options_;
};

}  // namespace viscoroll::line
