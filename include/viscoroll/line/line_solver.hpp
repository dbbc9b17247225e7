// viscoroll: the paper's 3-D solver, an ellipsoidal roller on a standard linear solid by the
// line-contact theory.
//
// Panek & Kalker (1980), Sections 5-7: the equations (33), (34), (36), (46), (47) and a
// leading-edge condition (line_residual.hpp; docs/theory.md section 4 for the form (L6) used by
// default and why the printed (44) is not), solved for the coefficients of a(y), b(y)
// (line_shape.hpp), l and d by a Levenberg-Marquardt iteration (a damped Gauss-Newton method with
// Marquardt's diagonal scaling; the system is square, so a converged solution has a zero residual
// to rounding). The static scene (V tau = 0), the elastic material (f = 0) and the glassy limit
// (V tau beyond ~40/eps half widths, strip_is_glassy) are Kalker's closed form
// (static_line_contact.hpp) with the long-term or the instantaneous compliance: no Bessel work.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <chrono>
#include <cmath>
#include <concepts>
#include <limits>
#include <optional>
#include <string>
#include <vector>
#include <boost/math/special_functions/fpclassify.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/strip_pressure.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/line_shape.hpp>
#include <viscoroll/line/static_line_contact.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

namespace viscoroll {

/// An ellipsoidal (doubly parabolic, Eq. 27) roller of curvatures c1 (across) and c2 (along the
/// axis) under total load `load`, rolling towards +x at `speed`.
template <RealScalar Real>
struct LineScene {
  Real c1;
  Real c2;
  Real load;
  Real speed;

  /// Throws std::invalid_argument naming the parameter unless c1 > 0, 0 < c2 < 8 e^-3 c1 (the
  /// contact is longer in y than in x), load > 0, speed >= 0, all finite.
  void validate() const {
    detail::require_positive("c1", c1);
    detail::require_positive("c2", c2);
    detail::require_positive("load", load);
    detail::require_non_negative("speed", speed);
    detail::require(c2 < max_line_contact_curvature_ratio<Real>() * c1, "c2", c2,
                    "0 < c2 < 8 e^-3 c1 = 0.398 c1 (a contact longer in y than in x)");
  }
};

/// How the line solver forms the Jacobian of its residual.
enum class LineJacobian {
  analytic,    ///< chain rule through the shape and the strip functions (LineResidual::jacobian)
  difference,  ///< forward differences, 2 terms + 3 residual evaluations
};

/// Runtime settings of the line solver.
struct LineOptions {
  /// Discretisation: ln a(y) has `terms` Chebyshev coefficients, b(y) has terms + 1; the
  /// equations are collocated at terms + 1 points.
  int terms = 8;
  /// Levenberg-Marquardt iterations allowed (each costs one residual evaluation per damping try,
  /// plus one Jacobian when it is refreshed: ~2.5 residual evaluations semi-analytic, 2 terms + 3
  /// by differences).
  int max_iterations = 100;
  /// Expansion variable of a(y), b(y); LineBasis::s_mapped with oversampling for the slow regime.
  LineBasis basis = LineBasis::t_squared;
  /// Collocation points per coefficient of b(y): the equations hold at oversampling (terms + 1)
  /// points. 1: the square system, solved exactly where it has a root. k > 1: the least-squares
  /// fit of the paper (Section 7), which converges with `terms` where the line equations have no
  /// solution at all (the slow regime, V tau <~ 0.1 a0; docs/line-solver.md, "Oversampling").
  int oversampling = 1;
  /// How the Jacobian is formed: semi-analytic (LineResidual::jacobian, default; the (L6) form
  /// only, the paper's (44) always uses differences) or by forward differences.
  LineJacobian jacobian = LineJacobian::analytic;
  /// Where Levenberg-Marquardt stops at a least-squares minimum with no root of the equations
  /// near it, minimise |r|^2 there by Newton's method with its second-order term (the paper's
  /// least-squares solution, Section 7; docs/line-solver.md, "Least-squares minima"). Needs the
  /// semi-analytic Jacobian and the (L6) form; otherwise such a stop is reported not converged.
  bool least_squares = true;

  void validate() const {
    detail::require(terms >= 1 && terms <= 64, "terms", terms, "1 <= terms <= 64");
    detail::require(oversampling >= 1 && oversampling <= 8, "oversampling", oversampling,
                    "1 <= oversampling <= 8");
    detail::require(max_iterations >= 1 && max_iterations <= 100000, "max_iterations",
                    max_iterations, "1 <= max_iterations <= 100000");
  }
};

/// The line-contact solution: the contact zone, the penetration, the line functions of Section 5
/// and the rolling friction of Section 6.
template <RealScalar Real, class Quadrature>
struct LineSolution {
  LineShape<Real> shape;  ///< a(y), b(y), l
  Real d;                 ///< penetration (Eq. 27)
  Real a_long_term;       ///< a0: half width at y = 0 of the static (V tau = 0) contact
  Real l_long_term;       ///< l0: its half length
  Real d_long_term;       ///< its penetration
  Real chi;               ///< rolling-friction coefficient, Eq. (54) in the form of section 4
  bool converged;         ///< the iteration met its tolerance (always true for a closed form)
  /// The residual vanishes (max |r| <= 64 sqrt(eps)): a root of the line equations. False with
  /// converged at a certified least-squares minimum where the equations have no root (the
  /// residual is then reported, and a warning says so).
  bool root;
  std::string reason;                 ///< why it stopped
  int iterations;                     ///< Levenberg-Marquardt iterations (0 for a closed form)
  Real residual;                      ///< max |r| of the scaled equations at the returned solution
  std::vector<std::string> warnings;  ///< outside the line theory's domain of validity

  Real c1, vtau, f, compliance;

  Real l() const { return shape.l; }
  Real a(Real y) const { return shape.a(y); }
  Real b(Real y) const { return shape.b(y); }
  /// G(y) of Eq. (36); 0 for a static or elastic scene.
  Real g(Real y) const { return functions(y).g; }
  /// F0(y) of Eq. (33).
  Real f0(Real y) const { return functions(y).f0; }
  /// Q(y) of Eq. (46).
  Real q(Real y) const { return functions(y).q; }

  /// The strip at y (|y| < l): Eqs. (32), (35) across the contact.
  StripPressure<Real, Quadrature> strip(Real y) const {
    const auto s = functions(y);
    return StripPressure<Real, Quadrature>(c1, s.a, s.b, s.g, vtau, f, compliance);
  }
  /// p(x, y), Eq. (35); zero outside the contact.
  Real pressure(Real x, Real y) const {
    using std::abs;
    if (!(abs(y) < shape.l)) return Real(0);
    return strip(y).pressure(x);
  }

  StripFunctions<Real> functions(Real y) const {
    const Real a = shape.a(y), b = shape.b(y);
    if (!(vtau > 0) || !(f > 0) || !(a > 0)) return {a, b, Real(0), c1 * a * a / 4, Real(0)};
    return strip_functions(c1, a, b, vtau, f);
  }
};

/// The line theory's domain (Section 3: the contact is slender, a(y) << l): a warning when
/// l/a(0) < 3, and one when a(y) somewhere reaches l/3 (a(y) can exceed a(0), as at the dip of
/// a(0) near V tau = 5 a0). a(y) is sampled at 65 points y = l k/64, k = 0..64. Empty inside it.
template <RealScalar Real>
std::vector<std::string> line_domain_warnings(const LineShape<Real>& shape) {
  std::vector<std::string> warnings;
  const Real l = shape.l, a0 = shape.a(Real(0));
  const Real aspect = l / a0;
  if (!(aspect >= 3))
    warnings.push_back("contact aspect l/a(0) = " + std::to_string(double(aspect)) +
                       " < 3: outside the line-contact theory's domain of validity");
  Real a_max = a0, y_max = 0;
  for (int k = 1; k <= 64; ++k) {
    const Real y = l * Real(k) / 64, a = shape.a(y);
    if (a > a_max) a_max = a, y_max = y;
  }
  if (a_max > a0 && !(l >= 3 * a_max))
    warnings.push_back("a(y) = " + std::to_string(double(a_max)) +
                       " at y = " + std::to_string(double(y_max)) +
                       " is not small against l = " + std::to_string(double(l)) +
                       " (l/max a(y) < 3): outside the line-contact theory's domain of validity");
  return warnings;
}

/// Solver of the line-contact equations over a scalar, a constitutive model and a nodal
/// quadrature rule (applied on the graded panels of every line integral).
template <RealScalar Real, ConstitutiveModel Material, class Quadrature = GaussLegendre<Real, 12>>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
class LineSolver {
 public:
  using Solution = LineSolution<Real, Quadrature>;
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

  explicit LineSolver(Material material, LineOptions options = {})
      : material_(std::move(material)), options_(options) {
    options_.validate();
  }

  const Material& material() const { return material_; }
  const LineOptions& options() const { return options_; }

  /// Solves the scene; `start` (a solution of a nearby scene, same material) seeds the iteration.
  /// A seed that is not a converged, finite solution is set aside, and an iteration from a seed
  /// that stops short is run again from the cold start; either is said in `warnings`.
  /// Throws std::invalid_argument for an invalid scene; a non-converged iteration is returned
  /// with converged == false and the reason.
  Solution solve(const LineScene<Real>& scene, const Solution* start = nullptr) const;

  /// The residual assembly for a scene (for tests and for users who drive their own iteration).
  LineResidual<Real, Quadrature> residual(const LineScene<Real>& scene) const {
    scene.validate();
    const Real c = material_.instantaneous_compliance();
    const Real f = material_.creep_ratio();
    const auto slow = static_line_contact(scene.c1, scene.c2, (1 + f) * c * scene.load);
    return LineResidual<Real, Quadrature>(
        problem(scene, slow, f, scene.speed * material_.relaxation_time()), options_.terms,
        options_.basis, options_.oversampling);
  }

 private:
  static LineProblem<Real> problem(const LineScene<Real>& scene,
                                   const StaticLineContact<Real>& slow, Real f, Real vtau) {
    return {
        scene.c1, scene.c2, vtau, f, slow.a0, slow.l, scene.c1 * slow.a0 * slow.a0 * slow.l / 3};
  }

  Solution closed_form(const LineScene<Real>& scene, const StaticLineContact<Real>& s,
                       const StaticLineContact<Real>& slow, Real c, Real f,
                       const char* reason) const {
    using std::log;
    LineShape<Real> shape{slow.a0, s.l, {log(s.a0 / slow.a0)}, {Real(0)}};
    // A glassy contact is the static one of the instantaneous compliance: G = 0 makes F0 = C1 a^2/4
    // the load of that compliance; it is reported as the static strip (vtau = 0 in the pressure).
    Solution sol{shape,  s.d, slow.a0, slow.l, slow.d,   Real(0), true, true,
                 reason, 0,   Real(0), {},     scene.c1, Real(0), f,    c};
    add_warnings(sol);
    return sol;
  }

  /// Terms of the continuation stages that lead to `terms`: 2, 4, 8, 16, 32 below
  /// it, then `terms` itself (docs/line-solver.md, "Continuation in N").
  static std::vector<int> continuation_stages(int terms) {
    std::vector<int> stages;
    for (int n : {2, 4, 8, 16, 32})
      if (n < terms) stages.push_back(n);
    stages.push_back(terms);
    return stages;
  }

  /// max |r| of the scaled equations below which the iterate is a root (`LineSolution::root`):
  /// the tolerance of iterate()'s stop, minimise()'s hand-back and the solution's flag.
  static Real root_tolerance() {
    using std::sqrt;
    return 64 * sqrt(std::numeric_limits<Real>::epsilon());
  }

  /// The outcome of one Levenberg-Marquardt run.
  struct Outcome {
    bool converged = false;
    bool undefined = false;  ///< the Jacobian could not be evaluated (left the equations' domain)
    bool minimum = false;    ///< stopped at a least-squares minimum with no root near (or no
                             ///< descent step): where `minimise` takes over
    bool root_near = false;  ///< `minimise` reached a residual below tolerance
    std::string reason = "iteration limit";
    int iterations = 0;
  };

  /// rolling() from `start` where it can seed the iteration, else from the cold start; a seeded
  /// iteration that stops short is run again from the cold start. The result's warnings say when
  /// a seed was set aside, so that a bad seed never decides the answer.
  Solution rolling_from(const LineScene<Real>& scene, const StaticLineContact<Real>& slow, Real c,
                        Real f, Real vtau, const Solution* start) const {
    if (start == nullptr) return rolling(scene, slow, c, f, vtau, nullptr);
    if (!usable_seed(*start)) {
      Solution cold = rolling(scene, slow, c, f, vtau, nullptr);
      cold.warnings.push_back(
          "the seed was set aside (not a converged solution with finite a(y), b(y), l and d): "
          "solved from the cold start");
      return cold;
    }
    Solution seeded = rolling(scene, slow, c, f, vtau, start);
    if (seeded.converged) return seeded;
    Solution cold = rolling(scene, slow, c, f, vtau, nullptr);
    cold.warnings.push_back("the iteration from the seed stopped (" + seeded.reason +
                            "): solved again from the cold start");
    return cold;
  }

  /// A converged solution whose shape and penetration are finite.
  static bool usable_seed(const Solution& s) {
    const auto finite = [](const std::vector<Real>& v) {
      for (const Real& x : v)
        if (!(boost::math::isfinite)(x)) return false;
      return true;
    };
    return s.converged && !s.shape.alpha.empty() && finite(s.shape.alpha) &&
           finite(s.shape.beta) && (boost::math::isfinite)(s.shape.l) && s.shape.l > 0 &&
           (boost::math::isfinite)(s.shape.a_ref) && s.shape.a_ref > 0 &&
           (boost::math::isfinite)(s.d);
  }

  Solution rolling(const LineScene<Real>& scene, const StaticLineContact<Real>& slow, Real c,
                   Real f, Real vtau, const Solution* start) const {
    using std::log;
    using std::pow;
    const LineProblem<Real> prob = problem(scene, slow, f, vtau);
    LineShape<Real> shape;
    Real d;
    std::vector<int> stages;
    if (start != nullptr && start->shape.alpha.size() > 0) {
      // A solution of a nearby scene: straight to the requested discretisation.
      shape = start->shape;
      d = start->d;
      stages = {options_.terms};
    } else {
      // Seed: the static contact shrunk and shifted as the plane solution at the same V tau/a0,
      // then continuation in N from two terms up: each stage starts from the previous solution,
      // which keeps the iteration on the branch of smooth solutions (a cold start at large N can
      // land on another root of the discrete equations, docs/line-solver.md).
      const PlaneSolver<Real, Material> plane(material_);
      const Real w_plane = scene.c1 * slow.a0 * slow.a0 / (4 * (1 + f) * c);  // plane a0 = slow.a0
      const auto ps = plane.solve(PlaneScene<Real>{scene.c1, w_plane, scene.speed});
      const Real ratio = pow(ps.a / slow.a0, Real(2) / 3);  // 3-D widths scale as (1+f)^(-1/3)
      shape = LineShape<Real>{slow.a0, slow.l * ratio, {log(ratio)}, {ps.b / slow.a0}};
      d = slow.d * ratio * ratio;
      stages = continuation_stages(options_.terms);
    }
    Outcome total;
    for (std::size_t k = 0; k < stages.size(); ++k) {
      const LineResidual<Real, Quadrature> res(prob, stages[k], options_.basis,
                                               options_.oversampling);
      Vector x = res.pack(shape, d);
      Vector r(res.equations());
      if (!res(x, r)) {
        if (k == 0) x = res.pack(LineShape<Real>{slow.a0, slow.l, {Real(0)}, {Real(0)}}, slow.d);
        if (!res(x, r))
          return failure(scene, slow, c, f, vtau, res, x, "initial guess outside the domain",
                         total.iterations);
      }
      Outcome out = iterate(res, x, r);
      total.iterations += out.iterations;
      const bool last = k + 1 == stages.size();
      if (last && out.minimum && options_.least_squares &&
          options_.jacobian == LineJacobian::analytic) {
        // The paper's least-squares solution where the equations have no root; if Newton's
        // method on |r|^2 finds a root after all, Levenberg-Marquardt certifies it.
        out = minimise(res, x, r);
        total.iterations += out.iterations;
        if (out.root_near) {
          out = iterate(res, x, r);
          total.iterations += out.iterations;
        }
      }
      if (out.undefined)
        return failure(scene, slow, c, f, vtau, res, x, "Jacobian undefined", total.iterations);
      shape = res.shape(x);
      d = res.penetration(x);
      // An intermediate stage that stops short still seeds the next one; only the last decides.
      if (last)
        return make(scene, slow, c, f, vtau, res, x, r, out.converged, out.reason,
                    total.iterations);
    }
    return failure(scene, slow, c, f, vtau,
                   LineResidual<Real, Quadrature>(prob, options_.terms, options_.basis,
                                                  options_.oversampling),
                   Vector::Zero(2 * options_.terms + 3), "no stage ran", total.iterations);
  }

  /// Levenberg-Marquardt with Marquardt's diagonal scaling, from x (with r = res(x)); x and r hold
  /// the last accepted iterate on return. The Jacobian (semi-analytic, LineResidual::jacobian, or a
  /// forward difference of 2 terms + 3 residual evaluations, LineOptions::jacobian) is refreshed
  /// only when needed: after an accepted step it takes Broyden's rank-one update
  /// J += (dr - J s) s^T / (s^T s), which satisfies the secant condition J s = dr
  /// (docs/line-solver.md, "Iteration"). When the updated Jacobian finds no descent step within a
  /// few dampings, the Jacobian is recomputed; "no descent step" is decided with a fresh one only,
  /// so the stopping reasons are those of the plain method.
  Outcome iterate(const LineResidual<Real, Quadrature>& res, Vector& x, Vector& r) const {
    using std::abs;
    using std::pow;
    using std::sqrt;
    const int n = res.unknowns();
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real step_tol = pow(eps, Real(0.6));
    const Real residual_tol = root_tolerance();
    Real cost = r.squaredNorm();
    Real mu = Real(1e-3);
    Matrix jac(res.equations(), n);
    Vector trial(n), rt(res.equations());
    Outcome out;
    bool fresh = false;
    bool near_jacobian = false;  // the Jacobian was refreshed at a residual below tolerance
    int stalled = 0;
    // |r|^2 at the ends of the last iterations, for the slow-progress test below.
    std::vector<Real> history;
    const auto refresh_jacobian = [&]() {
      if (options_.jacobian == LineJacobian::analytic && res.jacobian(x, rt, jac)) {
        fresh = true;
        return true;
      }
      for (int j = 0; j < n; ++j) {
        const Real h = sqrt(eps) * std::max(Real(1), Real(abs(x[j])));
        trial = x;
        trial[j] += h;
        if (!res(trial, rt)) {
          trial[j] = x[j] - h;
          if (!res(trial, rt)) return false;
          jac.col(j) = (r - rt) / h;
        } else {
          jac.col(j) = (rt - r) / h;
        }
      }
      fresh = true;
      return true;
    };
    for (; out.iterations < options_.max_iterations; ++out.iterations) {
      if (out.iterations == 0 && !refresh_jacobian()) {
        out.undefined = true;
        out.reason = "Jacobian undefined";
        return out;
      }
      bool accepted = false;
      Vector step;
      for (;;) {
        const Vector grad = jac.transpose() * r;
        Vector diag = jac.colwise().squaredNorm().transpose();
        for (int j = 0; j < n; ++j) diag[j] = std::max(diag[j], Real(1e-12));
        // A fresh Jacobian gets the full damping range; an updated one a few tries before refresh.
        const int attempts = fresh ? 40 : 4;
        for (int attempt = 0; attempt < attempts; ++attempt) {
          Matrix a = jac.transpose() * jac;
          for (int j = 0; j < n; ++j) a(j, j) += mu * diag[j];
          step = a.ldlt().solve(-grad);
          trial = x + step;
          if (res(trial, rt)) {
            const Real trial_cost = rt.squaredNorm();
            if (trial_cost < cost) {
              accepted = true;
              break;
            }
          }
          mu *= 8;
        }
        if (accepted || fresh) break;
        mu = std::max(Real(mu / pow(Real(8), Real(attempts))),
                      Real(1e-12));  // the damping of before the tries
        if (!refresh_jacobian()) {
          out.undefined = true;
          out.reason = "Jacobian undefined";
          return out;
        }
      }
      if (!accepted) {
        out.reason = "no descent step (Levenberg-Marquardt damping exhausted)";
        out.minimum = true;
        return out;
      }
      // Broyden's update with the accepted step s and the change of residual rt - r.
      const bool newton_step = fresh;
      const Real reduction = (cost - rt.squaredNorm()) / cost;
      const Real ss = step.squaredNorm();
      if (ss > 0) jac += ((rt - r) - jac * step) * (step.transpose() / ss);
      fresh = false;
      x = trial;
      r = rt;
      cost = r.squaredNorm();
      mu = std::max(mu / 4, Real(1e-12));
      const Real rmax = r.cwiseAbs().maxCoeff();
      // Near the root (residual below tolerance) the Jacobian is refreshed once: the next step is
      // Newton's, which about squares the residual (5.7e-8 to 1.1e-11 at V tau = a0, N = 4, from a
      // neighbouring speed's solution), and the updated Jacobian after it
      // differs from the true one by O(the error at the refresh) (the secant condition), so that
      // its step measures the remaining error. Converged: a step below eps^0.6 (1 + |x|) taken
      // with a Jacobian refreshed at this stage's end (or a fresh one), residual below tolerance.
      if (rmax <= residual_tol) {
        if (step.cwiseAbs().maxCoeff() <= step_tol * (1 + x.cwiseAbs().maxCoeff()) &&
            (newton_step || near_jacobian)) {
          out.converged = true;
          out.reason = "converged";
          ++out.iterations;
          return out;
        }
        if (!near_jacobian) {
          if (!refresh_jacobian()) {
            out.undefined = true;
            out.reason = "Jacobian undefined";
            return out;
          }
          near_jacobian = true;
        }
      }
      if (rmax <= 4 * eps) {
        out.converged = true;
        out.reason = "converged (residual at rounding level)";
        ++out.iterations;
        return out;
      }
      // Slow progress: |r|^2 fell by less than 5% over the last 20 accepted steps while the
      // residual is above tolerance. Near a root the steps converge quadratically; this is the
      // crawl of Levenberg-Marquardt along the valley of a least-squares minimum with no root near
      // (at a fold of the discrete equations, where the scaled Jacobian's smallest singular value
      // falls to ~1e-5, docs/line-solver.md). Passing a near-fold on the way to a root, the
      // iteration crawls too, but for fewer steps (at V tau = a0, N = 8: 12 steps, 3% in all).
      history.push_back(cost);
      if (rmax > residual_tol && history.size() > 20 &&
          history[history.size() - 21] - cost < Real(0.05) * history[history.size() - 21]) {
        out.reason =
            "stalled: |r|^2 fell by less than 5% over 20 steps (a least-squares minimum, no root "
            "near)";
        out.minimum = true;
        ++out.iterations;
        return out;
      }
      // Stagnation (MINPACK's ftol test): a step that lowers |r|^2 by less than sqrt(eps) of
      // itself. From an updated Jacobian, refresh it; from a fresh one three times running, the
      // iterate sits at a least-squares minimum with no root of the equations near it.
      if (rmax > residual_tol && reduction < sqrt(eps)) {
        if (!newton_step) {
          if (!fresh && !refresh_jacobian()) {
            out.undefined = true;
            out.reason = "Jacobian undefined";
            return out;
          }
        } else if (++stalled >= 3) {
          out.reason =
              "stalled at a least-squares minimum, no root near (|r|^2 falls by < sqrt(eps) per "
              "step)";
          out.minimum = true;
          ++out.iterations;
          return out;
        }
      } else {
        stalled = 0;
      }
    }
    return out;
  }

  /// Newton's method on phi = |r|^2 / 2 from where Levenberg-Marquardt stopped at a least-squares
  /// minimum (docs/line-solver.md, "Least-squares minima"; derivation in docs/theory.md section 9).
  /// There the Jacobian J is nearly singular and r lies along its smallest left singular vector,
  /// so the Gauss-Newton model J^T J misses the curvature of phi that matters, the second-order
  /// term S = sum_i r_i grad^2 r_i (M2). S is taken by central differences of the gradient
  /// g = J^T r (semi-analytic J) along the right singular directions of J in which it is not small
  /// against J^T J: sigma^2 <= 1e3 |S v_min| (M3). With D = H V (the differences) and
  /// E = D - J^T J V, S ~ E V^T + V E^T - V V^T E V^T, exact on span V. S is kept from step to
  /// step (it varies slowly) and taken afresh when a step fails or before the stop is trusted.
  /// Steps solve (J^T J + S + mu I) s = -g, mu = 0 when that is positive definite, accepted when
  /// phi falls. Converged (M4): the Hessian with a fresh S positive definite and Newton's
  /// predicted decrease g^T H^-1 g / 2 below the rounding of phi, 16 eps sqrt(m) |r| (each scaled
  /// equation sums terms of order one): a strict local minimum. A residual below the root
  /// tolerance on the way returns `root_near`.
  Outcome minimise(const LineResidual<Real, Quadrature>& res, Vector& x, Vector& r) const {
    using std::abs;
    using std::cbrt;
    using std::sqrt;
    const int n = res.unknowns(), m = res.equations();
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real residual_tol = root_tolerance();
    Outcome out;
    out.reason = "iteration limit (least-squares minimisation)";
    Matrix jac(m, n), jac_h(m, n), s_part(n, n);
    Vector r_h(m), rt(m), g_plus(n), g_minus(n);
    bool fresh = false;  // s_part was taken at the current x
    Real mu = 0;
    const auto undefined = [&out]() {
      out.undefined = true;
      out.reason = "Jacobian undefined";
      return out;
    };
    // S at x from the gradient's central differences along the weak directions of J (M3).
    const auto second_order = [&](const Matrix& jtj) {
      const Eigen::SelfAdjointEigenSolver<Matrix> gauss(jtj);  // eigenvalues ascending
      const Vector scale = jtj.diagonal().cwiseSqrt();         // |J e_j|: Marquardt's column scales
      const auto hessian_times = [&](const Vector& v, Vector& hv) {
        const Real h = cbrt(eps) / std::max(scale.cwiseProduct(v).norm(), eps);
        if (!res.jacobian(x + h * v, r_h, jac_h)) return false;
        g_plus = jac_h.transpose() * r_h;
        if (!res.jacobian(x - h * v, r_h, jac_h)) return false;
        g_minus = jac_h.transpose() * r_h;
        hv = (g_plus - g_minus) / (2 * h);
        return true;
      };
      Vector hv(n);
      if (!hessian_times(gauss.eigenvectors().col(0), hv)) return false;
      const Real s_scale = (hv - jtj * gauss.eigenvectors().col(0)).norm();
      int k = 1;
      while (k < n && gauss.eigenvalues()[k] <= 1000 * s_scale) ++k;
      const Matrix v = gauss.eigenvectors().leftCols(k);
      Matrix e(n, k);
      e.col(0) = hv;
      for (int j = 1; j < k; ++j) {
        if (!hessian_times(v.col(j), hv)) return false;
        e.col(j) = hv;
      }
      e -= jtj * v;
      s_part = e * v.transpose() + v * e.transpose() - v * (v.transpose() * e) * v.transpose();
      s_part = (s_part + s_part.transpose()).eval() / 2;
      fresh = true;
      return true;
    };
    for (; out.iterations < options_.max_iterations; ++out.iterations) {
      if (!res.jacobian(x, r, jac)) return undefined();
      if (r.cwiseAbs().maxCoeff() <= residual_tol) {
        out.root_near = true;
        out.reason = "root near";
        return out;
      }
      const Real phi = r.squaredNorm() / 2;
      const Real floor = 16 * eps * sqrt(Real(m)) * r.norm();  // rounding of phi
      const Vector g = jac.transpose() * r;
      const Matrix jtj = jac.transpose() * jac;
      if (out.iterations == 0 && !second_order(jtj)) return undefined();
      bool accepted = false;
      for (;;) {
        const Eigen::SelfAdjointEigenSolver<Matrix> newton(jtj + s_part);
        const Vector& lambda = newton.eigenvalues();
        const Vector qg = newton.eigenvectors().transpose() * g;
        const Real lmin = lambda[0], lmax = lambda[n - 1];
        const Real predicted =
            lmin > 0 ? Real((qg.array().square() / lambda.array()).sum() / 2) : Real(0);
        if (lmin > 0 && predicted <= floor) {
          if (!fresh) {
            if (!second_order(jtj)) return undefined();
            continue;  // the stop is trusted with S taken here only
          }
          // Below the rounding of phi: converged, after one more Newton step where the model
          // still promises more than eps phi and the step delivers it (kept if it lowers phi).
          bool minimum = predicted <= 16 * eps * phi;
          if (!minimum) {
            const Vector step = -(newton.eigenvectors() * (qg.array() / lambda.array()).matrix());
            const bool lower = res(x + step, rt) && rt.squaredNorm() / 2 < phi;
            if (lower) x += step;
            minimum = !lower || phi - rt.squaredNorm() / 2 <= floor;
            accepted = lower;
          }
          if (minimum) {
            if (accepted && !res(x, r)) return undefined();
            out.converged = true;
            out.reason = "least-squares minimum (no root of the line equations here)";
            ++out.iterations;
            return out;
          }
          break;
        }
        mu = lmin > 0 ? Real(0) : std::max(mu, 2 * abs(lmin));
        for (int attempt = 0; attempt < 40 && !accepted; ++attempt) {
          const Vector step =
              -(newton.eigenvectors() * (qg.array() / (lambda.array() + mu)).matrix());
          if (res(x + step, rt) && rt.squaredNorm() / 2 < phi) {
            x += step;
            accepted = true;
          } else {
            // From the smallest shift that tells: the curvature that matters is far below lmax.
            mu = std::max(8 * mu, 2 * std::max(-lmin, Real(0)) + eps * lmax);
          }
        }
        if (accepted || fresh) break;
        if (!second_order(jtj)) return undefined();  // a stale S: take it here and try again
        mu = 0;
      }
      if (!accepted) {
        out.reason = "no descent step (least-squares minimisation)";
        return out;
      }
      fresh = false;
      mu /= 8;
    }
    res(x, r);
    return out;
  }

  Solution make(const LineScene<Real>& scene, const StaticLineContact<Real>& slow, Real c, Real f,
                Real vtau, const LineResidual<Real, Quadrature>& res, const Vector& x,
                const Vector& r, bool converged, std::string reason, int iterations) const {
    const Real rmax = r.size() ? Real(r.cwiseAbs().maxCoeff()) : Real(0);
    const bool root = converged && rmax <= root_tolerance();
    Solution sol{
        res.shape(x),      res.penetration(x), slow.a0, slow.l, slow.d,   Real(0), converged, root,
        std::move(reason), iterations,         rmax,    {},     scene.c1, vtau,    f,         c};
    sol.chi = rolling_friction(sol);
    add_warnings(sol);
    if (converged && !root)
      sol.warnings.push_back(
          "the line equations have no root here: a least-squares minimum with max |r| = " +
          std::to_string(double(rmax)) +
          " (the line theory does not close at this speed and discretisation; "
          "docs/line-solver.md, \"Least-squares minima\")");
    return sol;
  }

  Solution failure(const LineScene<Real>& scene, const StaticLineContact<Real>& slow, Real c,
                   Real f, Real vtau, const LineResidual<Real, Quadrature>& res, const Vector& x,
                   const char* reason, int iterations) const {
    Vector r = Vector::Constant(1, std::numeric_limits<Real>::quiet_NaN());
    return make(scene, slow, c, f, vtau, res, x, r, false, reason, iterations);
  }

  /// chi = C1 int V n(y) dy / int F0 dy, V n = V (F0 f/(1+f) - Q) = (C1/4) strip_first_moment
  /// (Eq. 54 strip by strip in the form (P7); docs/theory.md section 4).
  static Real rolling_friction(const Solution& sol) {
    std::vector<Real> nodes, weights;
    const Real l = sol.shape.l;
    detail::append_graded_nodes<Quadrature>(nodes, weights, l, l / 2,
                                            l * std::numeric_limits<Real>::epsilon() * 16);
    Real num = 0, den = 0;
    for (std::size_t j = 0; j < nodes.size(); ++j) {
      const auto s = sol.functions(nodes[j]);
      if (!(s.a > 0)) continue;
      const Real alpha = (1 + sol.f) * s.a / sol.vtau;
      const Real vn =
          sol.c1 / 4 *
          strip_first_moment(s.a, s.b, s.g, sol.vtau, sol.f, special::bessel_i1_over_i0(alpha),
                             special::bessel_i2_over_i0(alpha));
      num += weights[j] * vn;
      den += weights[j] * s.f0;
    }
    return sol.c1 * num / den;
  }

  static void add_warnings(Solution& sol) {
    for (auto& w : line_domain_warnings(sol.shape)) sol.warnings.push_back(std::move(w));
  }

  Material material_;
  LineOptions options_;
};

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
auto LineSolver<Real, Material, Quadrature>::solve(const LineScene<Real>& scene,
                                                   const Solution* start) const -> Solution {
  scene.validate();
  const Real c = material_.instantaneous_compliance();
  const Real f = material_.creep_ratio();
  const Real vtau = scene.speed * material_.relaxation_time();
  const auto slow = static_line_contact(scene.c1, scene.c2, (1 + f) * c * scene.load);
  const Real eps = std::numeric_limits<Real>::epsilon();
  if constexpr (Material::is_viscoelastic) {
    if (f > 0 && vtau > 0) {
      if (strip_is_glassy(vtau, f, slow.a0)) {
        // Glassy limit: the instantaneous compliance; every strip's b, chi within eps (P6).
        const auto fast = static_line_contact(scene.c1, scene.c2, c * scene.load);
        // Reported as the static strip of the instantaneous compliance: f = 0, V tau = 0.
        return closed_form(scene, fast, slow, c, Real(0), "glassy limit (closed form)");
      }
      if (vtau > eps * slow.a0) return rolling_from(scene, slow, c, f, vtau, start);
    }
  }
  return closed_form(scene, slow, slow, c, f, "static (closed form)");
}

/// The common case: double precision, standard linear solid, 12-point Gauss-Legendre panels.
using LineSolverD = LineSolver<double, StandardLinearSolid<double>>;

// Compiled mode (docs/building.md): with VISCOROLL_COMPILED, which the CMake target
// viscoroll::compiled sets, the solvers below are instantiated once in that library (src/) and
// not in the including translation unit. Their entry points are defined out of the class (not
// inline), so that g++ does not instantiate them here for inlining either. Other instantiations
// are implicit, as in header-only mode.
#if defined(VISCOROLL_COMPILED)
extern template class LineSolver<float, StandardLinearSolid<float>>;
extern template class LineSolver<double, StandardLinearSolid<double>>;
extern template class LineSolver<long double, StandardLinearSolid<long double>>;
#endif

}  // namespace viscoroll
