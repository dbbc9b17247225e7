// viscoroll: the residual assembly of the line solver, for every material.
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
// One memory term is the fast path: its strip is closed-form in a and b ((32)-(36), (46)). A
// spectrum of M >= 2 terms (docs/theory.md section 14) has M leading-edge conditions per strip,
// right sides (L6) at lambda_k = V tau_k (S12), and (34) gains its constant (S13); two more
// functions of y, gamma = G0/a^2 and the centroid kappa, join the unknowns and carry the strips
// to the line integrals (S14). Shape, collocation, node rule, (34) and the load are shared. The
// kernels of each are in line/detail/line_residual_jacobian.hpp and line_residual_spectrum.hpp.
#pragma once

#include <Eigen/Core>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <concepts>
#include <limits>
#include <optional>
#include <utility>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/spectrum_strip.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/line_node_rule.hpp>
#include <viscoroll/line/line_operators.hpp>
#include <viscoroll/line/line_shape.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>
#include <viscoroll/special/bessel_ratio.hpp>

namespace viscoroll::line {

/// The scene's constants seen by the residual, lengths in one unit. One memory term: V tau > 0
/// and f > 0, `lengths` empty. A spectrum: `lengths` at the scene's speed (its lambda_k = V tau_k,
/// mu_i = V rho_i and creep ratio F), vtau and f unused.
template <RealScalar Real>
struct LineProblem {
  /// C1, C2, V tau and f of the scene.
  ///@{
  Real c1, c2, vtau, f;
  ///@}
  Real a_ref;        ///< long-term static half width at y = 0 (scale of a, b)
  Real l_ref;        ///< long-term static half length (scale of l)
  Real load_target;  ///< int F0 dy = (1 + f) c P, Eq. (47) with (52); (1 + F) c P for a spectrum
  plane::SpectrumLengths<Real> lengths{};  ///< a spectrum's lengths; empty for one term
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

/// The roller's drop h(y) along its axis in (34), a policy of LineResidual: a D provides
/// `Real drop(const Problem&, Real y) const` and `Real drop_slope(const Problem&, Real y) const`,
/// h(y) and h'(y) in the residual's units inside the contact; h even in y unless the residual is
/// asymmetric (its `asymmetric`: else it collocates on y > 0); Problem the residual's constants
/// (LineProblem). Models: ParabolicDrop (the paper's Eq. 27, from the problem's c2) and
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

/// What LineResidual takes: a NodalQuadratureRule, a LeadingEdgeCondition, a RollerDrop, and
/// MemoryTerms 1, or dynamic_memory_terms with (L6) (ExteriorLeadingEdge: a spectrum has no other).
template <class Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
concept LineResidualArguments = NodalQuadratureRule<Quadrature, Real> &&
    LeadingEdgeCondition<LeadingEdge, Real, Quadrature> && RollerDrop<Drop, Real> &&
    (MemoryTerms == 1 ||
     (MemoryTerms == dynamic_memory_terms && std::same_as<LeadingEdge, ExteriorLeadingEdge>));

/// Residual of the line equations at collocation points; `Quadrature` a NodalQuadratureRule,
/// `LeadingEdge` a LeadingEdgeCondition, `Drop` a RollerDrop. The problem decides the material:
/// one memory term (the closed-form strips, 2N + 3 unknowns) or a spectrum (its `lengths` set:
/// the strips' moments are unknowns too, 4N + 5; ExteriorLeadingEdge and oversampling 1 only).
/// `MemoryTerms`, as a ConstitutiveModel's memory_term_count: 1 for one term only (a spectrum's
/// members compile away), dynamic_memory_terms for either.
/// A least-squares problem for numerics::levenberg_marquardt, with a semi-analytic Jacobian.
template <RealScalar Real, class Quadrature, class LeadingEdge = ExteriorLeadingEdge,
          class Drop = ParabolicDrop, int MemoryTerms = 1>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
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
  /// d; the leading-edge condition at N + 1 points fixes the N + 1 coefficients of b (a spectrum's
  /// b, G0/a^2 and centroid at N + 1 points the N + 1 coefficients of b, gamma and kappa).
  /// oversampling k >= 1: k (N + 1) points instead, an overdetermined system whose least-squares
  /// solution is the paper's (Section 7; docs/theory.md section 10); 1 for a spectrum.
  /// quadrature_tolerance: the relative accuracy of every integral (LineNodeRule); 0, the default,
  /// the scalar's epsilon (every integral exact to rounding).
  /// drop: the roller's h(y) (the paper's C2 y^2/2 by default).
  /// asymmetric: the contact [c - l, c + l] of a roller whose drop is not even (a tilt;
  /// docs/theory.md (RP7)): every series takes an odd part of as many coefficients as its even
  /// part, the centre c is an unknown, and the equations are collocated at the points +-t_i; the
  /// even unknowns keep their places, the odd ones follow (unknowns()).
  LineResidual(LineProblem<Real> problem, int terms, LineBasis basis = LineBasis::t_squared,
               int oversampling = 1, Real quadrature_tolerance = Real(0), Drop drop = Drop{},
               bool asymmetric = false)
      : p_(std::move(problem)),
        drop_(std::move(drop)),
        n_(terms),
        oversampling_(oversampling),
        asymmetric_(asymmetric),
        spectrum_(!p_.lengths.retardation.empty()),
        basis_(basis) {
    detail::require(terms >= 1 && terms <= 64, "terms", terms, "1 <= terms <= 64");
    detail::require(oversampling >= 1 && oversampling <= 8, "oversampling", oversampling,
                    "1 <= oversampling <= 8");
    using std::cos;
    using std::sqrt;
    if (spectrum_) {
      detail::require(MemoryTerms == dynamic_memory_terms, "memory terms", MemoryTerms,
                      "dynamic_memory_terms for a spectrum's problem");
      detail::require(oversampling == 1, "oversampling", oversampling, "1 for a spectrum");
      if constexpr (MemoryTerms != 1) init_spectrum(quadrature_tolerance);
    } else {
      scale_ = basis == LineBasis::s_mapped ? LineShape<Real>::mapped_scale(p_.vtau, p_.f, p_.a_ref)
                                            : Real(0);
      rule_.emplace(basis_, scale_, terms, p_.vtau, p_.f, quadrature_tolerance);
    }
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
  /// Whether the problem is a spectrum's (the strips' moments are unknowns).
  bool spectrum() const { return spectrum_; }
  /// Unknowns: alpha_0..alpha_{N-1}, beta_0..beta_N, for a spectrum gamma_0..gamma_N and
  /// kappa_0..kappa_N, then ln(l / l_ref), d / (C1 a_ref^2); for an asymmetric contact then the
  /// odd parts' coefficients (N, N + 1, and N + 1, N + 1 for a spectrum, line_shape.hpp) and
  /// c / l_ref (the centre).
  int unknowns() const { return even_unknowns() + (asymmetric_ ? even_unknowns() - 1 : 0); }
  /// Equations: at each point (34) and the leading-edge condition (a spectrum's (34) and its
  /// strip's b, G0/a^2 and centroid against the expansions), then the load (47).
  int equations() const { return (spectrum_ ? 4 : 2) * points() + 1; }
  /// The collocation points t_i = (y - c)/l (+-t_i for an asymmetric contact).
  const std::vector<Real>& collocation() const { return t_; }
  /// The scene's constants.
  const LineProblem<Real>& problem() const { return p_; }
  /// A spectrum's lambda_k / a_ref below which a term's leading-edge condition is the strip's
  /// own (S16).
  static Real slow_fraction() { return Real(1) / 10; }
  /// A spectrum's terms whose leading-edge condition carries the line integrals (S12).
  int line_terms() const { return int(line_.size()); }

  /// The contact's shape a(y), b(y) and l of the unknowns x.
  LineShape<Real> shape(const Vector& x) const {
    using std::exp;
    LineShape<Real> s{p_.a_ref, p_.l_ref * exp(x[log_length()]), {}, {}, basis_, scale_};
    for (int k = 0; k < n_; ++k) s.alpha.push_back(x[k]);
    for (int k = 0; k <= n_; ++k) s.beta.push_back(x[n_ + k]);
    if (asymmetric_) {
      for (int k = 0; k < n_; ++k) s.alpha_odd.push_back(x[odd() + k]);
      for (int k = 0; k <= n_; ++k) s.beta_odd.push_back(x[odd() + n_ + k]);
      s.centre = x[centre_index()] * p_.l_ref;
    }
    return s;
  }
  /// A spectrum's series gamma and kappa of the unknowns x (empty for one term).
  LineSpectrumMoments<Real> moments(const Vector& x) const {
    LineSpectrumMoments<Real> m;
    if (!spectrum_) return m;
    for (int k = 0; k <= n_; ++k) {
      m.gamma.push_back(x[2 * n_ + 1 + k]);
      m.kappa.push_back(x[3 * n_ + 2 + k]);
      if (asymmetric_) {
        m.gamma_odd.push_back(x[odd() + 2 * n_ + 1 + k]);
        m.kappa_odd.push_back(x[odd() + 3 * n_ + 2 + k]);
      }
    }
    return m;
  }
  /// The penetration d of the unknowns x.
  Real penetration(const Vector& x) const {
    return x[log_length() + 1] * p_.c1 * p_.a_ref * p_.a_ref;
  }

  /// The unknowns of a shape and penetration (a spectrum's moments zero).
  Vector pack(const LineShape<Real>& given, Real d) const { return pack(given, {}, d); }
  /// The unknowns of a shape, a spectrum's moments (ignored for one term) and penetration. Series
  /// in the same variable with no more terms are padded with zeros (exact), a spectrum's longer
  /// ones truncated, others re-expanded; a shape in another unit a_ref (a seed whose active terms
  /// differ) is converted to this one.
  Vector pack(const LineShape<Real>& given, const LineSpectrumMoments<Real>& mo, Real d) const;

  /// Residual r(x), scaled: (34) by C1 a_ref^2 (plus V/a_ref times the leading-edge row, below),
  /// the leading-edge condition by its derivative with respect to b (so that it reads as an error
  /// in b / a_ref), a spectrum's b and centroid by a_ref, the load by its target. Returns false
  /// (and leaves r unspecified) where the equations are undefined: a leading edge x0 = a + b <= 0
  /// or a non-finite value.
  bool operator()(const Vector& x, Vector& r) const;

  /// int_{c-l}^{c+l} F0 dy (Eq. 47), on the rule's nodes over the contact (LineNodeRule::load);
  /// a spectrum's F0 from its moments.
  Real load(const LineShape<Real>& s, const LineSpectrumMoments<Real>& mo = {}) const {
    std::vector<Real> nodes, weights;
    rule_->load(s, asymmetric_, nodes, weights);
    Real sum = 0;
    for (std::size_t j = 0; j < nodes.size(); ++j) sum += weights[j] * f0_at(s, mo, nodes[j]);
    return sum;
  }

  /// F0 at y: one term's closed form (33), a spectrum's from its moments.
  Real f0_at(const LineShape<Real>& s, const LineSpectrumMoments<Real>& mo, Real y) const {
    if constexpr (MemoryTerms != 1)
      if (spectrum_) return functions(s, mo, y).f0;
    return plane::strip_functions(p_.c1, s.a(y), s.b(y), p_.vtau, p_.f).f0;
  }

  /// A spectrum's int F0 (b + kappa) dy / int F0 dy over the contact: the pressure's centroid
  /// from the axis, chi / C1 (Eq. 51 strip by strip, (S10), (S15)).
  Real centroid(const LineShape<Real>& s, const LineSpectrumMoments<Real>& mo) const;

  /// One term: (34) and the leading-edge residual at one y, |y - c| < l (scaled as in
  /// operator()).
  bool at_point(const LineShape<Real>& s, Real d, Real y, Real& r34, Real& rle) const {
    PointWork work;
    return at_point(s, d, y, r34, rle, work);
  }

  /// The residual r(x) and its Jacobian J = dr/dx (semi-analytic, docs/theory.md section 6; a
  /// spectrum's (S17)): the chain rule through a(y), b(y) (line_shape.hpp) and the strip functions
  /// (36), (33), (46), with d(I1/I0)/dx = 1 - (I1/I0)/x - (I1/I0)^2 (DLMF 10.29.2) and
  /// d(e^z K0)/dz = e^z (K0 - K1), d(e^z K1)/dz = e^z (K1 - K0 - K1/z) (DLMF 10.29.3), or through
  /// a spectrum's strip (SpectrumStripSlopes), at nodes held fixed in t = y/l; the kernels'
  /// dependence on the leading edge x0 = a + b and on l is differentiated in the same pass as the
  /// kernels (exterior_right's ExteriorSlopes). For the (L6) form only; returns false where
  /// operator() would, and r is operator()'s bit for bit.
  bool jacobian(const Vector& x, Vector& r,
                Matrix& jac) const requires std::same_as<LeadingEdge, ExteriorLeadingEdge>;

 private:
  /// The storage of one point's node set and differences, reused from point to point.
  struct PointWork {
    LineNodes<Real> nd;
    std::vector<Real> df0, dq;
  };

  /// One term: (34) and the leading-edge residual at y.
  bool at_point(const LineShape<Real>& s, Real d, Real y, Real& r34, Real& rle,
                PointWork& work) const;

  /// e^z K0(z), e^z K1(z) at z = a/V and the leading-edge row's scale C1 a (e^z K1 + r_i e^z K0),
  /// its slope in b at fixed a.
  struct EdgeTerms {
    Real k0, k1, slope;
  };

  /// One term: (34) and the leading-edge row at one point from the finite-part differences df0_j
  /// and the right side of the leading-edge condition; returns the terms of the row's left side.
  EdgeTerms point_rows(Real d, Real y, const plane::StripFunctions<Real>& here,
                       const LineNodes<Real>& nd, const std::vector<Real>& df0, Real right,
                       Real& r34, Real& rle) const;

  /// One term: G (36), F0 (33), Q (46) (as strip_functions) with their partial derivatives in a
  /// and b, and I1/I0 and its derivative; all zero for a <= 0 (beyond the ends).
  struct StripDerivatives {
    plane::StripFunctions<Real> value;
    Real g_a, g_b, f0_a, f0_b, q_a, q_b, ri, ri_x;
  };
  StripDerivatives strip_derivatives(Real a, Real b) const;

  /// One term: d a(y)/d x and d b(y)/d x at y for fixed t = (y - c)/l (zero in ln l, d and c).
  void shape_gradient(const LineShape<Real>& s, Real y, Real a, Vector& da, Vector& db) const;

  /// A spectrum's line functions at y from the expansions: a, b, gamma = G0/a^2, the centroid
  /// kappa of the strip and F0 = C1 a^2 (1/4 + gamma/2) (33) (all 0 but b where a = 0).
  struct Functions {
    Real a, b, gamma, kappa, f0;
  };
  Functions functions(const LineShape<Real>& s, const LineSpectrumMoments<Real>& mo, Real y) const;
  /// A spectrum's Q_k = F0 (1 - (b + kappa)/lambda_k) of term k (S14).
  Real q(const Functions& f, std::size_t k) const {
    return f.f0 * (1 - (f.b + f.kappa) / p_.lengths.retardation[k]);
  }
  /// A spectrum's scale, node rule and line terms (line/detail/line_residual_spectrum.hpp).
  void init_spectrum(Real tolerance);
  /// A spectrum's r(x) and, with `jac`, its Jacobian.
  bool spectrum_evaluate(const Vector& x, Vector& r, Matrix* jac) const;
  /// The rows d right_k / dx of a spectrum's line terms at one point (S17): from the slopes of
  /// (L6) and, at the point's nodes, a, F0, b + kappa, the Chebyshev values tv, and at the point
  /// its functions, Q_k (qs) and Chebyshev values ti.
  void spectrum_right_slopes(const Functions& here, const std::vector<ExteriorSlopes<Real>>& slopes,
                             const std::vector<Real>& as, const std::vector<Real>& f0s,
                             const std::vector<Real>& bks, const std::vector<Real>& qs,
                             const std::vector<Real>& tv, const Real* ti, Matrix& dright) const;
  /// A spectrum's load equation, row 4 m, and with `jac` its row of the Jacobian.
  void spectrum_load_row(const LineShape<Real>& s, const LineSpectrumMoments<Real>& mo, Vector& r,
                         Matrix* jac) const;
  /// T_0(u) ... T_N(u) into t (N + 1 values), then, for an asymmetric contact, t_y times them.
  void chebyshev_values(Real u, Real* t, Real t_y = 0) const;
  /// Values per abscissa in chebyshev_values: N + 1, twice that for an asymmetric contact.
  int series_values() const { return (n_ + 1) * (asymmetric_ ? 2 : 1); }
  /// Adds to row `row` of jac the derivative of a function g(a, b, gamma, kappa) at one abscissa
  /// with the Chebyshev values t, given dg/d ln a (ga), dg/db (gb), dg/dgamma (gg), dg/dkappa
  /// (gk), each times `scale`.
  void add_series_row(Matrix& jac, int row, const Real* t, Real ga, Real gb, Real gg, Real gk,
                      Real scale) const;

  /// The unknowns of the even parts: 2N + 3, 4N + 5 for a spectrum.
  int even_unknowns() const { return spectrum_ ? 4 * n_ + 5 : 2 * n_ + 3; }
  /// Where ln(l / l_ref) sits (d / (C1 a_ref^2) follows it).
  int log_length() const { return even_unknowns() - 2; }
  /// Where the asymmetric contact's odd parts start, and c / l_ref.
  int odd() const { return even_unknowns(); }
  int centre_index() const { return 2 * even_unknowns() - 2; }

  LineProblem<Real> p_;
  Drop drop_;
  int n_;
  int oversampling_;
  bool asymmetric_ = false;
  bool spectrum_ = false;
  LineBasis basis_;
  Real scale_ = 0;  ///< e of LineBasis::s_mapped, else 0
  std::optional<LineNodeRule<Real, Quadrature>> rule_;
  std::vector<Real> t_;
  Real lambda_sum_ = 0;            ///< a spectrum's sum of lambda_k
  std::vector<std::size_t> line_;  ///< the indices of the line terms
  std::vector<Real> line_lambda_;  ///< their retardation lengths
};

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
inline auto LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::pack(
    const LineShape<Real>& given, const LineSpectrumMoments<Real>& mo, Real d) const -> Vector {
  using std::log;
  const bool same = given.basis == basis_ && given.scale == scale_;
  const bool fits = int(given.alpha.size()) <= n_ && int(given.beta.size()) <= n_ + 1 &&
                    int(given.alpha_odd.size()) <= n_ && int(given.beta_odd.size()) <= n_ + 1;
  LineShape<Real> s = same && (fits || spectrum_) ? given : given.reexpanded(basis_, n_, scale_);
  // A shape in another unit a_ref: the same a(y), b(y) (exact where the units agree).
  const Real ratio = s.a_ref / p_.a_ref;
  if (ratio != 1) {
    if (s.alpha.empty()) s.alpha.push_back(Real(0));
    s.alpha[0] += log(ratio);
    for (Real& b : s.beta) b *= ratio;
    for (Real& b : s.beta_odd) b *= ratio;
  }
  Vector x = Vector::Zero(unknowns());
  for (int k = 0; k < n_ && k < int(s.alpha.size()); ++k) x[k] = s.alpha[k];
  for (int k = 0; k <= n_ && k < int(s.beta.size()); ++k) x[n_ + k] = s.beta[k];
  x[log_length()] = log(s.l / p_.l_ref);
  x[log_length() + 1] = d / (p_.c1 * p_.a_ref * p_.a_ref);
  if (asymmetric_) {
    const int o = odd();
    for (int k = 0; k < n_ && k < int(s.alpha_odd.size()); ++k) x[o + k] = s.alpha_odd[k];
    for (int k = 0; k <= n_ && k < int(s.beta_odd.size()); ++k) x[o + n_ + k] = s.beta_odd[k];
    x[centre_index()] = s.centre / p_.l_ref;
  }
  if (spectrum_) {
    for (int k = 0; k <= n_ && k < int(mo.gamma.size()); ++k) x[2 * n_ + 1 + k] = mo.gamma[k];
    for (int k = 0; k <= n_ && k < int(mo.kappa.size()); ++k)
      x[3 * n_ + 2 + k] = mo.kappa[k] * ratio;
    if (asymmetric_) {
      const int o = odd();
      for (int k = 0; k <= n_ && k < int(mo.gamma_odd.size()); ++k)
        x[o + 2 * n_ + 1 + k] = mo.gamma_odd[k];
      for (int k = 0; k <= n_ && k < int(mo.kappa_odd.size()); ++k)
        x[o + 3 * n_ + 2 + k] = mo.kappa_odd[k] * ratio;
    }
  }
  return x;
}

template <RealScalar Real, class Quadrature, class LeadingEdge, class Drop, int MemoryTerms>
requires LineResidualArguments<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>
auto LineResidual<Real, Quadrature, LeadingEdge, Drop, MemoryTerms>::operator()(const Vector& x,
                                                                                Vector& r) const
    -> bool {
  if constexpr (MemoryTerms != 1)
    if (spectrum_) return spectrum_evaluate(x, r, nullptr);
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

}  // namespace viscoroll::line

#include <viscoroll/line/detail/line_residual_jacobian.hpp>
#include <viscoroll/line/detail/line_residual_spectrum.hpp>

namespace viscoroll::line {

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

}  // namespace viscoroll::line
