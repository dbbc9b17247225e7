// viscoroll: time–temperature superposition (docs/materials.md, docs/theory.md section 11).
//
// A thermorheologically simple material at temperature T is the material at the reference
// temperature T_ref with every time multiplied by the shift factor a_T (R13):
//   rho_i(T) = a_T rho_i(T_ref),  tau_k(T) = a_T tau_k(T_ref),  moduli unchanged,
// so its moduli at frequency f and temperature T are those at f a_T and T_ref.
// Temperatures are in degrees Celsius throughout the library (the DMA CSV's temperature_c, the
// scene file's "temperature"); the Arrhenius law converts to kelvin internally (T + 273.15).
//   WLF (R11):        log10 a_T = -c1 (T - T_ref) / (c2 + T - T_ref),  T > T_ref - c2
//                     (c2 in kelvin, equal to degrees Celsius as a difference);
//   Arrhenius (R12):  ln a_T = (E_a / R) (1 / (T + 273.15) - 1 / (T_ref + 273.15)),
//                     E_a in J/mol, R = 8.314462618 J/(mol K), T > -273.15 degrees Celsius.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <variant>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>

namespace viscoroll {

namespace detail {
template <class Real>
Real checked_shift_factor(Real log_e_factor, Real temperature) {
  using std::exp;
  const Real a = exp(log_e_factor);
  require((boost::math::isfinite)(a) && a > 0, "temperature", temperature,
          "a temperature at which the shift factor a_T is finite and positive (a_T = exp(" +
              format_value(log_e_factor) + "))");
  return a;
}
}  // namespace detail

/// The Williams–Landel–Ferry shift (R11): constants c1 > 0, c2 > 0 (K), reference temperature
/// t_ref (degrees Celsius).
template <RealScalar Real>
class WlfShift {
 public:
  /// The scalar.
  using real_type = Real;
  /// Throws std::invalid_argument unless c1 > 0, c2 > 0 and t_ref finite.
  WlfShift(Real c1, Real c2, Real t_ref) : c1_(c1), c2_(c2), t_ref_(t_ref) {
    detail::require_positive("c1", c1);
    detail::require_positive("c2", c2);
    detail::require_finite("t_ref", t_ref, "t_ref finite");
  }
  /// c1 of (R11).
  Real c1() const { return c1_; }
  /// c2 of (R11) (K).
  Real c2() const { return c2_; }
  /// The reference temperature (degrees Celsius), where a_T = 1.
  Real t_ref() const { return t_ref_; }

  /// (R11): log10 a_T. Throws std::invalid_argument naming `temperature` unless
  /// T > t_ref - c2 (the law's singular temperature) and finite.
  Real log10_factor(Real temperature) const {
    const Real limit = t_ref_ - c2_;
    detail::require((boost::math::isfinite)(temperature) && temperature > limit, "temperature",
                    temperature,
                    "temperature > t_ref - c2 = " + detail::format_value(limit) +
                        " (degrees Celsius; the WLF shift is singular at t_ref - c2)");
    const Real dt = temperature - t_ref_;
    return -c1_ * dt / (c2_ + dt);
  }
  /// a_T = 10^log10_factor(T); 1 at t_ref.
  Real factor(Real temperature) const {
    using std::log;
    return detail::checked_shift_factor(log10_factor(temperature) * log(Real(10)), temperature);
  }

 private:
  Real c1_, c2_, t_ref_;
};

/// The Arrhenius shift (R12): activation energy E_a > 0 (J/mol), reference temperature t_ref
/// (degrees Celsius).
template <RealScalar Real>
class ArrheniusShift {
 public:
  /// The scalar.
  using real_type = Real;
  /// The molar gas constant R, J/(mol K) (exact in the 2019 SI).
  static constexpr long double gas_constant = 8.31446261815324L;
  /// 0 degrees Celsius in kelvin.
  static constexpr long double celsius_zero = 273.15L;

  /// Throws std::invalid_argument unless activation_energy > 0 and t_ref > -273.15, finite.
  ArrheniusShift(Real activation_energy, Real t_ref) : e_a_(activation_energy), t_ref_(t_ref) {
    detail::require_positive("activation_energy", activation_energy);
    detail::require((boost::math::isfinite)(t_ref) && t_ref > -Real(celsius_zero), "t_ref", t_ref,
                    "t_ref > -273.15 (degrees Celsius)");
  }
  /// E_a (J/mol).
  Real activation_energy() const { return e_a_; }
  /// The reference temperature (degrees Celsius), where a_T = 1.
  Real t_ref() const { return t_ref_; }

  /// (R12): ln a_T. Throws std::invalid_argument naming `temperature` unless T > -273.15.
  Real log_factor(Real temperature) const {
    detail::require((boost::math::isfinite)(temperature) && temperature > -Real(celsius_zero),
                    "temperature", temperature, "temperature > -273.15 (degrees Celsius)");
    const Real tk = temperature + Real(celsius_zero), rk = t_ref_ + Real(celsius_zero);
    // 1/T - 1/T_ref = (T_ref - T) / (T T_ref): the difference of temperatures, not of reciprocals.
    return e_a_ / Real(gas_constant) * ((t_ref_ - temperature) / (tk * rk));
  }
  /// log10 a_T = log_factor(T) / ln 10.
  Real log10_factor(Real temperature) const {
    using std::log;
    return log_factor(temperature) / log(Real(10));
  }
  /// a_T = exp(log_factor(T)); 1 at t_ref.
  Real factor(Real temperature) const {
    return detail::checked_shift_factor(log_factor(temperature), temperature);
  }

 private:
  Real e_a_, t_ref_;
};

/// Either law, for options and scene files.
template <RealScalar Real>
using ShiftLaw = std::variant<WlfShift<Real>, ArrheniusShift<Real>>;

template <RealScalar Real>
Real shift_factor(const ShiftLaw<Real>& law, Real temperature) {
  return std::visit([&](const auto& l) { return l.factor(temperature); }, law);
}
template <RealScalar Real>
Real reference_temperature(const ShiftLaw<Real>& law) {
  return std::visit([](const auto& l) { return l.t_ref(); }, law);
}

/// A shift law: `factor(T)` returns a_T.
template <class S, class Real>
concept TemperatureShift = requires(const S& s, Real t) {
  { s.factor(t) } -> std::convertible_to<Real>;
};

namespace detail {
template <class Real, class Shift>
Real factor_of(const Shift& shift, Real temperature) {
  if constexpr (requires { shift.index(); })
    return shift_factor<Real>(shift, temperature);
  else
    return shift.factor(temperature);
}
}  // namespace detail

/// A material whose times scale as one (time-temperature superposition, (R13)):
/// `m.time_scaled(a)` is the same material with every relaxation or retardation time times a > 0.
/// Models: Elastic (no time), StandardLinearSolid, PronyCreep, PronyRelaxation, and any user
/// material with that member (tests/material/time_scalable.test.cpp).
template <class M>
concept TimeScalable = ConstitutiveModel<M> && requires(const M& m, typename M::real_type a) {
  { m.time_scaled(a) } -> std::same_as<M>;
};

/// (R13): the material at `temperature` (degrees Celsius): every time of its spectrum times a_T
/// of the shift law `shift` (a ShiftLaw, WlfShift, ArrheniusShift or any TemperatureShift); an
/// elastic solid, which has none, is unchanged (the temperature is still validated).
template <TimeScalable M, class Shift>
M at_temperature(const M& m, const Shift& shift, typename M::real_type temperature) {
  return m.time_scaled(detail::factor_of<typename M::real_type>(shift, temperature));
}

}  // namespace viscoroll
