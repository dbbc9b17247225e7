// viscoroll: the exact 3-D boundary-element reference solver of the rolling contact.
//
// Panek & Kalker (1980), Eqs. (2), (3), (12), (13), (27), (51) solved without the line-contact
// approximation: the surface is divided into rectangles of constant pressure whose viscoelastic
// influence coefficients (rectangle_influence.hpp, docs/bem.md B1-B5) make the displacement a
// non-symmetric 2-D convolution applied by FFT (influence_operator.hpp, B6-B7). The contact set,
// the pressure and the penetration d under the total load come from a primal-dual active-set
// iteration (a semismooth Newton method for the complementarity p >= 0, g >= 0, p g = 0) whose
// linear systems, restricted to the active cells and bordered by the load equation, are solved by
// right-preconditioned restarted GMRES (B11). Nothing of it assumes a symmetric operator.
//
// Units and conventions: the roller moves towards +x; x is measured in the moving frame from the
// roller's lowest point; the gap profile h(x, y) (default C1 x^2/2 + C2 y^2/2) gives the paper's
// shape S = d - h (Eq. 27) and the gap g = u - S = u - d + h >= 0 (Eq. 13 in contact, g = 0).
// This header needs Eigen's unsupported FFT module; the umbrella header does not include it.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <boost/math/special_functions/fpclassify.hpp>
#include <chrono>
#include <cmath>
#include <complex>
#include <concepts>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>
#include <viscoroll/bem/detail/gmres.hpp>
#include <viscoroll/bem/hertz.hpp>
#include <viscoroll/bem/influence_operator.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/material/generalized_maxwell.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>

namespace viscoroll {

/// A rigid roller of curvatures c1 (across, x) and c2 (along, y) under total load `load`, rolling
/// towards +x at `speed`; `profile`, when set, replaces the doubly parabolic gap
/// h = c1 x^2/2 + c2 y^2/2 (S = d - h, Eq. 27). c1 and c2 still size the grid (the static Hertz
/// ellipse of the long-term compliance) and c1 enters chi (Eq. 51).
template <RealScalar Real>
struct BemScene {
  Real c1;
  Real c2;
  Real load;
  Real speed;
  std::function<Real(Real, Real)> profile = {};

  /// Throws std::invalid_argument naming the parameter unless c1 > 0, c2 > 0, 1e-10 <= c2/c1 <=
  /// 1e10, load > 0, speed >= 0, all finite. (The profile's values are checked by
  /// BemSolver::solve, at the cell centres of its grid.)
  void validate() const {
    detail::require_positive("c1", c1);
    detail::require_positive("c2", c2);
    detail::require(c2 / c1 >= Real(1e-10) && c2 / c1 <= Real(1e10), "c2/c1", c2 / c1,
                    "1e-10 <= c2/c1 <= 1e10");
    detail::require_positive("load", load);
    detail::require_non_negative("speed", speed);
  }

  Real gap_profile(Real x, Real y) const {
    return profile ? profile(x, y) : c1 * x * x / 2 + c2 * y * y / 2;
  }
};

/// Runtime settings of the boundary-element solver.
struct BemOptions {
  /// Elements per semi-axis of the static (V tau = 0, long-term) Hertz contact ellipse, in each
  /// direction: hx = a_H / grid, hy = b_H / grid.
  int grid = 16;
  /// The grid covers at least `extent` semi-axes each way from the roller's lowest point.
  double extent = 1.6;
  /// GMRES stops at relative residual `tolerance` (or 32 eps of the scalar, if larger); the
  /// active set must then be unchanged.
  double tolerance = 1e-10;
  int max_active_set_iterations = 200;
  int max_krylov_iterations = 5000;
  int restart = 80;
  /// Right-precondition GMRES with the inverse of the continuum symbol (B11).
  bool precondition = true;

  /// The most cells a grid may have, (2 ceil(extent grid) + 1)^2: the padded transforms then
  /// take 4 x 16 bytes per cell per complex array (about 270 MB in double).
  static constexpr long long max_cells = 1LL << 22;

  void validate() const {
    detail::require(grid >= 2 && grid <= 4096, "grid", grid, "2 <= grid <= 4096");
    detail::require(extent >= 1.6 && extent <= 64, "extent", extent, "1.6 <= extent <= 64");
    const long long side = 2 * static_cast<long long>(std::ceil(extent * grid - 1e-9)) + 1;
    detail::require(side * side <= max_cells, "grid", grid,
                    "(2 ceil(extent grid) + 1)^2 <= 4194304 cells (grid <= 639 at extent = " +
                        detail::format_value(extent) + ": " + std::to_string(side * side) +
                        " cells asked)");
    detail::require(tolerance >= 1e-15 && tolerance <= 1e-3, "tolerance", tolerance,
                    "1e-15 <= tolerance <= 1e-3");
    detail::require(max_active_set_iterations >= 1 && max_active_set_iterations <= 100000,
                    "max_active_set_iterations", max_active_set_iterations,
                    "1 <= max_active_set_iterations <= 100000");
    detail::require(max_krylov_iterations >= 1 && max_krylov_iterations <= 10000000,
                    "max_krylov_iterations", max_krylov_iterations,
                    "1 <= max_krylov_iterations <= 10000000");
    detail::require(restart >= 2 && restart <= 1000, "restart", restart, "2 <= restart <= 1000");
  }
};

/// The boundary-element solution: pressure on the grid, the contact's measures, diagnostics.
template <RealScalar Real>
struct BemSolution {
  bem::BemGrid<Real> grid;
  std::vector<Real> pressure;  ///< cell pressures, flat index i + nx j (grid.index)
  std::vector<Real> gap;  ///< g = u - d + h at the cell centres (0 in contact to the tolerance)
  Real d;                 ///< penetration (Eq. 27)
  Real a0;                ///< a(0): half width of the contact on y = 0 (B12, sub-cell)
  Real b0;                ///< b(0): offset of its centre ahead of the roller (Eq. 29)
  Real l;                 ///< half length of the contact (B12, sub-cell)
  Real chi;               ///< rolling friction C1 int x p / int p (Eq. 51)
  Real load;              ///< hx hy sum p (equals the scene's load to the tolerance)
  bem::HertzContact<Real> long_term;  ///< the static Hertz contact of the long-term compliance
  int contact_cells;
  bool converged;
  std::string reason;
  int iterations;         ///< active-set iterations
  int krylov_iterations;  ///< GMRES steps over all active-set iterations
  Real residual;          ///< max complementarity violation relative to d (B11)
  /// Quantities the solution does not claim although it converged (B12's edge model violated).
  std::vector<std::string> warnings;
  double seconds_setup;  ///< influence table and its transform
  double seconds_solve;  ///< active-set iteration

  Real p(int i, int j) const { return pressure[grid.index(i, j)]; }
};

/// Boundary-element solver over a scalar and a material (a ConstitutiveModel such as
/// StandardLinearSolid or Elastic, or a PronySeriesModel such as GeneralizedMaxwell).
template <RealScalar Real, bem::MemoryModel Material>
requires std::same_as<typename Material::real_type, Real>
class BemSolver {
 public:
  using Solution = BemSolution<Real>;
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  using Complex = std::complex<Real>;

  explicit BemSolver(Material material, BemOptions options = {})
      : material_(std::move(material)), options_(options) {
    options_.validate();
  }

  const Material& material() const { return material_; }
  const BemOptions& options() const { return options_; }

  /// The grid the solver uses for a scene: grid elements per semi-axis of the long-term static
  /// Hertz ellipse, odd counts covering `extent` semi-axes each way.
  bem::BemGrid<Real> grid_for(const BemScene<Real>& scene) const;

  /// Solves the scene; `start` (a solution on the same grid) seeds the active set and the
  /// pressure. Throws std::invalid_argument for an invalid scene; a non-converged iteration is
  /// returned with converged == false and the reason.
  Solution solve(const BemScene<Real>& scene, const Solution* start = nullptr) const;

  bem::HertzContact<Real> long_term_hertz(const BemScene<Real>& scene) const;

 private:
  /// The memory terms that act on the grid. A term whose memory length L = V tau_k is glassy on
  /// it is dropped (it leaves the instantaneous response, exactly the limit L -> inf). Its
  /// coefficients (B3) are at most (hx hy / L)(ln(L/h) + 10 + |ln(hx/hy)|), h = min(hx, hy)
  /// (docs/bem.md, "Glassy memory terms"; measured constant 7.2 for square cells, 8.8 at 5:1:
  /// tests/bem/rectangle_influence.test.cpp), against an elastic coefficient of at least about
  /// hx hy / R at the grid's diagonal R; the term goes when f_k times their ratio is <= eps. That
  /// covers L = +inf (speed x tau overflowed), where the recurrence (B4)-(B5) has no scale to
  /// step with.
  std::vector<PronyTerm<Real>> effective_terms(const bem::BemGrid<Real>& grid, Real speed) const {
    using std::abs;
    using std::log;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real diagonal = sqrt(Real(grid.nx) * grid.hx * Real(grid.nx) * grid.hx +
                               Real(grid.ny) * grid.hy * Real(grid.ny) * grid.hy);
    const Real h = std::min(grid.hx, grid.hy), shape = 10 + abs(log(grid.hx / grid.hy));
    std::vector<PronyTerm<Real>> kept;
    for (const auto& t : bem::memory_terms_of(material_)) {
      const Real length = speed * t.tau;
      if (length > diagonal) {
        const Real u = diagonal / length;
        if (!(u > 0) || t.f * u * (log(length / h) + shape) <= eps) continue;
      }
      kept.push_back(t);
    }
    return kept;
  }

  /// A user profile must be finite at every cell centre: a NaN or infinite gap would enter the
  /// complementarity test unseen (a NaN gap is never negative) or the linear systems.
  static void validate_profile(const BemScene<Real>& scene, const bem::BemGrid<Real>& grid) {
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

  /// (B11): the inverse continuum symbol |k| / (2 pi c (1 + sum f_k / (1 - i k_x V tau_k))) on
  /// the padded grid, |k| the discrete (finite-difference) wavenumber; the zero mode gets the
  /// value of the lowest non-zero one.
  static std::vector<Complex> preconditioner_symbol(const bem::BemGrid<Real>& grid,
                                                    const bem::ConvolutionOperator<Real>& op,
                                                    Real c,
                                                    const std::vector<PronyTerm<Real>>& terms,
                                                    Real speed) {
    using std::sin;
    using std::sqrt;
    const Real pi = boost::math::constants::pi<Real>();
    const int nfx = op.fft_nx(), nfy = op.fft_ny();
    std::vector<Complex> s(static_cast<std::size_t>(nfx) * static_cast<std::size_t>(nfy));
    const Real kmin = std::min(2 * pi / (Real(nfx) * grid.hx), 2 * pi / (Real(nfy) * grid.hy));
    for (int n = 0; n < nfy; ++n)
      for (int m = 0; m < nfx; ++m) {
        const int mm = m <= nfx / 2 ? m : m - nfx, nn = n <= nfy / 2 ? n : n - nfy;
        const Real kx = 2 * pi * Real(mm) / (Real(nfx) * grid.hx),
                   ky = 2 * pi * Real(nn) / (Real(nfy) * grid.hy);
        const Real qx = 2 * sin(kx * grid.hx / 2) / grid.hx,
                   qy = 2 * sin(ky * grid.hy / 2) / grid.hy;
        const Real k = std::max(sqrt(qx * qx + qy * qy), kmin);
        Complex memory(1);
        for (const auto& t : terms) memory += t.f / Complex(1, -kx * speed * t.tau);
        s[static_cast<std::size_t>(m) +
          static_cast<std::size_t>(nfx) * static_cast<std::size_t>(n)] = k / (2 * pi * c * memory);
      }
    return s;
  }

  Solution iterate(const BemScene<Real>& scene, const bem::BemGrid<Real>& grid,
                   const bem::HertzContact<Real>& hertz, const bem::ConvolutionOperator<Real>& op,
                   const std::vector<Complex>& symbol, const std::vector<PronyTerm<Real>>& terms,
                   const Solution* start) const {
    using std::abs;
    const std::size_t n = grid.size();
    std::vector<Real> h(n), p(n, Real(0)), u(n), full(n), tmp(n);
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i)
        h[grid.index(i, j)] = scene.gap_profile(grid.x(i), grid.y(j));
    const Real area = grid.hx * grid.hy;
    const Real d_ref = hertz.d;
    // Initial active set: the start's contact, or the Hertz ellipse of an effective compliance
    // between the long-term (V tau = 0) and the instantaneous (V tau -> inf) one.
    std::vector<char> active(n, 0);
    Real d = hertz.d;
    if (start != nullptr && start->grid.nx == grid.nx && start->grid.ny == grid.ny &&
        start->pressure.size() == n) {
      for (std::size_t q = 0; q < n; ++q) {
        active[q] = start->pressure[q] > 0;
        p[q] = start->pressure[q] * scene.load / start->load;
      }
      d = start->d;
    } else {
      Real weight = 0, f_total = 0;
      for (const auto& t : terms) {
        const Real vt = scene.speed * t.tau;
        weight += t.f * hertz.a / (hertz.a + vt);
        f_total += t.f;
      }
      const auto guess = bem::hertz_contact(
          scene.c1, scene.c2, (1 + weight) * material_.instantaneous_compliance(), scene.load);
      (void)f_total;
      for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) {
          const Real px = guess.pressure(grid.x(i), grid.y(j));
          active[grid.index(i, j)] = px > 0;
          p[grid.index(i, j)] = px;
        }
      d = guess.d;
    }
    std::vector<std::size_t> cells;
    std::set<std::vector<std::size_t>> seen;
    // The requested tolerance, but no tighter than the scalar allows (32 eps).
    const Real tol = std::max(Real(options_.tolerance), 32 * std::numeric_limits<Real>::epsilon());
    int iterations = 0, krylov = 0;
    bool converged = false;
    std::string reason = "active-set iteration limit";
    bool gmres_ok = true;
    for (; iterations < options_.max_active_set_iterations; ++iterations) {
      cells.clear();
      for (std::size_t q = 0; q < n; ++q)
        if (active[q]) cells.push_back(q);
      if (cells.empty()) {
        reason = "empty contact set";
        break;
      }
      if (!seen.insert(cells).second) {
        reason = "active set cycles";
        break;
      }
      const Eigen::Index na = static_cast<Eigen::Index>(cells.size());
      // Bordered system (B11) in displacement units: rows (K p)_A - d = -h_A and
      // d_ref (area sum p_A / P) = d_ref; unknowns y = [y_A, d] with p_A = (M y)_A.
      const auto apply_a = [&](const auto& x, Vector& out) {
        std::fill(full.begin(), full.end(), Real(0));
        for (Eigen::Index k = 0; k < na; ++k) full[cells[static_cast<std::size_t>(k)]] = x[k];
        op.apply(full, tmp);
        Real sum = 0;
        for (Eigen::Index k = 0; k < na; ++k) {
          out[k] = tmp[cells[static_cast<std::size_t>(k)]] - x[na];
          sum += x[k];
        }
        out[na] = d_ref * area * sum / scene.load;
      };
      const auto apply_m = [&](const auto& x, Vector& out) {
        out.resize(na + 1);
        if (!options_.precondition) {
          out = x;
          return;
        }
        std::fill(full.begin(), full.end(), Real(0));
        for (Eigen::Index k = 0; k < na; ++k) full[cells[static_cast<std::size_t>(k)]] = x[k];
        op.apply_symbol(symbol, full, tmp);
        for (Eigen::Index k = 0; k < na; ++k) out[k] = tmp[cells[static_cast<std::size_t>(k)]];
        out[na] = x[na];
      };
      Vector b(na + 1), x(na + 1);
      for (Eigen::Index k = 0; k < na; ++k) {
        b[k] = -h[cells[static_cast<std::size_t>(k)]];
        x[k] = std::max(p[cells[static_cast<std::size_t>(k)]], Real(0));
      }
      b[na] = d_ref;
      x[na] = d;
      const auto rep = bem::detail::gmres<Real>(apply_a, apply_m, b, x, tol, options_.restart,
                                                options_.max_krylov_iterations - krylov);
      krylov += rep.iterations;
      std::fill(p.begin(), p.end(), Real(0));
      for (Eigen::Index k = 0; k < na; ++k) p[cells[static_cast<std::size_t>(k)]] = x[k];
      d = x[na];
      if (!rep.converged) {
        gmres_ok = false;
        // format_value, not std::to_string: "%f" printed a residual of 3e-7 as 0.000000.
        reason = "GMRES did not converge (relative residual " +
                 detail::format_value(rep.relative_residual) + ")";
        ++iterations;
        break;
      }
      // Gap everywhere; primal-dual active-set update (B11).
      op.apply(p, u);
      bool changed = false;
      const Real gap_tol = tol * d_ref;
      for (std::size_t q = 0; q < n; ++q) {
        const Real g = u[q] - d + h[q];
        const bool now = active[q] ? p[q] > 0 : g < -gap_tol;
        if (now != static_cast<bool>(active[q])) changed = true;
        active[q] = now;
      }
      if (!changed) {
        converged = true;
        reason = "converged";
        ++iterations;
        break;
      }
    }
    op.apply(p, u);
    Solution sol;
    sol.grid = grid;
    sol.long_term = hertz;
    sol.d = d;
    sol.gap.resize(n);
    Real violation = 0, pmax = 0, load = 0, moment = 0;
    int contact = 0;
    for (std::size_t q = 0; q < n; ++q) pmax = std::max(pmax, p[q]);
    bool touches_edge = false;
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const std::size_t q = grid.index(i, j);
        const Real g = u[q] - d + h[q];
        sol.gap[q] = g;
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
    sol.pressure = p;
    sol.load = load * area;
    sol.chi = scene.c1 * moment / load;  // Eq. (51) on piecewise-constant cells
    sol.contact_cells = contact;
    sol.iterations = iterations;
    sol.krylov_iterations = krylov;
    sol.residual = std::max(violation, abs(sol.load - scene.load) / scene.load);
    sol.converged = converged && gmres_ok;
    sol.reason = reason;
    if (touches_edge) {
      sol.converged = false;
      sol.reason = "contact reaches the grid boundary (increase extent)";
    }
    locate_edges(sol);
    // A contact spanning fewer than three cells across (on y = 0) or fewer than three rows has no
    // discretisation error bound (B13 assumes a few cells per semi-axis): the glassy contact of a
    // large creep ratio on a grid sized by the long-term one, e.g. f = 1e4 at V tau = 1e4 a0 with
    // grid 8 (one cell, a(0) off by 35%). Not claimed: the user must refine the grid.
    if (sol.converged && (boost::math::isfinite)(sol.a0) && (boost::math::isfinite)(sol.l)) {
      const int cells_x = static_cast<int>(std::lround(static_cast<double>(2 * sol.a0 / grid.hx)));
      const int cells_y = static_cast<int>(std::lround(static_cast<double>(2 * sol.l / grid.hy)));
      if (cells_x < 3 || cells_y < 3) {
        sol.converged = false;
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
          sol.warnings.push_back(
              "leading-edge layer V tau/(1 + f) = " + detail::format_value(memory / (1 + f_total)) +
              " is under a quarter cell (hx = " + detail::format_value(grid.hx) +
              "): a0 and b0 are not resolved (d, chi and the load are)");
          break;
        }
      }
    }
    // std::max skips a NaN in its second argument: a result with a non-finite number gets a NaN
    // residual and is never reported converged.
    bool finite = (boost::math::isfinite)(sol.d) && (boost::math::isfinite)(sol.load) &&
                  (boost::math::isfinite)(sol.chi) && (boost::math::isfinite)(sol.a0) &&
                  (boost::math::isfinite)(sol.b0) && (boost::math::isfinite)(sol.l);
    for (std::size_t q = 0; q < n && finite; ++q)
      finite = (boost::math::isfinite)(sol.pressure[q]) && (boost::math::isfinite)(sol.gap[q]);
    if (!finite) {
      sol.residual = std::numeric_limits<Real>::quiet_NaN();
      if (sol.converged) {
        sol.converged = false;
        sol.reason = "non-finite value in the solution";
      }
    }
    return sol;
  }

  /// (B12): edges by extrapolating p^2 (linear in the distance to a square-root edge) from the
  /// last two contact cells to zero, within the cell beyond the last contact cell.
  static Real edge_offset(Real p_last, Real p_prev) {
    const Real a = p_last * p_last, b = p_prev * p_prev;
    if (!(b > a)) return Real(1) / 2;
    return std::min(a / (b - a), Real(1));
  }

  static void locate_edges(Solution& sol) {
    const auto& g = sol.grid;
    const int j0 = (g.ny - 1) / 2;
    int imax = 0;
    for (int i = 0; i < g.nx; ++i)
      if (sol.p(i, j0) > sol.p(imax, j0)) imax = i;
    if (!(sol.p(imax, j0) > 0)) {
      sol.a0 = sol.b0 = sol.l = Real(0);
      return;
    }
    int lead = imax, trail = imax;
    while (lead + 1 < g.nx && sol.p(lead + 1, j0) > 0) ++lead;
    while (trail > 0 && sol.p(trail - 1, j0) > 0) --trail;
    const Real xl =
        g.x(lead) +
        g.hx * (lead > trail ? edge_offset(sol.p(lead, j0), sol.p(lead - 1, j0)) : Real(1) / 2);
    const Real xt =
        g.x(trail) -
        g.hx * (lead > trail ? edge_offset(sol.p(trail, j0), sol.p(trail + 1, j0)) : Real(1) / 2);
    sol.a0 = (xl - xt) / 2;
    sol.b0 = (xl + xt) / 2;
    // l: the row loads F0(y_j) = hx sum_i p vanish linearly in y^2 at an elliptic tip (exactly
    // so for Hertz, (B12)); extrapolate the last two loaded rows to zero.
    std::vector<Real> row(static_cast<std::size_t>(g.ny), Real(0));
    int top = j0;
    for (int j = j0; j < g.ny; ++j) {
      for (int i = 0; i < g.nx; ++i) row[static_cast<std::size_t>(j)] += sol.p(i, j);
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
    sol.l = l;
  }

  Material material_;
  BemOptions options_;
};

template <RealScalar Real, bem::MemoryModel Material>
requires std::same_as<typename Material::real_type, Real>
auto BemSolver<Real, Material>::solve(const BemScene<Real>& scene, const Solution* start) const
    -> Solution {
  using clock = std::chrono::steady_clock;
  scene.validate();
  const auto t0 = clock::now();
  const auto hertz = long_term_hertz(scene);
  const auto grid = grid_for(scene);
  if (scene.profile) validate_profile(scene, grid);
  const auto terms = effective_terms(grid, scene.speed);
  const Real c = material_.instantaneous_compliance();
  const bem::InfluenceTable<Real> table(grid, c, terms, scene.speed);
  const bem::ConvolutionOperator<Real> op(table);
  const std::vector<Complex> symbol = preconditioner_symbol(grid, op, c, terms, scene.speed);
  const double setup = std::chrono::duration<double>(clock::now() - t0).count();
  Solution sol = iterate(scene, grid, hertz, op, symbol, terms, start);
  sol.seconds_setup = setup;
  sol.seconds_solve = std::chrono::duration<double>(clock::now() - t0).count() - setup;
  return sol;
}

template <RealScalar Real, bem::MemoryModel Material>
requires std::same_as<typename Material::real_type, Real>
auto BemSolver<Real, Material>::grid_for(const BemScene<Real>& scene) const -> bem::BemGrid<Real> {
  const auto h = long_term_hertz(scene);
  const int n = options_.grid;
  const int m = static_cast<int>(std::ceil(options_.extent * n - 1e-9));
  return {2 * m + 1, 2 * m + 1, h.a / Real(n), h.b / Real(n)};
}

template <RealScalar Real, bem::MemoryModel Material>
requires std::same_as<typename Material::real_type, Real>
auto BemSolver<Real, Material>::long_term_hertz(const BemScene<Real>& scene) const
    -> bem::HertzContact<Real> {
  scene.validate();
  return bem::hertz_contact(scene.c1, scene.c2,
                            (1 + material_.creep_ratio()) * material_.instantaneous_compliance(),
                            scene.load);
}

/// The common case: double precision, standard linear solid.
using BemSolverD = BemSolver<double, StandardLinearSolid<double>>;

// Compiled mode (docs/building.md): with VISCOROLL_COMPILED, which the CMake target
// viscoroll::compiled sets, the solvers below are instantiated once in that library (src/) and
// not in the including translation unit. Their entry points are defined out of the class (not
// inline), so that g++ does not instantiate them here for inlining either. Other instantiations
// are implicit, as in header-only mode.
#if defined(VISCOROLL_COMPILED)
extern template class BemSolver<float, StandardLinearSolid<float>>;
extern template class BemSolver<double, StandardLinearSolid<double>>;
extern template class BemSolver<long double, StandardLinearSolid<long double>>;
#endif

}  // namespace viscoroll
