// viscoroll: the line solver for a material with a spectrum (line_solver.hpp; docs/theory.md
// section 14): LineSolver::solve_spectrum and its steps, the long-term static contact and units,
// the solve of at most one active term, the static contact of the terms solved for, the cold start
// and the continuation stages. Out-of-class definitions of LineSolver's members, included at the
// end of line_solver.hpp.
#pragma once

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/spectrum_conditioning.hpp>
#include <viscoroll/core/spectrum_strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/detail/line_iteration.hpp>
#include <viscoroll/line/line_profile.hpp>
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/line_solution.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/line/static_line_contact.hpp>
#include <viscoroll/line/static_profile_contact.hpp>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/numerics/least_squares_minimum.hpp>
#include <viscoroll/numerics/levenberg_marquardt.hpp>

namespace viscoroll {

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
template <class Scene>
struct LineSolver<Real, Material, Quadrature>::SpectrumRun {
  /// Whether the scene is the paper's ellipsoid (else a roller profile).
  static constexpr bool ellipsoid = std::same_as<Scene, LineScene<Real>>;
  const Scene& scene;              ///< the scene
  Real c{};                        ///< the instantaneous compliance
  Real creep_ratio{};              ///< F, the sum of the terms' f
  Real c1{};                       ///< C1 of the scene in the caller's units
  Units u{};                       ///< the solver's units
  StaticLineContact<Real> slow{};  ///< the long-term static contact, compliance c (1 + F)
  std::optional<StaticProfileContact<Real>> slow_profile{};  ///< a profile's, in the caller's units
  bool asymmetric = false;  ///< a profile whose drop is not even (a tilt)
  Real relaxed{};           ///< the f of the terms folded into the compliance
  detail::ConditionedSpectrum<Real> conditioned{};  ///< the active terms, merged
  Real c_eff{};                                     ///< c (1 + relaxed)
  Solution base{};                ///< the solution's fields known before the iteration
  StaticLineContact<Real> eff{};  ///< the static contact of the terms solved for, c_eff (1 + F')
  Real eff_load{};                ///< (1 + F') c_eff P
  Real eff_a0{};                  ///< a profile's eff a(0), in the caller's units
  std::optional<StaticProfileContact<Real>> eff_profile{};  ///< a profile's eff, caller's units
  line::LineProblem<Real> prob{};                           ///< the residual's constants
};

// solve_spectrum (documented at its declaration in line_solver.hpp): the steps below in order.
template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
template <class Scene>
auto LineSolver<Real, Material, Quadrature>::solve_spectrum(const Scene& scene,
                                                            const Solution* start) const -> Solution
    requires(!SingleTimeModel<Material>) {
  constexpr bool ellipsoid = std::same_as<Scene, LineScene<Real>>;
  const auto inputs = detail::solve_prologue(scene, material_);
  detail::require(options_.basis == LineBasis::t_squared && options_.oversampling == 1, "basis",
                  int(options_.basis),
                  "LineBasis::t_squared with oversampling 1 for a material with a spectrum");
  const Real sqrt_eps = std::sqrt(std::numeric_limits<Real>::epsilon());
  const Real c = inputs.c;
  const auto& terms = material_.memory_terms();
  detail::require_spectrum_terms(terms.size(), "line");
  const Real creep_ratio = material_.creep_ratio();  // F = sum f_k
  const Real c1 = [&] {
    if constexpr (ellipsoid)
      return scene.c1;
    else
      return Real(scene.roller.c1());
  }();
  SpectrumRun<Scene> run{.scene = scene, .c = c, .creep_ratio = creep_ratio, .c1 = c1};
  // The long-term static contact, compliance c (1 + F): the unit of length.
  if (!spectrum_long_term(run, inputs))
    return profile_static_failure(*run.slow_profile, c, Real(0));
  const Units& u = run.u;
  const StaticLineContact<Real>& slow = run.slow;
  // Classify the terms (lengths in units). Relaxed: V tau_k <= sqrt(eps) a0 moves a, b and
  // chi/C1 by O(V tau_k) <= sqrt(eps) a0 (P6), below the line theory's own error, and keeps the
  // strips out of the slow regime of the line equations (docs/line-solver.md), where they have
  // no root. Relaxed terms: c -> c (1 + relaxed), the active f -> f / (1 + relaxed) (R6b).
  // Terms whose memory acts as relaxed or as glassy to within the line method's spectrum
  // budget are folded or dropped as well (S21).
  auto classes =
      detail::classify_spectrum(terms, scene.speed, u.length, sqrt_eps * slow.a0, slow.a0,
                                creep_ratio, line::line_spectrum_budget<Real>(), slow.l);
  run.relaxed = classes.relaxed;
  // Near-equal times merged where the closed-form strip would lose digits ((S19), (S20)).
  run.conditioned = detail::condition_spectrum(
      std::move(classes.active), detail::times_power_of_two(Real(1), u.length) / scene.speed);
  const auto& merged = run.conditioned.terms;
  run.c_eff = c * (1 + run.relaxed);
  Solution sol{};
  sol.c1 = c1;
  sol.active_terms = static_cast<int>(merged.size());
  sol.spectrum_error = run.conditioned.spectrum_error + classes.error;
  if (merged.size() <= 1) return spectrum_single(run, std::move(sol), start);
  run.base = sol;
  if (!spectrum_effective(run)) return profile_static_failure(*run.eff_profile, c, Real(0));
  // The cold start first, a seed only where it stops short (docs/line-solver.md, "Materials
  // with a spectrum"): the cold start carries the strips' moments at the scene's speed, a
  // neighbouring speed's seed those of its own, and from it the iteration stopped short (the
  // 12-term rubber of rubber_prony_bem.json at 0 degC, 0.01 m/s from 0.001 m/s) or reached a
  // root that is not the contact (l/a(0) = 0.67 on the paper's proportions at V = 10 from
  // V = 1) where the cold start converges, in no fewer iterations than the cold start.
  Solution result = spectrum_iterate(run, nullptr);
  if (start != nullptr && !result.converged && usable_seed(*start) &&
      !start->moments.gamma.empty()) {
    Solution seeded = spectrum_iterate(run, start);
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

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
template <class Scene, class Inputs>
bool LineSolver<Real, Material, Quadrature>::spectrum_long_term(SpectrumRun<Scene>& run,
                                                                const Inputs& inputs) const {
  constexpr bool ellipsoid = SpectrumRun<Scene>::ellipsoid;
  const Scene& scene = run.scene;
  const Real c = run.c, creep_ratio = run.creep_ratio;
  Units& u = run.u;
  StaticLineContact<Real>& slow = run.slow;
  std::optional<StaticProfileContact<Real>>& slow_profile = run.slow_profile;
  // A profile whose drop is not even (a tilt): the asymmetric contact ((RP5) with (RP7)).
  bool& asymmetric = run.asymmetric;
  if constexpr (!ellipsoid) asymmetric = !scene.roller.symmetric();
  if constexpr (ellipsoid) {
    std::tie(u, slow) = ellipse_units(scene, c, creep_ratio, inputs);
  } else {
    slow_profile = static_profile_contact(scene.roller, (1 + creep_ratio) * c * scene.load,
                                          profile_static_terms);
    if (!slow_profile->converged) return false;
    const Real a0_caller = slow_profile->a(slow_profile->centre());
    u = Units::profile(run.c1, a0_caller);
    const auto in_units = profile_in_units(*slow_profile, u, a0_caller, Real(0), asymmetric);
    slow = {in_units.first.a_ref, in_units.first.l, in_units.second};
  }
  return true;
}

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
template <class Scene>
auto LineSolver<Real, Material, Quadrature>::spectrum_single(const SpectrumRun<Scene>& run,
                                                             Solution sol,
                                                             const Solution* start) const
    -> Solution {
  const Scene& scene = run.scene;
  const Units& u = run.u;
  const auto& merged = run.conditioned.terms;
  const Real c_eff = run.c_eff;
  // The standard linear solid (or the elastic solid) of the remaining compliance: its own
  // solver, in the caller's units.
  const Real pi = boost::math::constants::pi<Real>();
  const Real mu = 1 / (2 * pi * c_eff);  // c = (1 - nu)/(2 pi mu) with nu = 0
  Solution one = [&] {
    if (merged.empty()) {
      const LineSolver<Real, Elastic<Real>, Quadrature> elastic(Elastic<Real>(mu, Real(0)),
                                                                options_);
      return elastic.solve(scene);
    }
    // tau back from lambda (units) through the speed: lambda 2^length / V.
    const Real tau = detail::times_power_of_two(merged[0].q, u.length) / scene.speed;
    const LineSolver<Real, StandardLinearSolid<Real>, Quadrature> sls(
        StandardLinearSolid<Real>(mu, Real(0), merged[0].w, tau), options_);
    // A seed with one active term is the standard linear solid's solution.
    const Solution* seed = start != nullptr && start->active_terms == 1 ? start : nullptr;
    return sls.solve(scene, seed);
  }();
  // The remaining compliance's solution, with the spectrum's count, error and long-term contact.
  one.active_terms = sol.active_terms;
  one.spectrum_error = sol.spectrum_error;
  if constexpr (SpectrumRun<Scene>::ellipsoid) {
    const auto full =
        static_line_contact(scene.c1, scene.c2, run.c * (1 + run.creep_ratio) * scene.load);
    one.a_long_term = full.a0;
    one.l_long_term = full.l;
    one.d_long_term = full.d;
  } else {
    one.a_long_term = run.slow_profile->a(run.slow_profile->centre());
    one.l_long_term = run.slow_profile->half_length();
    one.d_long_term = run.slow_profile->d;
  }
  return one;
}

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
template <class Scene>
bool LineSolver<Real, Material, Quadrature>::spectrum_effective(SpectrumRun<Scene>& run) {
  using std::cbrt;
  constexpr bool ellipsoid = SpectrumRun<Scene>::ellipsoid;
  const Scene& scene = run.scene;
  const Units& u = run.u;
  const StaticLineContact<Real>& slow = run.slow;
  const Real relaxed = run.relaxed, creep_ratio = run.creep_ratio, c_eff = run.c_eff;
  const bool asymmetric = run.asymmetric;
  StaticLineContact<Real>& eff = run.eff;
  Real& eff_load = run.eff_load;
  Real& eff_a0 = run.eff_a0;
  std::optional<StaticProfileContact<Real>>& eff_profile = run.eff_profile;
  const plane::SpectrumLengths<Real>& lengths = run.conditioned.lengths;
  // The static contact of the terms solved for, c_eff (1 + F'), in the same units: lengths
  // scale as the cube root of the compliance (Eq. 47 with (48)), d as its square; a profile's
  // is solved for (static_profile_contact, its a(0) in the caller's units eff_a0).
  const Real s = cbrt((1 + relaxed) * (1 + lengths.creep_ratio) / (1 + creep_ratio));
  eff = {slow.a0 * s, slow.l * s, slow.d * s * s};
  Real load_target = u.c1 * eff.a0 * eff.a0 * eff.l / 3;
  eff_load = c_eff * (1 + lengths.creep_ratio) * scene.load;  // (1 + F') c_eff P
  if constexpr (!ellipsoid) {
    eff_profile = static_profile_contact(scene.roller, eff_load, profile_static_terms);
    if (!eff_profile->converged) return false;
    eff_a0 = eff_profile->a(eff_profile->centre());
    const auto in_units = profile_in_units(*eff_profile, u, eff_a0, Real(0), asymmetric);
    eff = {in_units.first.a_ref, in_units.first.l, in_units.second};
    load_target = detail::times_power_of_two(eff_load, -(u.curvature + 3 * u.length));
  }
  run.prob = {.c1 = u.c1,
              .c2 = u.c2,
              .vtau = Real(0),
              .f = Real(0),
              .a_ref = eff.a0,
              .l_ref = eff.l,
              .load_target = load_target,
              .lengths = lengths};
  return true;
}

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
template <class Scene>
void LineSolver<Real, Material, Quadrature>::spectrum_start(const SpectrumRun<Scene>& run,
                                                            const Solution* seed,
                                                            LineShape<Real>& shape,
                                                            LineSpectrumMoments<Real>& moments,
                                                            Real& d) {
  using std::log;
  using std::pow;
  constexpr bool ellipsoid = SpectrumRun<Scene>::ellipsoid;
  const Scene& scene = run.scene;
  const Units& u = run.u;
  const StaticLineContact<Real>& eff = run.eff;
  const Real eff_load = run.eff_load, eff_a0 = run.eff_a0;
  const std::optional<StaticProfileContact<Real>>& eff_profile = run.eff_profile;
  const bool asymmetric = run.asymmetric;
  const plane::SpectrumLengths<Real>& lengths = run.conditioned.lengths;
  // The cold start: the plane strip of the spectrum at the load whose long-term width is a0
  // ((S8), TOMS 748 as the plane solver), shrunk as the 3-D widths, (1 + F)^(-1/3).
  if (seed != nullptr) {
    shape = u.shape_in_units(seed->shape);
    moments = seed->moments;
    d = u.penetration_in_units(seed->d);
  } else {
    const auto h = [&](Real A) {
      const auto st = plane::spectrum_strip(A * eff.a0, lengths);
      return A * A + 2 * st.g0 / (eff.a0 * eff.a0) - 1;
    };
    std::uintmax_t max_iter = 200;
    const Real lo = 1 / std::sqrt(1 + lengths.creep_ratio);
    const Real h_lo = h(lo), h_hi = h(Real(1));
    Real A = h_lo >= 0 ? lo : Real(1);
    if (h_lo < 0 && h_hi > 0) {
      const auto bracket = boost::math::tools::toms748_solve(
          h, lo, Real(1), h_lo, h_hi,
          boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits / 2), max_iter);
      A = (bracket.first + bracket.second) / 2;
    }
    const auto ps = plane::spectrum_strip(A * eff.a0, lengths);
    moments = {{ps.g0 / (A * A * eff.a0 * eff.a0)}, {ps.centroid / eff.a0}};
    if constexpr (ellipsoid) {
      const Real ratio = pow(A, Real(2) / 3);
      shape = LineShape<Real>{eff.a0, eff.l * ratio, {log(ratio)}, {ps.b / eff.a0}};
      d = eff.d * ratio * ratio;
    } else {
      // (RP8): the static contact at the compliance load whose (48) is A^(2/3) times eff's.
      const auto at_load =
          static_profile_contact(scene.roller, eff_load * A * A, profile_static_terms);
      std::tie(shape, d) = profile_in_units(at_load.converged ? at_load : *eff_profile, u, eff_a0,
                                            ps.b / eff.a0, asymmetric);
    }
  }
}

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
template <class Scene>
auto LineSolver<Real, Material, Quadrature>::spectrum_iterate(const SpectrumRun<Scene>& run,
                                                              const Solution* seed) const
    -> Solution {
  constexpr bool ellipsoid = SpectrumRun<Scene>::ellipsoid;
  const Scene& scene = run.scene;
  const Units& u = run.u;
  const StaticLineContact<Real>& slow = run.slow;
  const Real c_eff = run.c_eff;
  const bool asymmetric = run.asymmetric;
  const plane::SpectrumLengths<Real>& lengths = run.conditioned.lengths;
  const line::LineProblem<Real>& prob = run.prob;
  Solution sol = run.base;
  LineShape<Real> shape;
  LineSpectrumMoments<Real> moments;
  Real d;
  spectrum_start(run, seed, shape, moments, d);
  const numerics::LeastSquaresOptions<Real> settings = iteration_settings();
  int iterations = 0;
  Vector r;
  numerics::LeastSquaresOutcome out;
  const auto drop = [&] {
    if constexpr (ellipsoid)
      return line::ParabolicDrop{};
    else
      return line::ProfileDrop<std::remove_cvref_t<decltype(scene.roller)>>(scene.roller, u.length,
                                                                            u.curvature);
  }();
  std::optional<line::LineResidual<Real, Quadrature, line::ExteriorLeadingEdge,
                                   std::remove_const_t<decltype(drop)>, dynamic_memory_terms>>
      last;
  Vector x;
  Matrix jac;                // Levenberg-Marquardt's Jacobian at its last iterate
  bool jac_at_root = false;  // whether jac is the Jacobian at the returned root
  const bool least_squares = minimises();
  const std::vector<int> stages = detail::continuation_stages(options_.terms);
  for (std::size_t k = 0; k < stages.size(); ++k) {
    const int n = stages[k];
    last.emplace(prob, n, LineBasis::t_squared, 1, Real(options_.quadrature_tolerance), drop,
                 asymmetric);
    x = last->pack(shape, moments, d);
    r.resize(last->equations());
    if (!(*last)(x, r)) {
      out = {};
      out.undefined = true;
      out.code = StopCode::outside_domain;
      out.reason = "initial guess outside the domain";
      break;
    }
    out = numerics::levenberg_marquardt(*last, x, r,
                                        stage_settings(settings, k, k + 1 == stages.size()), jac);
    iterations += out.iterations;
    jac_at_root = out.converged;
    // The last stage: where the equations have no root, the least-squares solution.
    if (n == stages.back() && least_squares && !out.converged && !out.undefined) {
      out = detail::least_squares_solution(*last, x, r, settings, iterations);
      jac_at_root = false;
    }
    shape = last->shape(x);
    moments = last->moments(x);
    d = last->penetration(x);
    if (out.undefined) break;
  }
  const Real rmax = r.size() ? Real(r.cwiseAbs().maxCoeff()) : Real(0);
  // The root's error estimate, as the one-term path's.
  Real estimate = 0;
  if (out.converged && !out.undefined && least_squares && rmax <= root_tolerance())
    estimate = jac_at_root ? detail::newton_correction<Real>(jac, r)
                           : detail::newton_correction<Real>(*last, x);
  guard_narrow_scalar(out, estimate);
  sol.shape = shape;
  sol.moments = moments;
  sol.d = d;
  // A certified least-squares minimum is converged (as the one-term solver's); without the
  // minimisation (LineOptions::least_squares off, or a difference Jacobian) only a root is.
  sol.converged = out.converged && !out.undefined && (least_squares || rmax <= root_tolerance());
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
  require_contact(sol);
  warn_near_fold(sol, estimate);
  if constexpr (!ellipsoid) check_body_end(sol, scene.roller, u);
  if (sol.converged && !sol.root)
    add_warning(sol, WarningCode::least_squares_minimum, detail::minimum_warning(rmax));
  add_domain_warnings(sol, u);
  return sol;
}

}  // namespace viscoroll
