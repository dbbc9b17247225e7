// viscoroll: the line residual of a spectrum of M >= 2 retardation times (line_residual.hpp;
// docs/theory.md section 14, (S11)-(S17)): LineResidual's spectrum members, out-of-class
// definitions included at the end of line_residual.hpp.
//
// Each strip y is the closed-form strip of a spectrum (core/spectrum_strip.hpp, (S2)-(S10)) with
// M leading-edge conditions, one per retardation length lambda_k = V tau_k, whose right sides are
// the line form (L6) at lambda_k of Q_k = F0 - F1/lambda_k (S12); the interior equation (34)
// gains the spectrum's constant (S13). The strip's unknowns (U_i, W_i, b) are eliminated at each
// collocation point by its linear system, so the global unknowns do not grow with M: ln a(y) and
// b(y) as in line_shape.hpp, and two more functions of y (even, with odd parts for a tilted
// roller's asymmetric contact), gamma = G0/a^2 and the strip centroid kappa (the first moment),
// which carry F0 = C1 a^2 (1/4 + gamma/2) and F1 = F0 (b + kappa + sum mu_i) to the line
// integrals (S14). The equations at each collocation point: (34) with the spectrum's constant,
// and the strip's b, G0/a^2 and centroid equal to the expanded ones; and the load (47).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <boost/math/special_functions/fpclassify.hpp>
#include <cmath>
#include <cstddef>
#include <vector>
#include <viscoroll/core/spectrum_strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/detail/spectrum_memory.hpp>
#include <viscoroll/line/line_node_rule.hpp>
#include <viscoroll/line/line_operators.hpp>
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/line_shape.hpp>

namespace viscoroll::line {

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline void LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::init_spectrum(
    Real tolerance) {
  const auto& lam = p_.lengths.retardation;
  const auto& mu = p_.lengths.relaxation;
  detail::require(mu.size() == lam.size(), "relaxation lengths", mu.size(),
                  "as many as the retardation lengths");
  for (const Real& l : lam) lambda_sum_ += l;
  // The node rule of the s-integrals: its end panels on the nearest pole of G0, where
  // I0(a/mu_1) = 0 (f of the rule such that (1 + f)/V = 1/mu_1); the memory integrals of all
  // line terms share one x-grid (detail/spectrum_memory.hpp, (S18)).
  scale_ = basis_ == LineBasis::s_mapped ? Real(mu[0] / p_.a_ref) : Real(0);
  // Terms with lambda_k >= slow_fraction() a_ref carry the line integrals in their
  // leading-edge condition (S12); slower ones take the strip's own (plane) condition, right
  // side zero (S16): there the line correction is as large as its own error and the line
  // equations have no root (the slow regime, docs/theory.md section 4).
  for (std::size_t k = 0; k < lam.size(); ++k)
    if (lam[k] >= slow_fraction() * p_.a_ref) {
      line_.push_back(k);
      line_lambda_.push_back(lam[k]);
    }
  rule_.emplace(basis_, scale_, n_, lam[0], lam[0] / mu[0] - 1, tolerance);
}

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline auto LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::functions(
    const LineShape<Real>& s, const LineSpectrumMoments<Real>& mo, Real y) const -> Functions {
  const Real a = s.a(y);
  if (!(a > 0)) return {Real(0), s.b(y), Real(0), Real(0), Real(0)};
  const Real u = LineShape<Real>::coordinate(basis_, scale_, s.one_minus_t2(y));
  const Real t = s.t_at(y);
  const Real gamma = mo.gamma_at(u, t);
  return {a, s.b(y), gamma, mo.kappa_at(u, t) * p_.a_ref,
          p_.c1 * a * a * (Real(1) / 4 + gamma / 2)};
}

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline Real LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::centroid(
    const LineShape<Real>& s, const LineSpectrumMoments<Real>& mo) const {
  std::vector<Real> nodes, weights;
  rule_->load(s, asymmetric_, nodes, weights);
  Real num = 0, den = 0;
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    const Functions f = functions(s, mo, nodes[j]);
    num += weights[j] * f.f0 * (f.b + f.kappa);
    den += weights[j] * f.f0;
  }
  return num / den;
}

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline void LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::chebyshev_values(
    Real u, Real* t, Real t_y) const {
  t[0] = 1;
  if (n_ >= 1) t[1] = u;
  for (int k = 2; k <= n_; ++k) t[k] = 2 * u * t[k - 1] - t[k - 2];
  if (asymmetric_)
    for (int k = 0; k <= n_; ++k) t[n_ + 1 + k] = t_y * t[k];
}

// d ln a/d alpha_k = T_k, db/d beta_k = a_ref T_k, dgamma/dgamma_k = T_k, dkappa/dkappa_k =
// a_ref T_k, and the odd parts' t_y T_k alike.
template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline void LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::add_series_row(
    Matrix& jac, int row, const Real* t, Real ga, Real gb, Real gg, Real gk, Real scale) const {
  const Real ar = p_.a_ref;
  for (int part = 0; part < (asymmetric_ ? 2 : 1); ++part) {
    const int base = part == 0 ? 0 : odd();
    const Real* tk = t + part * (n_ + 1);
    for (int k = 0; k < n_; ++k) jac(row, base + k) += scale * ga * tk[k];
    for (int k = 0; k <= n_; ++k) {
      jac(row, base + n_ + k) += scale * gb * ar * tk[k];
      jac(row, base + 2 * n_ + 1 + k) += scale * gg * tk[k];
      jac(row, base + 3 * n_ + 2 + k) += scale * gk * ar * tk[k];
    }
  }
}

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline bool LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::spectrum_evaluate(
    const Vector& x, Vector& r, Matrix* jac) const {
  using std::log;
  r.resize(equations());
  const LineShape<Real> s = shape(x);
  const LineSpectrumMoments<Real> mo = moments(x);
  const Real d = penetration(x), c1 = p_.c1, ar = p_.a_ref;
  const int m = points(), nu = unknowns(), il = log_length(), id = log_length() + 1;
  const auto& lam = p_.lengths.retardation;
  const std::size_t mt = lam.size();
  const int nt = series_values();
  // Per point: the nodes, the functions there (once for all terms: the terms' node sets differ
  // in their t-nodes only), (L6) for each line term and its slopes.
  LineNodes<Real> nd;
  // At the nodes: a, F0, F0(y') - F0(y), b + kappa; tv: T_0..T_N at each node.
  std::vector<Real> as, f0s, df0, bks, tv, ti(nt), right(mt);
  std::vector<ExteriorSlopes<Real>> slopes;
  detail::SpectrumMemoryWork<Real> work;
  std::vector<Real> qs(line_.size()), line_right;
  Matrix dright;  // d right[k] / d x, row k
  plane::SpectrumStripSlopes<Real> ss;
  for (int i = 0; i < m; ++i) {
    const Real y = s.centre + t_[i] * s.l;
    const Functions here = functions(s, mo, y);
    const Real x0 = here.a + here.b;
    if (!(here.a > 0) || !(x0 > 0)) return false;
    nd = LineNodes<Real>{};
    rule_->point(s, y, x0, nd);
    const std::size_t count = nd.yp.size();
    as.resize(count);
    f0s.resize(count);
    df0.resize(count);
    bks.resize(count);
    for (std::size_t j = 0; j < count; ++j) {
      const Functions f = functions(s, mo, nd.yp[j]);
      as[j] = f.a;
      f0s[j] = f.f0;
      df0[j] = f.f0 - here.f0;
      bks[j] = f.b + f.kappa;
    }
    const Real u_here = LineShape<Real>::coordinate(basis_, scale_, s.one_minus_t2(y));
    if (jac) {
      tv.resize(count * nt);
      for (std::size_t j = 0; j < count; ++j)
        chebyshev_values(LineShape<Real>::coordinate(basis_, scale_, s.one_minus_t2(nd.yp[j])),
                         &tv[j * nt], s.t_at(nd.yp[j]));
      chebyshev_values(u_here, ti.data(), s.t_at(y));
      dright.setZero(Eigen::Index(mt), nu);
    }
    // (S12): the right sides are (L6) at lambda_k of Q_k, the line terms' on one x-grid
    // (S18).
    for (std::size_t c = 0; c < line_.size(); ++c) qs[c] = q(here, line_[c]);
    detail::exterior_right_terms<Quadrature>(nd, x0, line_lambda_, f0s, bks, qs, line_right, work,
                                             jac ? &slopes : nullptr);
    std::fill(right.begin(), right.end(), Real(0));
    for (std::size_t c = 0; c < line_.size(); ++c) right[line_[c]] = line_right[c];
    if (jac) spectrum_right_slopes(here, slopes, as, f0s, bks, qs, tv, ti.data(), dright);
    // The left side of (34): FP[F0] + F0 ln[16 (l^2 - y^2)/a^2].
    const Real lhs34 = near_field_strip(nd, df0, here.f0, here.a);
    const plane::SpectrumStrip<Real> st =
        plane::spectrum_strip(here.a, p_.lengths, &right, p_.c1, jac ? &ss : nullptr);
    const Real a = here.a, b = st.b;
    // (34) with (S13): FP[F0] + F0 ln[16 (l^2 - y^2)/a^2] = -C1 a^2/4 - C1 (Pi_g'(0) + e2)
    //   - C1 b (b - 2 Lambda_1)/2 - C2 y^2/2 + d, with the strip's b.
    const Real rhs34 =
        -c1 * a * a / 4 - c1 * st.pig1 - c1 * b * (b - 2 * lambda_sum_) / 2 - drop_.drop(p_, y) + d;
    r[i] = (lhs34 - rhs34) / (c1 * ar * ar);
    r[m + i] = (st.b - here.b) / ar;
    r[2 * m + i] = st.g0 / (a * a) - here.gamma;
    r[3 * m + i] = (st.centroid - here.kappa) / ar;
    if (!jac) continue;
    Matrix& J = *jac;
    // The strip's outputs: d out = sum_k out_right[k] d right_k + out_a da, da = a d ln a.
    const auto strip_row = [&](const std::vector<Real>& by_right, Real by_a, Real scale, int row) {
      for (const std::size_t k : line_)
        if (by_right[k] != 0)
          for (int c = 0; c < nu; ++c)
            J(row, c) += scale * by_right[k] * dright(Eigen::Index(k), c);
      for (int c = 0; c < n_; ++c) J(row, c) += scale * by_a * a * ti[c];
      if (asymmetric_)
        for (int c = 0; c < n_; ++c) J(row, odd() + c) += scale * by_a * a * ti[n_ + 1 + c];
    };
    const Real s34 = 1 / (c1 * ar * ar);
    // (34): lhs - rhs. FP[F0]: sum_j (w_j/s_j) (dF0_j - dF0(y)); the log: -2 F0 d ln a, and
    // 2 F0 d ln l (d1, d2 scale with l; the finite part does not).
    Real fsum = 0;
    for (std::size_t j = 0; j < count; ++j) {
      const Real w = finite_part_weight(nd, j) * s34;
      fsum += w;
      add_series_row(J, i, &tv[j * nt], 2 * f0s[j] * w, 0, c1 * as[j] * as[j] / 2 * w, 0, 1);
    }
    const Real logs = log(4 * nd.d1 / a) + log(4 * nd.d2 / a);
    add_series_row(J, i, ti.data(), 2 * here.f0 * (logs - fsum / s34) - 2 * here.f0, 0,
                   c1 * a * a / 2 * (logs - fsum / s34), 0, s34);
    J(i, il) += 2 * here.f0 * s34;
    // -rhs34: C1 a^2/4 + C1 pig1 + C1 (b - Lambda_1) db + h'(y) y d ln l - d.
    add_series_row(J, i, ti.data(), c1 * a * a / 2, 0, 0, 0, s34);
    strip_row(ss.pig1, ss.pig1_a, c1 * s34, i);
    strip_row(ss.b, ss.b_a, c1 * (b - lambda_sum_) * s34, i);
    const Real slope_h = drop_.drop_slope(p_, y);
    J(i, il) += slope_h * (y - s.centre) * s34;  // y - c = l t: y for a symmetric contact
    if (asymmetric_) J(i, centre_index()) += slope_h * p_.l_ref * s34;
    J(i, id) -= 1;
    // b, G0/a^2 and the centroid against the expansions.
    strip_row(ss.b, ss.b_a, 1 / ar, m + i);
    add_series_row(J, m + i, ti.data(), 0, -1 / ar, 0, 0, 1);
    strip_row(ss.g0, ss.g0_a, 1 / (a * a), 2 * m + i);
    add_series_row(J, 2 * m + i, ti.data(), -2 * st.g0 / (a * a), 0, -1, 0, 1);
    strip_row(ss.centroid, ss.centroid_a, 1 / ar, 3 * m + i);
    add_series_row(J, 3 * m + i, ti.data(), 0, 0, 0, -1 / ar, 1);
  }
  spectrum_load_row(s, mo, r, jac);
  for (int i = 0; i < r.size(); ++i)
    if (!(boost::math::isfinite)(r[i])) return false;
  return true;
}

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline void LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::spectrum_right_slopes(
    const Functions& here, const std::vector<ExteriorSlopes<Real>>& slopes,
    const std::vector<Real>& as, const std::vector<Real>& f0s, const std::vector<Real>& bks,
    const std::vector<Real>& qs, const std::vector<Real>& tv, const Real* ti,
    Matrix& dright) const {
  const auto& lam = p_.lengths.retardation;
  const Real c1 = p_.c1;
  const int nt = series_values(), il = log_length();
  const std::size_t count = as.size();
  for (std::size_t c = 0; c < line_.size(); ++c) {
    const std::size_t k = line_[c];
    const Eigen::Index kk = Eigen::Index(k);
    // d right_k = sum_j W_j dQ_k(y'_j) + (ends - sum_j W_j) dQ_k(y) + (L6)_x0 dx0
    //   + (L6)_ln l d ln l, with Q_k = F0 (1 - (b + kappa)/lambda_k): dQ/d ln a = 2 Q,
    //   dQ/db = dQ/dkappa = -F0/lambda_k, dQ/dgamma = C1 a^2 (1 - (b + kappa)/lambda_k)/2.
    const auto& sl = slopes[c];
    const int row = int(k);
    Real wsum = 0;
    for (std::size_t j = 0; j < count; ++j) {
      const Real w = sl.weight[j];
      wsum += w;
      const Real factor = 1 - bks[j] / lam[k];
      const Real gb = -f0s[j] / lam[k] * w;
      add_series_row(dright, row, &tv[j * nt], 2 * (f0s[j] * factor) * w, gb,
                     c1 * as[j] * as[j] * factor / 2 * w, gb, 1);
    }
    // At the point itself, with x0 = a + b: dx0/d ln a = a, dx0/db = 1.
    const Real e = sl.ends - wsum;
    const Real factor = 1 - (here.b + here.kappa) / lam[k];
    const Real gk = -e * here.f0 / lam[k];
    add_series_row(dright, row, ti, e * 2 * qs[c] + sl.x0 * here.a, gk + sl.x0,
                   e * c1 * here.a * here.a * factor / 2, gk, 1);
    dright(kk, il) += sl.l;
  }
}

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline void LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::spectrum_load_row(
    const LineShape<Real>& s, const LineSpectrumMoments<Real>& mo, Vector& r, Matrix* jac) const {
  const int m = points(), il = log_length();
  const Real c1 = p_.c1;
  if (!jac) {
    r[4 * m] = load(s, mo) / p_.load_target - 1;
    return;
  }
  // load()'s sum, in its order, with d load = sum_j w_j dF0(y_j) on its nodes (fixed in t), and
  // load d ln l.
  std::vector<Real> nodes, weights, t(series_values());
  rule_->load(s, asymmetric_, nodes, weights);
  Real total = 0;
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    const Functions f = functions(s, mo, nodes[j]);
    total += weights[j] * f.f0;
    chebyshev_values(LineShape<Real>::coordinate(basis_, scale_, s.one_minus_t2(nodes[j])),
                     t.data(), s.t_at(nodes[j]));
    add_series_row(*jac, 4 * m, t.data(), 2 * f.f0, 0, c1 * f.a * f.a / 2, 0,
                   weights[j] / p_.load_target);
  }
  r[4 * m] = total / p_.load_target - 1;
  (*jac)(4 * m, il) += total / p_.load_target;
}

}  // namespace viscoroll::line
