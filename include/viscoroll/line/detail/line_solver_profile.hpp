// viscoroll: the roller profiles' path of the line solver (line_solver.hpp):
// LineSolver::solve_profile (docs/theory.md section 16), the solve of a profile whose long-term
// static contact failed, and the check of a contact that reaches the roller's body end.
// Out-of-class definitions of LineSolver's members, included at the end of line_solver.hpp.
#pragma once

#include <limits>
#include <utility>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/line/line_profile.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/line/static_profile_contact.hpp>
#include <viscoroll/roller/profile.hpp>

namespace viscoroll {

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
auto LineSolver<Real, Material, Quadrature>::profile_static_failure(
    const StaticProfileContact<Real>& slow_c, Real c, Real f) -> Solution {
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
  sol.vtau = Real(0);
  sol.f = f;
  sol.compliance = c;
  sol.load_compliance = c * (1 + f);
  sol.code = slow_c.code == StopCode::contact_reaches_body_end ? slow_c.code
                                                               : StopCode::static_contact_failed;
  sol.reason = "the long-term static contact of the profile: " + slow_c.reason +
               " (the line theory needs a slender contact, its collocation points a half "
               "width apart, docs/theory.md (G5); a short contact is the BEM's)";
  detail::copy_warnings(sol, slow_c);
  return sol;
}

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && NodalQuadratureRule<Quadrature, Real>
template <class Profile>
void LineSolver<Real, Material, Quadrature>::check_body_end(Solution& sol, const Profile& roller,
                                                            const Units& u) {
  const Real l_caller = detail::times_power_of_two(sol.shape.l, u.length);
  const Real c_caller = detail::times_power_of_two(sol.shape.centre, u.length);
  const Real y_plus = c_caller + l_caller, y_minus = c_caller - l_caller;
  if (sol.converged && !(y_plus < roller.y_max() && y_minus > roller.y_min())) {
    sol.converged = false;
    sol.root = false;
    sol.code = StopCode::contact_reaches_body_end;
    sol.reason =
        "the contact reaches the roller's body end (it spans y = " + detail::format_value(y_minus) +
        " ... " + detail::format_value(y_plus) +
        ", the body ends at y = " + detail::format_value(roller.y_min()) + " and " +
        detail::format_value(roller.y_max()) + "): outside the line theory";
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
    const auto inputs = detail::solve_prologue(scene, material_);
    const Profile& roller = scene.roller;
    const Real c = inputs.c;
    const PronyTerm<Real> memory = detail::single_memory_term(material_);
    const Real f = memory.f;
    const Real c1 = roller.c1();
    // A drop that is not even (a tilt): the contact [c - l, c + l] with odd parts ((RP6), (RP7)).
    const bool asymmetric = !roller.symmetric();
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
    const auto speed = detail::binary<Real>(scene.speed), tau = detail::binary<Real>(memory.tau);
    const Real vtau = detail::times_power_of_two(Real(speed.m * tau.m), speed.e + tau.e - u.length);
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
          if (plane::strip_is_glassy(vtau, f, slow.a0)) {
            const auto fast = static_profile_contact(roller, c * scene.load, profile_static_terms);
            if (fast.converged)
              return static_solution(in_units(fast, Real(0)), Real(0),
                                     "glassy limit (static profile contact)");
          }
          if (vtau > std::numeric_limits<Real>::epsilon() * slow.a0) {
            const line::LineProblem<Real> prob{
                u.c1,
                Real(0),
                vtau,
                f,
                slow.a0,
                slow.l,
                detail::times_power_of_two((1 + f) * c * scene.load, -(d_unit + u.length))};
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
                                line::ProfileDrop<Profile>(roller, u.length, u.curvature), cold,
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

}  // namespace viscoroll
