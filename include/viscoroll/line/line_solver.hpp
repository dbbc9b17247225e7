// viscoroll: the paper's 3-D solver, an ellipsoidal roller on a standard linear solid by the
// line-contact theory.
//
// Panek & Kalker (1980), Sections 5-7: the equations (33), (34), (36), (46), (47) and the
// leading-edge condition in the form (L6) (line_residual.hpp; docs/theory.md section 4 for (L6)
// and why the printed (44), opt-in in line/paper_leading_edge.hpp, is not used), solved for the
// coefficients of a(y), b(y) (line_shape.hpp), l and d by a Levenberg-Marquardt iteration
// (numerics/levenberg_marquardt.hpp;
// the system is square, so a converged solution has a zero residual to rounding), or, where the
// equations have no root, as the certified least-squares minimum of the paper's Section 7
// (numerics/least_squares_minimum.hpp). The static scene (V tau = 0), the elastic material
// (f = 0) and the glassy limit (V tau beyond ~40/eps half widths, strip_is_glassy) are Kalker's
// closed form (static_line_contact.hpp) with the long-term or the instantaneous compliance: no
// Bessel work.
//
// The scene and the settings are line_scene.hpp and line_options.hpp; the iteration's steps that
// the one-term and the spectrum path share, the solver's units and the rolling friction are in
// line/detail/ (line_iteration.hpp, line_units.hpp, rolling_friction.hpp).
#pragma once

#include <Eigen/Core>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/roots.hpp>
#include <chrono>
#include <cmath>
#include <concepts>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/required_field.hpp>
#include <viscoroll/core/spectrum_conditioning.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/detail/line_iteration.hpp>
#include <viscoroll/line/detail/line_units.hpp>
#include <viscoroll/line/detail/rolling_friction.hpp>
#include <viscoroll/line/line_options.hpp>
#include <viscoroll/line/line_profile.hpp>
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/line_scene.hpp>
#include <viscoroll/line/line_shape.hpp>
#include <viscoroll/line/line_solution.hpp>
#include <viscoroll/line/line_spectrum.hpp>
#include <viscoroll/line/static_line_contact.hpp>
#include <viscoroll/material/detail/prony_spectrum.hpp>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/prony.hpp>  // compiled mode: PronyRelaxation<double>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/numerics/least_squares_minimum.hpp>
#include <viscoroll/numerics/levenberg_marquardt.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

namespace viscoroll {

/// Solver of the line-contact equations over a scalar, a constitutive model and a nodal
/// quadrature rule (applied on the graded panels of every line integral). A material with one
/// memory term (SingleTimeModel) is the paper's theory and its Solution a LineSolution; a
/// spectrum of several terms is the theory of docs/theory.md section 14 (line/line_spectrum.hpp)
/// and its Solution a LineSpectrumSolution.
template <RealScalar Real, ConstitutiveModel Material, class Quadrature = GaussLegendre<Real, 12>>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
class LineSolver {
 public:
  using Solution = std::conditional_t<SingleTimeModel<Material>, LineSolution<Real, Quadrature>,
                                      LineSpectrumSolution<Real, Quadrature>>;
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
  /// that stops short is run again from the cold start; either is said in `warnings`. For a
  /// spectrum the cold start runs first and the seed only where it stops short (solve_spectrum).
  /// Throws std::invalid_argument for an invalid scene; a non-converged iteration is returned
  /// with converged == false and the reason.
  Solution solve(const LineScene<Real>& scene, const Solution* start = nullptr) const;

  /// Solves the rolling line contact of a roller profile (roller/profile.hpp: a crowned
  /// cylinder, a logarithmic crown, a table, the ellipsoid, any of them tilted): (34) with the
  /// profile's drop h(y) (docs/theory.md section 16, (RP1); for a spectrum, (RP5) with section 14),
  /// every other equation as for the ellipsoid; an asymmetric profile's contact is [c - l, c + l]
  /// with the odd parts of (RP6), (RP7). The long-term and the glassy contact are the static
  /// profile contact (static_profile_contact.hpp) of the long-term and of the instantaneous
  /// compliance, expanded in the solver's representation; `a_long_term`, `l_long_term`,
  /// `d_long_term` are the long-term one's a at its centre, l and d. Throws std::invalid_argument
  /// for an invalid scene (LineProfileScene::validate); a contact that reaches the roller's body
  /// end, or a static contact that does not converge, is returned not converged with the reason.
  /// Every profile is solved through its ProfileView (roller/profile.hpp), by solve_profile.
  template <RollerProfile Profile>
  Solution solve(const LineProfileScene<Profile>& scene, const Solution* start = nullptr)
      const requires std::same_as<typename Profile::real_type, Real> {
    const LineProfileScene<ProfileView<Real>> viewed{
        .roller = ProfileView<Real>(scene.roller), .load = scene.load, .speed = scene.speed};
    return solve_profile(viewed, start);
  }

  /// solve(LineProfileScene) for the view of any profile: one function per scalar and material,
  /// not one per profile type (a member of the class's explicit instantiation in compiled mode).
  Solution solve_profile(const LineProfileScene<ProfileView<Real>>& scene,
                         const Solution* start = nullptr) const;

  /// The residual assembly for a scene (for tests and for users who drive their own iteration).
  LineResidual<Real, Quadrature> residual(const LineScene<Real>& scene) const requires
      SingleTimeModel<Material> {
    scene.validate();
    const Real c = material_.instantaneous_compliance();
    const PronyTerm<Real> memory = detail::single_memory_term(material_);
    const auto slow = static_line_contact(scene.c1, scene.c2, (1 + memory.f) * c * scene.load);
    return LineResidual<Real, Quadrature>(
        problem(Units{scene.c1, scene.c2, 0, 0}, slow, memory.f, scene.speed * memory.tau),
        options_.terms, options_.basis, options_.oversampling, Real(options_.quadrature_tolerance));
  }

 private:
  /// The solver's units (docs/theory.md, "Scaling"; line/detail/line_units.hpp).
  using Units = detail::LineUnits<Real>;

  /// The paper's ellipsoid in the solver's units (docs/theory.md, "Scaling"): C1, C2 in the unit
  /// of curvature of C1's power of two, lengths in a power of two near the long-term a0, and the
  /// long-term static contact of compliance (1 + creep_ratio) c in them, Eq. (47) with (52); c2/c1
  /// checked representable against `inputs`.
  template <class Inputs>
  static std::pair<Units, StaticLineContact<Real>> ellipse_units(const LineScene<Real>& scene,
                                                                 Real c, Real creep_ratio,
                                                                 const Inputs& inputs) {
    const auto k1 = binary<Real>(scene.c1), k2 = binary<Real>(scene.c2), cc = binary<Real>(c);
    const auto load = binary<Real>(scene.load), creep = binary<Real>(1 + creep_ratio);
    detail::representable(Real(k2.m / k1.m), k2.e - k1.e, "c2/c1", inputs, false);
    const Real c2 = times_power_of_two(k2.m, k2.e - k1.e);
    const auto slow_units = static_line_contact_in_units<Real>(
        k1.m, c2, {creep.m * cc.m * load.m, creep.e + cc.e + load.e}, k1.e);
    return {Units{k1.m, c2, k1.e, slow_units.length}, slow_units.contact};
  }

  static LineProblem<Real> problem(const Units& u, const StaticLineContact<Real>& slow, Real f,
                                   Real vtau) {
    return {u.c1, u.c2, vtau, f, slow.a0, slow.l, u.c1 * slow.a0 * slow.a0 * slow.l / 3};
  }

  /// A solution of the scene with shape and penetration d: converged, a root, no iterations;
  /// closed_form and make set what differs. In the solver's units until solve() converts it.
  static Solution solution(const Units& u, const StaticLineContact<Real>& slow, Real c, Real f,
                           Real vtau, LineShape<Real> shape, Real d) {
    return Solution{.shape = std::move(shape),
                    .d = d,
                    .a_long_term = slow.a0,
                    .l_long_term = slow.l,
                    .d_long_term = slow.d,
                    .chi = Real(0),
                    .converged = true,
                    .root = true,
                    .reason = {},
                    .code = StopCode::converged,
                    .iterations = 0,
                    .residual = Real(0),
                    .warnings = {},
                    .warning_codes = {},
                    .c1 = u.c1,
                    .vtau = vtau,
                    .f = f,
                    .compliance = c};
  }

  Solution closed_form(const Units& u, const StaticLineContact<Real>& s,
                       const StaticLineContact<Real>& slow, Real c, Real f,
                       const char* reason) const {
    using std::log;
    LineShape<Real> shape{slow.a0, s.l, {log(s.a0 / slow.a0)}, {Real(0)}};
    // A glassy contact is the static one of the instantaneous compliance: G = 0 makes F0 = C1 a^2/4
    // the load of that compliance; it is reported as the static strip (vtau = 0 in the pressure).
    Solution sol = solution(u, slow, c, f, Real(0), shape, s.d);
    sol.reason = reason;
    add_warnings(sol, u);
    return sol;
  }

  /// The coefficients of the static profile contacts behind a profile's solve (its default,
  /// docs/theory.md (G5)); their shapes are expanded in twice as many for the line solver.
  static constexpr int profile_static_terms = 12;

  /// A static profile contact as the solver's shape (unit a_ref given in the caller's units,
  /// b = b_over a_ref; with its odd parts and centre if `asymmetric`) and penetration, in the
  /// units u.
  static std::pair<LineShape<Real>, Real> profile_in_units(const StaticProfileContact<Real>& s,
                                                           const Units& u, Real a_ref, Real b_over,
                                                           bool asymmetric = false) {
    LineShape<Real> shape =
        profile_line_shape(s, a_ref, 2 * profile_static_terms, b_over, asymmetric);
    return {u.shape_in_units(std::move(shape)), u.penetration_in_units(s.d)};
  }
  /// The solve of a profile whose long-term static contact did not converge: not converged, its
  /// reason, in the caller's units.
  static Solution profile_static_failure(const StaticProfileContact<Real>& slow_c, Real c, Real f) {
    Solution sol{};
    sol.shape = LineShape<Real>{slow_c.a_ref, slow_c.half_length(), {Real(0)}, {Real(0)}};
    sol.d = slow_c.d;
    sol.a_long_term = slow_c.a_ref;
    sol.l_long_term = slow_c.half_length();
    sol.d_long_term = slow_c.d;
    sol.chi = Real(0);
    sol.converged = false;
    sol.root = false;
    sol.iterations = 0;
    sol.residual = std::numeric_limits<Real>::quiet_NaN();
    sol.c1 = slow_c.c1;
    if constexpr (SingleTimeModel<Material>) {
      sol.vtau = Real(0);
      sol.f = f;
      sol.compliance = c;
    }
    sol.code = slow_c.code == StopCode::contact_reaches_body_end ? slow_c.code
                                                                 : StopCode::static_contact_failed;
    sol.reason = "the long-term static contact of the profile: " + slow_c.reason +
                 " (the line theory needs a slender contact, its collocation points a half "
                 "width apart, docs/theory.md (G5); a short contact is the BEM's)";
    copy_warnings(sol, slow_c);
    return sol;
  }
  /// A contact that reaches the roller's body end is outside the line theory (a sharp end's
  /// pressure peak): reported, not returned as a plausible number. l in the units u.
  template <class Profile>
  static void check_body_end(Solution& sol, const Profile& roller, const Units& u) {
    const Real l_caller = times_power_of_two(sol.shape.l, u.length);
    const Real c_caller = times_power_of_two(sol.shape.centre, u.length);
    const Real y_plus = c_caller + l_caller, y_minus = c_caller - l_caller;
    if (sol.converged && !(y_plus < roller.y_max() && y_minus > roller.y_min())) {
      sol.converged = false;
      sol.root = false;
      sol.code = StopCode::contact_reaches_body_end;
      sol.reason = "the contact reaches the roller's body end (it spans y = " +
                   detail::format_value(y_minus) + " ... " + detail::format_value(y_plus) +
                   ", the body ends at y = " + detail::format_value(roller.y_min()) + " and " +
                   detail::format_value(roller.y_max()) + "): outside the line theory";
    }
  }

  /// max |r| of the scaled equations below which the iterate is a root (`LineSolution::root`):
  /// 64 sqrt(eps), the minimisers' stop at a root and the solution's flag.
  static Real root_tolerance() { return detail::line_root_tolerance<Real>(); }

  /// The Levenberg-Marquardt settings of every stage (the Jacobian semi-analytic unless
  /// LineOptions::jacobian asks for differences).
  numerics::LeastSquaresOptions<Real> iteration_settings() const {
    return {.max_iterations = options_.max_iterations,
            .root_tolerance = root_tolerance(),
            .analytic_jacobian = options_.jacobian == LineJacobian::analytic};
  }
  /// The settings of continuation stage k: an intermediate stage stops at
  /// LineOptions::stage_tolerance, a stage after the first starts at LineOptions::stage_damping.
  numerics::LeastSquaresOptions<Real> stage_settings(numerics::LeastSquaresOptions<Real> settings,
                                                     std::size_t k, bool last) const {
    if (!last) settings.stop_tolerance = Real(options_.stage_tolerance);
    if (k > 0) settings.initial_damping = Real(options_.stage_damping);
    return settings;
  }
  /// Whether a stop short of a root goes on to the certified least-squares minimum
  /// (least_squares_solution): LineOptions::least_squares, with the semi-analytic Jacobian.
  bool minimises() const {
    return options_.least_squares && options_.jacobian == LineJacobian::analytic;
  }

  /// a/a0 and b/a0 of the plane solution at V tau/a0 = v (Eq. P5), the seed of the cold start.
  struct PlaneSeed {
    Real a, b;
  };
  /// The cold start of the paper's ellipsoid: the static contact (48) shrunk and shifted as the
  /// plane solution at the same V tau/a0 (3-D widths scale as (1 + f)^(-1/3), the plane's as
  /// (1 + f)^(-1/2): a by (a/a0)^(2/3), l with it, d by its square; b the plane's).
  struct EllipseStart {
    std::pair<LineShape<Real>, Real> operator()(const StaticLineContact<Real>& slow,
                                                const PlaneSeed& ps) const {
      using std::log;
      using std::pow;
      const Real ratio = pow(ps.a, Real(2) / 3);
      return {LineShape<Real>{slow.a0, slow.l * ratio, {log(ratio)}, {ps.b}},
              slow.d * ratio * ratio};
    }
  };

  /// rolling() from `start` where it can seed the iteration, else from the cold start; a seeded
  /// iteration that stops short is run again from the cold start. The result's warnings say when
  /// a seed was set aside, so that a bad seed never decides the answer.
  /// `drop` the roller's h(y) (a RollerDrop), `cold` the cold start's shape and penetration
  /// from the plane seed (ColdStart), `asymmetric` the contact of a drop that is not even
  /// (LineResidual's).
  template <class Drop = ParabolicDrop, class ColdStart = EllipseStart>
  Solution rolling_from(const LineScene<Real>& scene, const Units& u,
                        const StaticLineContact<Real>& slow, const LineProblem<Real>& prob, Real c,
                        const Solution* given, const Drop& drop = {}, const ColdStart& cold = {},
                        bool asymmetric = false) const {
    if (given == nullptr) return rolling(scene, u, slow, prob, c, nullptr, drop, cold, asymmetric);
    // The seed in the solver's units (a shape from a far scene may leave the range there).
    Solution seed = *given;
    seed.shape = u.shape_in_units(std::move(seed.shape));
    seed.d = u.penetration_in_units(seed.d);
    const Solution* start = &seed;
    if (!usable_seed(*start)) {
      Solution again = rolling(scene, u, slow, prob, c, nullptr, drop, cold, asymmetric);
      add_warning(
          again, WarningCode::seed_set_aside,
          "the seed was set aside (not a converged solution with finite a(y), b(y), l and d): "
          "solved from the cold start");
      return again;
    }
    Solution seeded = rolling(scene, u, slow, prob, c, start, drop, cold, asymmetric);
    if (seeded.converged) return seeded;
    Solution again = rolling(scene, u, slow, prob, c, nullptr, drop, cold, asymmetric);
    // No root from the seed (its last stage stopped above the root tolerance with a finite
    // residual): the cold start's answer, a root or the certified minimum, without a warning,
    // since the seed had no say in it. Any other stop (outside the domain, a root that is not a
    // contact) is said.
    const bool no_root =
        (boost::math::isfinite)(seeded.residual) && seeded.residual > root_tolerance();
    if (!no_root)
      add_warning(again, WarningCode::seed_set_aside,
                  "the iteration from the seed stopped (" + seeded.reason +
                      "): solved again from the cold start");
    return again;
  }

  /// A converged solution whose shape and penetration are finite.
  static bool usable_seed(const Solution& s) {
    const auto finite = [](const std::vector<Real>& v) {
      for (const Real& x : v)
        if (!(boost::math::isfinite)(x)) return false;
      return true;
    };
    return s.converged && !s.shape.alpha.empty() && finite(s.shape.alpha) && finite(s.shape.beta) &&
           (boost::math::isfinite)(s.shape.l) && s.shape.l > 0 &&
           (boost::math::isfinite)(s.shape.a_ref) &&
           s.shape.a_ref >= (std::numeric_limits<Real>::min)() && (boost::math::isfinite)(s.d);
  }

  /// The plane solver with the line scene's material, curvature and speed, and the load whose
  /// long-term half width is the line's a0 (in the caller's units, where they are representable);
  /// else an equivalent scene of order-one numbers with the same f and V tau/a0 (the plane
  /// solution depends on nothing else, docs/theory.md "Scaling").
  PlaneSeed plane_seed(const LineScene<Real>& scene, const Units& u,
                       const StaticLineContact<Real>& slow, Real c, Real f, Real vtau) const {
    using std::abs;
    using limits = std::numeric_limits<Real>;
    // W = C1 a0^2 / (4 (1 + f) c), plane a0 = slow.a0, formed as its power-of-two scaled self.
    const Binary<Real> cc = binary(c);
    const Real w_plane = times_power_of_two(u.c1 * slow.a0 * slow.a0 / (4 * (1 + f) * cc.m),
                                            u.curvature + 2 * u.length - cc.e);
    const Real a0 = times_power_of_two(slow.a0, u.length);
    if ((boost::math::isfinite)(w_plane) && w_plane >= (limits::min)() &&
        (boost::math::isfinite)(a0) && a0 >= (limits::min)()) {
      try {
        const PlaneSolver<Real, Material> plane(material_);
        const auto ps =
            plane.solve(PlaneScene<Real>{.c1 = scene.c1, .load = w_plane, .speed = scene.speed});
        return {ps.a / a0, ps.b / a0};
      } catch (const std::invalid_argument&) {
        // a number of the plane solution not representable: the scene of order-one numbers
      }
    }
    const Real pi = boost::math::constants::pi<Real>();
    // c = (1 - 0)/(2 pi mu_D) = 1, tau = 1, C1 = 1, 4 c (1 + f) W / C1 = 1: a0 = 1, V tau = v.
    const PlaneSolver<Real, StandardLinearSolid<Real>> plane(
        StandardLinearSolid<Real>(1 / (2 * pi), Real(0), f, Real(1)));
    const auto ps = plane.solve(
        PlaneScene<Real>{.c1 = Real(1), .load = 1 / (4 * (1 + f)), .speed = vtau / slow.a0});
    return {ps.a / ps.a_long_term, ps.b / ps.a_long_term};
  }

  template <class Drop, class ColdStart>
  Solution rolling(const LineScene<Real>& scene, const Units& u,
                   const StaticLineContact<Real>& slow, const LineProblem<Real>& prob, Real c,
                   const Solution* start, const Drop& drop, const ColdStart& cold,
                   bool asymmetric = false) const {
    using Residual = LineResidual<Real, Quadrature, ExteriorLeadingEdge, Drop>;
    const Real f = prob.f, vtau = prob.vtau;
    LineShape<Real> shape;
    Real d;
    // Continuation in N from two terms up: each stage starts from the previous solution, which
    // keeps the iteration on the branch of smooth solutions (a start far from it at large N can
    // land on another root of the discrete equations, docs/line-solver.md). The first stage
    // starts from the seed re-expanded to its terms, so that a seed decides no more than where
    // the two-term iteration begins: the answer is the cold start's to the iteration's tolerance,
    // except in the slow regime where the two-term equations have several roots or stop short of
    // one from one start only (docs/line-solver.md, "Continuation in speed").
    const std::vector<int> stages = detail::continuation_stages(options_.terms);
    if (start != nullptr && start->shape.alpha.size() > 0) {
      // A solution of a nearby scene.
      shape = start->shape;
      d = start->d;
    } else {
      // The static contact shrunk and shifted as the plane solution at the same V tau/a0.
      std::tie(shape, d) = cold(slow, plane_seed(scene, u, slow, c, f, vtau));
    }
    // The paper's least-squares solution where the equations have no root (the last stage, with
    // the semi-analytic Jacobian of (L6)); if Newton's method on |r|^2 finds a root after all,
    // Levenberg-Marquardt certifies it. Only from the cold start: from a seed the iteration stops
    // short instead, and rolling_from runs the cold start, so that a minimum is never the seed's
    // (a seed near a fold of its own branch leads to a minimum of |r| where the cold start has a
    // root, docs/line-solver.md, "Continuation in speed").
    const bool least_squares = minimises();
    const bool minimise = least_squares && start == nullptr;
    const numerics::LeastSquaresOptions<Real> settings = iteration_settings();
    int iterations = 0;
    for (std::size_t k = 0; k < stages.size(); ++k) {
      const Residual res(prob, stages[k], options_.basis, options_.oversampling,
                         Real(options_.quadrature_tolerance), drop, asymmetric);
      Vector x = res.pack(shape, d);
      Vector r(res.equations());
      if (!res(x, r)) {
        // The cold start's plane seed outside the domain: the static contact (a seed given by
        // the caller is not replaced here: rolling_from runs the cold start and says so).
        if (k == 0 && start == nullptr) {
          const auto [s0, d0] = cold(slow, PlaneSeed{Real(1), Real(0)});
          x = res.pack(s0, d0);
        }
        if (!res(x, r))
          return failure(u, slow, c, f, vtau, res, x, StopCode::outside_domain,
                         "initial guess outside the domain", iterations);
      }
      const bool last = k + 1 == stages.size();
      Matrix jac;  // Levenberg-Marquardt's Jacobian at its last iterate
      numerics::LeastSquaresOutcome out =
          numerics::levenberg_marquardt(res, x, r, stage_settings(settings, k, last), jac);
      iterations += out.iterations;
      // Whether jac is the Jacobian at the returned root (not so once the minimisation ran).
      bool jac_at_root = out.converged;
      if (last && minimise && !out.converged && !out.undefined) {
        out = detail::least_squares_solution(res, x, r, settings, iterations);
        jac_at_root = false;
      }
      if (out.undefined)
        return failure(u, slow, c, f, vtau, res, x, StopCode::outside_domain, "Jacobian undefined",
                       iterations);
      shape = res.shape(x);
      d = res.penetration(x);
      // An intermediate stage that stops short still seeds the next one; only the last decides.
      if (last) {
        // The a posteriori error estimate of a root, the Newton correction max |J^+ r|. In a
        // scalar narrower than double a root is reported converged only where it is at most
        // sqrt(eps) (in float at V tau = 0.01 a0, N = 6, the residual's rounding floor 2e-5 over
        // the smallest singular value 2e-3 of J moved b(0) by 15%; docs/stability.md). In double
        // and wider it exceeds sqrt(eps) only at folds of the discrete equations (a residual
        // 2e-8 ... 9e-7 over a vanishing singular value), where the root is reported with a
        // warning naming the estimate (docs/line-solver.md, "Stops short of a root").
        Real estimate = 0;
        using std::sqrt;
        const Real sqrt_eps = sqrt(std::numeric_limits<Real>::epsilon());
        // At a root that Levenberg-Marquardt certified its own Jacobian serves: within
        // O(eps^0.6) of J(x) (its last step), which moves the estimate by a relative
        // O(eps^0.6 / sigma_min); what the estimate decides is its side of sqrt(eps), against
        // 1e-15 ... 1e-11 at ordinary roots and far beyond it at folds (docs/line-solver.md).
        if (out.converged && least_squares && r.cwiseAbs().maxCoeff() <= root_tolerance())
          estimate = jac_at_root ? detail::newton_correction<Real>(jac, r)
                                 : detail::newton_correction<Real>(res, x);
        const bool narrow = std::numeric_limits<Real>::digits < std::numeric_limits<double>::digits;
        if (narrow && !(estimate <= sqrt_eps)) {
          out.converged = false;
          out.code = StopCode::precision_exhausted;
          out.reason = "error estimate max |J^+ r| = " + std::to_string(double(estimate)) +
                       " of the unknowns exceeds sqrt(eps) = " + std::to_string(double(sqrt_eps)) +
                       ": the residual's rounding floor is beyond what this scalar carries here "
                       "(use double)";
        }
        Solution sol =
            make(u, slow, c, f, vtau, res, x, r, out.converged, out.code, out.reason, iterations);
        // A root of the discrete equations that is not a contact (d, a(0) or l not positive;
        // found at folds, e.g. by the property test of errors.md) is reported, not returned as
        // converged.
        const Real a_centre = sol.a(sol.shape.centre);
        if (sol.converged && !(sol.d > 0 && a_centre > 0 && sol.l() > 0)) {
          sol.converged = false;
          sol.code = StopCode::not_a_contact;
          sol.reason = "a root of the line equations that is not a contact (d = " +
                       detail::format_value(sol.d) +
                       ", a at the centre = " + detail::format_value(a_centre) +
                       ", l = " + detail::format_value(sol.l()) +
                       " in the solver's units of length; each must be positive)";
        }
        if (!narrow && !(estimate <= sqrt_eps))
          add_warning(sol, WarningCode::near_fold,
                      "a root where the Jacobian is nearly singular (a fold of the discrete "
                      "equations): its error estimate max |J^+ r| = " +
                          std::to_string(double(estimate)) +
                          " exceeds sqrt(eps), so the root is not determined to better than the "
                          "discretisation and another root may lie near (docs/line-solver.md, "
                          "\"Stops short "
                          "of a root\")");
        return sol;
      }
    }
    const Residual res(prob, options_.terms, options_.basis, options_.oversampling,
                       Real(options_.quadrature_tolerance), drop, asymmetric);
    return failure(u, slow, c, f, vtau, res, Vector::Zero(res.unknowns()), StopCode::not_run,
                   "no stage ran", iterations);
  }

  template <class Residual>
  Solution make(const Units& u, const StaticLineContact<Real>& slow, Real c, Real f, Real vtau,
                const Residual& res, const Vector& x, const Vector& r, bool converged,
                StopCode code, std::string reason, int iterations) const {
    const Real rmax = r.size() ? Real(r.cwiseAbs().maxCoeff()) : Real(0);
    const bool root = converged && rmax <= root_tolerance();
    Solution sol = solution(u, slow, c, f, vtau, res.shape(x), res.penetration(x));
    sol.converged = converged;
    sol.root = root;
    sol.code = code;
    sol.reason = std::move(reason);
    sol.iterations = iterations;
    sol.residual = rmax;
    // chi's graded panels halve toward the end y = l, where a(y) vanishes like a square root: an
    // n-point rule there errs by ~(3 + sqrt 8)^(-2n) (detail/graded_panels.hpp), 7e-10 at n = 6.
    // Integrals exact to rounding (quadrature_tolerance 0) take at least the 12-point rule; a
    // tolerance, the solver's own rule (docs/line-solver.md, "Rolling friction").
    if constexpr (Quadrature::points < 12) {
      sol.chi = options_.quadrature_tolerance > 0
                    ? detail::line_rolling_friction<Quadrature>(sol)
                    : detail::line_rolling_friction<GaussLegendre<Real, 12>>(sol);
    } else {
      sol.chi = detail::line_rolling_friction<Quadrature>(sol);
    }
    add_warnings(sol, u, std::same_as<typename Residual::drop_type, ParabolicDrop>);
    if (converged && !root)
      add_warning(sol, WarningCode::least_squares_minimum, detail::minimum_warning(rmax));
    return sol;
  }

  template <class Residual>
  Solution failure(const Units& u, const StaticLineContact<Real>& slow, Real c, Real f, Real vtau,
                   const Residual& res, const Vector& x, StopCode code, const char* reason,
                   int iterations) const {
    Vector r = Vector::Constant(1, std::numeric_limits<Real>::quiet_NaN());
    return make(u, slow, c, f, vtau, res, x, r, false, code, reason, iterations);
  }

  /// The domain of the line theory (line_domain_warnings) and chi's sign
  /// (line_chi_sign_warnings), for a solution of either path (one term or a spectrum).
  template <class AnySolution>
  static void add_domain_warnings(AnySolution& sol, const Units& u) {
    append_warnings(sol, line_domain_warnings(u.shape_in_caller_units(sol.shape)));
    append_warnings(sol, line_chi_sign_warnings(sol.converged, sol.chi));
  }

  /// The domain of the line theory (line_domain_warnings) and, for the paper's ellipsoid
  /// (`bounds`), the bounds of the rolling contact (line_bound_warnings, to the root tolerance,
  /// plus the residual of a least-squares minimum, which meets the equations only to it); for a
  /// profile (B2), (B3) are not derived (docs/theory.md (RP10)).
  static void add_warnings(Solution& sol, const Units& u, bool bounds = true) {
    add_domain_warnings(sol, u);
    if (!bounds) return;
    const Real tolerance = root_tolerance() + (sol.root ? Real(0) : sol.residual);
    append_warnings(sol, line_bound_warnings(sol, tolerance));
  }

  /// The line solver for a spectrum (docs/theory.md section 14): the terms classified at the
  /// scene's speed as the plane solver does (relaxed ones, V tau_k <= eps a0, folded into the
  /// compliance; not started ones, strip_is_glassy, dropped); none active: the static closed
  /// form of the remaining compliance; one: the standard linear solid (the paper's theory, the
  /// same digits as LineSolver over that material); two or more: LineSpectrumResidual. Scene: a
  /// LineScene (the paper's ellipsoid) or a LineProfileScene (a roller profile, whose
  /// static contacts are static_profile_contact's and whose drop enters (34), (RP5)). `start`
  /// seeds the iteration only where the one from the cold start stops short.
  template <class Scene>
  Solution solve_spectrum(const Scene& scene, const Solution* start) const
      requires(!SingleTimeModel<Material>) {
    using std::cbrt;
    using std::log;
    using std::pow;
    constexpr bool ellipsoid = std::same_as<Scene, LineScene<Real>>;
    scene.validate();
    detail::require(options_.basis == LineBasis::t_squared && options_.oversampling == 1, "basis",
                    int(options_.basis),
                    "LineBasis::t_squared with oversampling 1 for a material with a spectrum");
    const Real sqrt_eps = std::sqrt(std::numeric_limits<Real>::epsilon());
    const Real c = material_.instantaneous_compliance();
    const auto& terms = material_.memory_terms();
    detail::require_spectrum_terms(terms.size(), "line");
    Real creep_ratio = 0;
    for (std::size_t k = 0; k < terms.size(); ++k) creep_ratio += terms[k].f;
    const Real c1 = [&] {
      if constexpr (ellipsoid)
        return scene.c1;
      else
        return Real(scene.roller.c1());
    }();
    const auto inputs = [&] {
      std::string roller;
      if constexpr (ellipsoid)
        roller = ", c2 = " + detail::format_value(scene.c2);
      else
        roller = " (a roller profile)";
      return "c1 = " + detail::format_value(c1) + roller +
             ", load = " + detail::format_value(scene.load) +
             ", speed = " + detail::format_value(scene.speed) +
             ", compliance = " + detail::format_value(c) +
             ", sum of f = " + detail::format_value(creep_ratio) +
             ", terms = " + std::to_string(terms.size());
    };
    detail::representable(c, 0, "the instantaneous compliance c", inputs, false);
    // The long-term static contact, compliance c (1 + F): the unit of length.
    Units u;
    StaticLineContact<Real> slow;
    std::optional<StaticProfileContact<Real>> slow_profile;  // a profile's, in the caller's units
    // A profile whose drop is not even (a tilt): the asymmetric contact ((RP5) with (RP7)).
    bool asymmetric = false;
    if constexpr (!ellipsoid) asymmetric = !scene.roller.symmetric();
    if constexpr (ellipsoid) {
      std::tie(u, slow) = ellipse_units(scene, c, creep_ratio, inputs);
    } else {
      slow_profile = static_profile_contact(scene.roller, (1 + creep_ratio) * c * scene.load,
                                            profile_static_terms);
      if (!slow_profile->converged) return profile_static_failure(*slow_profile, c, Real(0));
      const Real a0_caller = slow_profile->a(slow_profile->centre());
      u = Units::profile(c1, a0_caller);
      const auto in_units = profile_in_units(*slow_profile, u, a0_caller, Real(0), asymmetric);
      slow = {in_units.first.a_ref, in_units.first.l, in_units.second};
    }
    // Classify the terms (lengths in units). Relaxed: V tau_k <= sqrt(eps) a0 moves a, b and
    // chi/C1 by O(V tau_k) <= sqrt(eps) a0 (P6), below the line theory's own error, and keeps the
    // strips out of the slow regime of the line equations (docs/line-solver.md), where they have
    // no root. Relaxed terms: c -> c (1 + relaxed), the active f -> f / (1 + relaxed) (R6b).
    // Terms whose memory acts as relaxed or as glassy to within the line method's spectrum
    // budget are folded or dropped as well (S21).
    auto classes =
        detail::classify_spectrum(terms, scene.speed, u.length, sqrt_eps * slow.a0, slow.a0,
                                  creep_ratio, line_spectrum_budget<Real>(), slow.l);
    const Real relaxed = classes.relaxed;
    // Near-equal times merged where the closed-form strip would lose digits ((S19), (S20)).
    const auto conditioned = detail::condition_spectrum(
        std::move(classes.active), times_power_of_two(Real(1), u.length) / scene.speed);
    const auto& merged = conditioned.terms;
    const Real c_eff = c * (1 + relaxed);
    Solution sol{};
    sol.c1 = c1;
    sol.active_terms = static_cast<int>(merged.size());
    sol.spectrum_error = conditioned.spectrum_error + classes.error;
    if (merged.size() <= 1) {
      // The standard linear solid (or the elastic solid) of the remaining compliance: its own
      // solver, in the caller's units.
      const Real pi = boost::math::constants::pi<Real>();
      const Real mu = 1 / (2 * pi * c_eff);  // c = (1 - nu)/(2 pi mu) with nu = 0
      LineSolution<Real, Quadrature> one = [&] {
        if (merged.empty()) {
          const LineSolver<Real, Elastic<Real>, Quadrature> elastic(Elastic<Real>(mu, Real(0)),
                                                                    options_);
          const auto e = elastic.solve(scene);
          return LineSolution<Real, Quadrature>(e);
        }
        // tau back from lambda (units) through the speed: lambda 2^length / V.
        const Real tau = times_power_of_two(merged[0].q, u.length) / scene.speed;
        const LineSolver<Real, StandardLinearSolid<Real>, Quadrature> sls(
            StandardLinearSolid<Real>(mu, Real(0), merged[0].w, tau), options_);
        const LineSolution<Real, Quadrature>* seed =
            start != nullptr && start->single ? &*start->single : nullptr;
        return sls.solve(scene, seed);
      }();
      sol.shape = one.shape;
      sol.d = one.d;
      sol.chi = one.chi;
      sol.converged = one.converged;
      sol.root = one.root;
      sol.code = one.code;
      sol.reason = one.reason;
      sol.iterations = one.iterations;
      sol.residual = one.residual;
      sol.warnings = one.warnings;
      sol.warning_codes = one.warning_codes;
      sol.load_compliance = one.f0_per_load();
      if constexpr (ellipsoid) {
        const auto full =
            static_line_contact(scene.c1, scene.c2, c * (1 + creep_ratio) * scene.load);
        sol.a_long_term = full.a0;
        sol.l_long_term = full.l;
        sol.d_long_term = full.d;
      } else {
        sol.a_long_term = slow_profile->a(slow_profile->centre());
        sol.l_long_term = slow_profile->half_length();
        sol.d_long_term = slow_profile->d;
      }
      if (!merged.empty()) sol.single = std::move(one);
      return sol;
    }
    const Solution base = sol;
    const SpectrumLengths<Real>& lengths = conditioned.lengths;
    // The static contact of the terms solved for, c_eff (1 + F'), in the same units: lengths
    // scale as the cube root of the compliance (Eq. 47 with (48)), d as its square; a profile's
    // is solved for (static_profile_contact, its a(0) in the caller's units eff_a0).
    const Real s = cbrt((1 + relaxed) * (1 + lengths.creep_ratio) / (1 + creep_ratio));
    StaticLineContact<Real> eff{slow.a0 * s, slow.l * s, slow.d * s * s};
    Real load_target = u.c1 * eff.a0 * eff.a0 * eff.l / 3;
    const Real eff_load = c_eff * (1 + lengths.creep_ratio) * scene.load;  // (1 + F') c_eff P
    Real eff_a0 = 0;
    std::optional<StaticProfileContact<Real>> eff_profile;
    if constexpr (!ellipsoid) {
      eff_profile = static_profile_contact(scene.roller, eff_load, profile_static_terms);
      if (!eff_profile->converged) return profile_static_failure(*eff_profile, c, Real(0));
      eff_a0 = eff_profile->a(eff_profile->centre());
      const auto in_units = profile_in_units(*eff_profile, u, eff_a0, Real(0), asymmetric);
      eff = {in_units.first.a_ref, in_units.first.l, in_units.second};
      load_target = times_power_of_two(eff_load, -(u.curvature + 3 * u.length));
    }
    const LineSpectrumProblem<Real> prob{u.c1, u.c2, lengths, eff.a0, eff.l, load_target};
    // The continuation stages from the cold start (seed == nullptr) or from a seed: the solution
    // in the solver's units.
    const auto iterate = [&](const Solution* seed) {
      Solution sol = base;
      // The cold start: the plane strip of the spectrum at the load whose long-term width is a0
      // ((S8), TOMS 748 as the plane solver), shrunk as the 3-D widths, (1 + F)^(-1/3).
      LineShape<Real> shape;
      LineSpectrumMoments<Real> moments;
      Real d;
      if (seed != nullptr) {
        shape = u.shape_in_units(seed->shape);
        moments = seed->moments;
        d = u.penetration_in_units(seed->d);
      } else {
        const auto h = [&](Real A) {
          const auto st = spectrum_strip(A * eff.a0, lengths);
          return A * A + 2 * st.g0 / (eff.a0 * eff.a0) - 1;
        };
        std::uintmax_t max_iter = 200;
        const Real lo = 1 / std::sqrt(1 + lengths.creep_ratio);
        const Real h_lo = h(lo), h_hi = h(Real(1));
        Real A = h_lo >= 0 ? lo : Real(1);
        if (h_lo < 0 && h_hi > 0) {
          const auto bracket = boost::math::tools::toms748_solve(
              h, lo, Real(1), h_lo, h_hi,
              boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits / 2),
              max_iter);
          A = (bracket.first + bracket.second) / 2;
        }
        const auto ps = spectrum_strip(A * eff.a0, lengths);
        moments = {{ps.g0 / (A * A * eff.a0 * eff.a0)}, {ps.centroid / eff.a0}};
        if constexpr (ellipsoid) {
          const Real ratio = pow(A, Real(2) / 3);
          shape = LineShape<Real>{eff.a0, eff.l * ratio, {log(ratio)}, {ps.b / eff.a0}};
          d = eff.d * ratio * ratio;
        } else {
          // (RP8): the static contact at the compliance load whose (48) is A^(2/3) times eff's.
          const auto at_load =
              static_profile_contact(scene.roller, eff_load * A * A, profile_static_terms);
          std::tie(shape, d) = profile_in_units(at_load.converged ? at_load : *eff_profile, u,
                                                eff_a0, ps.b / eff.a0, asymmetric);
        }
      }
      const numerics::LeastSquaresOptions<Real> settings = iteration_settings();
      int iterations = 0;
      Vector r;
      numerics::LeastSquaresOutcome out;
      const auto drop = [&] {
        if constexpr (ellipsoid)
          return ParabolicDrop{};
        else
          return ProfileDrop<std::remove_cvref_t<decltype(scene.roller)>>(scene.roller, u.length,
                                                                          u.curvature);
      }();
      std::optional<LineSpectrumResidual<Real, Quadrature, std::remove_const_t<decltype(drop)>>>
          last;
      const bool least_squares = minimises();
      const std::vector<int> stages = detail::continuation_stages(options_.terms);
      for (std::size_t k = 0; k < stages.size(); ++k) {
        const int n = stages[k];
        last.emplace(prob, n, LineBasis::t_squared, Real(options_.quadrature_tolerance), drop,
                     asymmetric);
        Vector x = last->pack(shape, moments, d);
        r.resize(last->equations());
        if (!(*last)(x, r)) {
          out = {};
          out.undefined = true;
          out.code = StopCode::outside_domain;
          out.reason = "initial guess outside the domain";
          break;
        }
        out = numerics::levenberg_marquardt(*last, x, r,
                                            stage_settings(settings, k, k + 1 == stages.size()));
        iterations += out.iterations;
        // The last stage: where the equations have no root, the least-squares solution.
        if (n == stages.back() && least_squares && !out.converged && !out.undefined)
          out = detail::least_squares_solution(*last, x, r, settings, iterations);
        shape = last->shape(x);
        moments = last->moments(x);
        d = last->penetration(x);
        if (out.undefined) break;
      }
      const Real rmax = r.size() ? Real(r.cwiseAbs().maxCoeff()) : Real(0);
      sol.shape = shape;
      sol.moments = moments;
      sol.d = d;
      // A certified least-squares minimum is converged (as the one-term solver's); without the
      // minimisation (LineOptions::least_squares off, or a difference Jacobian) only a root is.
      sol.converged =
          out.converged && !out.undefined && (least_squares || rmax <= root_tolerance());
      sol.root = sol.converged && rmax <= root_tolerance();
      sol.code = out.converged && !sol.converged ? StopCode::no_descent : out.code;
      sol.reason = out.converged && !sol.converged
                       ? "a least-squares minimum (the spectrum's line equations have no root here)"
                       : out.reason;
      sol.iterations = iterations;
      sol.residual = out.undefined ? std::numeric_limits<Real>::quiet_NaN() : rmax;
      sol.chi = (boost::math::isfinite)(rmax) ? u.c1 * last->centroid(shape, moments) : Real(0);
      sol.a_long_term = slow.a0;
      sol.l_long_term = slow.l;
      sol.d_long_term = slow.d;
      sol.load_compliance = c_eff * (1 + lengths.creep_ratio);
      if (sol.converged && !(sol.d > 0 && shape.a(shape.centre) > 0 && shape.l > 0)) {
        sol.converged = false;
        sol.root = false;
        sol.code = StopCode::not_a_contact;
        sol.reason =
            "a root of the line equations that is not a contact (d, a at the centre or l "
            "not positive)";
      }
      if constexpr (!ellipsoid) check_body_end(sol, scene.roller, u);
      if (sol.converged && !sol.root)
        add_warning(sol, WarningCode::least_squares_minimum, detail::minimum_warning(rmax));
      add_domain_warnings(sol, u);
      return sol;
    };
    // The cold start first, a seed only where it stops short (docs/line-solver.md, "Materials
    // with a spectrum"): the cold start carries the strips' moments at the scene's speed, a
    // neighbouring speed's seed those of its own, and from it the iteration stopped short (the
    // 12-term rubber of rubber_prony_bem.json at 0 degC, 0.01 m/s from 0.001 m/s) or reached a
    // root that is not the contact (l/a(0) = 0.67 on the paper's proportions at V = 10 from
    // V = 1) where the cold start converges, in no fewer iterations than the cold start.
    Solution result = iterate(nullptr);
    if (start != nullptr && !result.converged && usable_seed(*start) &&
        !start->moments.gamma.empty()) {
      Solution seeded = iterate(start);
      if (seeded.converged) {
        seeded.iterations += result.iterations;
        add_warning(seeded, WarningCode::solved_from_seed,
                    "the iteration from the cold start stopped (" + result.reason +
                        "): solved from the seed");
        result = std::move(seeded);
      } else {
        result.iterations += seeded.iterations;
        add_warning(result, WarningCode::seed_failed,
                    "the iteration from the seed stopped too (" + seeded.reason + ")");
      }
    }
    return detail::in_caller_units(std::move(result), u, c1, inputs);
  }

  Material material_;
  LineOptions options_;
};

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
auto LineSolver<Real, Material, Quadrature>::solve(const LineScene<Real>& scene,
                                                   const Solution* start) const -> Solution {
  if constexpr (!SingleTimeModel<Material>) {
    return solve_spectrum(scene, start);
  } else {
    scene.validate();
    // The material's compliance and its memory term (f, tau) of Eq. (1) (none for Elastic): the
    // strips' G (36) and the leading-edge condition's kernel are formed from V tau and f.
    const Real c = material_.instantaneous_compliance();
    const PronyTerm<Real> memory = detail::single_memory_term(material_);
    const Real f = memory.f;
    const auto inputs = [&] {
      return "c1 = " + detail::format_value(scene.c1) + ", c2 = " + detail::format_value(scene.c2) +
             ", load = " + detail::format_value(scene.load) +
             ", speed = " + detail::format_value(scene.speed) +
             ", compliance = " + detail::format_value(c) + ", f = " + detail::format_value(f) +
             ", tau = " + detail::format_value(memory.tau);
    };
    detail::representable(c, 0, "the instantaneous compliance c", inputs, false);
    // Scaling (docs/theory.md, "Scaling"): every product below rounds as in the caller's units.
    // The long-term static contact has the compliance (1 + f) c.
    const std::pair<Units, StaticLineContact<Real>> long_term = ellipse_units(scene, c, f, inputs);
    const Units u = long_term.first;
    const StaticLineContact<Real> slow = long_term.second;
    const auto speed = binary<Real>(scene.speed), tau = binary<Real>(memory.tau);
    const Real vtau = times_power_of_two(Real(speed.m * tau.m), speed.e + tau.e - u.length);
    const Real eps = std::numeric_limits<Real>::epsilon();
    Solution sol = [&] {
      if constexpr (Material::is_viscoelastic) {
        if (f > 0 && vtau > 0) {
          if (strip_is_glassy(vtau, f, slow.a0)) {
            // Glassy limit: the instantaneous compliance; every strip's b, chi within eps (P6).
            const auto [fast_units, fast] = ellipse_units(scene, c, Real(0), inputs);
            const int shift = fast_units.length - u.length;  // to the units of the long-term one
            const StaticLineContact<Real> glassy{times_power_of_two(fast.a0, shift),
                                                 times_power_of_two(fast.l, shift),
                                                 times_power_of_two(fast.d, 2 * shift)};
            // Reported as the static strip of the instantaneous compliance: f = 0, V tau = 0.
            return closed_form(u, glassy, slow, c, Real(0), "glassy limit (closed form)");
          }
          if (vtau > eps * slow.a0)
            return rolling_from(scene, u, slow, problem(u, slow, f, vtau), c, start);
        }
      }
      return closed_form(u, slow, slow, c, f, "static (closed form)");
    }();
    return detail::in_caller_units(std::move(sol), u, scene.c1, inputs);
  }
}

// Out of the class (not inline), as solve(LineScene) is: an explicit instantiation
// declaration (compiled mode) then keeps it out of the including translation unit.
template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
auto LineSolver<Real, Material, Quadrature>::solve_profile(
    const LineProfileScene<ProfileView<Real>>& scene, const Solution* start) const -> Solution {
  using Profile = ProfileView<Real>;
  if constexpr (!SingleTimeModel<Material>) {
    return solve_spectrum(scene, start);
  } else {
    scene.validate();
    const Profile& roller = scene.roller;
    const Real c = material_.instantaneous_compliance();
    const PronyTerm<Real> memory = detail::single_memory_term(material_);
    const Real f = memory.f;
    const Real c1 = roller.c1();
    // A drop that is not even (a tilt): the contact [c - l, c + l] with odd parts ((RP6), (RP7)).
    const bool asymmetric = !roller.symmetric();
    const auto inputs = [&] {
      return "c1 = " + detail::format_value(c1) + ", load = " + detail::format_value(scene.load) +
             ", speed = " + detail::format_value(scene.speed) +
             ", compliance = " + detail::format_value(c) + ", f = " + detail::format_value(f) +
             ", tau = " + detail::format_value(memory.tau) + ", a roller profile";
    };
    detail::representable(c, 0, "the instantaneous compliance c", inputs, false);
    const StaticProfileContact<Real> slow_c =
        static_profile_contact(roller, (1 + f) * c * scene.load, profile_static_terms);
    if (!slow_c.converged) return profile_static_failure(slow_c, c, f);
    const Real a0_caller = slow_c.a(slow_c.centre());
    const Units u = Units::profile(c1, a0_caller);
    const int d_unit = u.curvature + 2 * u.length;
    const auto in_units = [&](const StaticProfileContact<Real>& s, Real b_over) {
      return profile_in_units(s, u, a0_caller, b_over, asymmetric);
    };
    const std::pair<LineShape<Real>, Real> long_term = in_units(slow_c, Real(0));
    const StaticLineContact<Real> slow{long_term.first.a_ref, long_term.first.l, long_term.second};
    const auto speed = binary<Real>(scene.speed), tau = binary<Real>(memory.tau);
    const Real vtau = times_power_of_two(Real(speed.m * tau.m), speed.e + tau.e - u.length);
    const auto static_solution = [&](const std::pair<LineShape<Real>, Real>& s, Real ff,
                                     const char* reason) {
      Solution sol = solution(u, slow, c, ff, Real(0), s.first, s.second);
      sol.reason = reason;
      add_warnings(sol, u, false);
      return sol;
    };
    Solution sol = [&] {
      if constexpr (Material::is_viscoelastic) {
        if (f > 0 && vtau > 0) {
          if (strip_is_glassy(vtau, f, slow.a0)) {
            const auto fast = static_profile_contact(roller, c * scene.load, profile_static_terms);
            if (fast.converged)
              return static_solution(in_units(fast, Real(0)), Real(0),
                                     "glassy limit (static profile contact)");
          }
          if (vtau > std::numeric_limits<Real>::epsilon() * slow.a0) {
            const LineProblem<Real> prob{
                u.c1,
                Real(0),
                vtau,
                f,
                slow.a0,
                slow.l,
                times_power_of_two((1 + f) * c * scene.load, -(d_unit + u.length))};
            // (RP8): the static contact at the compliance load whose (48) is (a/a0)^(2/3) times
            // the long-term one's, b the plane's.
            const auto cold = [&](const StaticLineContact<Real>&, const PlaneSeed& ps) {
              if (ps.a == 1) return in_units(slow_c, ps.b);
              const auto s = static_profile_contact(roller, (1 + f) * c * scene.load * ps.a * ps.a,
                                                    profile_static_terms);
              return in_units(s.converged ? s : slow_c, ps.b);
            };
            const LineScene<Real> plane{
                .c1 = c1, .c2 = Real(0), .load = scene.load, .speed = scene.speed};
            return rolling_from(plane, u, slow, prob, c, start,
                                ProfileDrop<Profile>(roller, u.length, u.curvature), cold,
                                asymmetric);
          }
        }
      }
      return static_solution(long_term, f, "static (static profile contact)");
    }();
    check_body_end(sol, roller, u);
    return detail::in_caller_units(std::move(sol), u, c1, inputs);
  }
}

/// The scalar deduced from the material: LineSolver solver(StandardLinearSolid<double>(...)).
template <ConstitutiveModel Material>
LineSolver(Material) -> LineSolver<typename Material::real_type, Material>;
template <ConstitutiveModel Material>
LineSolver(Material, LineOptions) -> LineSolver<typename Material::real_type, Material>;

/// The common case: double precision, standard linear solid, 12-point Gauss-Legendre panels.
using LineSolverD = LineSolver<double, StandardLinearSolid<double>>;
/// The fast setting's solver: double, standard linear solid, 6-point Gauss-Legendre panels, to be
/// constructed with LineOptions::fast(). At the fast setting's integrals to 1e-4 a 6-point panel
/// spans about as much as a 12-point one (the panel width 2d/sinh(ln(4096/tol)/2n) of
/// docs/theory.md section 7 is about d for n = 6 and caps at the interval for n = 12), so it needs
/// about half the nodes: the same errors against the converged solution at the 100 speeds of
/// docs/performance.md ("The fast setting"), 1.5-1.7 times faster (0.72-1.26 ms a cold solve of
/// the paper's scene).
using FastLineSolverD = LineSolver<double, StandardLinearSolid<double>, GaussLegendre<double, 6>>;

// Compiled mode (docs/building.md): with VISCOROLL_COMPILED, which the CMake target
// viscoroll::compiled sets (VISCOROLL_COMPILED_DOUBLE, from viscoroll::compiled_double: the double
// ones only), the solvers below are instantiated once in that library (src/) and
// not in the including translation unit. Their entry points are defined out of the class (not
// inline), so that g++ does not instantiate them here for inlining either. Other instantiations
// are implicit, as in header-only mode.
#if defined(VISCOROLL_COMPILED)
extern template class LineSolver<float, StandardLinearSolid<float>>;
extern template class LineSolver<long double, StandardLinearSolid<long double>>;
#endif
#if defined(VISCOROLL_COMPILED) || defined(VISCOROLL_COMPILED_DOUBLE)
extern template class LineSolver<double, StandardLinearSolid<double>>;
extern template class LineSolver<double, StandardLinearSolid<double>, GaussLegendre<double, 6>>;
// A Prony series over double: its entry points only (the class's private steps are those of a
// single relaxation time): the paper's ellipsoid and the roller profiles (through ProfileView).
extern template LineSolver<double, PronyRelaxation<double>>::Solution
LineSolver<double, PronyRelaxation<double>>::solve(
    const LineScene<double>&, const LineSolver<double, PronyRelaxation<double>>::Solution*) const;
extern template LineSolver<double, PronyRelaxation<double>>::Solution
LineSolver<double, PronyRelaxation<double>>::solve_profile(
    const LineProfileScene<ProfileView<double>>&,
    const LineSolver<double, PronyRelaxation<double>>::Solution*) const;
#endif

}  // namespace viscoroll
