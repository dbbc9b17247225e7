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
// line/detail/ (line_iteration.hpp, line_units.hpp, rolling_friction.hpp). The long member
// functions of LineSolver are defined out of the class in line/detail/line_solver_rolling.hpp (the
// paper's ellipsoid and the one-term iteration), line_solver_profile.hpp (the roller profiles) and
// line_solver_spectrum.hpp (a spectrum), included at the end of this header.
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
#include <viscoroll/core/solve_inputs.hpp>
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
/// memory term (SingleTimeModel) is the paper's theory; a spectrum of several terms is the theory
/// of docs/theory.md section 14. Both go through one LineResidual and give a LineSolution.
template <RealScalar Real, ConstitutiveModel Material, class Quadrature = GaussLegendre<Real, 12>>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
class LineSolver {
 public:
  /// The solution, for every material.
  using Solution = LineSolution<Real, Quadrature>;
  /// A column vector of unknowns or residuals.
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  /// A dense matrix (a Jacobian).
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

  /// Throws std::invalid_argument if the options are invalid (LineOptions::validate).
  explicit LineSolver(Material material, LineOptions options = {})
      : material_(std::move(material)), options_(options) {
    options_.validate();
  }

  /// The material.
  const Material& material() const { return material_; }
  /// The settings.
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
  line::LineResidual<Real, Quadrature> residual(const LineScene<Real>& scene) const requires
      SingleTimeModel<Material> {
    scene.validate();
    const Real c = material_.instantaneous_compliance();
    const PronyTerm<Real> memory = detail::single_memory_term(material_);
    const auto slow = static_line_contact(scene.c1, scene.c2, (1 + memory.f) * c * scene.load);
    return line::LineResidual<Real, Quadrature>(
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
    const auto k1 = detail::binary<Real>(scene.c1), k2 = detail::binary<Real>(scene.c2),
               cc = detail::binary<Real>(c);
    const auto load = detail::binary<Real>(scene.load),
               creep = detail::binary<Real>(1 + creep_ratio);
    detail::representable(Real(k2.m / k1.m), k2.e - k1.e, "c2/c1", inputs, false);
    const Real c2 = detail::times_power_of_two(k2.m, k2.e - k1.e);
    const auto slow_units = line::static_line_contact_in_units<Real>(
        k1.m, c2, {creep.m * cc.m * load.m, creep.e + cc.e + load.e}, k1.e);
    return {Units{k1.m, c2, k1.e, slow_units.length}, slow_units.contact};
  }

  static line::LineProblem<Real> problem(const Units& u, const StaticLineContact<Real>& slow,
                                         Real f, Real vtau) {
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
                    .compliance = c,
                    .active_terms = f > 0 && vtau > 0 ? 1 : 0,
                    .load_compliance = c * (1 + f)};
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
        line::profile_line_shape(s, a_ref, 2 * profile_static_terms, b_over, asymmetric);
    return {u.shape_in_units(std::move(shape)), u.penetration_in_units(s.d)};
  }
  /// The solve of a profile whose long-term static contact did not converge: not converged, its
  /// reason, in the caller's units.
  static Solution profile_static_failure(const StaticProfileContact<Real>& slow_c, Real c, Real f);
  /// A contact that reaches the roller's body end is outside the line theory (a sharp end's
  /// pressure peak): reported, not returned as a plausible number. l in the units u.
  template <class Profile>
  static void check_body_end(Solution& sol, const Profile& roller, const Units& u);

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
  template <class Drop = line::ParabolicDrop, class ColdStart = EllipseStart>
  Solution rolling_from(const LineScene<Real>& scene, const Units& u,
                        const StaticLineContact<Real>& slow, const line::LineProblem<Real>& prob,
                        Real c, const Solution* given, const Drop& drop = {},
                        const ColdStart& cold = {}, bool asymmetric = false) const;

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
                       const StaticLineContact<Real>& slow, Real c, Real f, Real vtau) const;

  /// The continuation in N of the one-term iteration from `start` (a seed in the solver's units)
  /// or, for nullptr, from the cold start `cold`; rolling_from's step.
  template <class Drop, class ColdStart>
  Solution rolling(const LineScene<Real>& scene, const Units& u,
                   const StaticLineContact<Real>& slow, const line::LineProblem<Real>& prob, Real c,
                   const Solution* start, const Drop& drop, const ColdStart& cold,
                   bool asymmetric = false) const;

  /// Whether a root's a posteriori error estimate, the Newton correction max |J^+ r| of the
  /// unknowns, exceeds sqrt(eps): at folds of the discrete equations (a residual 2e-8 ... 9e-7
  /// over a vanishing singular value), or where the residual's rounding floor over the smallest
  /// singular value of J is beyond the scalar (docs/line-solver.md, "Stops short of a root").
  static bool beyond_estimate(Real estimate) {
    using std::sqrt;
    return !(estimate <= sqrt(std::numeric_limits<Real>::epsilon()));
  }
  /// In a scalar narrower than double a root is reported converged only where its estimate is at
  /// most sqrt(eps) (in float at V tau = 0.01 a0, N = 6, the residual's rounding floor 2e-5 over
  /// the smallest singular value 2e-3 of J moved b(0) by 15%; docs/stability.md). Both paths.
  static void guard_narrow_scalar(numerics::LeastSquaresOutcome& out, Real estimate) {
    if (!(std::numeric_limits<Real>::digits < std::numeric_limits<double>::digits)) return;
    if (!beyond_estimate(estimate)) return;
    using std::sqrt;
    out.converged = false;
    out.code = StopCode::precision_exhausted;
    out.reason = "error estimate max |J^+ r| = " + std::to_string(double(estimate)) +
                 " of the unknowns exceeds sqrt(eps) = " +
                 std::to_string(double(sqrt(std::numeric_limits<Real>::epsilon()))) +
                 ": the residual's rounding floor is beyond what this scalar carries here "
                 "(use double)";
  }
  /// In double and wider, a root whose estimate exceeds sqrt(eps) (a fold of the discrete
  /// equations) is reported with a warning naming the estimate. Both paths.
  template <class AnySolution>
  static void warn_near_fold(AnySolution& sol, Real estimate) {
    if (std::numeric_limits<Real>::digits < std::numeric_limits<double>::digits) return;
    if (!beyond_estimate(estimate)) return;
    add_warning(sol, WarningCode::near_fold,
                "a root where the Jacobian is nearly singular (a fold of the discrete "
                "equations): its error estimate max |J^+ r| = " +
                    std::to_string(double(estimate)) +
                    " exceeds sqrt(eps), so the root is not determined to better than the "
                    "discretisation and another root may lie near (docs/line-solver.md, \"Stops "
                    "short of a root\")");
  }
  /// A root of the discrete equations that is not a contact (d, a at the centre or l not
  /// positive; found at folds, e.g. by the property test of errors.md) is reported, not returned
  /// as converged. Both paths; the values are in the solver's units.
  template <class AnySolution>
  static void require_contact(AnySolution& sol) {
    const Real a_centre = sol.shape.a(sol.shape.centre);
    if (!sol.converged || (sol.d > 0 && a_centre > 0 && sol.shape.l > 0)) return;
    detail::set_stop(
        sol, StopCode::not_a_contact,
        "a root of the line equations that is not a contact (d = " + detail::format_value(sol.d) +
            ", a at the centre = " + detail::format_value(a_centre) +
            ", l = " + detail::format_value(sol.shape.l) +
            " in the solver's units of length; each must be positive)");
  }

  /// The solution of the iterate x with residual r, in the solver's units: its rolling friction,
  /// the warnings of the line theory's domain and bounds, and whether it is a root.
  template <class Residual>
  Solution make(const Units& u, const StaticLineContact<Real>& slow, Real c, Real f, Real vtau,
                const Residual& res, const Vector& x, const Vector& r, bool converged,
                StopCode code, std::string reason, int iterations) const;

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
    detail::append_warnings(sol, line::line_domain_warnings(u.shape_in_caller_units(sol.shape)));
    detail::append_warnings(sol, line::line_chi_sign_warnings(sol.converged, sol.chi));
  }

  /// The domain of the line theory (line_domain_warnings) and, for the paper's ellipsoid
  /// (`bounds`), the bounds of the rolling contact (line_bound_warnings, to the root tolerance,
  /// plus the residual of a least-squares minimum, which meets the equations only to it); for a
  /// profile (B2), (B3) are not derived (docs/theory.md (RP10)).
  static void add_warnings(Solution& sol, const Units& u, bool bounds = true) {
    add_domain_warnings(sol, u);
    if (!bounds) return;
    const Real tolerance = root_tolerance() + (sol.root ? Real(0) : sol.residual);
    detail::append_warnings(sol, line::line_bound_warnings(sol, tolerance));
  }

  /// The line solver for a spectrum (docs/theory.md section 14): the terms classified at the
  /// scene's speed as the plane solver does (relaxed ones, V tau_k <= eps a0, folded into the
  /// compliance; not started ones, strip_is_glassy, dropped); none active: the static closed
  /// form of the remaining compliance; one: the standard linear solid (the paper's theory, the
  /// same digits as LineSolver over that material); two or more: LineResidual with the spectrum's
  /// lengths. Scene: a LineScene (the paper's ellipsoid) or a LineProfileScene (a roller profile,
  /// whose static contacts are static_profile_contact's and whose drop enters (34), (RP5)). `start`
  /// seeds the iteration only where the one from the cold start stops short.
  template <class Scene>
  Solution solve_spectrum(const Scene& scene, const Solution* start) const
      requires(!SingleTimeModel<Material>);
  /// What the steps of solve_spectrum share: the scene, its compliance, units and long-term
  /// static contact, the classified terms and, for two or more active ones, the static contact of
  /// the terms solved for and the residual's constants (line/detail/line_solver_spectrum.hpp).
  template <class Scene>
  struct SpectrumRun;
  /// solve_spectrum's long-term static contact, compliance c (1 + F), and the units it sets;
  /// false where a profile's does not converge (then run.slow_profile says why).
  template <class Scene, class Inputs>
  bool spectrum_long_term(SpectrumRun<Scene>& run, const Inputs& inputs) const;
  /// solve_spectrum with at most one active term: the standard linear solid (or the elastic
  /// solid) of the remaining compliance by its own solver, in the caller's units.
  template <class Scene>
  Solution spectrum_single(const SpectrumRun<Scene>& run, Solution sol,
                           const Solution* start) const;
  /// The static contact of the terms solved for and the residual's constants (run.eff,
  /// run.prob); false where a profile's does not converge (then run.eff_profile says why).
  template <class Scene>
  static bool spectrum_effective(SpectrumRun<Scene>& run);
  /// The start of a spectrum's iteration: the seed in the solver's units, or the cold start.
  template <class Scene>
  static void spectrum_start(const SpectrumRun<Scene>& run, const Solution* seed,
                             LineShape<Real>& shape, LineSpectrumMoments<Real>& moments, Real& d);
  /// The continuation stages from the cold start (seed == nullptr) or from a seed: the solution
  /// in the solver's units.
  template <class Scene>
  Solution spectrum_iterate(const SpectrumRun<Scene>& run, const Solution* seed) const;

  Material material_;
  LineOptions options_;
};

}  // namespace viscoroll

#include <viscoroll/line/detail/line_solver_profile.hpp>
#include <viscoroll/line/detail/line_solver_rolling.hpp>
#include <viscoroll/line/detail/line_solver_spectrum.hpp>

namespace viscoroll {

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

// Compiled mode (docs/building.md, "Compiled mode"; as PlaneSolver's in plane_solver.hpp): these
// are instantiated once in viscoroll::compiled (or compiled_double), not here.
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
