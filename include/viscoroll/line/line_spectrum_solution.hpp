// viscoroll: the solution of the line solver for a material with a spectrum
// (line_solver.hpp over PronyCreep, PronyRelaxation or GeneralizedMaxwell; docs/theory.md
// section 14): the contact, the strips' moments gamma = G0/a^2 and kappa (S14) that carry F0 and
// F1 to the line integrals, and the standard linear solid's solution where one term is active.
// The residual that determines them is line_spectrum.hpp's.
#pragma once

#include <algorithm>
#include <limits>
#include <optional>
#include <string>
#include <vector>
#include <viscoroll/core/along_roller.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/line/line_shape.hpp>
#include <viscoroll/line/line_solution.hpp>

namespace viscoroll {

/// The functions gamma(y) = G0/a^2 and kappa(y)/a_ref of the spectrum's line solution,
/// Chebyshev series in u = 2 t^2 - 1, t = (y - c)/l (docs/theory.md (S14)): even, plus for an
/// asymmetric contact the odd parts t sum gamma_odd_k T_k(u), t sum kappa_odd_k T_k(u) (as
/// line_shape.hpp's; empty otherwise).
template <RealScalar Real>
struct LineSpectrumMoments {
  /// The even Chebyshev coefficients of gamma = G0/a^2 and kappa/a_ref.
  ///@{
  std::vector<Real> gamma, kappa;
  ///@}
  /// The odd parts' coefficients (empty for a symmetric contact).
  ///@{
  std::vector<Real> gamma_odd{}, kappa_odd{};
  ///@}
  /// The even part of gamma at u.
  Real gamma_at(Real u) const { return LineShape<Real>::chebyshev(gamma, u); }
  /// The even part of kappa/a_ref at u.
  Real kappa_at(Real u) const { return LineShape<Real>::chebyshev(kappa, u); }
  /// gamma and kappa/a_ref at u with their odd parts at t.
  Real gamma_at(Real u, Real t) const {
    if (gamma_odd.empty()) return gamma_at(u);
    return gamma_at(u) + t * LineShape<Real>::chebyshev(gamma_odd, u);
  }
  /// kappa/a_ref at u with its odd part at t.
  Real kappa_at(Real u, Real t) const {
    if (kappa_odd.empty()) return kappa_at(u);
    return kappa_at(u) + t * LineShape<Real>::chebyshev(kappa_odd, u);
  }
};

/// The line-contact solution for a material with a spectrum (LineSolver over PronyCreep,
/// PronyRelaxation or GeneralizedMaxwell): the contact zone, the penetration, F0(y) and the
/// rolling friction. With one memory term active at the scene's speed (the others relaxed, folded
/// into the compliance, or not started, dropped) it is the standard linear solid's solution
/// (`single`); with none, the static closed form.
template <RealScalar Real, class Quadrature>
struct LineSpectrumSolution {
  LineShape<Real> shape;              ///< a(y), b(y), l
  LineSpectrumMoments<Real> moments;  ///< gamma = G0/a^2 and kappa/a_ref (two or more terms)
  Real d;                             ///< penetration (Eq. 27)
  Real a_long_term;                   ///< a0: half width at y = 0 of the static contact, c (1 + F)
  Real l_long_term;                   ///< l0: its half length
  Real d_long_term;                   ///< its penetration
  Real chi;                           ///< rolling-friction coefficient C1 xbar (Eq. 51), (S15)
  bool converged;                     ///< the iteration met its tolerance (true for a closed form)
  bool root;                          ///< max |r| <= 64 sqrt(eps)
  std::string reason;                 ///< why it stopped
  StopCode code = StopCode::converged;     ///< why it stopped, as a code (core/outcome.hpp)
  int iterations;                          ///< Levenberg-Marquardt iterations (0 for a closed form)
  Real residual;                           ///< max |r| of the scaled equations
  std::vector<std::string> warnings;       ///< what qualifies the result, in words
  std::vector<WarningCode> warning_codes;  ///< the warnings' codes, index for index
  int active_terms;  ///< memory terms solved for at this speed (after merging near-equal times)
  /// Bound on the relative change of the complex compliance made by merging near-equal times
  /// (docs/theory.md (S19), (S20)) plus the share of the terms folded into the compliance or
  /// dropped as acting relaxed or glassy (S21), at most line_spectrum_budget(); 0 if neither.
  Real spectrum_error{};
  /// C1 of the scene.
  Real c1;
  /// The long-term compliance of the terms solved for, c (1 + relaxed)(1 + F') (Eq. 47 with
  /// (52): F0 integrates to it times the load); f0_per_load() reads it.
  Real load_compliance{};
  /// The standard linear solid's solution where exactly one term is active.
  std::optional<LineSolution<Real, Quadrature>> single;

  /// F0(y) per unit load per length: the long-term compliance of the terms solved for.
  Real f0_per_load() const { return single ? single->f0_per_load() : load_compliance; }

  /// The contact along the roller at `stations` evenly spaced points inside (y_minus, y_plus),
  /// as LineSolution::along_roller: the load per unit length F0(y)/f0_per_load(), a(y), b(y); the
  /// strip's peak pressure where one term is active (`single`), else NaN (the strip of a spectrum
  /// in the line theory is carried by its moments, not by a pressure, docs/theory.md (S14)).
  AlongRoller<Real> along_roller(int stations = 65) const {
    if (single) return single->along_roller(stations);
    AlongRoller<Real> out;
    out.y_minus = y_minus();
    out.y_plus = y_plus();
    const int n = std::max(stations, 1);
    for (int k = 1; k <= n; ++k) {
      const Real y = shape.centre + shape.l * (Real(2 * k) / Real(n + 1) - 1);
      out.y.push_back(y);
      out.f0.push_back(f0(y) / load_compliance);
      out.a.push_back(shape.a(y));
      out.b.push_back(shape.b(y));
      out.p_max.push_back(std::numeric_limits<Real>::quiet_NaN());
      if (out.f0.back() > out.f0_max) {
        out.f0_max = out.f0.back();
        out.f0_max_y = y;
      }
    }
    return out;
  }

  /// The contact's half length l.
  Real l() const { return shape.l; }
  /// The contact's ends c - l and c + l (-l and l for a symmetric contact).
  Real y_minus() const { return shape.centre - shape.l; }
  /// c + l.
  Real y_plus() const { return shape.centre + shape.l; }
  /// The half width a(y) of the contact.
  Real a(Real y) const { return shape.a(y); }
  /// b(y), the offset of the contact's centre ahead of the roller's axis.
  Real b(Real y) const { return shape.b(y); }
  /// F0(y) = C1 a^2 (1/4 + G0/(2 a^2)), Eq. (33) with (S8): the load per unit length times the
  /// long-term compliance of the terms solved for.
  Real f0(Real y) const {
    if (single) return single->f0(y);
    const Real a = shape.a(y);
    if (!(a > 0)) return Real(0);
    if (moments.gamma.empty()) return c1 * a * a / 4;
    const Real u = LineShape<Real>::coordinate(shape.basis, shape.scale, shape.one_minus_t2(y));
    return c1 * a * a * (Real(1) / 4 + moments.gamma_at(u, shape.t_at(y)) / 2);
  }
};

}  // namespace viscoroll
