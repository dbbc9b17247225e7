// viscoroll: the fixed matrices of the static profile contact's discretisation
// (static_profile_contact.hpp): the finite part (G4) of each Chebyshev polynomial, the integral
// over [-1, 1] and the Chebyshev tail of F0 from its values at the Chebyshev-Lobatto points, and
// the tables of T_k at the collocation and interpolation points.
#pragma once

#include <Eigen/Dense>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <vector>

namespace viscoroll::detail {

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

}  // namespace viscoroll::detail
