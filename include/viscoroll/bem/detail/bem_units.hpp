// viscoroll: the boundary-element solver's units (bem_solver.hpp; docs/bem.md, "Scaling"): the
// scene in the units of the solve, the grid and the substrate's sizing factor (B19) there, and a
// solution's way in and out of them: members of BemSolver defined out of the class.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <viscoroll/bem/bem_scene.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/bem/hertz.hpp>
#include <viscoroll/bem/influence_operator.hpp>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/solve_inputs.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll {

// The scene in the units of the solve (docs/bem.md, "Scaling").
template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires detail::BemSolverArguments<Real, Material, Quadrature>
auto BemSolver<Real, Material, Quadrature>::scaled(const BemScene<Real>& scene) const -> Scaled {
  // As the plane and line solvers (core/solve_inputs.hpp): a compliance outside the normal range
  // (mu_D near the largest or smallest double overflows or underflows (1 - nu)/(2 pi mu_D) in
  // the material) is an error. The words are kept for the solve's later errors.
  const auto prologue = detail::solve_prologue(scene, material_);
  const Real c = prologue.c, f = material_.creep_ratio();
  const std::string inputs = prologue();
  detail::representable(
      1 + f, 0, "1 + f", [&] { return inputs; }, false);
  const detail::Binary<Real> bc = detail::binary(c), bf = detail::binary(1 + f),
                             bp = detail::binary(scene.load), b1 = detail::binary(scene.c1),
                             b2 = detail::binary(scene.c2);
  const int compliance_e = bc.e + bf.e;
  const int sum = bp.e + compliance_e - b1.e;
  const int length = sum >= 0 ? (sum + 1) / 3 : -((-sum + 1) / 3);
  // u = c K p (K a length) in units: c' = c 2^(length + pressure - displacement), which is
  // c 2^(-compliance_e) with pressure = displacement - length - compliance_e; the load
  // P = 2^(pressure + 2 length) P'; the gap C1 x^2/2 = 2^displacement (C1 2^(2 length -
  // displacement)) x'^2/2.
  const int displacement = 2 * length + b1.e;
  const int pressure = displacement - length - compliance_e;
  Scaled out{.scene = {.c1 = b1.m,
                       .c2 = detail::times_power_of_two(b2.m, b2.e - b1.e),
                       .load = detail::times_power_of_two(bp.m, bp.e - pressure - 2 * length),
                       .speed = Real(1),
                       .profile = {},
                       .y_min = detail::times_power_of_two(scene.y_min, -length),
                       .y_max = detail::times_power_of_two(scene.y_max, -length)},
             .compliance = detail::times_power_of_two(bc.m, -bf.e),
             .terms = {},
             .length = length,
             .displacement = displacement,
             .pressure = pressure,
             .inputs = inputs};
  if (scene.profile) {
    const auto& h = scene.profile;
    out.scene.profile = [h, length, displacement](Real x, Real y) {
      return detail::times_power_of_two(
          h(detail::times_power_of_two(x, length), detail::times_power_of_two(y, length)),
          -displacement);
    };
  }
  if (substrate_) {
    out.thickness = detail::times_power_of_two(substrate_->thickness, -length);
    out.sizing = sizing_factor(out);
  }
  const detail::Binary<Real> bv = detail::binary(scene.speed);
  for (const auto& t : bem::memory_terms_of(material_)) {
    const detail::Binary<Real> bt = detail::binary(t.tau);
    out.terms.push_back(
        PronyTerm<Real>{t.f, scene.speed == 0 || t.tau == 0
                                 ? Real(0)
                                 : detail::times_power_of_two(bv.m * bt.m, bv.e + bt.e - length)});
  }
  return out;
}

// The grid of `n` elements per semi-axis in the units of `u`.
template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires detail::BemSolverArguments<Real, Material, Quadrature>
auto BemSolver<Real, Material, Quadrature>::grid_in_units(const Scaled& u,
                                                          const bem::HertzContact<Real>& hertz,
                                                          int n, Real across) const
    -> BemGrid<Real> {
  const int m = static_cast<int>(std::ceil(options_.extent * n - 1e-9));
  int my = m;
  if (u.scene.profile && u.sizing < 1) {
    const auto half_space = bem::hertz_contact(
        u.scene.c1, u.scene.c2, (1 + material_.creep_ratio()) * u.compliance, u.scene.load);
    my = static_cast<int>(std::ceil(options_.extent * n * half_space.b / hertz.b - 1e-9));
  }
  return {2 * m + 1, 2 * my + 1, (across > 0 ? across : hertz.a) / Real(n), hertz.b / Real(n)};
}

// (B19): the substrate's sizing factor F, by bisection in ln F.
template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires detail::BemSolverArguments<Real, Material, Quadrature>
auto BemSolver<Real, Material, Quadrature>::sizing_factor(const Scaled& u) const -> Real {
  using std::exp;
  using std::log;
  const Real lt = (1 + material_.creep_ratio()) * u.compliance;
  const auto g = [&](Real ln_f) {
    const auto hz = bem::hertz_contact(u.scene.c1, u.scene.c2, lt * exp(ln_f), u.scene.load);
    const W t = substrate_->surface_factor(W(2) / W(std::min(hz.a, hz.b)), u.thickness);
    return Real(log(t)) - ln_f;
  };
  Real lo = 0, hi = 0;
  while (g(lo) < 0 && lo > -600) lo -= 8;
  while (g(hi) > 0 && hi < 600) hi += 8;
  for (int k = 0; k < 80 && hi - lo > Real(1e-6); ++k) {
    const Real mid = (lo + hi) / 2;
    (g(mid) < 0 ? hi : lo) = mid;
  }
  return exp((lo + hi) / 2);
}

// A start solution in the caller's units, in the units of `u` (or null).
template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires detail::BemSolverArguments<Real, Material, Quadrature>
auto BemSolver<Real, Material, Quadrature>::start_in_units(const Solution* start, const Scaled& u)
    -> std::optional<Solution> {
  if (start == nullptr) return std::nullopt;
  Solution s = *start;
  s.grid.hx = detail::times_power_of_two(s.grid.hx, -u.length);
  s.grid.hy = detail::times_power_of_two(s.grid.hy, -u.length);
  for (auto& p : s.pressure) p = detail::times_power_of_two(p, -u.pressure);
  s.load = detail::times_power_of_two(s.load, -u.pressure - 2 * u.length);
  s.d = detail::times_power_of_two(s.d, -u.displacement);
  if (!(s.load > 0) || !(boost::math::isfinite)(s.load) || !(boost::math::isfinite)(s.d))
    return std::nullopt;
  return s;
}

// The solution of the units of `u` in the caller's units.
template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires detail::BemSolverArguments<Real, Material, Quadrature>
void BemSolver<Real, Material, Quadrature>::to_caller_units(Solution& s, const Scaled& u) {
  const int k = u.length, w = u.displacement, pe = u.pressure;
  Real pmax = 0;
  for (const Real p : s.pressure) pmax = std::max(pmax, p);
  const auto inputs = [&] { return u.inputs; };
  if (s.converged) {
    detail::representable(s.d, w, "the penetration d", inputs, false);
    detail::representable(s.a0, k, "a(0)", inputs, false);
    detail::representable(s.l, k, "l", inputs, false);
    detail::representable(pmax, pe, "the peak pressure", inputs, false);
    detail::representable(s.load, 2 * k + pe, "the load", inputs, false);
    detail::representable(s.chi, w - k, "chi", inputs);
  }
  for (auto& p : s.pressure) p = detail::times_power_of_two(p, pe);
  for (auto& g : s.gap) g = detail::times_power_of_two(g, w);
  s.grid.hx = detail::times_power_of_two(s.grid.hx, k);
  s.grid.hy = detail::times_power_of_two(s.grid.hy, k);
  s.d = detail::times_power_of_two(s.d, w);
  s.a0 = detail::times_power_of_two(s.a0, k);
  s.b0 = detail::times_power_of_two(s.b0, k);
  s.l = detail::times_power_of_two(s.l, k);
  // chi = C1 x_mean = (C1' 2^(w - 2k)) (x_mean' 2^k).
  s.chi = detail::times_power_of_two(s.chi, w - k);
  s.load = detail::times_power_of_two(s.load, 2 * k + pe);
  s.long_term = {
      detail::times_power_of_two(s.long_term.a, k), detail::times_power_of_two(s.long_term.b, k),
      detail::times_power_of_two(s.long_term.d, w), detail::times_power_of_two(s.long_term.p0, pe)};
}

}  // namespace viscoroll
