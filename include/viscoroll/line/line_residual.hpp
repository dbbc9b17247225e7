// viscoroll: the residual assembly of the line solver.
//
// Panek & Kalker (1980), Sections 5 and 7. The unknowns are the coefficients of a(y) and b(y)
// (line_shape.hpp), ln l and d; the equations, at collocation points y_i = l t_i, are
//   (34)  FP[F0](y) + F0(y) ln[16 (l^2 - y^2)/a^2]
//           + C1 a^2/4 + (C1/2) b (b - 2 V) + h(y) - d = 0
//         h(y) the roller's drop along its axis, a RollerDrop policy: C2 y^2/2 (Eq. 27, the
//         default ParabolicDrop), or a roller profile (line_profile.hpp, docs/theory.md (RP1):
//         h enters only here; y - c and l -+ (y - c) for an asymmetric contact centred at c)
//   (LE)  the leading-edge condition C1 {a b e^z K1(z) - G e^z K0(z)} = right side, z = a/V,
//         Eq. (42) with the right side of a LeadingEdgeCondition policy: by default (L6) of
//         docs/theory.md section 4,
//           (Lambda - I_x0)[Q](y) - V int_0^inf e^-t d/dx I[Q, x0 + V t](y) dt
//         (exterior_right of line_operators.hpp); the paper's (44) in paper_leading_edge.hpp
//   (47)  int F0 dy = C1 a0^2 l0 / 3 = (1 + f) c P
// with G (36), F0 (33), Q (46) pointwise, V = V tau, x0 = a + b, Lambda the near-field operator
// (24), I the extended operator (41). Every integral at a point is a sum over one node set
// (LineNodeRule, docs/theory.md section 7) of the differences F(y') - F(y), taken by the
// operators of line_operators.hpp: near_field_strip for (34), exterior_right for (L6).
//
// LineResidual::jacobian is defined in line/detail/line_residual_jacobian.hpp, included at the end
// of this header.
#pragma once

#include <Eigen/Core>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <concepts>
#include <limits>
#include <utility>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/line_node_rule.hpp>
#include <viscoroll/line/line_operators.hpp>
#include <viscoroll/line/line_shape.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>
#include <viscoroll/special/bessel_ratio.hpp>

namespace viscoroll {

/// The scene's constants seen by the residual (V tau > 0, f > 0).
template <RealScalar Real>
struct LineProblem {
  /// C1, C2, V tau and f of the scene.
  ///@{
  Real c1, c2, vtau, f;
  ///@}
  Real a_ref;        ///< long-term static half width at y = 0 (scale of a, b)
  Real l_ref;        ///< long-term static half length (scale of l)
  Real load_target;  ///< int F0 dy = (1 + f) c P, Eq. (47) with (52)
};

/// Leading-edge policy of LineResidual: the right side of the leading-edge condition in the
/// scaling of Eq. (42), C1 e^z {a b K1(z) - G K0(z)} = right side.
///
/// A policy E provides `static Real E::right<Quadrature>(problem, shape, y, x0, nodes, dq, q)`:
/// the right side at y (|y| < shape.l) with leading edge x0 = a(y) + b(y) > 0, from the residual's
/// node set there (LineNodeRule) and dq_j = Q(y'_j) - Q(y), q = Q(y), Q of Eq. (46). Models:
/// ExteriorLeadingEdge, (L6) (the default, and the one LineResidual::jacobian differentiates);
/// PaperLeadingEdge in paper_leading_edge.hpp, the paper's (44).
template <class E, class Real, class Quadrature>
concept LeadingEdgeCondition = requires(const LineProblem<Real>& p, const LineShape<Real>& s,
                                        const LineNodes<Real>& nd, const std::vector<Real>& dq,
                                        Real y) {
  { E::template right<Quadrature>(p, s, y, y, nd, dq, y) } -> std::convertible_to<Real>;
};

/// The leading-edge condition (L6) of docs/theory.md section 4: (42) with only the second of the
/// paper's two small-argument steps, I[F1, x0] -> Lambda[F1] (exterior_right).
struct ExteriorLeadingEdge {
  /// The right side of (L6) at y: exterior_right(nd, dq, q, x0, V tau).
  template <class Quadrature, class Real>
  static Real right(const LineProblem<Real>& p, const LineShape<Real>&, Real, Real x0,
                    const LineNodes<Real>& nd, const std::vector<Real>& dq, Real q) {
    return exterior_right(nd, dq, q, x0, p.vtau);
  }
};

/// The roller's drop h(y) along its axis in (34), a policy of the line residuals (LineResidual,
/// LineSpectrumResidual): a D provides `Real drop(const Problem&, Real y) const` and
/// `Real drop_slope(const Problem&, Real y) const`, h(y) and h'(y) in the residual's units inside
/// the contact; h even in y unless the residual is asymmetric (the residuals' `asymmetric`:
/// else they collocate on y > 0); Problem the residual's constants (LineProblem,
/// LineSpectrumProblem). Models: ParabolicDrop (the paper's Eq. 27, from the problem's c2) and
/// ProfileDrop (line_profile.hpp, a RollerProfile).
template <class D, class Real, class Problem = LineProblem<Real>>
concept RollerDrop = requires(const D& d, const Problem& p, Real y) {
  { d.drop(p, y) } -> std::convertible_to<Real>;
  { d.drop_slope(p, y) } -> std::convertible_to<Real>;
};

/// The paper's drop h = C2 y^2/2 (Eq. 27), C2 = the problem's c2.
struct ParabolicDrop {
  /// h(y) = C2 y^2 / 2.
  template <class Problem, class Real>
  Real drop(const Problem& p, Real y) const {
    return p.c2 * y * y / 2;
  }
  /// h'(y) = C2 y.
  template <class Problem, class Real>
  Real drop_slope(const Problem& p, Real y) const {
    return p.c2 * y;
  }
};

/// Residual of the line equations at collocation points; `Quadrature` a NodalQuadratureRule,
/// `LeadingEdge` a LeadingEdgeCondition, `Drop` a RollerDrop.
template <RealScalar Real, class Quadrature, class LeadingEdge = ExteriorLeadingEdge,
          class Drop = ParabolicDrop>
requires NodalQuadratureRule<Quadrature, Real> &&
    LeadingEdgeCondition<LeadingEdge, Real, Quadrature> && RollerDrop<Drop, Real>
class LineResidual {
 public:
  /// A column vector of unknowns or residuals.
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  /// A dense matrix (the Jacobian).
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  /// The roller's drop policy.
  using drop_type = Drop;

  /// terms: N >= 1; ln a has N coefficients, b has N + 1, collocation at N + 1 points. The count
  /// balances each block: (34) at N + 1 points and the load (47) fix the N coefficients of a, l and
  /// d; the leading-edge condition at N + 1 points fixes the N + 1 coefficients of b.
  /// oversampling k >= 1: k (N + 1) points instead, an overdetermined system whose least-squares
  /// solution is the paper's (Section 7; docs/theory.md section 10).
  /// quadrature_tolerance: the relative accuracy of every integral (LineNodeRule); 0, the default,
  /// the scalar's epsilon (every integral exact to rounding).
  /// drop: the roller's h(y) (the paper's C2 y^2/2 by default).
  /// asymmetric: the contact [c - l, c + l] of a roller whose drop is not even (a tilt;
  /// docs/theory.md (RP7)): a(y), b(y) take odd parts of as many coefficients as their even parts,
  /// the centre c is an unknown, and the equations are collocated at the points +-t_i; the even
  /// unknowns keep their places, the odd ones follow (unknowns()).
  LineResidual(LineProblem<Real> problem, int terms, LineBasis basis = LineBasis::t_squared,
               int oversampling = 1, Real quadrature_tolerance = Real(0), Drop drop = Drop{},
               bool asymmetric = false)
      : p_(problem),
        drop_(std::move(drop)),
        n_(terms),
        oversampling_(oversampling),
        asymmetric_(asymmetric),
        basis_(basis),
        scale_(basis == LineBasis::s_mapped
                   ? LineShape<Real>::mapped_scale(problem.vtau, problem.f, problem.a_ref)
                   : Real(0)),
        rule_(basis_, scale_, terms, problem.vtau, problem.f, quadrature_tolerance) {
    detail::require(terms >= 1 && terms <= 64, "terms", terms, "1 <= terms <= 64");
    detail::require(oversampling >= 1 && oversampling <= 8, "oversampling", oversampling,
                    "1 <= oversampling <= 8");
    using std::cos;
    using std::sqrt;
    const Real pi = boost::math::constants::pi<Real>();
    const int m = (n_ + 1) * oversampling_;
    for (int i = 1; i <= m; ++i) {
      // Chebyshev points in the expansion variable v; t = sqrt(1 - w(v)) in (0, 1).
      const Real v = cos(pi * Real(2 * i - 1) / Real(2 * m));
      t_.push_back(sqrt(1 - LineShape<Real>::one_minus_t2_at(basis_, scale_, v)));
    }
    // The asymmetric contact's points on t < 0: the mirror images, exactly (negation).
    if (asymmetric_)
      for (int i = 0; i < m; ++i) t_.push_back(-t_[i]);
  }

  /// N, the number of coefficients of ln a.
  int terms() const { return n_; }
  /// Collocation points: (N + 1) times the oversampling (N + 1 for the square system), twice
  /// that for an asymmetric contact.
  int points() const { return (n_ + 1) * oversampling_ * (asymmetric_ ? 2 : 1); }
  /// k, the oversampling of the collocation points.
  int oversampling() const { return oversampling_; }
  /// Whether the contact has odd parts and a centre.
  bool asymmetric() const { return asymmetric_; }
  /// Unknowns: alpha_0..alpha_{N-1}, beta_0..beta_N, ln(l / l_ref), d / (C1 a_ref^2); for an
  /// asymmetric contact then gamma_0..gamma_{N-1}, delta_0..delta_N (the odd parts,
  /// line_shape.hpp) and c / l_ref (the centre).
  int unknowns() const { return 2 * n_ + 3 + (asymmetric_ ? 2 * n_ + 2 : 0); }
  /// Equations: (34) and the leading-edge condition at each point, then the load (47).
  int equations() const { return 2 * points() + 1; }
  /// The collocation points t_i = (y - c)/l (+-t_i for an asymmetric contact).
  const std::vector<Real>& collocation() const { return t_; }
  /// The scene's constants.
  const LineProblem<Real>& problem() const { return p_; }

  /// The contact's shape a(y), b(y) and l of the unknowns x.
  LineShape<Real> shape(const Vector& x) const {
    using std::exp;
    LineShape<Real> s{p_.a_ref, p_.l_ref * exp(x[2 * n_ + 1]), {}, {}, basis_, scale_};
    for (int k = 0; k < n_; ++k) s.alpha.push_back(x[k]);
    for (int k = 0; k <= n_; ++k) s.beta.push_back(x[n_ + k]);
    if (asymmetric_) {
      for (int k = 0; k < n_; ++k) s.alpha_odd.push_back(x[odd_alpha() + k]);
      for (int k = 0; k <= n_; ++k) s.beta_odd.push_back(x[odd_beta() + k]);
      s.centre = x[centre_index()] * p_.l_ref;
    }
    return s;
  }
  /// The penetration d of the unknowns x.
  Real penetration(const Vector& x) const { return x[2 * n_ + 2] * p_.c1 * p_.a_ref * p_.a_ref; }

  /// The unknowns of a shape and penetration.
  Vector pack(const LineShape<Real>& given, Real d) const {
    using std::log;
    // Same variable and no more terms: pad with zeros (exact); otherwise re-expand.
    const bool pad = given.basis == basis_ && given.scale == scale_ &&
                     int(given.alpha.size()) <= n_ && int(given.beta.size()) <= n_ + 1 &&
                     int(given.alpha_odd.size()) <= n_ && int(given.beta_odd.size()) <= n_ + 1;
    const LineShape<Real> s = pad ? given : given.reexpanded(basis_, n_, scale_);
    Vector x = Vector::Zero(unknowns());
    for (int k = 0; k < n_ && k < int(s.alpha.size()); ++k) x[k] = s.alpha[k];
    for (int k = 0; k <= n_ && k < int(s.beta.size()); ++k) x[n_ + k] = s.beta[k];
    x[2 * n_ + 1] = log(s.l / p_.l_ref);
    x[2 * n_ + 2] = d / (p_.c1 * p_.a_ref * p_.a_ref);
    if (asymmetric_) {
      for (int k = 0; k < n_ && k < int(s.alpha_odd.size()); ++k)
        x[odd_alpha() + k] = s.alpha_odd[k];
      for (int k = 0; k <= n_ && k < int(s.beta_odd.size()); ++k) x[odd_beta() + k] = s.beta_odd[k];
      x[centre_index()] = s.centre / p_.l_ref;
    }
    return x;
  }

  /// Residual r(x), scaled: (34) by C1 a_ref^2 (plus V/a_ref times the leading-edge row, below),
  /// the leading-edge condition by its derivative with respect to b (so that it reads as an error
  /// in b / a_ref), the load by its target. Returns false
  /// (and leaves r unspecified) where the equations are undefined: a leading edge x0 = a + b <= 0
  /// or a non-finite value.
  bool operator()(const Vector& x, Vector& r) const;

  /// int_{c-l}^{c+l} F0 dy (Eq. 47), on the rule's nodes over the contact (LineNodeRule::load).
  Real load(const LineShape<Real>& s) const {
    std::vector<Real> nodes, weights;
    rule_.load(s, asymmetric_, nodes, weights);
    Real sum = 0;
    for (std::size_t j = 0; j < nodes.size(); ++j)
      sum += weights[j] * strip_functions(p_.c1, s.a(nodes[j]), s.b(nodes[j]), p_.vtau, p_.f).f0;
    return sum;
  }

  /// (34) and the leading-edge residual at one y, |y - c| < l (scaled as in operator()).
  bool at_point(const LineShape<Real>& s, Real d, Real y, Real& r34, Real& rle) const {
    PointWork work;
    return at_point(s, d, y, r34, rle, work);
  }

 private:
  /// The storage of one point's node set and differences, reused from point to point.
  struct PointWork {
    LineNodes<Real> nd;
    std::vector<Real> df0, dq;
  };

  bool at_point(const LineShape<Real>& s, Real d, Real y, Real& r34, Real& rle,
                PointWork& work) const {
    const Real c1 = p_.c1;
    const auto here = strip_functions(c1, s.a(y), s.b(y), p_.vtau, p_.f);
    if (!(here.a > 0) || !(here.a + here.b > 0)) return false;
    LineNodes<Real>& nd = work.nd;
    rule_.point(s, y, here.a + here.b, nd);
    std::vector<Real>& df0 = work.df0;
    std::vector<Real>& dq = work.dq;
    df0.resize(nd.yp.size());
    dq.resize(nd.yp.size());
    for (std::size_t j = 0; j < nd.yp.size(); ++j) {
      const auto there = strip_functions(c1, s.a(nd.yp[j]), s.b(nd.yp[j]), p_.vtau, p_.f);
      df0[j] = there.f0 - here.f0;
      dq[j] = there.q - here.q;
    }
    const Real right =
        LeadingEdge::template right<Quadrature>(p_, s, y, here.a + here.b, nd, dq, here.q);
    point_rows(d, y, here, nd, df0, right, r34, rle);
    return true;
  }

 public:
  /// The residual r(x) and its Jacobian J = dr/dx (semi-analytic, docs/theory.md section 6):
  /// the chain rule through a(y), b(y) (line_shape.hpp) and the strip functions (36),
  /// (33), (46), with d(I1/I0)/dx = 1 - (I1/I0)/x - (I1/I0)^2 (DLMF 10.29.2) and
  /// d(e^z K0)/dz = e^z (K0 - K1), d(e^z K1)/dz = e^z (K1 - K0 - K1/z) (DLMF 10.29.3), at nodes
  /// held fixed in t = y/l; the kernels' dependence on the leading edge x0 = a + b and on l is
  /// differentiated in the same pass as the kernels (exterior_right's ExteriorSlopes). For the
  /// (L6) form only; returns false where operator() would.
  bool jacobian(const Vector& x, Vector& r,
                Matrix& jac) const requires std::same_as<LeadingEdge, ExteriorLeadingEdge>;

 private:
  /// e^z K0(z), e^z K1(z) at z = a/V and the leading-edge row's scale C1 a (e^z K1 + r_i e^z K0),
  /// its slope in b at fixed a.
  struct EdgeTerms {
    Real k0, k1, slope;
  };

  /// (34) and the leading-edge row at one point from the finite-part differences df0_j and the
  /// right side of the leading-edge condition; returns the terms of the row's left side.
  EdgeTerms point_rows(Real d, Real y, const StripFunctions<Real>& here, const LineNodes<Real>& nd,
                       const std::vector<Real>& df0, Real right, Real& r34, Real& rle) const {
    const Real c1 = p_.c1, v = p_.vtau, a = here.a, b = here.b;
    // (34), scaled by C1 a_ref^2.
    const Real lhs34 = near_field_strip(nd, df0, here.f0, a);
    const Real rhs34 = -c1 * a * a / 4 - c1 * b * (b - 2 * v) / 2 - drop_.drop(p_, y) + d;
    r34 = (lhs34 - rhs34) / (c1 * p_.a_ref * p_.a_ref);
    // Leading-edge condition.
    const Real z = a / v;
    const Real k0 = special::bessel_k0_scaled(z), k1 = special::bessel_k1_scaled(z);
    const Real bessel = c1 * (a * b * k1 - here.g * k0);  // C1 e^z {a b K1 - G K0}, Eq. (42)
    const Real r_i = special::bessel_i1_over_i0_fast(strip_alpha(a, v, p_.f));
    const Real slope = c1 * a * (k1 + r_i * k0);  // d(bessel)/db at fixed a
    rle = (bessel - right) / (slope * p_.a_ref);
    return {k0, k1, slope};
  }

  /// G (36), F0 (33), Q (46) (as strip_functions) with their partial derivatives in a and b,
  /// and I1/I0 and its derivative; all zero for a <= 0 (beyond the ends).
  struct StripDerivatives {
    StripFunctions<Real> value;
    Real g_a, g_b, f0_a, f0_b, q_a, q_b, ri, ri_x;
  };
  StripDerivatives strip_derivatives(Real a, Real b) const {
    using std::sqrt;
    const Real c1 = p_.c1, v = p_.vtau, f = p_.f;
    if (!(a > 0)) return {{Real(0), b, Real(0), Real(0), Real(0)}, 0, 0, 0, 0, 0, 0, 0, 0};
    const Real alpha = strip_alpha(a, v, f);
    const Real ri = special::bessel_i1_over_i0_fast(alpha);  // I1/I0
    // DLMF 10.29.2: (I1/I0)' = 1 - (I1/I0)/x - (I1/I0)^2; 1/2 - 3x^2/16 + ... at 0.
    const Real ri_x = alpha < sqrt(std::numeric_limits<Real>::epsilon())
                          ? Real(0.5)
                          : Real(1 - ri / alpha - ri * ri);
    const StripFunctions<Real> value = strip_functions_from_ratio(c1, a, b, v, f, ri);
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

  /// d a(y)/d x and d b(y)/d x at y for fixed t = (y - c)/l (zero in ln l, d and c).
  void shape_gradient(const LineShape<Real>& s, Real y, Real a, Vector& da, Vector& db) const {
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
        if (k < n_) da[odd_alpha() + k] = a * t * tval;
        db[odd_beta() + k] = p_.a_ref * t * tval;
      }
      if (k >= 1) {
        const Real next = 2 * u * tk - tkm1;
        tkm1 = tk;
        tk = next;
      }
    }
  }

  /// Where the asymmetric contact's unknowns sit: gamma, delta, c / l_ref.
  int odd_alpha() const { return 2 * n_ + 3; }
  int odd_beta() const { return 3 * n_ + 3; }
  int centre_index() const { return 4 * n_ + 4; }

  LineProblem<Real> p_;
  Drop drop_;
  int n_;
  int oversampling_;
  bool asymmetric_ = false;
  LineBasis basis_;
  Real scale_;  ///< e of LineBasis::s_mapped, else 0
  LineNodeRule<Real, Quadrature> rule_;
  std::vector<Real> t_;
};

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop>
requires NodalQuadratureRule<Quadrature, Real> &&
    LeadingEdgeCondition<LeadingEdge, Real, Quadrature> && RollerDrop<Drop, Real>
auto LineResidual<Real, Quadrature, LeadingEdge, Drop>::operator()(const Vector& x, Vector& r) const
    -> bool {
  r.resize(equations());
  const LineShape<Real> s = shape(x);
  const Real d = penetration(x);
  const int m = points();
  PointWork work;
  for (int i = 0; i < m; ++i) {
    Real r34 = 0, rle = 0;
    if (!at_point(s, d, s.centre + t_[i] * s.l, r34, rle, work)) return false;
    // (34) depends on b through C1 V b, the leading-edge condition through its slope C1 V (as
    // V tau >> a): adding V/a_ref times the latter (scaled to an error in b/a_ref) cancels the b
    // dependence of (34) to first order, so that (34) speaks for a, l and d at every speed. A row
    // operation: the solution is unchanged, the Jacobian's condition number no longer grows as V.
    r[i] = r34 + p_.vtau / p_.a_ref * rle;
    r[m + i] = rle;
  }
  r[2 * m] = load(s) / p_.load_target - 1;
  for (int i = 0; i < r.size(); ++i)
    if (!(boost::math::isfinite)(r[i])) return false;
  return true;
}

}  // namespace viscoroll

#include <viscoroll/line/detail/line_residual_jacobian.hpp>

namespace viscoroll {

// Compiled mode (docs/building.md): with VISCOROLL_COMPILED, which the CMake target
// viscoroll::compiled sets (VISCOROLL_COMPILED_DOUBLE, from viscoroll::compiled_double: the double
// ones only), the residuals of the line solvers' default rule (12-point
// Gauss-Legendre), and in double of the fast setting's (6-point), are instantiated once in that
// library (src/) and not in the including
// translation unit; operator() and jacobian() are defined out of the class (not inline), so that
// g++ does not instantiate them here for inlining either.
#if defined(VISCOROLL_COMPILED)
extern template class LineResidual<float, GaussLegendre<float, 12>>;
extern template class LineResidual<long double, GaussLegendre<long double, 12>>;
#endif
#if defined(VISCOROLL_COMPILED) || defined(VISCOROLL_COMPILED_DOUBLE)
extern template class LineResidual<double, GaussLegendre<double, 12>>;
extern template class LineResidual<double, GaussLegendre<double, 6>>;
#endif

}  // namespace viscoroll
