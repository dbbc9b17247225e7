// viscoroll: the line residual's kernels for one memory term (line_residual.hpp): the rows at
// one point, and the semi-analytic Jacobian (docs/theory.md section 6) with the strip's
// derivatives; out-of-class definitions of LineResidual's members, included at the end of
// line_residual.hpp (a spectrum's are in line_residual_spectrum.hpp).
#pragma once

#include <boost/math/special_functions/fpclassify.hpp>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <vector>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/line/line_node_rule.hpp>
#include <viscoroll/line/line_operators.hpp>
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/line_shape.hpp>
#include <viscoroll/special/bessel_ratio.hpp>

namespace viscoroll::line {

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline bool LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::at_point(
    const LineShape<Real>& s, Real d, Real y, Real& r34, Real& rle, PointWork& work) const {
  const Real c1 = p_.c1;
  const auto here = plane::strip_functions(c1, s.a(y), s.b(y), p_.vtau, p_.f);
  if (!(here.a > 0) || !(here.a + here.b > 0)) return false;
  LineNodes<Real>& nd = work.nd;
  rule_->point(s, y, here.a + here.b, nd);
  std::vector<Real>& df0 = work.df0;
  std::vector<Real>& dq = work.dq;
  df0.resize(nd.yp.size());
  dq.resize(nd.yp.size());
  for (std::size_t j = 0; j < nd.yp.size(); ++j) {
    const auto there = plane::strip_functions(c1, s.a(nd.yp[j]), s.b(nd.yp[j]), p_.vtau, p_.f);
    df0[j] = there.f0 - here.f0;
    dq[j] = there.q - here.q;
  }
  const Real right =
      LeadingEdge::template right<Quadrature>(p_, s, y, here.a + here.b, nd, dq, here.q);
  point_rows(d, y, here, nd, df0, right, r34, rle);
  return true;
}

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline auto LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::point_rows(
    Real d, Real y, const plane::StripFunctions<Real>& here, const LineNodes<Real>& nd,
    const std::vector<Real>& df0, Real right, Real& r34, Real& rle) const -> EdgeTerms {
  const Real c1 = p_.c1, v = p_.vtau, a = here.a, b = here.b;
  // (34), scaled by C1 a_ref^2.
  const Real lhs34 = near_field_strip(nd, df0, here.f0, a);
  const Real rhs34 = -c1 * a * a / 4 - c1 * b * (b - 2 * v) / 2 - drop_.drop(p_, y) + d;
  r34 = (lhs34 - rhs34) / (c1 * p_.a_ref * p_.a_ref);
  // Leading-edge condition.
  const Real z = a / v;
  const Real k0 = special::bessel_k0_scaled(z), k1 = special::bessel_k1_scaled(z);
  const Real bessel = c1 * (a * b * k1 - here.g * k0);  // C1 e^z {a b K1 - G K0}, Eq. (42)
  const Real r_i = special::bessel_i1_over_i0_fast(plane::strip_alpha(a, v, p_.f));
  const Real slope = c1 * a * (k1 + r_i * k0);  // d(bessel)/db at fixed a
  rle = (bessel - right) / (slope * p_.a_ref);
  return {k0, k1, slope};
}

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
auto LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::jacobian(const Vector& x,
                                                                              Vector& r,
                                                                              Matrix& jac) const
    -> bool requires std::same_as<LeadingEdge, ExteriorLeadingEdge> {
  using std::log;
  if constexpr (MemoryTerms != 1)
    if (spectrum_) {
      jac.setZero(equations(), unknowns());
      return spectrum_evaluate(x, r, &jac) && jac.allFinite();
    }
  const int m = points(), nu = unknowns(), lam = 2 * n_ + 1, del = 2 * n_ + 2;
  r.resize(equations());
  jac.setZero(equations(), nu);
  const LineShape<Real> s = shape(x);
  const Real d = penetration(x), c1 = p_.c1, v = p_.vtau;
  const Real scale34 = c1 * p_.a_ref * p_.a_ref;
  Vector da_i(nu), db_i(nu), df0_i(nu), dq_i(nu), dright(nu), dlhs(nu), dnode(nu), dan(nu), dbn(nu);
  // Storage reused from point to point.
  LineNodes<Real> nd;
  std::vector<Real> df0, dq;
  std::vector<StripDerivatives> dn;
  ExteriorSlopes<Real> slopes;
  for (int i = 0; i < m; ++i) {
    const Real t = t_[i], y = s.centre + t * s.l;
    const auto dh = strip_derivatives(s.a(y), s.b(y));
    const auto& here = dh.value;
    const Real a = here.a, b = here.b, x0 = a + b;
    if (!(a > 0) || !(x0 > 0)) return false;
    shape_gradient(s, y, a, da_i, db_i);
    df0_i = dh.f0_a * da_i + dh.f0_b * db_i;
    dq_i = dh.q_a * da_i + dh.q_b * db_i;
    rule_->point(s, y, x0, nd);
    const std::size_t count = nd.yp.size();
    df0.resize(count);
    dq.resize(count);
    dlhs.setZero();
    dright.setZero();
    dn.resize(count);
    for (std::size_t j = 0; j < count; ++j) {
      dn[j] = strip_derivatives(s.a(nd.yp[j]), s.b(nd.yp[j]));
      df0[j] = dn[j].value.f0 - here.f0;
      dq[j] = dn[j].value.q - here.q;
    }
    const Real right = exterior_right(nd, dq, here.q, x0, v, &slopes);
    Real r34 = 0, rle = 0;
    const auto edge = point_rows(d, y, here, nd, df0, right, r34, rle);
    r[i] = r34 + v / p_.a_ref * rle;
    r[m + i] = rle;
    // Node values: d F(y'_j) at fixed t'_j; the differences' second terms via the weight sums.
    Real w0sum = 0, wqsum = 0;
    for (std::size_t j = 0; j < count; ++j) {
      const Real w0 = finite_part_weight(nd, j);
      w0sum += w0;
      wqsum += slopes.weight[j];
      const auto& dj = dn[j];
      if (!(dj.value.a > 0)) continue;  // at an end: F0 = Q = 0 there for every coefficient
      shape_gradient(s, nd.yp[j], dj.value.a, dan, dbn);
      dnode = dj.f0_a * dan + dj.f0_b * dbn;
      dlhs += w0 * dnode;
      dnode = dj.q_a * dan + dj.q_b * dbn;
      dright += slopes.weight[j] * dnode;
    }
    dlhs -= w0sum * df0_i;
    dright += (slopes.ends - wqsum) * dq_i;
    // The kernels' dependence on x0 and on l (nodes fixed in t).
    dright += slopes.x0 * (da_i + db_i);
    dright[lam] += slopes.l;
    // (34): lhs = FP + F0 ln[16 (l^2 - y^2)/a^2],
    //       rhs = -C1 a^2/4 - C1 b (b - 2V)/2 - h(y) + d, dh/d ln l = h'(y) y at fixed t.
    const Real lnfac = log(4 * nd.d1 / a) + log(4 * nd.d2 / a);
    dlhs += lnfac * df0_i - (2 * here.f0 / a) * da_i;
    dlhs[lam] += 2 * here.f0;
    Vector drhs = -(c1 * a / 2) * da_i - c1 * (b - v) * db_i;
    const Real slope_h = drop_.drop_slope(p_, y);
    drhs[lam] -= slope_h * (y - s.centre);  // y - c = l t: y for a symmetric contact
    if (asymmetric_) drhs[centre_index()] -= slope_h * p_.l_ref;
    drhs[del] += scale34;
    const Vector dr34 = (dlhs - drhs) / scale34;
    // Leading edge: rle = (bessel - right) / (slope a_ref).
    const Real z = a / v, e0 = edge.k0, e1 = edge.k1, slope = edge.slope, ri = dh.ri;
    const Real e0z = e0 - e1, e1z = e1 - e0 - e1 / z;
    const Real bessel_a = c1 * (b * e1 + a * b * e1z / v - dh.g_a * e0 - here.g * e0z / v);
    const Real bessel_b = c1 * (a * e1 - dh.g_b * e0);
    const Real slope_a =
        c1 * (e1 + ri * e0) + c1 * a * (e1z / v + dh.ri_x * (1 + p_.f) / v * e0 + ri * e0z / v);
    const Vector dbessel = bessel_a * da_i + bessel_b * db_i;
    const Vector drle = (dbessel - dright) / (slope * p_.a_ref) - (rle * slope_a / slope) * da_i;
    jac.row(i) = (dr34 + (v / p_.a_ref) * drle).transpose();
    jac.row(m + i) = drle.transpose();
  }
  // Load (47) on load()'s nodes, fixed in t: d/d ln l of the integral is the integral itself.
  std::vector<Real> nodes, weights;
  rule_->load(s, asymmetric_, nodes, weights);
  Real sum = 0;
  Vector dsum = Vector::Zero(nu);
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    const auto dj = strip_derivatives(s.a(nodes[j]), s.b(nodes[j]));
    const auto& sf = dj.value;
    sum += weights[j] * sf.f0;
    if (!(sf.a > 0)) continue;
    shape_gradient(s, nodes[j], sf.a, dan, dbn);
    dsum += weights[j] * (dj.f0_a * dan + dj.f0_b * dbn);
  }
  r[2 * m] = sum / p_.load_target - 1;
  jac.row(2 * m) = (dsum / p_.load_target).transpose();
  jac(2 * m, lam) = sum / p_.load_target;
  for (int i = 0; i < r.size(); ++i)
    if (!(boost::math::isfinite)(r[i])) return false;
  return jac.allFinite();
}

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline auto LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::strip_derivatives(
    Real a, Real b) const -> StripDerivatives {
  using std::sqrt;
  const Real c1 = p_.c1, v = p_.vtau, f = p_.f;
  if (!(a > 0)) return {{Real(0), b, Real(0), Real(0), Real(0)}, 0, 0, 0, 0, 0, 0, 0, 0};
  const Real alpha = plane::strip_alpha(a, v, f);
  const Real ri = special::bessel_i1_over_i0_fast(alpha);  // I1/I0
  // DLMF 10.29.2: (I1/I0)' = 1 - (I1/I0)/x - (I1/I0)^2; 1/2 - 3x^2/16 + ... at 0.
  const Real ri_x = alpha < sqrt(std::numeric_limits<Real>::epsilon())
                        ? Real(0.5)
                        : Real(1 - ri / alpha - ri * ri);
  const plane::StripFunctions<Real> value = plane::strip_functions_from_ratio(c1, a, b, v, f, ri);
  const Real k = v * f / (1 + f) - b, g = value.g;
  const Real g_a = k * (ri + alpha * ri_x), g_b = -a * ri;
  return {value,
          g_a,
          g_b,
          c1 * (a / 2 + g_a / 2),
          c1 * g_b / 2,
          c1 * g_a * (v - b) / (2 * v),
          c1 * (g_b * (v - b) - g) / (2 * v),
          ri,
          ri_x};
}

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline void LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::shape_gradient(
    const LineShape<Real>& s, Real y, Real a, Vector& da, Vector& db) const {
  da.setZero(unknowns());
  db.setZero(unknowns());
  const Real w = s.one_minus_t2(y);
  const Real u = LineShape<Real>::coordinate(basis_, scale_, w > 0 ? w : Real(0));
  const Real t = asymmetric_ ? s.t_at(y) : Real(0);
  Real tkm1 = 1, tk = u;  // T_0, T_1
  for (int k = 0; k <= n_; ++k) {
    const Real tval = k == 0 ? Real(1) : tk;
    if (k < n_) da[k] = a * tval;
    db[n_ + k] = p_.a_ref * tval;
    if (asymmetric_) {
      if (k < n_) da[odd() + k] = a * t * tval;
      db[odd() + n_ + k] = p_.a_ref * t * tval;
    }
    if (k >= 1) {
      const Real next = 2 * u * tk - tkm1;
      tkm1 = tk;
      tk = next;
    }
  }
}

}  // namespace viscoroll::line
