// The model validity checks (core/validity.hpp, docs/theory.md section 18) on a result record of
// any method, shared by viscoroll-solve and the Python bindings: the record's contact against the
// scene's roller and rubber. A breach joins the record's warnings (a field `warnings` is added to
// a record that has none); --strict (Python strict=True) makes it an error.
#pragma once

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>
#include <viscoroll/core/validity.hpp>

#include "scene_file.hpp"

namespace viscoroll::cli {

/// What the checks need of the scene besides the record: the roller's radius across (a scene
/// file's `radius`, else 1/c1), where its body ends along y (+-inf: the ellipsoid, the cylinder),
/// and the rubber's shear-wave speed sqrt(mu_glassy / density) where a density is given (else
/// NaN: not checked).
struct ValidityFacts {
  double radius = std::numeric_limits<double>::quiet_NaN();
  double body_min = -std::numeric_limits<double>::infinity();
  double body_max = std::numeric_limits<double>::infinity();
  double shear_wave_speed = std::numeric_limits<double>::quiet_NaN();
};

/// The rubber's shear-wave speed sqrt(mu_glassy / density) for ValidityFacts, mu_glassy =
/// (1 - nu)/(2 pi c) from the material's instantaneous compliance `c` and Poisson's ratio `nu`.
inline double shear_wave_speed(double c, double nu, double density) {
  return std::sqrt((1 - nu) / (2 * std::numbers::pi * c) / density);
}

/// The value of `key` in `record` (a sequence of (key, value) pairs or fields, the value a
/// std::variant) when it holds a T, or null.
template <class T, class Record>
auto record_value(Record& record, std::string_view key)
    -> std::conditional_t<std::is_const_v<Record>, const T*, T*> {
  for (auto& [name, value] : record)
    if (name == key)
      if (auto* x = std::get_if<T>(&value)) return x;
  return nullptr;
}

/// The number of `key` in `record`, or NaN.
template <class Record>
double record_number(const Record& record, std::string_view key) {
  const auto* x = record_value<double>(record, key);
  return x ? *x : std::numeric_limits<double>::quiet_NaN();
}

/// The flag `key` of `record`, or `fallback` where it has none.
template <class Record>
bool record_flag(const Record& record, std::string_view key, bool fallback) {
  const auto* b = record_value<bool>(record, key);
  return b ? *b : fallback;
}

/// "<method> solution for tau = T, speed = V" (temperature = T for a prony material with a shift
/// law): how both front doors name a result in their messages.
template <class Record>
std::string record_label(const Record& record) {
  const auto* method = record_value<std::string>(record, "method");
  std::string out = (method ? *method : std::string("the")) + " solution for ";
  const double t = record_number(record, "temperature"), tau = record_number(record, "tau");
  if (!std::isnan(t))
    out += "temperature = " + scene_detail::shortest(t) + ", ";
  else if (!std::isnan(tau))
    out += "tau = " + scene_detail::shortest(tau) + ", ";
  return out + "speed = " + scene_detail::shortest(record_number(record, "speed"));
}

/// Adds `list` to the record's `warnings` and their codes to its `warning_codes` (each field
/// appended when the record has none): after the warnings it has, or before them with `first`.
template <class Record>
void add_warnings(Record& record, const std::vector<Warning>& list, bool first = false) {
  if (list.empty()) return;
  std::vector<std::string> texts, codes;
  for (const auto& w : list) {
    texts.push_back(w.text);
    codes.emplace_back(to_string(w.code));
  }
  for (auto [field, values] : {std::pair{"warnings", &texts}, std::pair{"warning_codes", &codes}}) {
    if (auto* have = record_value<std::vector<std::string>>(record, field))
      have->insert(first ? have->begin() : have->end(), values->begin(), values->end());
    else
      record.push_back(typename Record::value_type{field, *values});
  }
}

/// The breaches of the result `record` (converged; its method named by the field `method`)
/// against `facts`. A result that did not converge has no contact to check: none.
template <class Record>
std::vector<ValidityBreach<double>> record_breaches(const Record& record,
                                                    const ValidityFacts& facts) {
  if (!record_flag(record, "converged", false)) return {};
  const auto* method = record_value<std::string>(record, "method");
  ValidityInputs<double> in;
  in.radius = facts.radius;
  in.a0 = record_number(record, "a0");
  in.l = record_number(record, "l");
  in.y_minus = record_number(record, "y_minus");
  in.y_plus = record_number(record, "y_plus");
  in.body_min = facts.body_min;
  in.body_max = facts.body_max;
  in.line_theory = method && *method == "line";
  if (const auto* terms = record_value<long long>(record, "active_terms"))
    in.memory_terms = static_cast<int>(*terms);
  in.speed = record_number(record, "speed");
  in.shear_wave_speed = facts.shear_wave_speed;
  return check_validity(in);
}

/// Adds the breaches to the record's warnings and warning_codes (add_warnings) and returns them.
template <class Record>
std::vector<Warning> add_validity_warnings(Record& record, const ValidityFacts& facts) {
  std::vector<Warning> breaches;
  for (const auto& b : record_breaches(record, facts))
    breaches.push_back({warning_code(b.check), b.message});
  add_warnings(record, breaches);
  return breaches;
}

/// (V1), (V2) on a scene's long-term static contact, before any solve, so that a result that
/// does not converge still says why the scene is suspect: the contact of half width `a0` and
/// half length `l0` (the ellipsoid's Hertz contact, a roller's line-theory contact; l0 NaN: not
/// checked along the roller, the cylinder's); where the line theory has none on a roller of
/// finite length (a0 NaN: it reaches the roller's ends), the narrowest contact along the whole
/// roller, a = sqrt(4 C w / c1) at the load per length w = load / (body_max - body_min) (the
/// cylinder's Eq. 47, C the long-term compliance). Each message starts with what was checked.
inline std::vector<Warning> scene_breaches(const ValidityFacts& facts, double a0, double l0,
                                           double long_term_compliance, double load, double c1) {
  ValidityInputs<double> in;
  in.radius = facts.radius;
  in.body_min = facts.body_min;
  in.body_max = facts.body_max;
  std::string prefix = "its long-term static contact: ";
  if (std::isfinite(a0)) {
    in.a0 = a0;
    if (std::isfinite(l0)) {
      in.y_minus = -l0;
      in.y_plus = l0;
    }
  } else if (std::isfinite(facts.body_max - facts.body_min)) {
    in.a0 = std::sqrt(4 * long_term_compliance * (load / (facts.body_max - facts.body_min)) / c1);
    prefix = "its long-term static contact reaches the roller's ends; along the whole roller ";
  }
  std::vector<Warning> out;
  for (const auto& b : check_validity(in))
    out.push_back({warning_code(b.check), prefix + b.message});
  return out;
}

}  // namespace viscoroll::cli
