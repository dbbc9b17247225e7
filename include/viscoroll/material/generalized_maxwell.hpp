// viscoroll: a generalised Maxwell (Prony series) half space, the multi-time generalisation of
// the standard linear solid of Panek & Kalker (1980), Eq. (1).
//
// Creep in shear under a constant stress sigma applied at t = 0:
//   e(t) = sigma / mu_D [1 + sum_k f_k (1 - exp(-t / tau_k))] H(t)       (docs/bem.md (B9),
//                                                                          docs/theory.md (R2))
// Hunter's steady-state superposition that gives Eq. (2) applies term by term, so the moving-frame
// displacement is u = u_e + sum_k f_k int_0^inf e^(-eta) u_e(x + V tau_k eta, y) d eta (B10).
// One term (f_1, tau_1) is the standard linear solid (f, tau).
//
// GeneralizedMaxwell<Real>(mu_d, nu, {{f, tau}, ...}) is PronyCreep<Real> of
// material/prony.hpp, the creep (retardation) form; the relaxation form G(t) = G_inf +
// sum g_i exp(-t / rho_i) is PronyRelaxation<Real>, and each converts exactly into the other.
// Its memory_terms() are a run-time list (memory_term_count = dynamic_memory_terms): not a
// SingleTimeModel, so the plane and the line solver take their spectrum theories for it
// (docs/theory.md sections 12 and 14); the BemSolver sums its memory terms.
#pragma once

#include <viscoroll/material/prony.hpp>

namespace viscoroll {

/// The creep form of a generalised Maxwell solid: PronyCreep (material/prony.hpp).
template <RealScalar Real>
using GeneralizedMaxwell = PronyCreep<Real>;

}  // namespace viscoroll
