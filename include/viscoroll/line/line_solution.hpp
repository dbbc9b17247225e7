// viscoroll: the line-contact solution (Panek & Kalker 1980, Sections 5 and 6): the contact zone
// a(y), b(y), l, the penetration, the strip at each y and the rolling friction, as LineSolver
// (line_solver.hpp) returns it; and the warnings of the line theory's domain of validity.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>
#include <viscoroll/core/along_roller.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/line/line_shape.hpp>

namespace viscoroll {

namespace line {

/// The budget of docs/theory.md (S21): a spectrum's fastest and slowest terms whose share of the
/// dissipation (and of the penetration) is within 1e-3 in all are folded into the compliance or
/// dropped by the line method, a tenth of its stated error against the exact solution (1% in d
/// and chi).
template <class Real>
Real line_spectrum_budget() {
  return Real(1e-3);
}

}  // namespace line

/// The line-contact solution, for any material: the contact zone, the penetration, the line
/// functions of Section 5 and the rolling friction of Section 6. A material with one memory term
/// active at the scene's speed (a standard linear solid, or a spectrum whose other terms are
/// relaxed, folded into the compliance, or not started, dropped) has the paper's strips (32),
/// (35): pressure(), strip() and q(). With two or more active terms (docs/theory.md section 14)
/// the strips are carried by their moments gamma = G0/a^2 and kappa (S14), not by a pressure:
/// has_pressure() is false, and pressure(), strip() and q() are not available.
template <RealScalar Real, class Quadrature>
struct LineSolution {
  LineShape<Real> shape;  ///< a(y), b(y), l
  Real d;                 ///< penetration (Eq. 27)
  Real a_long_term;       ///< a0: half width at y = 0 of the static (V tau = 0) contact
  Real l_long_term;       ///< l0: its half length
  Real d_long_term;       ///< its penetration
  Real chi;        ///< rolling-friction coefficient, Eq. (54) in the form of section 4, (S15)
  bool converged;  ///< the iteration met its tolerance (always true for a closed form)
  /// The residual vanishes (max |r| <= 64 sqrt(eps)): a root of the line equations. False with
  /// converged at a certified least-squares minimum where the equations have no root (the
  /// residual is then reported, and a warning says so).
  bool root;
  std::string reason;                   ///< why it stopped
  StopCode code = StopCode::converged;  ///< why it stopped, as a code (core/outcome.hpp)
  int iterations;                       ///< Levenberg-Marquardt iterations (0 for a closed form)
  Real residual;                      ///< max |r| of the scaled equations at the returned solution
  std::vector<std::string> warnings;  ///< outside the line theory's domain of validity
  std::vector<WarningCode> warning_codes;  ///< the warnings' codes, index for index

  /// C1, V tau, f and the instantaneous compliance (1 - nu)/(2 pi mu_D) of the one active term:
  /// what strip() needs (V tau = f = 0 with none active or with two or more).
  ///@{
  Real c1, vtau, f, compliance;
  ///@}
  /// gamma = G0/a^2 and kappa/a_ref with two or more active terms (S14); empty otherwise.
  LineSpectrumMoments<Real> moments{};
  /// Memory terms solved for at this speed: 0 for an elastic, static or glassy contact, 1 for the
  /// paper's theory, the count after merging near-equal times for a spectrum.
  int active_terms = 0;
  /// Bound on the relative change of the complex compliance made by merging near-equal times
  /// (docs/theory.md (S19), (S20)) plus the share of the terms folded into the compliance or
  /// dropped as acting relaxed or glassy (S21), at most line_spectrum_budget(); 0 if neither
  /// (always 0 for a material with one memory term).
  Real spectrum_error{};
  /// The long-term compliance of the terms solved for, c (1 + f) (Eq. 47 with (52): F0 integrates
  /// to it times the load); f0_per_load() reads it.
  Real load_compliance{};

  /// The strips have the paper's pressure (35): at most one memory term active.
  bool has_pressure() const { return moments.gamma.empty(); }
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
  /// G(y) of Eq. (36), G0 = gamma a^2 of (S8) with two or more active terms; 0 for a static or
  /// elastic scene.
  Real g(Real y) const { return functions(y).g; }
  /// F0(y) of Eq. (33).
  Real f0(Real y) const { return functions(y).f0; }
  /// Q(y) of Eq. (46) (NaN with two or more active terms: chi is then (S15)'s).
  Real q(Real y) const { return functions(y).q; }

  /// The strip at y (y_minus() < y < y_plus()): Eqs. (32), (35) across the contact. Throws
  /// std::logic_error where has_pressure() is false.
  StripPressure<Real, Quadrature> strip(Real y) const {
    if (!has_pressure())
      throw std::logic_error(
          "viscoroll: LineSolution::strip is not available with " + std::to_string(active_terms) +
          " active memory terms (the line theory of a spectrum carries the strips by their "
          "moments, docs/theory.md (S14); the bem method gives the pressure)");
    const auto s = functions(y);
    return StripPressure<Real, Quadrature>(c1, s.a, s.b, s.g, vtau, f, compliance);
  }
  /// p(x, y), Eq. (35); zero outside the contact. Throws std::logic_error where has_pressure() is
  /// false (strip).
  Real pressure(Real x, Real y) const {
    using std::abs;
    if (!(abs(y - shape.centre) < shape.l)) return Real(0);
    return strip(y).pressure(x);
  }

  /// F0(y) per unit load per length, the long-term compliance of the terms solved for,
  /// (1 + f) c for one term (Eq. 47 with (52)).
  Real f0_per_load() const { return load_compliance; }

  /// The contact along the roller at `stations` evenly spaced points inside (y_minus, y_plus)
  /// (>= 1): the load per unit length F0(y)/f0_per_load() (Eq. 33 with (47): the strip's
  /// pseudo-pressure integrates to (1 + f) c times its load), a(y), b(y), the strip's peak
  /// pressure (Eq. 35; NaN where has_pressure() is false), the ends and the peak of the load
  /// (docs/rollers.md).
  AlongRoller<Real> along_roller(int stations = 65) const {
    AlongRoller<Real> out;
    out.y_minus = y_minus();
    out.y_plus = y_plus();
    const Real per_load = f0_per_load();
    for (int k = 1; k <= std::max(stations, 1); ++k) {
      const Real y = shape.centre + shape.l * (Real(2 * k) / Real(std::max(stations, 1) + 1) - 1);
      const auto s = functions(y);
      out.y.push_back(y);
      out.f0.push_back(s.f0 / per_load);
      out.a.push_back(s.a);
      out.b.push_back(s.b);
      out.p_max.push_back(has_pressure() ? strip(y).peak().pressure
                                         : std::numeric_limits<Real>::quiet_NaN());
      if (out.f0.back() > out.f0_max) {
        out.f0_max = out.f0.back();
        out.f0_max_y = y;
      }
    }
    return out;
  }

  /// a, b, G, F0 and Q at y (StripFunctions): the strip's (36), (33), (46) with at most one
  /// active term; with two or more, G0 = gamma a^2 and F0 = C1 a^2 (1/4 + gamma/2) (Eq. 33 with
  /// (S8)) from the moments, and Q NaN.
  plane::StripFunctions<Real> functions(Real y) const {
    const Real a = shape.a(y), b = shape.b(y);
    if (!has_pressure()) {
      if (!(a > 0)) return {a, b, Real(0), Real(0), std::numeric_limits<Real>::quiet_NaN()};
      const Real u = LineShape<Real>::coordinate(shape.basis, shape.scale, shape.one_minus_t2(y));
      const Real gamma = moments.gamma_at(u, shape.t_at(y));
      return {a, b, gamma * a * a, c1 * a * a * (Real(1) / 4 + gamma / 2),
              std::numeric_limits<Real>::quiet_NaN()};
    }
    if (!(vtau > 0) || !(f > 0) || !(a > 0)) return {a, b, Real(0), c1 * a * a / 4, Real(0)};
    return plane::strip_functions(c1, a, b, vtau, f);
  }
};

namespace line {

/// The line theory's domain (Section 3: the contact is slender, a(y) << l): a warning when
/// l/a(0) < 3, and one when a(y) somewhere reaches l/3 (a(y) can exceed a(0), as at the dip of
/// a(0) near V tau = 5 a0). a(y) is sampled at 65 points y = l k/64, k = 0..64 (from the centre c
/// both ways for an asymmetric contact, whose a(0) is read at c). Empty inside it.
template <RealScalar Real>
std::vector<Warning> line_domain_warnings(const LineShape<Real>& shape) {
  std::vector<Warning> warnings;
  const Real l = shape.l, a0 = shape.a(shape.centre);
  const Real aspect = l / a0;
  if (!(aspect >= 3))
    warnings.push_back({WarningCode::line_aspect,
                        "contact aspect l/a(0) = " + std::to_string(double(aspect)) +
                            " < 3: outside the line-contact theory's domain of validity"});
  Real a_max = a0, y_max = 0;
  for (int k = 1; k <= 64; ++k)
    for (int side : {1, -1}) {
      if (side < 0 && !shape.asymmetric()) continue;
      const Real y = shape.centre + side * (l * Real(k) / 64), a = shape.a(y);
      if (a > a_max) a_max = a, y_max = y;
    }
  if (a_max > a0 && !(l >= 3 * a_max))
    warnings.push_back(
        {WarningCode::line_width,
         "a(y) = " + std::to_string(double(a_max)) + " at y = " + std::to_string(double(y_max)) +
             " is not small against l = " + std::to_string(double(l)) +
             " (l/max a(y) < 3): outside the line-contact theory's domain of validity"});
  return warnings;
}

/// The bounds of a rolling contact of a standard linear solid (docs/theory.md, "Bounds of the
/// rolling contact"): a(0) <= a0 and l <= l0, the long-term static contact's, and b(0) >= 0. A
/// warning for each that a converged solution breaks by more than `tolerance` (relative to a0 and
/// l0; LineSolver passes its root tolerance 64 sqrt(eps)): its discretisation error exceeds its
/// distance to the bound (in the slow regime, V tau <~ 0.1 a0, at small N; docs/line-solver.md,
/// "Oversampling"). Empty for a solution that keeps them or has not converged.
template <RealScalar Real, class Quadrature>
std::vector<Warning> line_bound_warnings(const LineSolution<Real, Quadrature>& s, Real tolerance) {
  std::vector<Warning> warnings;
  if (!s.converged) return warnings;
  const Real a0 = s.a(Real(0)), b0 = s.b(Real(0)), l = s.l();
  const auto text = [](Real x) { return std::to_string(double(x)); };
  const char* advice =
      ": the discretisation error exceeds the distance to the bound (docs/theory.md, \"Bounds of "
      "the rolling contact\"); raise the terms, or use oversampling 2 with the mapped basis "
      "(docs/line-solver.md, \"Oversampling\")";
  if (!(a0 <= s.a_long_term * (1 + tolerance)))
    warnings.push_back({WarningCode::rolling_bound,
                        "a(0)/a0 = " + text(a0 / s.a_long_term) +
                            " > 1 breaks the bound a(0) <= a0 of the long-term static contact" +
                            advice});
  if (!(l <= s.l_long_term * (1 + tolerance)))
    warnings.push_back({WarningCode::rolling_bound,
                        "l/l0 = " + text(l / s.l_long_term) +
                            " > 1 breaks the bound l <= l0 of the long-term static contact" +
                            advice});
  if (!(b0 >= -tolerance * s.a_long_term))
    warnings.push_back(
        {WarningCode::rolling_bound,
         "b(0)/a0 = " + text(b0 / s.a_long_term) + " < 0 breaks the bound b(0) >= 0" + advice});
  return warnings;
}

/// A converged chi below zero (docs/errors.md, "chi below zero"): rolling dissipates, so chi >= 0;
/// a negative chi is the method's discretisation error on a nearly elastic material, and the
/// rolling resistance is zero to the method's accuracy. Empty otherwise.
template <class Real>
std::vector<Warning> line_chi_sign_warnings(bool converged, Real chi) {
  if (!converged || !(chi < 0)) return {};
  std::ostringstream text;
  text.precision(3);
  text << "chi = " << double(chi)
       << " < 0: rolling dissipates energy, so chi >= 0; a negative chi is the line method's "
          "discretisation error on a nearly elastic material: the rolling resistance is zero to "
          "the method's accuracy (the bem method resolves it)";
  return {{WarningCode::chi_negative, text.str()}};
}

}  // namespace line

}  // namespace viscoroll
