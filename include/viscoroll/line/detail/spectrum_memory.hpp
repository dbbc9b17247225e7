// viscoroll: the right sides (L6) of the M leading-edge conditions of a spectrum's strip at one
// point of the line (docs/theory.md (S12), (S18)), on one node set in x shared by the M memory
// integrals.
//
// exterior_right (line_operators.hpp) sums the memory kernel of one retardation length lambda,
//   K(s) = -lambda int_0^inf e^-t x_t (x_t^2 + s^2)^(-3/2) dt = -int_x0^inf e^-(x - x0)/lambda
//          x (x^2 + s^2)^(-3/2) dx,                                      x_t = x0 + lambda t,
// on its own t-nodes: M terms cost M times (s-nodes x t-nodes) square roots. In the variable x the
// kernels of all terms share the factor x (x^2 + s^2)^(-3/2) and differ in the weight
// e^-(x - x0)/lambda_k only, so on one x-grid that resolves every term the M kernels are one
// matrix product: K = -A Omega / x0^2, A_jq = u_q (u_q^2 + sigma_j^2)^(-3/2) (u = x/x0,
// sigma = s/x0), Omega_qk = dx_q e^-(x_q - x0)/lambda_k. The grid: equal panels in
// ln(1 + (x - x0)/h), h = min(x0, min_k lambda_k), up to x0 + lambda_max (-ln tol + 8): for term
// k this is the rule of LineNodeRule with c = h/lambda_k <= min(x0/lambda_k, 1), which keeps every
// singular point at |Im w| >= pi/2 (docs/theory.md section 7), over a range at least as long.
// The slopes in x0 follow without further sums (S18): by Leibniz's rule,
// dK/dx0 = x0 (x0^2 + s^2)^(-3/2) + K/lambda, which cancels the near-field kernel's slope.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/line/detail/graded_panels.hpp>
#include <viscoroll/line/line_operators.hpp>

namespace viscoroll::detail {

/// Scratch of exterior_right_terms, reused from call to call (its matrices are large enough that
/// allocating them at every point of every residual costs page faults).
template <RealScalar Real>
struct SpectrumMemoryWork {
  Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic> a, b, omega, k2, k2_l, y, z;
  std::vector<Real> tn, tw;
};

/// (L6) at each retardation length lambda[k] of Q_k = F0 (1 - c/lambda_k), from the s-nodes of nd
/// (its t-nodes are not used), f0[j] = F0(y'_j), c[j] = (b + kappa)(y'_j) and q[k] = Q_k(y),
/// leading edge x0 > 0: into right[k], and with slopes (one per term) what the Jacobian needs, as
/// exterior_right's ExteriorSlopes. The integrals to the relative accuracy nd.tolerance (0: the
/// scalar's epsilon).
///
/// The memory part sum_j k2_jk dq_jk, dq_jk = Q_k(y'_j) - Q_k(y), is summed over j first:
/// sum_j A_jq w_j dq_jk = Z_q0 - Z_q1/lambda_k - q_k Z_q2 with Z = A^T [w f0, w f0 c, w] (S18),
/// three columns whatever M, so that the product with Omega costs (x-nodes x M) instead of
/// (s-nodes x x-nodes x M). The kernel is bounded, so the split loses nothing to cancellation that
/// the per-node form Q_k = F0 (1 - c/lambda_k) does not; the near field's 1/s-like kernel is summed
/// per node on dq itself.
template <class Quadrature, RealScalar Real>
void exterior_right_terms(const line::LineNodes<Real>& nd, Real x0, const std::vector<Real>& lambda,
                          const std::vector<Real>& f0, const std::vector<Real>& c,
                          const std::vector<Real>& q, std::vector<Real>& right,
                          SpectrumMemoryWork<Real>& work,
                          std::vector<line::ExteriorSlopes<Real>>* slopes = nullptr) {
  using std::exp;
  using std::hypot;
  using std::log;
  using std::log1p;
  using std::sqrt;
  using Array = Eigen::Array<Real, Eigen::Dynamic, 1>;
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  const std::size_t m = lambda.size(), ns = nd.dist.size();
  right.assign(m, Real(0));
  if (m == 0) return;
  const Real lmin = *std::min_element(lambda.begin(), lambda.end());
  const Real lmax = *std::max_element(lambda.begin(), lambda.end());
  // The shared grid, in t' = (x - x0)/lambda_max with c = h/lambda_max.
  const Real tol = quadrature_tolerance(nd.tolerance);
  const Real h = std::min(x0, lmin);
  std::vector<Real>& tn = work.tn;
  std::vector<Real>& tw = work.tw;
  tn.clear();
  tw.clear();
  append_log_mapped_nodes<Quadrature>(tn, tw, Real(-log(tol) + 8), Real(h / lmax),
                                      boost::math::constants::half_pi<Real>(), tol);
  const Eigen::Index nx = Eigen::Index(tn.size());
  Array u(nx);
  Matrix& omega = work.omega;
  omega.resize(nx, Eigen::Index(m));
  for (Eigen::Index i = 0; i < nx; ++i) {
    const Real dx = lmax * tn[std::size_t(i)];  // x - x0
    u[i] = (x0 + dx) / x0;
    for (std::size_t k = 0; k < m; ++k)
      omega(i, Eigen::Index(k)) = lmax * tw[std::size_t(i)] * exp(-dx / lambda[k]);
  }
  const auto dq = [&](std::size_t j, std::size_t k) {
    return f0[j] * (1 - c[j] / lambda[k]) - q[k];
  };
  Array sigma2(static_cast<Eigen::Index>(ns));
  for (std::size_t j = 0; j < ns; ++j) {
    const Real sigma = nd.dist[j] / x0;
    sigma2[Eigen::Index(j)] = sigma * sigma;
  }
  // A (and B = A/(u^2 + sigma^2) for the slopes in l) in blocks of rows small enough that the
  // products' packing buffers stay on the stack (a heap buffer of this size is mapped and
  // unmapped at every call): Z = A^T Y, and for the slopes k2 = A Omega, k2_l = B Omega
  // (k2(j, k) w_j = -x0^2 w_j K_k(s_j)).
  Matrix& a = work.a;
  Matrix& b = work.b;
  Matrix& k2 = work.k2;
  Matrix& k2_l = work.k2_l;
  Matrix& y = work.y;
  Matrix& z = work.z;
  z.setZero(nx, 3);
  if (slopes) {
    k2.resize(Eigen::Index(ns), Eigen::Index(m));
    k2_l.resize(Eigen::Index(ns), Eigen::Index(m));
  }
  constexpr Eigen::Index block = 32;
  for (Eigen::Index j0 = 0; j0 < Eigen::Index(ns); j0 += block) {
    const Eigen::Index rows = std::min(block, Eigen::Index(ns) - j0);
    a.resize(rows, nx);
    y.resize(rows, 3);
    if (slopes) b.resize(rows, nx);
    for (Eigen::Index i = 0; i < nx; ++i) {
      const Array p2 = (sigma2.segment(j0, rows) + u[i] * u[i]).inverse();
      a.col(i) = (u[i] * (p2 * p2.sqrt())).matrix();
      if (slopes) b.col(i) = (a.col(i).array() * p2).matrix();
    }
    for (Eigen::Index r = 0; r < rows; ++r) {
      const std::size_t j = std::size_t(j0 + r);
      const Real w = nd.weight[j];
      y(r, 0) = w * f0[j];
      y(r, 1) = w * f0[j] * c[j];
      y(r, 2) = w;
    }
    z.noalias() += a.transpose() * y;
    if (slopes) {
      k2.middleRows(j0, rows).noalias() = a * omega;
      k2_l.middleRows(j0, rows).noalias() = b * omega;
    }
  }
  // The ends: ln((h + d)/(2 d)) of the near field and the memory's int e^-(x - x0)/lambda
  // x sum_d 1/(g_d (g_d + d)) dx, g_d = hypot(x, d) (exterior_right's), on the same grid.
  const Real d1 = nd.d1, d2 = nd.d2;
  const Real h1 = hypot(x0, d1), h2 = hypot(x0, d2);
  const Real ends_l =
      -(log1p(x0 * x0 / (2 * d1 * (h1 + d1))) + log1p(x0 * x0 / (2 * d2 * (h2 + d2))));
  Eigen::Matrix<Real, Eigen::Dynamic, 1> e(nx), e_l(slopes ? nx : 0);
  for (Eigen::Index i = 0; i < nx; ++i) {
    const Real x = u[i] * x0;
    const Real g1 = hypot(x, d1), g2 = hypot(x, d2);
    e[i] = x * (1 / (g1 * (g1 + d1)) + 1 / (g2 * (g2 + d2)));
    if (slopes) e_l[i] = -x * (d1 / (g1 * g1 * g1) + d2 / (g2 * g2 * g2));
  }
  const Eigen::Matrix<Real, Eigen::Dynamic, 1> ends_2 = omega.transpose() * e;
  // Omega^T Z: the memory sums of every term, three columns.
  const Matrix oz = omega.transpose() * z;
  Eigen::Matrix<Real, Eigen::Dynamic, 1> ends_2_l;
  if (slopes) {
    ends_2_l = omega.transpose() * e_l;
    slopes->resize(m);
  }
  // The near-field kernel x0^2/(s h (s + h)) = 1/s - 1/h (exterior_right's) and h/x0 per node.
  Array k1(static_cast<Eigen::Index>(ns)), hu(static_cast<Eigen::Index>(ns));
  for (std::size_t j = 0; j < ns; ++j) {
    const Eigen::Index jj = Eigen::Index(j);
    const Real sigma = nd.dist[j] / x0;
    hu[jj] = sqrt(1 + sigma2[jj]);
    k1[jj] = nd.weight[j] / (x0 * sigma * hu[jj] * (sigma + hu[jj]));
  }
  for (std::size_t k = 0; k < m; ++k) {
    const Eigen::Index kk = Eigen::Index(k);
    Real s1 = 0;
    for (std::size_t j = 0; j < ns; ++j) s1 += k1[Eigen::Index(j)] * dq(j, k);
    // sum_j k2_jk dq_jk = -(1/x0^2) sum_q Omega_qk (Z_q0 - Z_q1/lambda_k - q_k Z_q2).
    const Real s2 = -(oz(kk, 0) - oz(kk, 1) / lambda[k] - q[k] * oz(kk, 2)) / (x0 * x0);
    const Real memory = s2 + q[k] * ends_2[kk];
    right[k] = (s1 + q[k] * ends_l) - memory;
    if (!slopes) continue;
    line::ExteriorSlopes<Real>& sl = (*slopes)[k];
    sl.weight.resize(ns);
    Real s_l = 0;
    for (std::size_t j = 0; j < ns; ++j) {
      const Eigen::Index jj = Eigen::Index(j);
      const Real w = nd.weight[j];
      const Real k2j = -w * k2(jj, kk) / (x0 * x0);
      sl.weight[j] = k1[jj] - k2j;
      // d/d ln l: k1 -> -w x0^2/h^3; k2 -> k2 + 3 w sigma^2 (B Omega)/x0^2.
      const Real k2l = k2j + 3 * w * sigma2[jj] * k2_l(jj, kk) / (x0 * x0);
      s_l += (-w / (x0 * hu[jj] * hu[jj] * hu[jj]) - k2l) * dq(j, k);
    }
    sl.ends = ends_l - ends_2[kk];
    // (S18): d/dx0 at fixed dq, q is -(the memory part)/lambda_k (near field and memory slopes
    // cancel by Leibniz's rule, the ends' likewise).
    sl.x0 = -memory / lambda[k];
    const Real e1 = x0 / (h1 * (h1 + d1)), e2 = x0 / (h2 * (h2 + d2));
    sl.l = s_l + q[k] * (x0 * (e1 + e2) - ends_2_l[kk]);
  }
}

}  // namespace viscoroll::detail
