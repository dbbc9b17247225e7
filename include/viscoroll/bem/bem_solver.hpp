// viscoroll: the exact 3-D boundary-element reference solver of the rolling contact.
//
// Panek & Kalker (1980), Eqs. (2), (3), (12), (13), (27), (51) solved without the line-contact
// approximation: the surface is divided into rectangles of constant pressure whose viscoelastic
// influence coefficients (rectangle_influence.hpp, docs/bem.md B1-B5) make the displacement a
// non-symmetric 2-D convolution applied by FFT (influence_operator.hpp, B6-B7). The contact set,
// the pressure and the penetration d under the total load come from the primal-dual active-set
// iteration of numerics/active_set.hpp, whose linear systems, restricted to the active cells and
// bordered by the load equation, are solved by GMRES right-preconditioned with the continuum
// symbol (B11). Nothing of it assumes a symmetric operator. The scene, the options and the
// solution are in bem_scene.hpp, with the units and conventions.
// This header needs Eigen's unsupported FFT module; the umbrella header does not include it.
#pragma once

#include <algorithm>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/roots.hpp>
#include <chrono>
#include <cmath>
#include <complex>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include <viscoroll/bem/bem_scene.hpp>
#include <viscoroll/bem/hertz.hpp>
#include <viscoroll/bem/influence_operator.hpp>
#include <viscoroll/bem/rectangle_influence.hpp>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/material/generalized_maxwell.hpp>
#include <viscoroll/material/prony.hpp>  // compiled mode: PronyRelaxation<double>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/numerics/active_set.hpp>
#include <viscoroll/substrate/substrate.hpp>

namespace viscoroll {

/// Boundary-element solver over a scalar, a material (any ConstitutiveModel: Elastic,
/// StandardLinearSolid, or a spectrum such as GeneralizedMaxwell, term by term (B10)) and the
/// NodalQuadratureRule of the memory coefficients' panels (B4)-(B5), bem::MemoryPanelRule
/// (16-point Gauss-Legendre) by default: GaussLegendre<double, 24> there measures the default's
/// quadrature error (rectangle_influence.hpp).
///   - BemSolver(material, options): throws std::invalid_argument for invalid options;
///   - solve(scene, start): the contact (B11) and its measures (B12), a BemSolution;
///   - grid_for(scene): the grid solve() uses; long_term_hertz(scene): Hertz's contact of the
///     long-term compliance (B8), which sizes it;
///   - material(), options(): what the solver was built with.
template <RealScalar Real, ConstitutiveModel Material,
          class Quadrature = bem::MemoryPanelRule<Real>>
requires std::same_as<typename Material::real_type, Real> &&
    NodalQuadratureRule<Quadrature, bem::coefficient_real_t<Real>>
class BemSolver {
 public:
  using Solution = BemSolution<Real>;
  using Complex = std::complex<Real>;
  using W = bem::coefficient_real_t<Real>;

  explicit BemSolver(Material material, BemOptions options = {})
      : material_(std::move(material)), options_(options) {
    options_.validate();
  }

  /// The solver on a substrate other than the half space (core/concepts.hpp, Substrate): a Layer,
  /// a SpringBed or a user's body, with the material's Poisson's ratio `material.nu()`. Its
  /// kernel (bem/substrate_kernel.hpp, (B15)) is tabulated here, once.
  template <Substrate S>
  requires std::same_as<typename S::real_type, Real> && requires(const Material& m) {
    { m.nu() } -> std::convertible_to<Real>;
  }
  BemSolver(Material material, BemOptions options, const S& substrate)
      : material_(std::move(material)), options_(options) {
    options_.validate();
    if constexpr (S::kind != SubstrateKind::half_space)
      substrate_ = std::make_shared<const bem::SubstrateKernel<W>>(
          bem::substrate_kernel<W>(substrate, W(material_.nu())));
  }

  const Material& material() const { return material_; }
  const BemOptions& options() const { return options_; }

  /// The grid the solver uses for a scene: grid elements per semi-axis of the long-term static
  /// Hertz ellipse, odd counts covering `extent` semi-axes each way.
  BemGrid<Real> grid_for(const BemScene<Real>& scene) const;

  /// Solves the scene; `start` (a solution on the same grid) seeds the active set and the
  /// pressure. Throws std::invalid_argument for an invalid scene; a non-converged iteration is
  /// returned with converged == false and the reason.
  Solution solve(const BemScene<Real>& scene, const Solution* start = nullptr) const;

  /// Hertz's contact (B8) of the scene on the long-term compliance (1 + f) c: the V tau = 0
  /// solution, which sizes the grid and scales d.
  HertzContact<Real> long_term_hertz(const BemScene<Real>& scene) const;

 private:
  /// The memory terms that act on the grid. A term whose memory length L = V tau_k is glassy on
  /// it is dropped (it leaves the instantaneous response, exactly the limit L -> inf). Its
  /// coefficients (B3) are at most (hx hy / L)(ln(L/h) + 10 + |ln(hx/hy)|), h = min(hx, hy)
  /// (docs/bem.md, "Glassy memory terms"; measured constant 7.2 for square cells, 8.8 at 5:1:
  /// tests/bem/rectangle_influence.test.cpp), against an elastic coefficient of at least about
  /// hx hy / R at the grid's diagonal R; the term goes when f_k times their ratio is <= eps. That
  /// covers L = +inf (speed x tau overflowed), where the recurrence (B4)-(B5) has no scale to
  /// step with. A term whose L is under eps hx takes L = 0 (the long-term limit, below).
  static std::vector<PronyTerm<Real>> effective_terms(const BemGrid<Real>& grid, Real speed,
                                                      const std::vector<PronyTerm<Real>>& all) {
    using std::abs;
    using std::log;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real diagonal = sqrt(Real(grid.nx) * grid.hx * Real(grid.nx) * grid.hx +
                               Real(grid.ny) * grid.hy * Real(grid.ny) * grid.hy);
    const Real h = std::min(grid.hx, grid.hy), shape = 10 + abs(log(grid.hx / grid.hy));
    std::vector<PronyTerm<Real>> kept;
    for (const auto& t : all) {
      const Real length = speed * t.tau;
      if (length > diagonal) {
        const Real u = diagonal / length;
        // ln L - ln h, not ln(L/h): L/h overflows for L near the largest double (speed 1e308).
        if (!(u > 0) || t.f * u * (log(length) - log(h) + shape) <= eps) continue;
      }
      // A memory length under eps hx is the long-term limit M_L = K_e + O((L/hx) ln(hx/L))
      // (B3): the recurrence (B4) cannot step with it (its panels round to zero width), so the
      // term takes L = 0, which the table evaluates as K_e exactly.
      if (length > 0 && length < eps * grid.hx) {
        kept.push_back(PronyTerm<Real>{t.f, Real(0)});
        continue;
      }
      kept.push_back(t);
    }
    return kept;
  }

  /// A user profile must be finite at every cell centre: a NaN or infinite gap would enter the
  /// complementarity test unseen (a NaN gap is never negative) or the linear systems.
  static void validate_profile(const BemScene<Real>& scene, const BemGrid<Real>& grid) {
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const Real h = scene.gap_profile(grid.x(i), grid.y(j));
        if (!(boost::math::isfinite)(h))
          detail::require(
              false, "profile(x, y)", h,
              "finite at every cell centre; here x = " + detail::format_value(grid.x(i)) +
                  ", y = " + detail::format_value(grid.y(j)));
      }
  }

  /// The BEM's operator of the active-set iteration (numerics::ContactOperator): K of (B6)-(B7),
  /// preconditioned by the inverse continuum symbol of (B11), or by nothing when `symbol` is null.
  struct ActiveSetOperator {
    const bem::ConvolutionOperator<Real>& op;
    const std::vector<Complex>* symbol;

    void apply(const std::vector<Real>& p, std::vector<Real>& u) const { op.apply(p, u); }
    void precondition(const std::vector<Real>& v, std::vector<Real>& out) const {
      if (symbol != nullptr)
        op.apply_symbol(*symbol, v, out);
      else
        out = v;
    }
  };

  /// The active-set iteration's start: the contact and pressure of `start` (a solution on the
  /// same grid) scaled to the load, else the Hertz contact of an effective compliance between
  /// the long-term (V tau = 0) and the instantaneous (V tau -> inf) one, each memory term weighted
  /// by a/(a + V tau_k).
  numerics::ActiveSetState<Real> initial_state(const BemScene<Real>& scene,
                                               const BemGrid<Real>& grid,
                                               const HertzContact<Real>& hertz,
                                               const std::vector<PronyTerm<Real>>& terms,
                                               Real compliance, const Solution* start) const {
    const std::size_t n = grid.size();
    numerics::ActiveSetState<Real> state{
        .p = std::vector<Real>(n, Real(0)), .d = hertz.d, .active = std::vector<char>(n, 0)};
    if (start != nullptr && start->grid.nx == grid.nx && start->grid.ny == grid.ny &&
        start->grid.hx == grid.hx && start->grid.hy == grid.hy && start->pressure.size() == n) {
      for (std::size_t q = 0; q < n; ++q) {
        state.active[q] = start->pressure[q] > 0;
        state.p[q] = start->pressure[q] * scene.load / start->load;
      }
      state.d = start->d;
      return state;
    }
    Real weight = 0;
    for (const auto& t : terms) weight += t.f * hertz.a / (hertz.a + scene.speed * t.tau);
    const auto guess = hertz_contact(scene.c1, scene.c2, (1 + weight) * compliance, scene.load);
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const Real px = guess.pressure(grid.x(i), grid.y(j));
        state.active[grid.index(i, j)] = px > 0;
        state.p[grid.index(i, j)] = px;
      }
    state.d = guess.d;
    return state;
  }

  /// (B18): a local bed's contact, exactly. Its rows are independent and its operator is
  /// triangular along x (a cell sinks under its own pressure and, through the memory of Eq. (2),
  /// the pressures ahead of it): for a penetration d, the cells from the front back take
  ///   p_i = max(0, (d - h_i - sum_{k > i} K(i - k, 0) p_k) / K(0, 0)),
  /// the complementarity solution of the row; the load grows with d, and TOMS 748 meets it to
  /// the scalar's precision. The active-set iteration then starts from the right set and
  /// confirms it in one solve (the primal-dual iteration alone can cycle here: the memory
  /// couplings are positive, the operator is not an M-matrix).
  static numerics::ActiveSetState<Real> local_bed_state(
      const BemGrid<Real>& grid, const bem::InfluenceTable<Real, Quadrature>& table,
      const std::vector<Real>& h, Real load, Real d_scale) {
    const std::size_t n = grid.size();
    std::vector<Real> p(n);
    const Real k0 = table(0, 0), area = grid.hx * grid.hy;
    const auto sweep = [&](Real d) {
      Real total = 0;
      for (int j = 0; j < grid.ny; ++j)
        for (int i = grid.nx - 1; i >= 0; --i) {
          Real u = 0;
          for (int k = i + 1; k < grid.nx; ++k) u += table(i - k, 0) * p[grid.index(k, j)];
          const Real v = std::max(Real(0), (d - h[grid.index(i, j)] - u) / k0);
          p[grid.index(i, j)] = v;
          total += v;
        }
      return total * area - load;
    };
    Real hi = d_scale, f_hi = sweep(hi);
    for (int k = 0; k < 200 && f_hi < 0; ++k) f_hi = sweep(hi *= 2);
    Real lo = 0;
    std::uintmax_t iterations = 200;
    const auto root = boost::math::tools::toms748_solve(
        sweep, lo, hi, sweep(lo), f_hi,
        boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 2), iterations);
    const Real d = (root.first + root.second) / 2;
    sweep(d);
    numerics::ActiveSetState<Real> state{.p = p, .d = d, .active = std::vector<char>(n, 0)};
    for (std::size_t q = 0; q < n; ++q) state.active[q] = p[q] > 0;
    return state;
  }

  /// The contact of (B11): the active-set iteration (numerics/active_set.hpp) on the gap
  /// g = u - d + h of the cell centres (Eqs. 13, 27) under the load hx hy sum p = P, its load row
  /// and gap tolerance in units of the long-term Hertz penetration.
  Solution iterate(const BemScene<Real>& scene, const BemGrid<Real>& grid,
                   const HertzContact<Real>& hertz, const bem::ConvolutionOperator<Real>& op,
                   const std::vector<Complex>& symbol, const std::vector<PronyTerm<Real>>& terms,
                   Real compliance, int length_exponent, const Solution* start,
                   const bem::InfluenceTable<Real, Quadrature>* local = nullptr) const {
    std::vector<Real> h(grid.size());
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i)
        h[grid.index(i, j)] = scene.gap_profile(grid.x(i), grid.y(j));
    auto state = local != nullptr ? local_bed_state(grid, *local, h, scene.load, hertz.d)
                                  : initial_state(scene, grid, hertz, terms, compliance, start);
    // GMRES' tolerance, but no tighter than the scalar allows (32 eps).
    const Real tol =
        std::max(Real(options_.gmres_tolerance), 32 * std::numeric_limits<Real>::epsilon());
    // The final solve's, likewise (none where that is not below tol, e.g. in float).
    const Real final_tol =
        options_.final_tolerance > 0
            ? std::max(Real(options_.final_tolerance), 32 * std::numeric_limits<Real>::epsilon())
            : Real(0);
    const auto report = numerics::active_set(
        ActiveSetOperator{op, options_.precondition ? &symbol : nullptr}, h,
        numerics::LoadEquation<Real>{
            .weight = grid.hx * grid.hy, .total = scene.load, .scale = hertz.d},
        numerics::ActiveSetSettings<Real>{.tolerance = tol,
                                          .restart = options_.restart,
                                          .max_iterations = options_.max_active_set_iterations,
                                          .max_krylov_iterations = options_.max_krylov_iterations,
                                          .coarse_tolerance = Real(options_.coarse_tolerance),
                                          .final_tolerance = final_tol},
        state);
    Solution sol = measure(scene, grid, hertz, op, h, std::move(state), report);
    judge(sol, scene, terms, length_exponent);
    return sol;
  }

  /// The solution of the last iterate: the gap, the load, chi (Eq. 51 on piecewise-constant
  /// cells), the edges (B12) and the residual, the largest violation of p >= 0, g >= 0, p g = 0
  /// or of the load relative to d of Hertz (B11). A contact cell on the grid's border fails it.
  static Solution measure(const BemScene<Real>& scene, const BemGrid<Real>& grid,
                          const HertzContact<Real>& hertz, const bem::ConvolutionOperator<Real>& op,
                          const std::vector<Real>& h, numerics::ActiveSetState<Real> state,
                          const numerics::ActiveSetReport& report) {
    using std::abs;
    const std::vector<Real>& p = state.p;
    const Real d = state.d, d_ref = hertz.d;
    std::vector<Real> u(grid.size()), gap(grid.size());
    op.apply(p, u);
    Real violation = 0, pmax = 0, load = 0, moment = 0;
    int contact = 0;
    for (const Real v : p) pmax = std::max(pmax, v);
    bool touches_edge = false;
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const std::size_t q = grid.index(i, j);
        const Real g = u[q] - d + h[q];
        gap[q] = g;
        if (p[q] > 0) {
          ++contact;
          violation = std::max(violation, abs(g) / d_ref);
          if (i == 0 || j == 0 || i == grid.nx - 1 || j == grid.ny - 1) touches_edge = true;
        } else {
          violation = std::max(violation, std::max(-g, Real(0)) / d_ref);
          violation = std::max(violation, -p[q] / pmax);
        }
        load += p[q];
        moment += grid.x(i) * p[q];
      }
    const Real area = grid.hx * grid.hy, total = load * area;
    const auto edges = locate_edges(grid, p);
    return {.grid = grid,
            .pressure = std::move(state.p),
            .gap = std::move(gap),
            .d = d,
            .a0 = edges.a0,
            .b0 = edges.b0,
            .l = edges.l,
            .chi = scene.c1 * moment / load,
            .load = total,
            .long_term = hertz,
            .contact_cells = contact,
            .converged = report.converged && !touches_edge,
            .reason = touches_edge ? "contact reaches the grid boundary (increase extent)"
                                   : report.reason,
            .code = touches_edge ? StopCode::contact_reaches_grid_boundary : report.code,
            .iterations = report.iterations,
            .krylov_iterations = report.krylov_iterations,
            .residual = std::max(violation, abs(total - scene.load) / scene.load),
            .warnings = {},
            .warning_codes = {},
            .elements = 0,
            .error = {},
            .tolerance_met = false,
            .seconds_setup = 0,
            .seconds_solve = 0};
  }

  /// What a converged solution does not claim: a contact under three cells across, where (B13)
  /// gives no error bound, is not converged; a pressure front sharper than the grid leaves a(0)
  /// and b(0) unclaimed (a warning); a non-finite value makes the residual NaN and the solution
  /// not converged.
  void judge(Solution& sol, const BemScene<Real>& scene, const std::vector<PronyTerm<Real>>& terms,
             int length_exponent) const {
    const auto& grid = sol.grid;
    // A contact spanning fewer than three cells across (on y = 0) or fewer than three rows has no
    // discretisation error bound (B13 assumes a few cells per semi-axis): the glassy contact of a
    // large creep ratio on a grid sized by the long-term one, e.g. f = 1e4 at V tau = 1e4 a0 with
    // grid 8 (one cell, a(0) off by 35%). Not claimed: the user must refine the grid.
    if (sol.converged && (boost::math::isfinite)(sol.a0) && (boost::math::isfinite)(sol.l)) {
      const int cells_x = static_cast<int>(std::lround(static_cast<double>(2 * sol.a0 / grid.hx)));
      const int cells_y = static_cast<int>(std::lround(static_cast<double>(2 * sol.l / grid.hy)));
      if (cells_x < 3 || cells_y < 3) {
        sol.converged = false;
        sol.code = StopCode::under_resolved;
        sol.reason = "contact resolved by fewer than 3 cells across (" + std::to_string(cells_x) +
                     " x " + std::to_string(cells_y) + "; increase grid)";
      }
    }
    // (B12) assumes a square-root edge. When the memory length V tau_k exceeds a cell while the
    // leading-edge layer V tau_k/(1 + f) is under a quarter cell, the pressure front is a step on
    // the grid (f = 1e4 at V tau = a0, grid 8: a(0) = 0.43 a0 against the line theory's 0.56;
    // d and chi agree with it to 1e-5 and 1.5%): a(0) and b(0) are then not claimed.
    if (sol.converged) {
      const Real f_total = material_.creep_ratio();
      for (const auto& t : terms) {
        const Real memory = scene.speed * t.tau;
        if (memory > grid.hx && memory / (1 + f_total) < grid.hx / 4) {
          add_warning(sol, WarningCode::edge_layer_unresolved,
                      "leading-edge layer V tau/(1 + f) = " +
                          detail::format_binary(memory / (1 + f_total), length_exponent) +
                          " is under a quarter cell (hx = " +
                          detail::format_binary(grid.hx, length_exponent) +
                          "): a0 and b0 are not resolved");
          break;
        }
      }
    }
    // A contact that reaches the roller's end (a cell whose neighbour lies beyond the body) has
    // a pressure peak there that only the grid bounds (bem_profile.hpp).
    if (sol.converged && (scene.y_min > -std::numeric_limits<Real>::infinity() ||
                          scene.y_max < std::numeric_limits<Real>::infinity())) {
      for (int j = 0; j < grid.ny; ++j) {
        const Real y = grid.y(j);
        if (!(y - grid.hy <= scene.y_min || y + grid.hy >= scene.y_max)) continue;
        if (!(y > scene.y_min && y < scene.y_max)) continue;
        bool loaded = false;
        for (int i = 0; i < grid.nx && !loaded; ++i) loaded = sol.p(i, j) > 0;
        if (loaded) {
          add_warning(
              sol, WarningCode::contact_at_roller_end,
              "the contact reaches the roller's end at y = " +
                  detail::format_binary(y < 0 ? scene.y_min : scene.y_max, length_exponent) +
                  ": its end pressure peak is resolved only to the grid (hy = " +
                  detail::format_binary(grid.hy, length_exponent) +
                  "); the line theory does not apply there");
          break;
        }
      }
    }
    // std::max skips a NaN in its second argument: a result with a non-finite number gets a NaN
    // residual and is never reported converged.
    bool finite = (boost::math::isfinite)(sol.d) && (boost::math::isfinite)(sol.load) &&
                  (boost::math::isfinite)(sol.chi) && (boost::math::isfinite)(sol.a0) &&
                  (boost::math::isfinite)(sol.b0) && (boost::math::isfinite)(sol.l);
    for (std::size_t q = 0; q < sol.pressure.size() && finite; ++q)
      finite = (boost::math::isfinite)(sol.pressure[q]) && (boost::math::isfinite)(sol.gap[q]);
    if (!finite) {
      sol.residual = std::numeric_limits<Real>::quiet_NaN();
      if (sol.converged) {
        sol.converged = false;
        sol.code = StopCode::non_finite;
        sol.reason = "non-finite value in the solution";
      }
    }
  }

  struct Edges {
    Real a0, b0, l;
  };

  /// (B12): a(0), b(0) and l of the pressure p on grid g.
  static Edges locate_edges(const BemGrid<Real>& g, const std::vector<Real>& p) {
    const auto at = [&](int i, int j) { return p[g.index(i, j)]; };
    const int j0 = (g.ny - 1) / 2;
    const auto centre = bem::row_contact(g, p, j0);
    if (!(centre.p_max > 0)) return {Real(0), Real(0), Real(0)};
    const Real xl = centre.leading, xt = centre.trailing;
    // l: the row loads F0(y_j) = hx sum_i p vanish linearly in y^2 at an elliptic tip (exactly
    // so for Hertz, (B12)); extrapolate the last two loaded rows to zero.
    std::vector<Real> row(static_cast<std::size_t>(g.ny), Real(0));
    int top = j0;
    for (int j = j0; j < g.ny; ++j) {
      for (int i = 0; i < g.nx; ++i) row[static_cast<std::size_t>(j)] += at(i, j);
      if (row[static_cast<std::size_t>(j)] > 0)
        top = j;
      else
        break;
    }
    Real l = g.y(top) + g.hy / 2;
    if (top - 1 > j0) {
      const Real y1 = g.y(top - 1), y2 = g.y(top);
      const Real f1 = row[static_cast<std::size_t>(top - 1)],
                 f2 = row[static_cast<std::size_t>(top)];
      if (f1 > f2) {
        using std::sqrt;
        const Real l2 = y2 * y2 + f2 * (y2 * y2 - y1 * y1) / (f1 - f2);
        l = std::min(sqrt(l2), y2 + g.hy);
      }
    }
    return {.a0 = (xl - xt) / 2, .b0 = (xl + xt) / 2, .l = l};
  }

  /// The scene in the units of the solve (docs/bem.md, "Scaling"): lengths in the surface
  /// plane in 2^length, displacements (d, the gap, the profile) in 2^displacement, pressures in
  /// 2^pressure, all powers of two, so that every product and quotient rounds as in the caller's
  /// units wherever those neither overflow nor underflow (core/binary.hpp). The displacement
  /// unit makes C1 lie in [1, 2) (displacement = 2 length + exponent of C1: d ~ C1 a^2); the
  /// pressure unit makes the long-term compliance (1 + f) c lie in [1, 4); the length unit makes
  /// the long-term Hertz semi-axis a_H of order one (a_H^3 ~ (1 + f) c P / C1, (B8)). The memory
  /// terms become (f_k, V tau_k / 2^length), their memory lengths in the units, at the speed 1:
  /// an overflowed length is +inf (the glassy limit, dropped by effective_terms), one under
  /// eps hx the long-term limit.
  struct Scaled {
    BemScene<Real> scene;
    Real compliance;                     ///< instantaneous c in the units
    std::vector<PronyTerm<Real>> terms;  ///< (f_k, V tau_k) in the units
    int length, displacement, pressure;  ///< binary exponents of the units
    std::string inputs;                  ///< the inputs, for an error message
    W thickness = 0;                     ///< the substrate's thickness in the units
    /// The substrate's factor T(kappa/a) at the long-term contact it gives (B19): the compliance
    /// that sizes the grid and starts the iteration is (1 + f) c times it; 1 on the half space.
    Real sizing = 1;
  };

  Scaled scaled(const BemScene<Real>& scene) const {
    scene.validate();
    const Real c = material_.instantaneous_compliance(), f = material_.creep_ratio();
    const std::string inputs = "c1 = " + detail::format_value(scene.c1) +
                               ", c2 = " + detail::format_value(scene.c2) +
                               ", load = " + detail::format_value(scene.load) +
                               ", speed = " + detail::format_value(scene.speed) +
                               ", compliance (1 - nu)/(2 pi mu_D) = " + detail::format_value(c) +
                               ", f = " + detail::format_value(f);
    // As the plane solver: a compliance outside the normal range (mu_D near the largest or
    // smallest double overflows or underflows (1 - nu)/(2 pi mu_D) in the material) is an error.
    detail::representable(
        c, 0, "the instantaneous compliance c", [&] { return inputs; }, false);
    detail::representable(
        1 + f, 0, "1 + f", [&] { return inputs; }, false);
    const Binary<Real> bc = binary(c), bf = binary(1 + f), bp = binary(scene.load),
                       b1 = binary(scene.c1), b2 = binary(scene.c2);
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
                         .c2 = times_power_of_two(b2.m, b2.e - b1.e),
                         .load = times_power_of_two(bp.m, bp.e - pressure - 2 * length),
                         .speed = Real(1),
                         .profile = {},
                         .y_min = times_power_of_two(scene.y_min, -length),
                         .y_max = times_power_of_two(scene.y_max, -length)},
               .compliance = times_power_of_two(bc.m, -bf.e),
               .terms = {},
               .length = length,
               .displacement = displacement,
               .pressure = pressure,
               .inputs = inputs};
    if (scene.profile) {
      const auto& h = scene.profile;
      out.scene.profile = [h, length, displacement](Real x, Real y) {
        return times_power_of_two(h(times_power_of_two(x, length), times_power_of_two(y, length)),
                                  -displacement);
      };
    }
    if (substrate_) {
      out.thickness = times_power_of_two(substrate_->thickness, -length);
      out.sizing = sizing_factor(out);
    }
    const Binary<Real> bv = binary(scene.speed);
    for (const auto& t : bem::memory_terms_of(material_)) {
      const Binary<Real> bt = binary(t.tau);
      out.terms.push_back(
          PronyTerm<Real>{t.f, scene.speed == 0 || t.tau == 0
                                   ? Real(0)
                                   : times_power_of_two(bv.m * bt.m, bv.e + bt.e - length)});
    }
    return out;
  }

  /// The grid of `n` elements per semi-axis in the units of `u`: of the long-term Hertz ellipse,
  /// or across (x) of `across` when given (the refinement's, which sizes the cells by the contact
  /// the grid before found). A roller profile on a body stiffer than the half space (B19's
  /// F < 1) keeps the cells of the sized ellipse but covers along y what the half space's grid
  /// covers: bem_scene() sized C2 for the half space, and a profile's contact is as long as its
  /// drop allows (a flat roller's, its flat length), not shorter by F^(1/3) as an ellipsoid's.
  BemGrid<Real> grid_in_units(const Scaled& u, const HertzContact<Real>& hertz, int n,
                              Real across = 0) const {
    const int m = static_cast<int>(std::ceil(options_.extent * n - 1e-9));
    int my = m;
    if (u.scene.profile && u.sizing < 1) {
      const auto half_space = hertz_contact(
          u.scene.c1, u.scene.c2, (1 + material_.creep_ratio()) * u.compliance, u.scene.load);
      my = static_cast<int>(std::ceil(options_.extent * n * half_space.b / hertz.b - 1e-9));
    }
    return {2 * m + 1, 2 * my + 1, (across > 0 ? across : hertz.a) / Real(n), hertz.b / Real(n)};
  }

  /// Hertz's long-term contact (B8) in the units of `u`, on the compliance (1 + f) c times the
  /// substrate's sizing factor (B19).
  static HertzContact<Real> hertz_in_units(const Scaled& u, Real creep_ratio) {
    return hertz_contact(u.scene.c1, u.scene.c2, (1 + creep_ratio) * u.compliance * u.sizing,
                         u.scene.load);
  }

  /// (B19): the factor F = T(kappa / min(a, b)) of the Hertz contact (a, b) on the compliance
  /// (1 + f) c F, kappa = 2, by bisection in ln F (T(kappa/a(F)) falls as F grows).
  Real sizing_factor(const Scaled& u) const {
    using std::exp;
    using std::log;
    const Real lt = (1 + material_.creep_ratio()) * u.compliance;
    const auto g = [&](Real ln_f) {
      const auto hz = hertz_contact(u.scene.c1, u.scene.c2, lt * exp(ln_f), u.scene.load);
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

  /// A start solution in the caller's units, in the units of `u` (or null).
  static std::optional<Solution> start_in_units(const Solution* start, const Scaled& u) {
    if (start == nullptr) return std::nullopt;
    Solution s = *start;
    s.grid.hx = times_power_of_two(s.grid.hx, -u.length);
    s.grid.hy = times_power_of_two(s.grid.hy, -u.length);
    for (auto& p : s.pressure) p = times_power_of_two(p, -u.pressure);
    s.load = times_power_of_two(s.load, -u.pressure - 2 * u.length);
    s.d = times_power_of_two(s.d, -u.displacement);
    if (!(s.load > 0) || !(boost::math::isfinite)(s.load) || !(boost::math::isfinite)(s.d))
      return std::nullopt;
    return s;
  }

  /// The solution of the units of `u` in the caller's units. A converged solution's d, a(0), l,
  /// peak pressure and load must be normal numbers there, else an error names them and the
  /// inputs.
  static void to_caller_units(Solution& s, const Scaled& u) {
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
    for (auto& p : s.pressure) p = times_power_of_two(p, pe);
    for (auto& g : s.gap) g = times_power_of_two(g, w);
    s.grid.hx = times_power_of_two(s.grid.hx, k);
    s.grid.hy = times_power_of_two(s.grid.hy, k);
    s.d = times_power_of_two(s.d, w);
    s.a0 = times_power_of_two(s.a0, k);
    s.b0 = times_power_of_two(s.b0, k);
    s.l = times_power_of_two(s.l, k);
    // chi = C1 x_mean = (C1' 2^(w - 2k)) (x_mean' 2^k).
    s.chi = times_power_of_two(s.chi, w - k);
    s.load = times_power_of_two(s.load, 2 * k + pe);
    s.long_term = {times_power_of_two(s.long_term.a, k), times_power_of_two(s.long_term.b, k),
                   times_power_of_two(s.long_term.d, w), times_power_of_two(s.long_term.p0, pe)};
  }

  /// One solve on the grid of `n` elements per semi-axis (across: of `across`, in the units of
  /// `u`, when given), in the caller's units.
  Solution solve_on(const Scaled& u, int n, const Solution* start, Real across = 0) const;

  /// The refinement of BemOptions::tolerance (docs/theory.md, "The boundary-element solver's
  /// error estimate").
  Solution refine(const Scaled& u, const Solution* start) const;

  Material material_;
  BemOptions options_;
  std::shared_ptr<const bem::SubstrateKernel<W>> substrate_;  ///< null: the half space
};

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> &&
    NodalQuadratureRule<Quadrature, bem::coefficient_real_t<Real>>
auto BemSolver<Real, Material, Quadrature>::solve(const BemScene<Real>& scene,
                                                  const Solution* start) const -> Solution {
  const Scaled u = scaled(scene);
  if (options_.tolerance > 0) return refine(u, start);
  return solve_on(u, options_.grid, start);
}

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> &&
    NodalQuadratureRule<Quadrature, bem::coefficient_real_t<Real>>
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
requires std::same_as<typename Material::real_type, Real> &&
    NodalQuadratureRule<Quadrature, bem::coefficient_real_t<Real>>
auto BemSolver<Real, Material, Quadrature>::refine(const Scaled& u, const Solution* start) const
    -> Solution {
  using std::abs;
  const Real tol = Real(options_.tolerance);
  // chi's floor: 1e-6 C1 a_H, the long-term Hertz semi-axis in the caller's units.
  const HertzContact<Real> hertz = hertz_in_units(u, material_.creep_ratio());
  const Real chi_floor =
      Real(1e-6) * times_power_of_two(u.scene.c1 * hertz.a, u.displacement - u.length);
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
    if (reach > 0) across = std::min(across, times_power_of_two(reach, -u.length));
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

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> &&
    NodalQuadratureRule<Quadrature, bem::coefficient_real_t<Real>>
auto BemSolver<Real, Material, Quadrature>::grid_for(const BemScene<Real>& scene) const
    -> BemGrid<Real> {
  const Scaled u = scaled(scene);
  BemGrid<Real> g = grid_in_units(u, hertz_in_units(u, material_.creep_ratio()), options_.grid);
  const auto inputs = [&] { return u.inputs; };
  g.hx = detail::representable(g.hx, u.length, "the cell width hx", inputs, false);
  g.hy = detail::representable(g.hy, u.length, "the cell length hy", inputs, false);
  return g;
}

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> &&
    NodalQuadratureRule<Quadrature, bem::coefficient_real_t<Real>>
auto BemSolver<Real, Material, Quadrature>::long_term_hertz(const BemScene<Real>& scene) const
    -> HertzContact<Real> {
  const Scaled u = scaled(scene);
  const HertzContact<Real> h = hertz_in_units(u, material_.creep_ratio());
  const auto inputs = [&] { return u.inputs; };
  return {
      detail::representable(h.a, u.length, "the long-term Hertz semi-axis a", inputs, false),
      detail::representable(h.b, u.length, "the long-term Hertz semi-axis b", inputs, false),
      detail::representable(h.d, u.displacement, "the long-term Hertz penetration", inputs, false),
      detail::representable(h.p0, u.pressure, "the long-term Hertz pressure", inputs, false)};
}

/// The scalar deduced from the material: BemSolver solver(GeneralizedMaxwell<double>(...)).
template <ConstitutiveModel Material>
BemSolver(Material) -> BemSolver<typename Material::real_type, Material>;
template <ConstitutiveModel Material>
BemSolver(Material, BemOptions) -> BemSolver<typename Material::real_type, Material>;

/// The common case: double precision, standard linear solid.
using BemSolverD = BemSolver<double, StandardLinearSolid<double>>;

// Compiled mode (docs/building.md): with VISCOROLL_COMPILED, which the CMake target
// viscoroll::compiled sets (VISCOROLL_COMPILED_DOUBLE, from viscoroll::compiled_double: the double
// ones only), the solvers below are instantiated once in that library (src/) and
// not in the including translation unit. Their entry points are defined out of the class (not
// inline), so that g++ does not instantiate them here for inlining either. Other instantiations
// are implicit, as in header-only mode.
#if defined(VISCOROLL_COMPILED)
extern template class BemSolver<float, StandardLinearSolid<float>>;
extern template class BemSolver<long double, StandardLinearSolid<long double>>;
#endif
#if defined(VISCOROLL_COMPILED) || defined(VISCOROLL_COMPILED_DOUBLE)
extern template class BemSolver<double, StandardLinearSolid<double>>;
extern template class BemSolver<double, PronyRelaxation<double>>;
#endif

}  // namespace viscoroll
