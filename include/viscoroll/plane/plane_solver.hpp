// viscoroll: the plane problem, a rigid cylinder rolling on a standard-linear-solid half space.
// The strip it solves for is core/strip.hpp's; this header finds its half width.
//
// Hunter (1961), J. Appl. Mech. 28, 611-617; in the notation of Panek & Kalker (1980), to whose
// equations the plane problem reduces when nothing varies along y. The contact [b - a, b + a]
// carries the pseudo-pressure (32); the trailing-edge condition (36), the load (33) with (52),
// and contact at the leading edge, G K0(a / V tau) = a b K1(a / V tau) (the plane analogue of
// (38)-(44), derived in docs/theory.md, "The plane problem"), fix a, b and G. Eliminating b and G
// leaves one equation for A = a / a0, a0 the long-term Hertz half width (docs/theory.md, (P5)):
//   A^2 + 2 f/(1+f) (V tau / a0) A R = 1,   R = r_I r_K / (r_I + r_K),
//   r_I = I1(alpha)/I0(alpha), alpha = (1+f) a/(V tau);  r_K = K1(beta)/K0(beta), beta = a/(V tau).
// An elastic material (if constexpr), V tau <= eps a0 and the glassy limit (V tau >~ 40 a0/eps in
// double, or +inf) are Hertz's closed form with no Bessel work (docs/theory.md, (P6)).
// The solver computes in units of powers of two in which a0, C1 and c are of order one, with the
// bits of the caller's units wherever these neither overflow nor underflow, and converts the
// solution back, each number checked to be representable (docs/theory.md, "Scaling";
// docs/errors.md).
#pragma once

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/required_field.hpp>
#include <viscoroll/core/solve_inputs.hpp>
#include <viscoroll/core/spectrum_conditioning.hpp>
#include <viscoroll/core/spectrum_strip.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/material/detail/prony_spectrum.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/quadrature/gauss_legendre.hpp>
#include <viscoroll/special/bessel_ratio.hpp>

namespace viscoroll {

/// A rigid cylinder of curvature c1 = 1/R pressed with load per unit length `load` and rolling
/// towards +x at `speed`.
template <RealScalar Real>
struct PlaneScene {
  /// C1 = 1/R, the cylinder's curvature, > 0.
  Real c1 = detail::required_field<Real>();
  /// W, the load per unit length, > 0.
  Real load = detail::required_field<Real>();
  /// V, the rolling speed, >= 0.
  Real speed = detail::required_field<Real>();

  /// Throws std::invalid_argument naming the parameter unless c1 > 0, load > 0, speed >= 0.
  void validate() const {
    detail::require_positive("c1", c1);
    detail::require_positive("load", load);
    detail::require_non_negative("speed", speed);
  }
  /// "c1 = ..., load = ..., speed = ...": the scene in an error's message.
  std::string describe() const {
    return "c1 = " + detail::format_value(c1) + ", load = " + detail::format_value(load) +
           ", speed = " + detail::format_value(speed);
  }
};

/// Runtime settings of the plane solver.
struct PlaneOptions {
  /// Iterations allowed to the root finder for a (TOMS 748); each costs four Bessel ratios.
  int max_iterations = 100;

  /// Throws std::invalid_argument unless 1 <= max_iterations <= 100000.
  void validate() const {
    detail::require(max_iterations >= 1 && max_iterations <= 100000, "max_iterations",
                    max_iterations, "1 <= max_iterations <= 100000");
  }
};

/// The plane solution, for any material: the contact, the pressure and the rolling friction. A
/// material with at most one memory term (Elastic, StandardLinearSolid) is solved by (P1)-(P7);
/// a spectrum (PronyCreep, PronyRelaxation) by the closed form of docs/theory.md section 12,
/// whose pressure is the weighted sum of one-term strips (S9). A static or glassy scene, or one
/// whose terms are all relaxed or glassy at this speed, has Hertz's strip.
template <RealScalar Real, class Quadrature>
struct PlaneSolution {
  Real a;  ///< contact half width
  Real b;  ///< offset of the contact centre ahead of the cylinder axis (Eq. 29)
  Real g;  ///< G of Eqs. (33), (36); G0 = Pi_h(0) of (S8) for a spectrum
  /// a0: the V tau -> 0 (long-term Hertz) half width, a0^2 = 4 c (1 + f) W / C1, with the sum of
  /// the creep ratios for a spectrum.
  Real a_long_term;
  Real f0;         ///< F0 = int p* dx = c (1 + f) W (Eq. 52); c W in the glassy closed form
  Real q;          ///< Q of Eq. (46) (NaN for a spectrum: its chi is (S10)'s)
  Real chi;        ///< rolling-friction coefficient C1 int x p / int p (Eq. 51, (P7), (S10))
  bool converged;  ///< the root for a met the tolerance within the allowed iterations
  int iterations;  ///< root-finder iterations (0 for a closed form)
  StopCode code = StopCode::converged;  ///< why it stopped, as a code (core/outcome.hpp)
  std::string reason{};                 ///< empty when converged, else why not
  /// |A^2 + 2 f/(1+f) (V tau/a0) A R - 1| (P5), or |A^2 (1 + 2 G0/a^2) - 1| (S8) for a spectrum,
  /// at the returned a, A = a / a0 of the terms solved for.
  Real residual;
  /// The strip's pressure (35), (S9), from which pressure() and peak() are read.
  PlaneStrip<Real, Quadrature> strip;
  /// Memory terms solved for at this speed: 0 for Hertz's strip (elastic, static, glassy, or a
  /// spectrum's terms all relaxed or glassy), 1 for the paper's, the count after merging
  /// near-equal times for a spectrum.
  int active_terms = 0;
  Real linear_residual{};  ///< relative residual of the linear system (S5); 0 for one term
  /// Rounding amplification of the closed form (theory.md (S20): the larger of sum |A_i| and
  /// the crowding of the retardation lengths); 1 for one term and for Hertz.
  Real amplification = 1;
  /// Bound on chi's rounding error, 64 eps amplification^(3/2) C1 a (theory.md (S20), which
  /// for one term, amplification 1, bounds (P7)'s sum of non-negative terms): a chi within it of
  /// zero (of either sign) is zero to rounding; no converged chi is below -chi_rounding. 0 for
  /// Hertz's strip, whose chi is exactly 0.
  Real chi_rounding{};
  /// Bound on the relative change of the complex compliance made by merging near-equal times
  /// (docs/theory.md (S19), (S20)); 0 where no term was merged (always for one term).
  Real spectrum_error{};

  /// Eq. (35), (S9): the pressure at x (moving frame; the cylinder axis is x = 0).
  Real pressure(Real x) const { return strip.pressure(x); }
  /// Eq. (32): the pseudo-pressure at x (one memory term; PlaneStrip::pseudo_pressure).
  Real pseudo_pressure(Real x) const { return strip.pseudo_pressure(x); }
  /// The pressure peak and its location.
  PressurePeak<Real> peak() const { return strip.peak(); }
};

/// Solver of the plane problem over a scalar, a constitutive model and a quadrature rule (the
/// rule serves the pressure reconstruction (35); a, b, G and chi are closed-form given a). A model
/// with at most one memory term (SingleTimeModel: Elastic, StandardLinearSolid) is solved by
/// (P1)-(P7); a spectrum (PronyCreep, PronyRelaxation) by the closed form of section 12 of
/// docs/theory.md. Both give a PlaneSolution.
template <RealScalar Real, ConstitutiveModel Material, class Quadrature = GaussLegendre<Real, 24>>
requires std::same_as<typename Material::real_type, Real> && QuadratureRule<Quadrature, Real>
class PlaneSolver {
 public:
  /// The solution, for every material.
  using Solution = PlaneSolution<Real, Quadrature>;

  /// Throws std::invalid_argument for invalid options (PlaneOptions::validate).
  explicit PlaneSolver(Material material, PlaneOptions options = {})
      : material_(std::move(material)), options_(options) {
    options_.validate();
  }

  /// The material.
  const Material& material() const { return material_; }

  /// Solves the scene; throws std::invalid_argument for an invalid scene, or one whose solution
  /// is not representable in Real (a number of it beyond the largest finite or, not being zero,
  /// below the smallest normal one; docs/errors.md).
  Solution solve(const PlaneScene<Real>& scene) const;

 private:
  /// The reason of a root for a that did not meet its tolerance.
  static std::string root_failure(int iterations) {
    return "the root finder for the half width a did not converge in " +
           std::to_string(iterations) + " iterations (PlaneOptions::max_iterations)";
  }

  /// The rolling solution in `units` (StripUnits; c1, c, vtau and a0 given in them): (P5) for
  /// A = a/a0, then b, G, Q, F0 and chi. Its numbers are in the units too (F0, Q and chi carry
  /// the curvature's: PlaneSolver::solve converts them).
  Solution rolling(plane::StripUnits units, Real c1, Real c, Real f, Real vtau, Real a0) const {
    using special::bessel_i1_over_i0;
    using special::bessel_i2_over_i0;
    using special::bessel_k1_over_k0;
    const Real v = vtau / a0;
    const Real creep = f / (1 + f);
    // (P5): h(A) = A^2 + 2 f/(1+f) v A R(A) - 1, increasing from h < 0 at the glassy width
    // A = (1+f)^(-1/2) to h > 0 at the long-term width A = 1.
    auto h = [&](Real A) {
      const Real r_i = bessel_i1_over_i0(plane::strip_alpha(A, v, f));
      const Real r_k = bessel_k1_over_k0(A / v);
      return A * A + 2 * creep * v * A * (r_i * r_k / (r_i + r_k)) - 1;
    };
    using std::sqrt;
    Real lo = 1 / sqrt(1 + f), hi = Real(1);
    const Real h_lo = h(lo), h_hi = h(hi);
    Real A;
    bool converged = true;
    int iterations = 0;
    if (h_lo >= 0) {
      A = lo;  // the glassy limit to rounding
    } else if (h_hi <= 0) {
      A = hi;  // the long-term limit to rounding
    } else {
      std::uintmax_t max_iter = static_cast<std::uintmax_t>(options_.max_iterations);
      const auto bracket = boost::math::tools::toms748_solve(
          h, lo, hi, h_lo, h_hi,
          boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 2), max_iter);
      iterations = static_cast<int>(max_iter);
      A = (bracket.first + bracket.second) / 2;
      using std::abs;
      converged =
          abs(bracket.second - bracket.first) <= 8 * std::numeric_limits<Real>::epsilon() * abs(A);
    }
    using std::abs;
    const Real residual = abs(h(A));
    const Real a = A * a0;
    const Real alpha = plane::strip_alpha(a, vtau, f);
    const Real r_i = bessel_i1_over_i0(alpha);
    const Real r_k = bessel_k1_over_k0(a / vtau);
    // (P4): b from (36) = leading-edge condition (G = a b K1/K0); then G (36) and Q (46) of the
    // strip, and F0 = C1 a0^2 / 4 from the load, Eq. (33) with (52).
    const Real b = vtau * creep * r_i / (r_i + r_k);
    const auto sf = plane::strip_functions_from_ratio(c1, a, b, vtau, f, r_i);
    const Real g = sf.g, q = sf.q;
    const Real f0 = c1 * a0 * a0 / 4;
    // (P7): chi = C1 xbar, xbar = [2 b G + V tau (f a^2 I2/I0 + 2 a b r_I) / (1+f)] / a0^2,
    // every term non-negative (the paper's (54) cancels as V tau grows).
    const Real delta = bessel_i2_over_i0(alpha);
    const Real xbar = plane::strip_first_moment(a, b, g, vtau, f, r_i, delta) / (a0 * a0);
    return Solution{.a = a,
                    .b = b,
                    .g = g,
                    .a_long_term = a0,
                    .f0 = f0,
                    .q = q,
                    .chi = c1 * xbar,
                    .converged = converged,
                    .iterations = iterations,
                    .code = converged ? StopCode::converged : StopCode::root_finder_failed,
                    .reason = converged ? std::string() : root_failure(iterations),
                    .residual = residual,
                    .strip = PlaneStrip<Real, Quadrature>(
                        StripPressure<Real, Quadrature>(units, c1, a, b, g, vtau, f, c)),
                    .active_terms = 1,
                    .chi_rounding = 64 * std::numeric_limits<Real>::epsilon() * c1 * a};
  }

  /// Hertz's strip of half width a under the compliance (1 + f) c, in `units` as rolling():
  /// b = G = Q = chi = 0, F0 = C1 a^2 / 4 (Eq. 33 with G = 0). The glassy limit is reported in
  /// this form with f = 0 (the instantaneous compliance alone), as LineSolver reports its glassy
  /// closed form.
  static Solution static_solution(plane::StripUnits units, Real c1, Real a, Real a0, Real c,
                                  Real f) {
    const StripPressure<Real, Quadrature> strip(units, c1, a, Real(0), Real(0), Real(0), f, c);
    return Solution{.a = a,
                    .b = Real(0),
                    .g = Real(0),
                    .a_long_term = a0,
                    .f0 = c1 * a * a / 4,
                    .q = Real(0),
                    .chi = Real(0),
                    .converged = true,
                    .iterations = 0,
                    .code = StopCode::converged,
                    .reason = {},
                    .residual = Real(0),
                    .strip = PlaneStrip<Real, Quadrature>(strip)};
  }

  /// The glassy closed form is within eps of the rolling solution (strip_is_glassy, (P6)).
  static bool glassy(Real vtau, Real f, Real a0) { return plane::strip_is_glassy(vtau, f, a0); }

  /// The scene in the strip's units (docs/theory.md, "Scaling"): C1, c and the load W as m 2^e,
  /// and the long-term half width a0 = sqrt(4 c (1 + F) W / C1) (the load (33) with (52):
  /// a^2 + 2 G = a0^2) in a power of two of its own, the unit of length; every product rounds as
  /// in the caller's units.
  struct Scaled {
    detail::Binary<Real> c1, c, load, a0;
    plane::StripUnits units;
  };
  static Scaled scaled(const PlaneScene<Real>& scene, Real c, Real creep_ratio) {
    const auto c1 = detail::binary<Real>(scene.c1), cc = detail::binary<Real>(c),
               load = detail::binary<Real>(scene.load);
    const auto creep = detail::binary<Real>(1 + creep_ratio);
    const auto a0 = detail::binary_sqrt<Real>(4 * cc.m * creep.m * load.m / c1.m,
                                              cc.e + creep.e + load.e - c1.e);
    return {c1, cc, load, a0, {a0.e, c1.e, cc.e}};
  }

  /// A spectrum (docs/theory.md, section 12): at this speed every retardation length
  /// lambda_k = V tau_k is relaxed (lambda_k <= eps a, folded into the compliance), glassy
  /// (strip_is_glassy: dropped, its creep never starts) or active; the active terms' relaxation
  /// lengths are the zeros of (R7), and (S5)-(S8) with the load (S8) give a by TOMS 748 in
  /// [glassy, long-term] Hertz widths of the active problem.
  Solution solve_spectrum(const PlaneScene<Real>& scene) const
      requires(!SingleTimeModel<Material>) {
    const auto inputs = detail::solve_prologue(scene, material_);
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real c = inputs.c;
    const auto& terms = material_.memory_terms();
    detail::require_spectrum_terms(terms.size(), "plane");
    const Real creep_ratio = material_.creep_ratio();  // F = sum f_k
    const Scaled sc = scaled(scene, c, creep_ratio);
    const auto &c1 = sc.c1, &cc = sc.c, &load = sc.load, &a0 = sc.a0;
    const plane::StripUnits& units = sc.units;
    const Real a_glassy = a0.m / sqrt(1 + creep_ratio);
    // Classify the terms at this speed (lengths in units); relaxed ones folded into the
    // compliance, c (1 + relaxed), the active f scaled by 1/(1 + relaxed) (R6b).
    auto classes = detail::classify_spectrum(terms, scene.speed, units.length, eps * a_glassy, a0.m,
                                             creep_ratio);
    const Real relaxed = classes.relaxed, glassy_f = classes.glassy;
    auto& active = classes.active;
    const Real c_eff = cc.m * (1 + relaxed);
    // a0 of the problem solved: a0^2 (1 + F - F_glassy) / (1 + F).
    const Real a0_eff = a0.m * sqrt((1 + creep_ratio - glassy_f) / (1 + creep_ratio));
    Solution s{};
    s.q = std::numeric_limits<Real>::quiet_NaN();  // chi is (S10)'s
    s.a_long_term = a0.m;
    s.converged = true;
    s.amplification = 1;
    if (active.empty()) {
      s.a = a0_eff;
      s.f0 = c1.m * a0_eff * a0_eff / 4;
      s.strip = PlaneStrip<Real, Quadrature>(StripPressure<Real, Quadrature>(
          units, c1.m, a0_eff, Real(0), Real(0), Real(0), creep_ratio - glassy_f, cc.m));
    } else {
      // Near-equal times merged where the closed form would lose digits ((S19), (S20)).
      const auto conditioned = detail::condition_spectrum(
          std::move(active), detail::times_power_of_two(Real(1), units.length) / scene.speed);
      const auto& merged = conditioned.terms;
      const plane::SpectrumLengths<Real>& lengths = conditioned.lengths;
      s.spectrum_error = conditioned.spectrum_error;
      const Real creep_active = lengths.creep_ratio;
      // (S8) load: a^2 + 2 G0 = a0^2, i.e. h(A) = A^2 + 2 G0(A a0) / a0^2 - 1, A = a / a0.
      auto h = [&](Real A) {
        const auto st = plane::spectrum_strip(A * a0_eff, lengths);
        return A * A + 2 * st.g0 / (a0_eff * a0_eff) - 1;
      };
      Real lo = 1 / sqrt(1 + creep_active), hi = Real(1);
      Real h_lo = h(lo), h_hi = h(hi);
      Real A = hi;
      int iterations = 0;
      bool converged = true;
      if (h_lo >= 0) {
        A = lo;
      } else if (h_hi <= 0) {
        A = hi;
      } else {
        std::uintmax_t max_iter = static_cast<std::uintmax_t>(options_.max_iterations);
        const auto bracket = boost::math::tools::toms748_solve(
            h, lo, hi, h_lo, h_hi,
            boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 2),
            max_iter);
        iterations = static_cast<int>(max_iter);
        A = (bracket.first + bracket.second) / 2;
        using std::abs;
        converged = abs(bracket.second - bracket.first) <= 8 * eps * abs(A);
      }
      const Real a = A * a0_eff;
      const auto st = plane::spectrum_strip(a, lengths);
      using std::abs;
      s.a = a;
      s.b = st.b;
      s.g = st.g0;
      s.f0 = c1.m * a0_eff * a0_eff / 4;  // (33) with (S8)
      // (S10): the centroid of p from the axis, xbar = b + centroid.
      const Real xbar = st.b + st.centroid;
      s.chi = c1.m * xbar;
      // The closed form's rounding, measured to grow as eps amplification^(3/2) (S20): the
      // load's residual may not exceed 64 times it, and chi carries it on its scale C1 a.
      using std::pow;
      const Real rounding = 64 * eps * pow(conditioned.amplification, Real(3) / 2);
      s.chi_rounding = rounding * c1.m * a;
      // Converged: the root met its tolerance, the linear solve (S5) its residual, the
      // amplification is within the limit of (S20) and the load's residual within the rounding.
      s.residual = abs(A * A + 2 * st.g0 / (a0_eff * a0_eff) - 1);
      s.converged = converged && st.residual <= 64 * eps * Real(2 * merged.size() + 1) &&
                    conditioned.amplification <= detail::spectrum_amplification_limit<Real>() &&
                    s.residual <= rounding;
      s.iterations = iterations;
      if (!converged) {
        s.code = StopCode::root_finder_failed;
        s.reason = root_failure(iterations);
      } else if (!s.converged) {
        s.code = StopCode::precision_exhausted;
        s.reason = "the closed form's rounding (amplification " +
                   detail::format_value(conditioned.amplification) + ", load residual " +
                   detail::format_value(s.residual) + ", linear residual " +
                   detail::format_value(st.residual) +
                   ") exceeds what this scalar carries (docs/theory.md (S20))";
      }
      s.linear_residual = st.residual;
      s.amplification = conditioned.amplification;
      s.active_terms = static_cast<int>(merged.size());
      s.strip = PlaneStrip<Real, Quadrature>(units, c1.m, a, st, lengths, c_eff);
    }
    in_caller_units(s, units, load, inputs);
    return s;
  }

  /// A solution `s` computed in `units` (one term or a spectrum) in the caller's units: each
  /// number zero or normal and finite, else an error naming the `inputs` (docs/errors.md).
  template <class Inputs>
  static void in_caller_units(Solution& s, const plane::StripUnits& units,
                              const detail::Binary<Real>& load, const Inputs& inputs) {
    const int length = units.length, area = 2 * length, curvature = units.curvature;
    const auto in = [&](Real x, int exponent, std::string_view what) {
      return detail::representable(x, exponent, what, inputs);
    };
    constexpr bool spectrum = !SingleTimeModel<Material>;
    const Real mean_pressure = load.m / (2 * s.a);  // in `units`, before a is converted
    s.a_long_term = in(s.a_long_term, length,
                       spectrum ? "the long-term half width a0 = sqrt(4 c (1+F) load/c1)"
                                : "the long-term half width a0 = sqrt(4 c (1+f) load/c1)");
    s.a = in(s.a, length, "the contact half width a");
    s.b = in(s.b, length, "the offset b of the contact");
    s.g = in(s.g, area, spectrum ? "G0 of (S8)" : "G of Eq. (36)");
    s.f0 = in(s.f0, curvature + area, "F0 of Eq. (33)");
    if constexpr (!spectrum) s.q = in(s.q, curvature + area, "Q of Eq. (46)");
    s.chi = in(s.chi, curvature + length, "the rolling-friction coefficient chi of Eq. (51)");
    s.chi_rounding = detail::times_power_of_two(s.chi_rounding, curvature + length);
    in(mean_pressure, load.e - length, "the mean pressure load / (2 a)");
  }

  Material material_;
  PlaneOptions options_;
};

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires std::same_as<typename Material::real_type, Real> && QuadratureRule<Quadrature, Real>
auto PlaneSolver<Real, Material, Quadrature>::solve(const PlaneScene<Real>& scene) const
    -> Solution {
  if constexpr (!SingleTimeModel<Material>) {
    return solve_spectrum(scene);
  } else {
    // The material's compliance and its memory term (f, tau) of Eq. (1) (none for Elastic).
    const auto inputs = detail::solve_prologue(scene, material_);
    const Real c = inputs.c;
    const PronyTerm<Real> memory = detail::single_memory_term(material_);
    const Real f = memory.f;
    const Scaled sc = scaled(scene, c, f);
    const auto &c1 = sc.c1, &cc = sc.c, &load = sc.load, &a0 = sc.a0;
    const plane::StripUnits& units = sc.units;
    Solution s = [&] {
      if constexpr (Material::is_viscoelastic) {
        const auto speed = detail::binary<Real>(scene.speed),
                   tau = detail::binary<Real>(memory.tau);
        const Real vtau =
            detail::times_power_of_two(Real(speed.m * tau.m), speed.e + tau.e - units.length);
        if (f > 0 && vtau > std::numeric_limits<Real>::epsilon() * a0.m) {
          if (!glassy(vtau, f, a0.m)) return rolling(units, c1.m, cc.m, f, vtau, a0.m);
          // (P6) V tau -> inf: Hertz with the instantaneous compliance, a = a0 (1 + f)^(-1/2).
          const auto a = detail::binary_sqrt<Real>(4 * cc.m * load.m / c1.m, cc.e + load.e - c1.e);
          const Real a_glassy = detail::times_power_of_two(a.m, a.e - units.length);
          return static_solution(units, c1.m, a_glassy, a0.m, cc.m, Real(0));
        }
      }
      // Static (V tau <= eps a0: a, b and chi move by less than eps/2 of a0, (P6)) or elastic:
      // Hertz with the long-term compliance, no Bessel work.
      return static_solution(units, c1.m, a0.m, a0.m, cc.m, f);
    }();
    in_caller_units(s, units, load, inputs);
    return s;
  }
}

/// The scalar deduced from the material: PlaneSolver solver(StandardLinearSolid<double>(...)).
template <ConstitutiveModel Material>
PlaneSolver(Material) -> PlaneSolver<typename Material::real_type, Material>;
template <ConstitutiveModel Material>
PlaneSolver(Material, PlaneOptions) -> PlaneSolver<typename Material::real_type, Material>;

/// The common case: double precision, standard linear solid, 24-point Gauss-Legendre panels.
using PlaneSolverD = PlaneSolver<double, StandardLinearSolid<double>>;

// Compiled mode (docs/building.md): with VISCOROLL_COMPILED, which the CMake target
// viscoroll::compiled sets (VISCOROLL_COMPILED_DOUBLE, from viscoroll::compiled_double: the double
// ones only), the solvers below are instantiated once in that library (src/) and
// not in the including translation unit. Their entry points are defined out of the class (not
// inline), so that g++ does not instantiate them here for inlining either. Other instantiations
// are implicit, as in header-only mode.
#if defined(VISCOROLL_COMPILED)
extern template class PlaneSolver<float, StandardLinearSolid<float>>;
extern template class PlaneSolver<long double, StandardLinearSolid<long double>>;
#endif
#if defined(VISCOROLL_COMPILED) || defined(VISCOROLL_COMPILED_DOUBLE)
extern template class PlaneSolver<double, StandardLinearSolid<double>>;
#endif

}  // namespace viscoroll
