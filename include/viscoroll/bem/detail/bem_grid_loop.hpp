// viscoroll: the boundary-element solver's grids (bem_solver.hpp): one solve on a grid, and the
// refinement of BemOptions::tolerance over grids with its error estimate (docs/theory.md, "The
// boundary-element solver's error estimate"): members of BemSolver defined out of the class.
#pragma once

#include <algorithm>
#include <boost/math/special_functions/fpclassify.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
#include <viscoroll/bem/bem_scene.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/bem/hertz.hpp>
#include <viscoroll/bem/influence_operator.hpp>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/outcome.hpp>

namespace viscoroll {

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires detail::BemSolverArguments<Real, Material, Quadrature>
auto BemSolver<Real, Material, Quadrature>::solve_on(const Scaled& u, int n, const Solution* start,
                                                     Real across) const -> Solution {
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const auto hertz = hertz_in_units(u, material_.creep_ratio());
  const auto grid = grid_in_units(u, hertz, n, across);
  if (u.scene.profile) validate_profile(u.scene, grid);
  const auto terms = effective_terms(grid, u.scene.speed, u.terms);
  const Real c = u.compliance;
  const bem::InfluenceTable<Real, Quadrature> table(grid, c, terms, u.scene.speed, options_.threads,
                                                    substrate_.get(), u.thickness);
  const bem::ConvolutionOperator<Real> op(table);
  const std::vector<Complex> symbol =
      bem::preconditioner_symbol(grid, op, c, terms, u.scene.speed, substrate_.get(), u.thickness);
  const double setup = std::chrono::duration<double>(clock::now() - t0).count();
  const auto seed = start_in_units(start, u);
  const bool local = substrate_ && substrate_->kind == SubstrateKind::local;
  Solution sol = iterate(u.scene, grid, hertz, op, symbol, terms, c * u.sizing, u.length,
                         seed ? &*seed : nullptr, local ? &table : nullptr);
  to_caller_units(sol, u);
  sol.elements = n;
  sol.seconds_setup = setup;
  sol.seconds_solve = std::chrono::duration<double>(clock::now() - t0).count() - setup;
  return sol;
}

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires detail::BemSolverArguments<Real, Material, Quadrature>
auto BemSolver<Real, Material, Quadrature>::refine(const Scaled& u, const Solution* start) const
    -> Solution {
  using std::abs;
  const Real tol = Real(options_.tolerance);
  // chi's floor: 1e-6 C1 a_H, the long-term Hertz semi-axis in the caller's units.
  const bem::HertzContact<Real> hertz = hertz_in_units(u, material_.creep_ratio());
  const Real chi_floor =
      Real(1e-6) * detail::times_power_of_two(u.scene.c1 * hertz.a, u.displacement - u.length);
  double setup = 0, seconds = 0;
  std::optional<Solution> coarse, last;
  std::optional<BemErrorEstimate<Real>> before_change;  // the change between the two grids before
  bool three_grids = false;                             // the last estimate had three grids
  // The cells' semi-axis across: the long-term Hertz a_H, then the reach of the contact found on
  // the grid before, |x| + 3 hx/2 of its farthest loaded cell (the edge lies within a cell of
  // that cell's centre), when that is less (the faster, the narrower the contact: the glassy one
  // is (1 + f)^(-1/3) a_H wide), so that hx at least halves. A contact that outgrows a grid sized
  // so (it reaches the grid's border, as an end-loaded roller's edge peak can) is solved again on
  // a grid twice as wide across, up to a_H.
  Real across = hertz.a;
  for (int n = options_.grid; n <= options_.max_grid; n *= 2) {
    last = solve_on(u, n, start, across);
    setup += last->seconds_setup;
    seconds += last->seconds_solve;
    while (!last->converged && last->code == StopCode::contact_reaches_grid_boundary &&
           across < hertz.a) {
      across = std::min(hertz.a, 2 * across);
      last = solve_on(u, n, start, across);
      setup += last->seconds_setup;
      seconds += last->seconds_solve;
    }
    Solution& s = *last;
    Real reach = 0;
    for (int j = 0; j < s.grid.ny; ++j)
      for (int i = 0; i < s.grid.nx; ++i)
        if (s.p(i, j) > 0) reach = std::max(reach, abs(s.grid.x(i)) + 3 * s.grid.hx / 2);
    if (reach > 0) across = std::min(across, detail::times_power_of_two(reach, -u.length));
    // A grid too coarse for the contact (fewer than 3 cells across) is refined; any other
    // failure is returned as it is.
    if (!s.converged) {
      if (s.code == StopCode::under_resolved) continue;
      break;
    }
    if (coarse) {
      // (E1)-(E3): the change from the grid before, or half the change before that when it is
      // larger (a change that is small by coincidence, two grids landing near each other), times
      // Roache's safety factor 5/4; the edges, located to a quarter cell (B12, B13), also carry
      // that. The tolerance is met only on the third converged grid or later.
      const BemErrorEstimate<Real> change = {
          .d = abs(s.d - coarse->d),
          .chi = abs(s.chi - coarse->chi),
          .a0 = abs(s.a0 - coarse->a0),
          .b0 = abs(s.b0 - coarse->b0),
          .l = abs(s.l - coarse->l),
          .p_max = abs(s.peak_pressure() - coarse->peak_pressure())};
      const auto bound = [&](Real now, Real before) {
        return Real(5) / 4 * (before_change ? std::max(now, before / 2) : now);
      };
      const BemErrorEstimate<Real> b = before_change.value_or(change);
      const Real qx = s.grid.hx / 4, qy = s.grid.hy / 4;
      s.error = {.d = bound(change.d, b.d),
                 .chi = bound(change.chi, b.chi),
                 .a0 = bound(change.a0, b.a0) + qx,
                 .b0 = bound(change.b0, b.b0) + qx,
                 .l = bound(change.l, b.l) + qy,
                 .p_max = bound(change.p_max, b.p_max)};
      three_grids = before_change.has_value();
      s.tolerance_met = three_grids && s.error.d <= tol * abs(s.d) &&
                        s.error.chi <= tol * std::max(abs(s.chi), chi_floor);
      if (s.tolerance_met) break;
      before_change = change;
    }
    coarse = s;
  }
  Solution sol = std::move(*last);
  sol.seconds_setup = setup;
  sol.seconds_solve = seconds;
  if (sol.converged && !sol.tolerance_met) {
    // The tolerance as given, an estimate to two digits.
    const auto percent = [](Real x, int digits = std::numeric_limits<Real>::digits10) {
      std::ostringstream out;
      out.precision(digits);
      out << Real(100) * x << "%";
      return out.str();
    };
    const std::string estimates = percent(sol.error.d / abs(sol.d), 2) + " in d, " +
                                  percent(sol.error.chi / std::max(abs(sol.chi), chi_floor), 2) +
                                  " in chi";
    add_warning(
        sol,
        !(boost::math::isfinite)(sol.error.d) || !three_grids ? WarningCode::tolerance_not_verified
                                                              : WarningCode::tolerance_not_met,
        !(boost::math::isfinite)(sol.error.d)
            ? "the tolerance " + percent(tol) + " is not verified: only the grid " +
                  std::to_string(sol.elements) + " resolved the contact (max_grid " +
                  std::to_string(options_.max_grid) + ")"
        : !three_grids
            ? "the tolerance " + percent(tol) +
                  " is not verified: it needs three grids and only two resolved the contact "
                  "up to the largest grid " +
                  std::to_string(sol.elements) + " (max_grid; estimated errors " + estimates + ")"
            : "the tolerance " + percent(tol) + " is not met at the largest grid " +
                  std::to_string(sol.elements) + " (max_grid): estimated errors " + estimates);
  }
  return sol;
}

}  // namespace viscoroll
