// viscoroll: the paper's ellipsoid and the one-term iteration of the line solver
// (line_solver.hpp): LineSolver::solve for a LineScene, the seed policy (rolling_from), the plane
// seed of the cold start, the continuation in N (rolling) and the solution it makes (make).
// Out-of-class definitions of LineSolver's members, included at the end of line_solver.hpp.
#pragma once

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/fpclassify.hpp>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/line/detail/line_iteration.hpp>
#include <viscoroll/line/detail/rolling_friction.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/numerics/least_squares_minimum.hpp>
#include <viscoroll/numerics/levenberg_marquardt.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>

namespace viscoroll {

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
auto LineSolver<Real, Material, Quadrature>::solve(const LineScene<Real>& scene,
                                                   const Solution* start) const -> Solution {
  if constexpr (!SingleTimeModel<Material>) {
    return solve_spectrum(scene, start);
  } else {
    // The material's compliance and its memory term (f, tau) of Eq. (1) (none for Elastic): the
    // strips' G (36) and the leading-edge condition's kernel are formed from V tau and f.
    const auto inputs = detail::solve_prologue(scene, material_);
    const Real c = inputs.c;
    const PronyTerm<Real> memory = detail::single_memory_term(material_);
    const Real f = memory.f;
    // Scaling (docs/theory.md, "Scaling"): every product below rounds as in the caller's units.
    // The long-term static contact has the compliance (1 + f) c.
    const std::pair<Units, StaticLineContact<Real>> long_term = ellipse_units(scene, c, f, inputs);
    const Units u = long_term.first;
    const StaticLineContact<Real> slow = long_term.second;
    const auto speed = detail::binary<Real>(scene.speed), tau = detail::binary<Real>(memory.tau);
    const Real vtau = detail::times_power_of_two(Real(speed.m * tau.m), speed.e + tau.e - u.length);
    const Real eps = std::numeric_limits<Real>::epsilon();
    Solution sol = [&] {
      if constexpr (Material::is_viscoelastic) {
        if (f > 0 && vtau > 0) {
          if (plane::strip_is_glassy(vtau, f, slow.a0)) {
            // Glassy limit: the instantaneous compliance; every strip's b, chi within eps (P6).
            const auto [fast_units, fast] = ellipse_units(scene, c, Real(0), inputs);
            const int shift = fast_units.length - u.length;  // to the units of the long-term one
            const StaticLineContact<Real> glassy{detail::times_power_of_two(fast.a0, shift),
                                                 detail::times_power_of_two(fast.l, shift),
                                                 detail::times_power_of_two(fast.d, 2 * shift)};
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

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
template <class Drop, class ColdStart>
auto LineSolver<Real, Material, Quadrature>::rolling_from(
    const LineScene<Real>& scene, const Units& u, const StaticLineContact<Real>& slow,
    const line::LineProblem<Real>& prob, Real c, const Solution* given, const Drop& drop,
    const ColdStart& cold, bool asymmetric) const -> Solution {
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

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
auto LineSolver<Real, Material, Quadrature>::plane_seed(const LineScene<Real>& scene,
                                                        const Units& u,
                                                        const StaticLineContact<Real>& slow, Real c,
                                                        Real f, Real vtau) const -> PlaneSeed {
  using std::abs;
  using limits = std::numeric_limits<Real>;
  // W = C1 a0^2 / (4 (1 + f) c), plane a0 = slow.a0, formed as its power-of-two scaled self.
  const detail::Binary<Real> cc = detail::binary(c);
  const Real w_plane = detail::times_power_of_two(u.c1 * slow.a0 * slow.a0 / (4 * (1 + f) * cc.m),
                                                  u.curvature + 2 * u.length - cc.e);
  const Real a0 = detail::times_power_of_two(slow.a0, u.length);
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

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
template <class Drop, class ColdStart>
auto LineSolver<Real, Material, Quadrature>::rolling(const LineScene<Real>& scene, const Units& u,
                                                     const StaticLineContact<Real>& slow,
                                                     const line::LineProblem<Real>& prob, Real c,
                                                     const Solution* start, const Drop& drop,
                                                     const ColdStart& cold, bool asymmetric) const
    -> Solution {
  using Residual = line::LineResidual<Real, Quadrature, line::ExteriorLeadingEdge, Drop>;
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
      // The a posteriori error estimate of a root, the Newton correction max |J^+ r|, judged
      // as on the spectrum path (guard_narrow_scalar, require_contact, warn_near_fold).
      Real estimate = 0;
      // At a root that Levenberg-Marquardt certified its own Jacobian serves: within
      // O(eps^0.6) of J(x) (its last step), which moves the estimate by a relative
      // O(eps^0.6 / sigma_min); what the estimate decides is its side of sqrt(eps), against
      // 1e-15 ... 1e-11 at ordinary roots and far beyond it at folds (docs/line-solver.md).
      if (out.converged && least_squares && r.cwiseAbs().maxCoeff() <= root_tolerance())
        estimate = jac_at_root ? detail::newton_correction<Real>(jac, r)
                               : detail::newton_correction<Real>(res, x);
      guard_narrow_scalar(out, estimate);
      Solution sol =
          make(u, slow, c, f, vtau, res, x, r, out.converged, out.code, out.reason, iterations);
      require_contact(sol);
      warn_near_fold(sol, estimate);
      return sol;
    }
  }
  const Residual res(prob, options_.terms, options_.basis, options_.oversampling,
                     Real(options_.quadrature_tolerance), drop, asymmetric);
  return failure(u, slow, c, f, vtau, res, Vector::Zero(res.unknowns()), StopCode::not_run,
                 "no stage ran", iterations);
}

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
template <class Residual>
auto LineSolver<Real, Material, Quadrature>::make(const Units& u,
                                                  const StaticLineContact<Real>& slow, Real c,
                                                  Real f, Real vtau, const Residual& res,
                                                  const Vector& x, const Vector& r, bool converged,
                                                  StopCode code, std::string reason,
                                                  int iterations) const -> Solution {
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
  add_warnings(sol, u, std::same_as<typename Residual::drop_type, line::ParabolicDrop>);
  if (converged && !root)
    add_warning(sol, WarningCode::least_squares_minimum, detail::minimum_warning(rmax));
  return sol;
}

}  // namespace viscoroll
