// viscoroll: a primal-dual active-set solver (a semismooth Newton method: Hintermueller, Ito &
// Kunisch, SIAM J. Optim. 13 (2003) 865) for a contact's complementarity problem with a bordered
// load equation. Over n unknowns p (pressures) and one d (the approach), with an operator K that
// need not be symmetric, it finds
//   g = K p - d + h >= 0,  p >= 0,  p_q g_q = 0 for every q,  w sum_q p_q = P.
// Each iteration takes an active set A (the unknowns in contact), sets p = 0 off A and solves the
// system restricted to A and bordered by the load equation (docs/bem.md, (B11)),
//   (K p)_A - d = -h_A,  s w sum_A p / P = s,                                        (AS1)
// by right-preconditioned restarted GMRES (numerics/gmres.hpp), then updates the set from the
// new p and the gap g everywhere,
//   A <- {q in A : p_q > 0} + {q not in A : g_q < -tol s},                           (AS2)
// and stops when A no longer changes. The scale s (a displacement) puts the load row in the units
// of the others and sets the gap tolerance.
// Inexact early solves (an inexact semismooth Newton method): with a coarse tolerance set, (AS1)
// is solved only to it while A changes; once a coarse solve leaves A unchanged, the same A is
// solved again to the tolerance, and the iteration stops only when that tight solve leaves A
// unchanged. The stopping test is the exact one, so the result is that of the exact iteration to
// the tolerance; the early sets, far from the final one, cost fewer GMRES steps.
// A final solve: GMRES' relative residual bounds p only to about cond(AS1) times it, and two
// iterations that reach the same final set from different iterates (coarse early solves or not)
// differ by that much. With a final tolerance set, the set that a solve leaves unchanged (a tight
// one, or a coarse one directly) is solved once more to it from there, and the iteration stops
// when that solve leaves the set unchanged: both then give the solution of the final set to the
// final tolerance's effect. The final solve runs one GMRES cycle at a time while each cycle at
// least halves the residual; should it stall above the final tolerance (GMRES' attainable
// residual being above it), the solve counts if it reached the tolerance, and otherwise the set is
// solved again to the tolerance without a final solve.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstddef>
#include <limits>
#include <set>
#include <string>
#include <vector>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/numerics/gmres.hpp>

namespace viscoroll::numerics {

/// The operator of the complementarity problem over n unknowns. An operator K provides
///   - `void apply(const std::vector<Real>& p, std::vector<Real>& u) const`: u = K p (n entries
///     each);
///   - `void precondition(const std::vector<Real>& v, std::vector<Real>& out) const`: out = M v,
///     an approximate inverse of K (or out = v). The solver applies it to vectors that vanish off
///     the active set and keeps the active entries of the result: the right preconditioner of
///     (AS1) is M restricted to A, the identity on d.
template <class Op, class Real>
concept ContactOperator = requires(const Op& op, const std::vector<Real>& in,
                                   std::vector<Real>& out) {
  op.apply(in, out);
  op.precondition(in, out);
};

/// The load equation w sum_q p_q = P and the scale s of d (AS1).
template <class Real>
struct LoadEquation {
  Real weight;  ///< w, e.g. the area of a cell
  Real total;   ///< P, the prescribed total
  Real scale;   ///< s > 0, a typical d: the load row's factor and the gap tolerance's unit
};

/// Limits and tolerance of the iteration.
template <class Real>
struct ActiveSetSettings {
  Real tolerance;      ///< GMRES' relative residual; the gap tolerance of (AS2) in units of s
  int restart;         ///< GMRES steps per cycle
  int max_iterations;  ///< active-set iterations
  int max_krylov_iterations;  ///< GMRES steps over all active-set iterations
  /// GMRES' relative residual while A changes (see above); 0 or <= tolerance: every solve to the
  /// tolerance.
  Real coarse_tolerance = 0;
  /// GMRES' relative residual of the final solve of the set that no longer changes (see above); 0
  /// or >= tolerance: none, the last solve to the tolerance.
  Real final_tolerance = 0;
};

/// The iterate: on entry the starting guess, on exit the last iterate.
template <class Real>
struct ActiveSetState {
  std::vector<Real> p;       ///< n unknowns; max(p_q, 0) of the active q start GMRES
  Real d;                    ///< the approach, the load equation's multiplier
  std::vector<char> active;  ///< n flags: q in A
};

/// What active_set() did.
struct ActiveSetReport {
  bool converged = false;  ///< A unchanged by (AS2) after a converged GMRES solve
  /// "converged", "active-set iteration limit", "empty contact set", "active set cycles" (a set
  /// seen before: the iteration would repeat) or "GMRES did not converge (relative residual r)".
  std::string reason = "active-set iteration limit";
  StopCode code = StopCode::iteration_limit;  ///< `reason` as a code (core/outcome.hpp)
  int iterations = 0;                         ///< active-set iterations (systems (AS1) solved)
  int krylov_iterations = 0;                  ///< GMRES steps over all of them
};

/// Solves the complementarity problem of operator `op`, gap offset h (n values) and load equation
/// `load` from `state`, which it leaves at the last iterate (p = 0 off the last active set).
template <class Real, ContactOperator<Real> Op>
ActiveSetReport active_set(const Op& op, const std::vector<Real>& h, const LoadEquation<Real>& load,
                           const ActiveSetSettings<Real>& settings, ActiveSetState<Real>& state) {
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  const std::size_t n = h.size();
  std::vector<Real>& p = state.p;
  std::vector<char>& active = state.active;
  std::vector<Real> u(n), full(n), tmp(n);
  std::vector<std::size_t> cells;
  std::set<std::vector<std::size_t>> seen;
  ActiveSetReport report;
  bool coarse = settings.coarse_tolerance > settings.tolerance;
  bool polish = settings.final_tolerance > 0 && settings.final_tolerance < settings.tolerance;
  bool last = false;  // this solve is the final one, to final_tolerance
  for (; report.iterations < settings.max_iterations; ++report.iterations) {
    cells.clear();
    for (std::size_t q = 0; q < n; ++q)
      if (active[q]) cells.push_back(q);
    if (cells.empty()) {
      report.reason = "empty contact set";
      report.code = StopCode::empty_contact;
      break;
    }
    if (!seen.insert(cells).second) {
      if (!coarse) {
        report.reason = "active set cycles";
        report.code = StopCode::active_set_cycles;
        break;
      }
      // A coarse iterate returned to a set: from here on every solve is tight.
      coarse = false;
      seen.clear();
      seen.insert(cells);
    }
    const Eigen::Index na = static_cast<Eigen::Index>(cells.size());
    const auto cell = [&](Eigen::Index k) { return cells[static_cast<std::size_t>(k)]; };
    // (AS1): unknowns y = [p_A, d].
    const auto apply_a = [&](const auto& x, Vector& out) {
      std::fill(full.begin(), full.end(), Real(0));
      for (Eigen::Index k = 0; k < na; ++k) full[cell(k)] = x[k];
      op.apply(full, tmp);
      Real sum = 0;
      for (Eigen::Index k = 0; k < na; ++k) {
        out[k] = tmp[cell(k)] - x[na];
        sum += x[k];
      }
      out[na] = load.scale * load.weight * sum / load.total;
    };
    const auto apply_m = [&](const auto& x, Vector& out) {
      out.resize(na + 1);
      std::fill(full.begin(), full.end(), Real(0));
      for (Eigen::Index k = 0; k < na; ++k) full[cell(k)] = x[k];
      op.precondition(full, tmp);
      for (Eigen::Index k = 0; k < na; ++k) out[k] = tmp[cell(k)];
      out[na] = x[na];
    };
    Vector b(na + 1), x(na + 1);
    for (Eigen::Index k = 0; k < na; ++k) {
      b[k] = -h[cell(k)];
      x[k] = std::max(p[cell(k)], Real(0));
    }
    b[na] = load.scale;
    x[na] = state.d;
    const Real tolerance = last     ? settings.final_tolerance
                           : coarse ? settings.coarse_tolerance
                                    : settings.tolerance;
    const int budget = settings.max_krylov_iterations - report.krylov_iterations;
    GmresReport rep;
    if (!last) {
      rep = gmres<Real>(apply_a, apply_m, b, x, tolerance, settings.restart, budget);
    } else {
      // The final solve, one GMRES cycle at a time while each at least halves the residual: it
      // stops where rounding stalls GMRES above the final tolerance.
      double before = std::numeric_limits<double>::infinity();
      while (true) {
        const auto cycle = gmres<Real>(apply_a, apply_m, b, x, tolerance, settings.restart,
                                       std::min(settings.restart, budget - rep.iterations));
        rep.iterations += cycle.iterations;
        rep.converged = cycle.converged;
        rep.relative_residual = cycle.relative_residual;
        if (rep.converged || rep.iterations >= budget || !(rep.relative_residual < before / 2))
          break;
        before = rep.relative_residual;
      }
    }
    report.krylov_iterations += rep.iterations;
    std::fill(p.begin(), p.end(), Real(0));
    for (Eigen::Index k = 0; k < na; ++k) p[cell(k)] = x[k];
    state.d = x[na];
    if (!rep.converged && last &&
        !(rep.relative_residual <= static_cast<double>(settings.tolerance))) {
      // The final tolerance out of reach, and the tolerance not met: solve the set again to it,
      // from here, with no final solve.
      last = polish = false;
      seen.erase(cells);
      continue;
    }
    if (!rep.converged && !last) {
      // format_value, not std::to_string: "%f" printed a residual of 3e-7 as 0.000000.
      report.code = StopCode::linear_solver_failed;
      report.reason = "GMRES did not converge (relative residual " +
                      detail::format_value(rep.relative_residual) + ")";
      ++report.iterations;
      break;
    }
    // (AS2) from the gap everywhere.
    op.apply(p, u);
    bool changed = false;
    const Real gap_tol = settings.tolerance * load.scale;
    for (std::size_t q = 0; q < n; ++q) {
      const Real g = u[q] - state.d + h[q];
      const bool now = active[q] ? p[q] > 0 : g < -gap_tol;
      if (now != static_cast<bool>(active[q])) changed = true;
      active[q] = now;
    }
    if (!changed && coarse) {
      // The set of a coarse solve: solve it again to the tolerance, or to the final one.
      coarse = false;
      last = polish;
      seen.erase(cells);
      continue;
    }
    if (!changed && polish && !last) {
      // The set of a tight solve: solve it again to the final tolerance.
      last = true;
      seen.erase(cells);
      continue;
    }
    // A final solve that changed the set: the next sets to the tolerance, then a final solve.
    if (changed) last = false;
    if (!changed) {
      report.converged = true;
      report.reason = "converged";
      report.code = StopCode::converged;
      ++report.iterations;
      break;
    }
  }
  return report;
}

}  // namespace viscoroll::numerics
