// viscoroll: what the boundary-element solver (bem_solver.hpp) is given and what it returns: the
// scene (Eqs. 12, 13, 27), the runtime options, the grid of cells and the solution.
//
// Units and conventions: the roller moves towards +x; x is measured in the moving frame from the
// roller's lowest point; the gap profile h(x, y) (default C1 x^2/2 + C2 y^2/2) gives the paper's
// shape S = d - h (Eq. 27) and the gap g = u - S = u - d + h >= 0 (Eq. 13 in contact, g = 0).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>
#include <viscoroll/bem/hertz.hpp>
#include <viscoroll/core/along_roller.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/required_field.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll {

/// A rigid roller of curvatures c1 (across, x) and c2 (along, y) under total load `load`, rolling
/// towards +x at `speed`; `profile`, when set, replaces the doubly parabolic gap
/// h = c1 x^2/2 + c2 y^2/2 (S = d - h, Eq. 27). c1 and c2 still size the grid (the static Hertz
/// ellipse of the long-term compliance) and c1 enters chi (Eq. 51).
template <RealScalar Real>
struct BemScene {
  Real c1 = detail::required_field<Real>();      ///< curvature across the roller (x), 1/m
  Real c2 = detail::required_field<Real>();      ///< curvature along the roller (y), 1/m
  Real load = detail::required_field<Real>();    ///< total load P, N
  Real speed = detail::required_field<Real>();   ///< rolling speed V, m/s
  std::function<Real(Real, Real)> profile = {};  ///< h(x, y), or empty for the parabolic gap
  /// Where the roller's body ends along y (+-inf: it does not). The solver warns when the
  /// contact reaches a cell at an end; the gap beyond is the profile's (bem_scene() makes it a
  /// chamfer, bem_profile.hpp).
  Real y_min = -std::numeric_limits<Real>::infinity();
  /// The body's end on the side y > 0 (+inf: none).
  Real y_max = std::numeric_limits<Real>::infinity();

  /// Throws std::invalid_argument naming the parameter unless c1 > 0, c2 > 0, 1e-10 <= c2/c1 <=
  /// 1e10, load > 0, speed >= 0, all finite, and y_min < 0 < y_max (not NaN). (The profile's
  /// values are checked by BemSolver::solve, at the cell centres of its grid.)
  void validate() const {
    detail::require_positive("c1", c1);
    detail::require_positive("c2", c2);
    detail::require(c2 / c1 >= Real(1e-10) && c2 / c1 <= Real(1e10), "c2/c1", c2 / c1,
                    "1e-10 <= c2/c1 <= 1e10");
    detail::require_positive("load", load);
    detail::require_non_negative("speed", speed);
    detail::require(y_min < 0, "y_min", y_min, "y_min < 0 (the body holds the section y = 0)");
    detail::require(y_max > 0, "y_max", y_max, "y_max > 0 (the body holds the section y = 0)");
  }
  /// "c1 = ..., c2 = ..., load = ..., speed = ...": the scene in an error's message.
  std::string describe() const {
    return "c1 = " + detail::format_value(c1) + ", c2 = " + detail::format_value(c2) +
           ", load = " + detail::format_value(load) + ", speed = " + detail::format_value(speed);
  }

  /// h(x, y): the profile, or c1 x^2/2 + c2 y^2/2.
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
  /// The accuracy asked of d and chi, relative (docs/theory.md, section 17): 0 solves once on
  /// `grid`; a tolerance in [1e-4, 0.5] solves on `grid`, 2 grid, 4 grid, ... elements up to
  /// `max_grid`, each grid after the first sized across by the contact the one before found,
  /// until, on the third converged grid or later, the estimated errors of d and of chi
  /// (BemErrorEstimate) are at most `tolerance` times |d| and |chi| (chi's: or 1e-6 C1 a_H, a_H
  /// the long-term Hertz semi-axis, when |chi| is below that), and returns the last grid's
  /// solution with the estimates
  /// (BemSolution::error, tolerance_met; a warning when the tolerance is not met).
  double tolerance = 0;
  /// The largest grid of the refinement `tolerance` asks for (elements per semi-axis).
  int max_grid = 128;
  /// GMRES stops at relative residual `gmres_tolerance` (or 32 eps of the scalar, if larger);
  /// the active set must then be unchanged.
  double gmres_tolerance = 1e-10;
  /// The largest number of active-set iterations.
  int max_active_set_iterations = 200;
  int max_krylov_iterations = 5000;  ///< GMRES steps over all active-set iterations
  int restart = 80;                  ///< GMRES steps per cycle
  /// GMRES' relative residual while the active set changes (numerics/active_set.hpp, inexact
  /// early solves); the set that one leaves unchanged is solved again to `gmres_tolerance`, which
  /// alone decides convergence. 0 solves every set to `gmres_tolerance`.
  double coarse_tolerance = 1e-3;
  /// GMRES' relative residual of a final solve of the converged active set (or 32 eps of the
  /// scalar, if larger; numerics/active_set.hpp): GMRES' `gmres_tolerance` bounds the pressure to
  /// about cond times it (a(0) and the peak pressure to about 1e-8 at 1e-10), and two iterations
  /// that reach the same set differently (coarse_tolerance or not) differ by that much; solved
  /// again to 1e-13, they agree to 1e-10 (docs/bem.md, B11). 0 (or >= gmres_tolerance): no final
  /// solve.
  double final_tolerance = 1e-13;
  /// Threads that build the influence table (its rows are independent; the result does not
  /// depend on the count). 1 leaves the other cores to a sweep over speeds.
  int threads = 1;
  /// Right-precondition GMRES with the inverse of the continuum symbol (B11).
  bool precondition = true;

  /// The most cells a grid may have, (2 ceil(extent grid) + 1)^2: the padded transforms then
  /// take 4 x 16 bytes per cell per complex array (about 270 MB in double).
  static constexpr long long max_cells = 1LL << 22;

  /// Throws std::invalid_argument naming the first option out of its range.
  void validate() const {
    detail::require(grid >= 2 && grid <= 4096, "grid", grid, "2 <= grid <= 4096");
    detail::require(extent >= 1.6 && extent <= 64, "extent", extent, "1.6 <= extent <= 64");
    const long long side = 2 * static_cast<long long>(std::ceil(extent * grid - 1e-9)) + 1;
    detail::require(side * side <= max_cells, "grid", grid,
                    "(2 ceil(extent grid) + 1)^2 <= 4194304 cells (grid <= 639 at extent = " +
                        detail::format_value(extent) + ": " + std::to_string(side * side) +
                        " cells asked)");
    detail::require(tolerance == 0 || (tolerance >= 1e-4 && tolerance <= 0.5), "tolerance",
                    tolerance, "0 (one grid) or 1e-4 <= tolerance <= 0.5");
    if (tolerance > 0) {
      detail::require(max_grid >= grid && max_grid <= 4096, "max_grid", max_grid,
                      "grid <= max_grid <= 4096 (grid = " + std::to_string(grid) + ")");
      const long long top = 2 * static_cast<long long>(std::ceil(extent * max_grid - 1e-9)) + 1;
      detail::require(top * top <= max_cells, "max_grid", max_grid,
                      "(2 ceil(extent max_grid) + 1)^2 <= 4194304 cells (" +
                          std::to_string(top * top) + " cells asked)");
    }
    detail::require(gmres_tolerance >= 1e-15 && gmres_tolerance <= 1e-3, "gmres_tolerance",
                    gmres_tolerance, "1e-15 <= gmres_tolerance <= 1e-3");
    detail::require(coarse_tolerance == 0 || (coarse_tolerance >= 1e-15 && coarse_tolerance <= 0.1),
                    "coarse_tolerance", coarse_tolerance,
                    "0 (off) or 1e-15 <= coarse_tolerance <= 0.1");
    detail::require(final_tolerance == 0 || (final_tolerance >= 1e-15 && final_tolerance <= 1e-3),
                    "final_tolerance", final_tolerance,
                    "0 (off) or 1e-15 <= final_tolerance <= 1e-3");
    detail::require(threads >= 1 && threads <= 1024, "threads", threads, "1 <= threads <= 1024");
    detail::require(max_active_set_iterations >= 1 && max_active_set_iterations <= 100000,
                    "max_active_set_iterations", max_active_set_iterations,
                    "1 <= max_active_set_iterations <= 100000");
    detail::require(max_krylov_iterations >= 1 && max_krylov_iterations <= 10000000,
                    "max_krylov_iterations", max_krylov_iterations,
                    "1 <= max_krylov_iterations <= 10000000");
    detail::require(restart >= 2 && restart <= 1000, "restart", restart, "2 <= restart <= 1000");
  }
};

/// A uniform grid of nx x ny cells hx x hy, centred on the origin (nx, ny odd, so a row of cell
/// centres lies on y = 0 and a column on x = 0). Cell (i, j) has centre
/// ((i - (nx-1)/2) hx, (j - (ny-1)/2) hy); the flat index is i + nx j.
///   - x(i), y(j): the centre of column i, of row j;
///   - size(): nx ny; index(i, j): i + nx j.
template <RealScalar Real>
struct BemGrid {
  /// The cells per row (x) and per column (y), odd.
  ///@{
  int nx, ny;
  ///@}
  /// The cell's size along x and along y.
  ///@{
  Real hx, hy;
  ///@}

  /// The centre of column i.
  Real x(int i) const { return Real(i - (nx - 1) / 2) * hx; }
  /// The centre of row j.
  Real y(int j) const { return Real(j - (ny - 1) / 2) * hy; }
  /// nx ny, the number of cells.
  std::size_t size() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  /// The flat index of cell (i, j): i + nx j.
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * static_cast<std::size_t>(j);
  }
};

namespace bem {

/// (B12): where a square-root pressure edge lies beyond the last contact cell, in cells from its
/// centre: p^2 (linear in the distance to the edge) extrapolated from the last two cells'
/// pressures to zero, within the cell beyond; half a cell when that is not defined.
template <RealScalar Real>
Real edge_offset(Real p_last, Real p_prev) {
  const Real a = p_last * p_last, b = p_prev * p_prev;
  if (!(b > a)) return Real(1) / 2;
  return std::min(a / (b - a), Real(1));
}

/// The contact of one grid row: its largest pressure and, when that is positive, the trailing
/// and leading edges of the stretch of contact cells around it, by edge_offset (B12).
template <RealScalar Real>
struct RowContact {
  Real p_max = 0;  ///< the row's largest pressure (first cell of several)
  ///@{
  Real trailing = 0, leading = 0;  ///< the edges; both 0 when p_max <= 0
  ///@}
};

/// RowContact of row j of the cell pressures p on grid g.
template <RealScalar Real>
RowContact<Real> row_contact(const BemGrid<Real>& g, const std::vector<Real>& p, int j) {
  const auto at = [&](int i) { return p[g.index(i, j)]; };
  int peak = 0;
  for (int i = 0; i < g.nx; ++i)
    if (at(i) > at(peak)) peak = i;
  if (!(at(peak) > 0)) return {};
  int lead = peak, trail = peak;
  while (lead + 1 < g.nx && at(lead + 1) > 0) ++lead;
  while (trail > 0 && at(trail - 1) > 0) --trail;
  const bool wide = lead > trail;
  return {
      .p_max = at(peak),
      .trailing = g.x(trail) - g.hx * (wide ? edge_offset(at(trail), at(trail + 1)) : Real(1) / 2),
      .leading = g.x(lead) + g.hx * (wide ? edge_offset(at(lead), at(lead - 1)) : Real(1) / 2)};
}

}  // namespace bem

/// The estimated discretisation errors of a boundary-element solution refined to a tolerance
/// (BemOptions::tolerance): each 5/4 of the change of its quantity from the grid before (cells
/// at least twice as large), or of half the change before that when larger, which bounds the
/// error of an O(h^p), p >= 1, convergence with a margin (docs/theory.md, section 17,
/// (E1)-(E3)); a0, b0 and l, edges located to a fraction of a cell (B12), add a quarter of the
/// cell (hx, hy). Absolute, in the quantity's units; NaN where not estimated.
template <RealScalar Real>
struct BemErrorEstimate {
  /// Of the penetration d.
  Real d = std::numeric_limits<Real>::quiet_NaN();
  /// Of the rolling friction coefficient chi.
  Real chi = std::numeric_limits<Real>::quiet_NaN();
  /// Of the half width a(0).
  Real a0 = std::numeric_limits<Real>::quiet_NaN();
  /// Of the offset b(0).
  Real b0 = std::numeric_limits<Real>::quiet_NaN();
  /// Of the half length l.
  Real l = std::numeric_limits<Real>::quiet_NaN();
  Real p_max = std::numeric_limits<Real>::quiet_NaN();  ///< of peak_pressure()
};

/// The boundary-element solution: pressure on the grid, the contact's measures, diagnostics.
template <RealScalar Real>
struct BemSolution {
  /// The grid the solution was computed on.
  BemGrid<Real> grid;
  std::vector<Real> pressure;  ///< cell pressures, flat index i + nx j (grid.index)
  std::vector<Real> gap;  ///< g = u - d + h at the cell centres (0 in contact to the tolerance)
  Real d;                 ///< penetration (Eq. 27); on a layer or bed, from its base (B15)
  Real a0;                ///< a(0): half width of the contact on y = 0 (B12, sub-cell)
  Real b0;                ///< b(0): offset of its centre ahead of the roller (Eq. 29)
  Real l;                 ///< half length of the contact (B12, sub-cell)
  Real chi;               ///< rolling friction C1 int x p / int p (Eq. 51)
  Real load;              ///< hx hy sum p (equals the scene's load to the tolerance)
  /// The static Hertz contact of the long-term compliance (on a substrate, of that compliance
  /// times the sizing factor of (B19): the estimate that sized the grid)
  bem::HertzContact<Real> long_term;
  int contact_cells;   ///< cells with p > 0
  bool converged;      ///< every claimed quantity holds to the tolerance (else see reason)
  std::string reason;  ///< "converged", or why not
  StopCode code = StopCode::converged;  ///< why it stopped, as a code (core/outcome.hpp)
  int iterations;                       ///< active-set iterations
  int krylov_iterations;                ///< GMRES steps over all active-set iterations
  Real residual;                        ///< max complementarity violation relative to d (B11)
  /// Quantities the solution does not claim although it converged (B12's edge model violated),
  /// and a tolerance the refinement did not meet.
  std::vector<std::string> warnings;
  std::vector<WarningCode> warning_codes;  ///< the warnings' codes, index for index
  int elements;  ///< elements per semi-axis of `grid` (BemOptions::grid, or the refinement's)
  /// The estimated discretisation errors (absolute; NaN where not estimated: one grid).
  BemErrorEstimate<Real> error;
  /// BemOptions::tolerance > 0 and the estimates of d and chi met it.
  bool tolerance_met;
  double seconds_setup;  ///< influence table and its transform
  double seconds_solve;  ///< active-set iteration

  /// The pressure of cell (i, j).
  Real p(int i, int j) const { return pressure[grid.index(i, j)]; }

  /// The largest cell pressure (the first of equal ones; 0 without cells).
  Real peak_pressure() const {
    return pressure.empty() ? Real(0) : *std::max_element(pressure.begin(), pressure.end());
  }

  /// The contact along the roller, row by row: F0 = hx sum_i p (the midpoint rule of Eq. 33 on
  /// the cells), the edges of each row's contact (the stretch of contact cells around the row's
  /// peak) by (B12)'s square-root extrapolation, and the ends y_minus, y_plus by extrapolating
  /// F0 linearly to zero from the last two loaded rows (F0 ~ a^2 vanishes linearly at a
  /// square-root tip, Eq. 48), within the row beyond. Error: of order hx in a, b and hy in the
  /// ends (docs/bem.md, B12). Empty when no cell is loaded.
  AlongRoller<Real> along_roller() const {
    AlongRoller<Real> out;
    const auto at = [&](int i, int j) { return pressure[grid.index(i, j)]; };
    std::vector<Real> row(static_cast<std::size_t>(grid.ny), Real(0));
    int first = -1, last = -1;
    for (int j = 0; j < grid.ny; ++j) {
      for (int i = 0; i < grid.nx; ++i)
        row[static_cast<std::size_t>(j)] += std::max(at(i, j), Real(0));
      if (row[static_cast<std::size_t>(j)] > 0) {
        if (first < 0) first = j;
        last = j;
      }
    }
    if (first < 0) return out;
    for (int j = first; j <= last; ++j) {
      const auto c = bem::row_contact(grid, pressure, j);
      out.y.push_back(grid.y(j));
      out.f0.push_back(grid.hx * row[static_cast<std::size_t>(j)]);
      out.p_max.push_back(c.p_max);
      out.a.push_back((c.leading - c.trailing) / 2);
      out.b.push_back((c.leading + c.trailing) / 2);
    }
    // F0 vanishes linearly at a square-root tip: its zero from the last two rows, within the row
    // beyond (half a row when the rows do not fall towards the end).
    const auto tip = [&](int j, int inner) {
      const Real f_end = row[static_cast<std::size_t>(j)];
      const Real f_in =
          inner >= first && inner <= last ? row[static_cast<std::size_t>(inner)] : Real(0);
      return f_in > f_end ? std::min(f_end / (f_in - f_end), Real(1)) : Real(1) / 2;
    };
    out.y_plus = grid.y(last) + grid.hy * tip(last, last - 1);
    out.y_minus = grid.y(first) - grid.hy * tip(first, first + 1);
    const auto peak = std::max_element(out.f0.begin(), out.f0.end());
    out.f0_max = *peak;
    out.f0_max_y = out.y[static_cast<std::size_t>(peak - out.f0.begin())];
    return out;
  }
};

}  // namespace viscoroll
