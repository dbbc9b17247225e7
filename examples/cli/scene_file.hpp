// viscoroll-solve: the scene file (docs/cli.md), a JSON object in SI units. parse_scene is a pure
// function from text to a Scene, so that tests and the fuzzer drive it without files;
// read_scene_file does the file's part (missing, not a regular file, empty, over 1 MiB). Every
// error throws std::invalid_argument whose message names the file, the key with its path
// ("material.f", "speeds[2]") and the valid range. Uses nlohmann-json, a dependency of the
// command-line tool only (never of include/).
//
// A new material model or roller profile is one alternative of MaterialModel or RollerProfile
// and one entry of material_readers() or roller_readers().
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>
#include <viscoroll/input_limits.hpp>

#include "solve_options.hpp"

namespace viscoroll::cli {

/// A linear elastic half space: shear modulus mu (Pa), Poisson's ratio nu.
struct ElasticModel {
  double mu = 0, nu = 0;
};

/// Eq. (1) of the paper: instantaneous shear modulus mu_d (Pa), nu, creep ratio f, relaxation
/// time tau (s).
struct StandardLinearSolidModel {
  double mu_d = 0, nu = 0, f = 0, tau = 0;
};

/// One term of a Prony series in relaxation form: modulus g (Pa) and relaxation time tau (s).
struct PronyTermSpec {
  double g = 0, tau = 0;
};

/// A time-temperature shift (docs/materials.md): law "wlf" (c1, c2 in K, t_ref in degrees
/// Celsius) or "arrhenius" (activation_energy in J/mol, t_ref).
struct ShiftSpec {
  std::string law;
  double c1 = 0, c2 = 0, activation_energy = 0, t_ref = 0;
};

/// A generalised Maxwell solid in relaxation form, G(t) = g_inf + sum g exp(-t / tau): either its
/// terms, or `dma`, a DMA CSV file (as written in the scene, relative to the scene file's
/// directory) to fit them from (then g_inf is fitted too). Optionally a shift law.
struct PronyModel {
  double nu = 0, g_inf = 0;
  std::vector<PronyTermSpec> terms;
  std::string dma;
  std::optional<ShiftSpec> shift;
};

using MaterialModel = std::variant<ElasticModel, StandardLinearSolidModel, PronyModel>;

/// The doubly parabolic roller of the paper (Eq. 27): curvatures c1 across, c2 along (1/m).
struct EllipsoidProfile {
  double c1 = 0, c2 = 0;
};

/// A cylinder of radius `radius` (m): the plane method's roller, c1 = 1/radius.
struct CylinderProfile {
  double radius = 0;
};

/// A cylinder of radius `radius` with a flat part of length flat_length and circular crowns of
/// radius crown_radius beyond it, cut at length (inf: at the crown circle's end), run misaligned
/// by tilt (rad): viscoroll::CrownedCylinder in viscoroll::Tilted (docs/rollers.md).
struct CrownedProfile {
  double radius = 0, flat_length = 0, crown_radius = 0;
  double length = std::numeric_limits<double>::infinity(), tilt = 0;
};

/// A logarithmic crown h = -A ln(1 - k (2y/L)^2) on a roller of radius and length L, scale A,
/// end drop z_m (inf: Lundberg's), run misaligned by tilt: viscoroll::LogarithmicCrown.
struct LogarithmicProfile {
  double radius = 0, length = 0, scale = 0;
  double end_drop = std::numeric_limits<double>::infinity(), tilt = 0;
};

/// A drop h(y) tabulated at y (m, strictly increasing, at least 4 points), interpolated by the
/// modified Akima spline, run misaligned by tilt: viscoroll::TabulatedProfile.
struct TableProfile {
  double radius = 0;
  std::vector<double> y, h;
  double tilt = 0;
};

using RollerProfile = std::variant<EllipsoidProfile, CylinderProfile, CrownedProfile,
                                   LogarithmicProfile, TableProfile>;

/// The profiles of a roller of finite length, which the bem and line methods take, tilted or not
/// (docs/rollers.md).
inline bool is_axial_profile(const RollerProfile& r) {
  return std::holds_alternative<CrownedProfile>(r) ||
         std::holds_alternative<LogarithmicProfile>(r) || std::holds_alternative<TableProfile>(r);
}

/// The scene's "substrate": the body the roller presses (docs/bem.md B15-B19,
/// docs/plane-substrate.md): "half_space" (the default), "layer" of `thickness` (m) on a rigid
/// base, "bonded" or "frictionless", or "spring_bed" of `thickness` (the belt-conveyor model
/// u = h p/E). The bem method solves it, and the plane method for a cylinder.
struct SubstrateSpec {
  std::string model = "half_space";
  double thickness = 0;
  std::string base = "bonded";

  bool is_half_space() const { return model == "half_space"; }
  /// "layer (6 mm, bonded)"-like words for messages.
  std::string describe() const;
};

struct Scene {
  std::string description;
  MaterialModel material;
  RollerProfile roller;
  double load = 0;  ///< N (line, bem) or N/m (plane)
  std::vector<double> speeds;
  std::optional<Method> method;
  std::optional<long> grid;
  /// "setting": "default" or "fast" (none: not given), the line method's setting
  /// (viscoroll-solve --setting, which replaces it); the plane and bem methods ignore it.
  std::optional<LineSetting> setting;
  /// The top level's "temperature" (degrees Celsius): a prony material with a shift only.
  std::vector<double> temperatures;
  /// "tolerance": the bem method's relative accuracy in d and chi (BemOptions::tolerance), or the
  /// plane method's on a layer or a spring bed in a, d and chi (PlaneSubstrateOptions::tolerance);
  /// read in either range, checked against the method's by check_scene_for_method
  /// (viscoroll-solve --tolerance replaces it).
  std::optional<double> tolerance;
  /// "density" (kg/m^3): the rubber's, for the quasi-static check (core/validity.hpp, (V4)).
  std::optional<double> density;
  /// "strict": a result outside its model's assumptions is an error (viscoroll-solve --strict).
  bool strict = false;
  SubstrateSpec substrate = {};
};

/// The largest scene file read, in bytes (viscoroll::limits::scene_file_bytes).
inline constexpr std::size_t max_scene_bytes = limits::scene_file_bytes;

namespace scene_detail {

using nlohmann::json;

/// Why `text` is not UTF-8 text, or empty if it is: a UTF-16 or UTF-32 byte order mark, a NUL
/// byte (UTF-16 text without a mark) or the first byte that is not part of a UTF-8 sequence.
inline std::string not_utf8(std::string_view text) {
  const auto starts = [&](std::string_view mark) { return text.substr(0, mark.size()) == mark; };
  if (starts(std::string_view("\xFF\xFE\0\0", 4)) || starts(std::string_view("\0\0\xFE\xFF", 4)))
    return "a UTF-32 byte order mark";
  if (starts("\xFF\xFE") || starts("\xFE\xFF")) return "a UTF-16 byte order mark";
  const auto bad = [](std::size_t at, unsigned char byte) -> std::string {
    if (byte == 0) return "a NUL byte at offset " + std::to_string(at) + ", as in UTF-16 text";
    char hex[2] = {"0123456789abcdef"[byte >> 4], "0123456789abcdef"[byte & 15]};
    return "byte 0x" + std::string(hex, 2) + " at offset " + std::to_string(at);
  };
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == 0) return bad(i, c);
    // The length of the sequence a lead byte starts, and the range of its second byte
    // (excluding overlong forms, surrogates and code points beyond U+10FFFF).
    std::size_t length = 1;
    unsigned char lo = 0x80, hi = 0xBF;
    if (c < 0x80) {
      ++i;
      continue;
    } else if (c >= 0xC2 && c <= 0xDF) {
      length = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
      length = 3;
      if (c == 0xE0) lo = 0xA0;
      if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      length = 4;
      if (c == 0xF0) lo = 0x90;
      if (c == 0xF4) hi = 0x8F;
    } else {
      return bad(i, c);
    }
    for (std::size_t k = 1; k < length; ++k) {
      if (i + k >= text.size()) return bad(i, c);
      const auto next = static_cast<unsigned char>(text[i + k]);
      if (next < (k == 1 ? lo : 0x80) || next > (k == 1 ? hi : 0xBF)) return bad(i + k, next);
    }
    i += length;
  }
  return {};
}

/// The shortest decimal that reads back as x ("0.7", "inf").
inline std::string shortest(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
  return ec == std::errc() ? std::string(buffer, end) : std::string("?");
}

inline std::string type_of(const json& value) {
  if (value.is_number_integer()) return "integer";
  if (value.is_number()) return "number";
  return value.type_name();
}

/// One JSON object of the scene, read key by key. The constructor rejects keys outside
/// `allowed` (unless it is empty); each reader names the key with its path in its error.
class ObjectReader {
 public:
  ObjectReader(std::string source, const json& object, std::string path,
               std::vector<std::string> allowed, std::string what)
      : source_(std::move(source)), object_(object), path_(std::move(path)) {
    if (!object_.is_object())
      fail((path_.empty() ? std::string("the scene") : path_) + " must be a JSON object, got " +
           type_of(object_));
    for (const auto& item : object_.items())
      if (!allowed.empty() &&
          std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end()) {
        std::string list;
        for (const auto& key : allowed) {
          if (!list.empty()) list += ", ";
          list += key;
        }
        fail("unknown key " + name(item.key()) + " (" + what + " has the keys " + list + ")");
      }
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw std::invalid_argument("viscoroll-solve: " + source_ + ": " + message);
  }

  std::string name(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }

  bool has(std::string_view key) const { return object_.contains(key); }

  const json& at(std::string_view key) const {
    const auto it = object_.find(key);
    if (it == object_.end()) fail("missing key " + name(key));
    return *it;
  }

  std::string string(std::string_view key) const {
    const json& value = at(key);
    if (!value.is_string()) fail(name(key) + " must be a string, got " + type_of(value));
    return value.get<std::string>();
  }

  /// A number that meets `ok`, else an error quoting the key's range_of().
  double number(std::string_view key, const std::function<bool(double)>& ok) const;

  double checked_number(const json& value, const std::string& label,
                        const std::function<bool(double)>& ok, std::string_view range) const {
    if (!value.is_number()) fail(label + " must be a number, got " + type_of(value));
    const double x = value.get<double>();
    if (!std::isfinite(x) || !ok(x))
      fail(label + " = " + shortest(x) + " is outside the valid range " + std::string(range));
    return x;
  }

  const std::string& source() const { return source_; }

 private:
  std::string source_;
  const json& object_;
  std::string path_;
};

/// The valid range of each numeric key (the last part of its path; "speeds" for each speed), as
/// the library's validate() states it, with the unit.
inline std::string range_of(std::string_view key) {
  static const std::vector<std::pair<std::string_view, std::string_view>> ranges = {
      {"mu", "mu > 0 (Pa, finite)"},
      {"mu_d", "mu_d > 0 (Pa, finite)"},
      {"nu", "-1 < nu <= 0.5"},
      {"f", "f >= 0 (finite)"},
      {"tau", "tau >= 0 (s, finite)"},
      {"c1", "c1 > 0 (1/m, finite)"},
      {"c2", "c2 > 0 (1/m, finite; line: c2 < 8 e^-3 c1)"},
      {"radius", "radius > 0 (m, finite)"},
      {"flat_length", "flat_length >= 0 (m, finite)"},
      {"crown_radius", "crown_radius > 0 (m, finite)"},
      {"length", "length > 0 (m, finite; crowned: length > flat_length)"},
      {"scale", "scale > 0 (m, finite)"},
      {"end_drop", "end_drop > 0 (m, finite; leave it out for Lundberg's profile)"},
      {"tilt", "|tilt| < 0.1 (rad)"},
      {"load", "load > 0 (N; N/m for the plane method; finite)"},
      {"speeds", "speed >= 0 (m/s, finite)"},
      {"grid", "1 <= grid <= 64 (line), 2 <= grid <= 512 (bem)"},
      {"tolerance",
       "0 (one grid) or 1e-4 <= tolerance <= 0.5 (bem: relative, in d and chi), or "
       "64 eps = 1.4e-14 <= tolerance <= 0.1 (plane on a layer or a spring bed: relative, in a, d "
       "and chi)"},
      {"density", "density > 0 (kg/m^3, finite)"},
      {"g_inf", "g_inf > 0 (Pa, finite)"},
      {"g", "g >= 0 (Pa, finite)"},
      {"activation_energy", "activation_energy > 0 (J/mol, finite)"},
      {"temperature", "a finite temperature (degrees Celsius) above the shift law's limit"},
      {"thickness", "thickness > 0 (m, finite)"},
  };
  for (const auto& [name, range] : ranges)
    if (name == key) return std::string(range);
  return "a finite number";
}

inline double ObjectReader::number(std::string_view key,
                                   const std::function<bool(double)>& ok) const {
  return checked_number(at(key), name(key), ok, range_of(key));
}

inline bool positive(double x) { return x > 0; }
inline bool non_negative(double x) { return x >= 0; }
inline bool poisson(double x) { return x > -1 && x <= 0.5; }
inline bool finite(double x) { return std::isfinite(x); }

/// The shift law at `key` of `r` ("material.shift").
/// "substrate": {"model": ..., "thickness": ..., "base": ...}; thickness for a layer or a bed
/// only, base for a layer only.
inline SubstrateSpec read_substrate(const ObjectReader& top) {
  const ObjectReader r(top.source(), top.at("substrate"), "substrate",
                       {"model", "thickness", "base"}, "substrate");
  SubstrateSpec s;
  s.model = r.string("model");
  if (s.model != "half_space" && s.model != "layer" && s.model != "spring_bed")
    r.fail("substrate.model = \"" + s.model + "\" is not one of half_space, layer, spring_bed");
  if (s.is_half_space()) {
    if (r.has("thickness") || r.has("base"))
      r.fail("substrate.model = \"half_space\" takes no thickness or base");
    return s;
  }
  s.thickness = r.number("thickness", positive);
  if (r.has("base")) {
    if (s.model != "layer")
      r.fail("substrate.base is a layer's (bonded or frictionless), not a spring_bed's");
    s.base = r.string("base");
    if (s.base != "bonded" && s.base != "frictionless")
      r.fail("substrate.base = \"" + s.base + "\" is not one of bonded, frictionless");
  }
  return s;
}

inline ShiftSpec read_shift(const ObjectReader& r, std::string_view key) {
  const std::string path = r.name(key);
  const ObjectReader head(r.source(), r.at(key), path, {}, path);
  ShiftSpec s;
  s.law = head.string("law");
  const auto number = [](const ObjectReader& o, std::string_view k,
                         const std::function<bool(double)>& ok, std::string_view range) {
    return o.checked_number(o.at(k), o.name(k), ok, range);
  };
  if (s.law == "wlf") {
    const ObjectReader o(r.source(), r.at(key), path, {"law", "c1", "c2", "t_ref"},
                         path + " of law wlf");
    s.c1 = number(o, "c1", positive, "c1 > 0 (finite)");
    s.c2 = number(o, "c2", positive, "c2 > 0 (K, finite)");
    s.t_ref = number(
        o, "t_ref", [](double) { return true; }, "t_ref finite (degrees Celsius)");
  } else if (s.law == "arrhenius") {
    const ObjectReader o(r.source(), r.at(key), path, {"law", "activation_energy", "t_ref"},
                         path + " of law arrhenius");
    s.activation_energy =
        number(o, "activation_energy", positive, "activation_energy > 0 (J/mol, finite)");
    s.t_ref = number(
        o, "t_ref", [](double t) { return t > -273.15; },
        "t_ref > -273.15 (degrees Celsius, finite)");
  } else {
    head.fail(head.name("law") + " = \"" + s.law + "\" is not one of wlf, arrhenius");
  }
  return s;
}

/// The prony material: nu, then either g_inf and terms or dma, and an optional shift.
inline MaterialModel read_prony(const ObjectReader& r) {
  PronyModel m;
  m.nu = r.number("nu", poisson);
  const bool terms = r.has("terms"), dma = r.has("dma");
  if (terms && dma)
    r.fail(r.name("terms") + " and " + r.name("dma") +
           " are both given; give one (the relaxation terms, or a DMA CSV file to fit them from)");
  if (!terms && !dma)
    r.fail("missing key " + r.name("terms") + " (or " + r.name("dma") +
           ", a DMA CSV file to fit the terms from)");
  if (terms) {
    m.g_inf = r.number("g_inf", positive);
    const json& list = r.at("terms");
    const std::string path = r.name("terms");
    if (!list.is_array())
      r.fail(path + " must be an array of objects {\"g\": ..., \"tau\": ...}, got " +
             type_of(list));
    if (list.empty()) r.fail(path + " is empty; give at least one term {\"g\": ..., \"tau\": ...}");
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string item = path + "[" + std::to_string(k) + "]";
      const ObjectReader t(r.source(), list[k], item, {"g", "tau"}, item);
      m.terms.push_back(
          {t.checked_number(t.at("g"), t.name("g"), non_negative, "g >= 0 (Pa, finite)"),
           t.checked_number(t.at("tau"), t.name("tau"), positive, "tau > 0 (s, finite)")});
    }
  } else {
    if (r.has("g_inf"))
      r.fail("unknown key " + r.name("g_inf") +
             " with dma (the fit gives the long-term modulus; give g_inf with terms only)");
    m.dma = r.string("dma");
    if (m.dma.empty()) r.fail(r.name("dma") + " is empty; give a DMA CSV file's name");
  }
  if (r.has("shift")) m.shift = read_shift(r, "shift");
  return m;
}

/// The shift law's limit on temperature: a number at which a_T is finite, with its range.
inline void check_temperature(const ObjectReader& top, const std::string& label, double t,
                              const ShiftSpec& shift) {
  if (shift.law == "wlf") {
    const double limit = shift.t_ref - shift.c2;
    if (!(t > limit))
      top.fail(label + " = " + shortest(t) +
               " is outside the valid range temperature > t_ref - c2 = " + shortest(limit) +
               " (degrees Celsius; the WLF shift is singular at t_ref - c2)");
  } else if (!(t > -273.15)) {
    top.fail(label + " = " + shortest(t) +
             " is outside the valid range temperature > -273.15 (degrees Celsius)");
  }
  // a_T must be a finite positive number (WLF far below t_ref, Arrhenius near absolute zero).
  const double log_a =
      shift.law == "wlf"
          ? -shift.c1 * (t - shift.t_ref) / (shift.c2 + t - shift.t_ref) * std::log(10.0)
          : shift.activation_energy / 8.31446261815324 * (shift.t_ref - t) /
                ((t + 273.15) * (shift.t_ref + 273.15));
  const double a = std::exp(log_a);
  if (!(std::isfinite(a) && a > 0))
    top.fail(label + " = " + shortest(t) +
             " is outside the valid range of a temperature at which the shift factor a_T is "
             "finite and positive (ln a_T = " +
             shortest(log_a) + ")");
}

struct MaterialReader {
  std::string model;
  std::vector<std::string> keys;  ///< besides "model"
  std::function<MaterialModel(const ObjectReader&)> read;
};

inline const std::vector<MaterialReader>& material_readers() {
  static const std::vector<MaterialReader> readers = {
      {"elastic",
       {"mu", "nu"},
       [](const ObjectReader& r) -> MaterialModel {
         return ElasticModel{r.number("mu", positive), r.number("nu", poisson)};
       }},
      {"standard_linear_solid",
       {"mu_d", "nu", "f", "tau"},
       [](const ObjectReader& r) -> MaterialModel {
         return StandardLinearSolidModel{r.number("mu_d", positive), r.number("nu", poisson),
                                         r.number("f", non_negative),
                                         r.number("tau", non_negative)};
       }},
      {"prony", {"nu", "g_inf", "terms", "dma", "shift"}, read_prony},
  };
  return readers;
}

/// The optional "tilt" of a roller (rad, |tilt| < 0.1; 0 when absent).
inline double read_tilt(const ObjectReader& r) {
  if (!r.has("tilt")) return 0;
  return r.number("tilt", [](double x) { return std::abs(x) < 0.1; });
}

/// The array of numbers at `key` (at least `min_size`, each finite), named "roller.y[3]".
inline std::vector<double> read_numbers(const ObjectReader& r, std::string_view key,
                                        std::size_t min_size) {
  const json& list = r.at(key);
  const std::string path = r.name(key);
  if (!list.is_array()) r.fail(path + " must be an array of numbers, got " + type_of(list));
  if (list.size() < min_size)
    r.fail(path + " has " + std::to_string(list.size()) + " values; give at least " +
           std::to_string(min_size));
  std::vector<double> out;
  for (std::size_t k = 0; k < list.size(); ++k)
    out.push_back(r.checked_number(list[k], path + "[" + std::to_string(k) + "]", finite,
                                   "a finite number (m)"));
  return out;
}

struct RollerReader {
  std::string profile;
  std::vector<std::string> keys;  ///< besides "profile"
  std::function<RollerProfile(const ObjectReader&)> read;
};

inline const std::vector<RollerReader>& roller_readers() {
  static const std::vector<RollerReader> readers = {
      {"ellipsoid",
       {"c1", "c2"},
       [](const ObjectReader& r) -> RollerProfile {
         return EllipsoidProfile{r.number("c1", positive), r.number("c2", positive)};
       }},
      {"cylinder",
       {"radius"},
       [](const ObjectReader& r) -> RollerProfile {
         return CylinderProfile{r.number("radius", positive)};
       }},
      {"crowned",
       {"radius", "flat_length", "crown_radius", "length", "tilt"},
       [](const ObjectReader& r) -> RollerProfile {
         CrownedProfile c;
         c.radius = r.number("radius", positive);
         c.flat_length = r.number("flat_length", non_negative);
         c.crown_radius = r.number("crown_radius", positive);
         if (r.has("length")) {
           c.length = r.number("length", positive);
           if (!(c.length > c.flat_length))
             r.fail(r.name("length") + " = " + shortest(c.length) +
                    " is outside the valid range length > flat_length = " +
                    shortest(c.flat_length) + " (m)");
         }
         c.tilt = read_tilt(r);
         return c;
       }},
      {"logarithmic",
       {"radius", "length", "scale", "end_drop", "tilt"},
       [](const ObjectReader& r) -> RollerProfile {
         LogarithmicProfile g;
         g.radius = r.number("radius", positive);
         g.length = r.number("length", positive);
         g.scale = r.number("scale", positive);
         if (r.has("end_drop")) g.end_drop = r.number("end_drop", positive);
         g.tilt = read_tilt(r);
         return g;
       }},
      {"table",
       {"radius", "y", "h", "tilt"},
       [](const ObjectReader& r) -> RollerProfile {
         TableProfile t;
         t.radius = r.number("radius", positive);
         t.y = read_numbers(r, "y", 4);
         t.h = read_numbers(r, "h", 4);
         if (t.h.size() != t.y.size())
           r.fail(r.name("h") + " has " + std::to_string(t.h.size()) +
                  " values; give one per point of " + r.name("y") + " (" +
                  std::to_string(t.y.size()) + ")");
         for (std::size_t k = 1; k < t.y.size(); ++k)
           if (!(t.y[k] > t.y[k - 1]))
             r.fail(r.name("y") + "[" + std::to_string(k) + "] = " + shortest(t.y[k]) +
                    " is outside the valid range y[k] > y[k-1] = " + shortest(t.y[k - 1]) +
                    " (m, strictly increasing)");
         if (!(t.y.front() < 0 && t.y.back() > 0))
           r.fail(r.name("y") + " = [" + shortest(t.y.front()) + " ... " + shortest(t.y.back()) +
                  "] must hold y = 0 strictly inside (the roller's centre section)");
         t.tilt = read_tilt(r);
         return t;
       }},
  };
  return readers;
}

/// Reads the object at `key` of `parent` with the reader its `selector` key names.
template <class Result, class Reader>
Result read_by_kind(const ObjectReader& parent, std::string_view key, std::string_view selector,
                    const std::vector<Reader>& readers, std::string Reader::*kind) {
  const json& object = parent.at(key);
  const std::string path = parent.name(key);
  std::string kinds;
  for (const auto& reader : readers) {
    if (!kinds.empty()) kinds += ", ";
    kinds += reader.*kind;
  }
  // The selector first, so that an unknown key is reported with the keys of the right kind.
  const ObjectReader head(parent.source(), object, path, {}, path);
  const std::string name = head.string(selector);
  for (const auto& reader : readers)
    if (reader.*kind == name) {
      std::vector<std::string> allowed = {std::string(selector)};
      allowed.insert(allowed.end(), reader.keys.begin(), reader.keys.end());
      const ObjectReader r(parent.source(), object, path, allowed,
                           path + " of " + std::string(selector) + " " + name);
      return reader.read(r);
    }
  head.fail(head.name(selector) + " = \"" + name + "\" is not one of " + kinds);
}

/// Follows the parser through the document: rejects a key repeated within one object
/// (nlohmann-json would keep the last) and knows the path of the value being read, for the
/// parser's own errors (a number that overflows a double).
class PathTracker {
 public:
  explicit PathTracker(std::string source) : source_(std::move(source)) {}

  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
        frames_.push_back({event == json::parse_event_t::array_start, {}, {}, -1});
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!frames_.empty()) frames_.pop_back();
        break;
      case json::parse_event_t::key:
        if (!frames_.empty()) {
          frames_.back().key = parsed.get<std::string>();
          if (!frames_.back().keys.insert(frames_.back().key).second)
            throw std::invalid_argument("viscoroll-solve: " + source_ + ": duplicate key " +
                                        path() + " (each key may appear once per object)");
        }
        break;
      case json::parse_event_t::value:
        if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
        break;
    }
    return true;
  }

  /// The path of the value being read ("material.f", "speeds[2]").
  std::string path(bool next_element = false) const {
    std::string out;
    for (std::size_t k = 0; k < frames_.size(); ++k) {
      const Frame& f = frames_[k];
      if (f.array) {
        const long index = f.index + (next_element && k + 1 == frames_.size() ? 1 : 0);
        out += '[';
        out += std::to_string(index < 0 ? 0 : index);
        out += ']';
      } else {
        if (!out.empty()) out += '.';
        out += f.key;
      }
    }
    return out;
  }

  /// The last part of path(): the key, or the array's key for an element.
  std::string key() const {
    for (auto f = frames_.rbegin(); f != frames_.rend(); ++f)
      if (!f->array) return f->key;
    return "";
  }

 private:
  struct Frame {
    bool array;
    std::set<std::string> keys;
    std::string key;
    long index;
  };
  std::string source_;
  std::vector<Frame> frames_;
};

}  // namespace scene_detail

/// The scene in `text`; `source` (the file's name) starts every error message.
inline Scene parse_scene(std::string_view text, const std::string& source) {
  using scene_detail::json;
  using scene_detail::ObjectReader;
  if (text.size() > max_scene_bytes)
    throw std::invalid_argument(
        "viscoroll-solve: " + source + ": size = " + std::to_string(text.size()) +
        " bytes is over the limit of " + viscoroll::detail::byte_size(max_scene_bytes) +
        " for a scene file");
  if (const std::string why = scene_detail::not_utf8(text); !why.empty())
    throw std::invalid_argument("viscoroll-solve: " + source + ": scene file is not UTF-8 text (" +
                                why + "); save it as UTF-8");
  json root;
  scene_detail::PathTracker tracker(source);
  const auto message = [](const json::exception& e) {
    const std::string what = e.what();
    const auto close = what.find("] ");
    return what.starts_with("[json.exception.") && close != std::string::npos
               ? what.substr(close + 2)
               : what;
  };
  try {
    root = json::parse(text.begin(), text.end(),
                       [&tracker](int depth, json::parse_event_t event, json& parsed) {
                         return tracker(depth, event, parsed);
                       });
  } catch (const json::parse_error& e) {
    throw std::invalid_argument("viscoroll-solve: " + source + ": not valid JSON: " + message(e));
  } catch (const json::out_of_range& e) {
    // A number beyond the range of a double (1e999): the parser stops at it.
    std::string what = message(e), literal = "?";
    if (const auto open = what.find('\''), close = what.rfind('\'');
        open != std::string::npos && close > open)
      literal = what.substr(open + 1, close - open - 1);
    const std::string where = tracker.path(true);
    throw std::invalid_argument("viscoroll-solve: " + source + ": " +
                                (where.empty() ? std::string("the scene") : where) + " = " +
                                literal + " is outside the valid range " +
                                scene_detail::range_of(tracker.key()) + " (" + what + ")");
  } catch (const json::exception& e) {
    throw std::invalid_argument("viscoroll-solve: " + source + ": not valid JSON: " + message(e));
  }
  const ObjectReader top(source, root, "",
                         {"description", "material", "roller", "load", "speeds", "method", "grid",
                          "setting", "temperature", "tolerance", "density", "strict", "substrate"},
                         "the scene");
  Scene scene;
  if (top.has("description")) scene.description = top.string("description");
  scene.material = scene_detail::read_by_kind<MaterialModel>(top, "material", "model",
                                                             scene_detail::material_readers(),
                                                             &scene_detail::MaterialReader::model);
  scene.roller = scene_detail::read_by_kind<RollerProfile>(top, "roller", "profile",
                                                           scene_detail::roller_readers(),
                                                           &scene_detail::RollerReader::profile);
  scene.load = top.number("load", scene_detail::positive);
  const json& speeds = top.at("speeds");
  if (!speeds.is_array())
    top.fail("speeds must be an array of numbers, got " + scene_detail::type_of(speeds));
  if (speeds.empty()) top.fail("speeds is empty; give at least one speed >= 0 (m/s)");
  if (const std::string over =
          viscoroll::detail::count_over_limit("speeds", speeds.size(), limits::speeds);
      !over.empty())
    top.fail(over);
  for (std::size_t k = 0; k < speeds.size(); ++k)
    scene.speeds.push_back(top.checked_number(speeds[k], "speeds[" + std::to_string(k) + "]",
                                              scene_detail::non_negative,
                                              scene_detail::range_of("speeds")));
  if (top.has("method")) {
    const std::string method = top.string("method");
    scene.method = parse_method(method);
    if (!scene.method) top.fail("method = \"" + method + "\" is not one of plane, line, bem, auto");
  }
  if (top.has("grid")) {
    const json& grid = top.at("grid");
    if (!grid.is_number_integer())
      top.fail("grid must be an integer, got " + scene_detail::type_of(grid));
    const bool ok =
        grid.is_number_unsigned()
            ? grid.get<unsigned long long>() >= 1 && grid.get<unsigned long long>() <= 512
            : grid.get<long long>() >= 1 && grid.get<long long>() <= 512;
    if (!ok)
      top.fail("grid = " + grid.dump() + " is outside the valid range " +
               scene_detail::range_of("grid"));
    scene.grid = grid.get<long>();
  }
  if (top.has("tolerance")) {
    // Either method's range here; the method's own in check_scene_for_method.
    scene.tolerance = top.number("tolerance", [](double x) {
      return tolerance_in_range(x, false) || tolerance_in_range(x, true);
    });
  }
  if (top.has("density")) scene.density = top.number("density", scene_detail::positive);
  if (top.has("strict")) {
    const json& strict = top.at("strict");
    if (!strict.is_boolean())
      top.fail("strict must be true or false, got " + scene_detail::type_of(strict));
    scene.strict = strict.get<bool>();
  }
  if (top.has("setting")) {
    const std::string setting = top.string("setting");
    scene.setting = parse_line_setting(setting);
    if (!scene.setting) top.fail("setting = \"" + setting + "\" is not one of default, fast");
  }
  if (top.has("substrate")) scene.substrate = scene_detail::read_substrate(top);
  if (top.has("temperature")) {
    const auto* prony = std::get_if<PronyModel>(&scene.material);
    if (!prony || !prony->shift)
      top.fail(
          "temperature is given but the material has no shift law: it is valid only with a "
          "material of model prony with a \"shift\" (wlf or arrhenius)");
    const json& t = top.at("temperature");
    const auto one = [&](const json& value, const std::string& label) {
      const double x = top.checked_number(value, label, scene_detail::finite,
                                          scene_detail::range_of("temperature"));
      scene_detail::check_temperature(top, label, x, *prony->shift);
      scene.temperatures.push_back(x);
    };
    if (t.is_array()) {
      if (t.empty())
        top.fail("temperature is empty; give a number or a non-empty list (degrees Celsius)");
      for (std::size_t k = 0; k < t.size(); ++k)
        one(t[k], "temperature[" + std::to_string(k) + "]");
    } else {
      one(t, "temperature");
    }
  }
  return scene;
}

/// The scene file's name of a roller profile ("crowned").
inline std::string roller_profile_name(const RollerProfile& r) {
  static const char* const names[] = {"ellipsoid", "cylinder", "crowned", "logarithmic", "table"};
  return names[r.index()];
}

/// The tilt of a roller of finite length (rad); 0 for the ellipsoid and the cylinder.
inline double roller_tilt(const RollerProfile& r) {
  return std::visit(
      [](const auto& p) -> double {
        if constexpr (requires { p.tilt; })
          return p.tilt;
        else
          return 0;
      },
      r);
}

inline std::string SubstrateSpec::describe() const {
  if (is_half_space()) return "half_space";
  return model + " (thickness " + scene_detail::shortest(thickness) + " m" +
         (model == "layer" ? ", " + base : std::string()) + ")";
}

/// Checks what depends on the method: the cylinder is the plane method's roller only; a roller
/// of finite length (crowned, logarithmic, table; tilted or not) is the bem's and the line
/// method's, on any material (LineSolver::solve(LineProfileScene), of a spectrum by
/// docs/theory.md (RP5)); the line method needs a slender
/// contact (0 < c2 < 8 e^-3 c1, LineScene::validate), the bem method 1e-10 <= c2/c1 <= 1e10
/// (BemScene::validate); a layer or a spring bed is the bem's and the plane method's
/// (PlaneSubstrateSolver), not the line theory's; the file's grid and tolerance, their method's
/// range (the auto method on a cylinder answers by the plane method, which takes no grid).
inline void check_scene_for_method(const Scene& scene, Method method, const std::string& source) {
  const auto fail = [&](const std::string& message) {
    throw std::invalid_argument("viscoroll-solve: " + source + ": " + message);
  };
  const std::string m = method_name(method);
  const bool cylinder = std::holds_alternative<CylinderProfile>(scene.roller);
  // A layer or a bed is the bem's and the plane method's: the line theory is the half space's.
  if (!scene.substrate.is_half_space() && method == Method::line)
    fail("substrate.model = \"" + scene.substrate.model +
         "\" is solved by the bem method, and on a \"cylinder\" roller by the plane method, not by "
         "line: the line method's theory is the half space's (give \"method\": " +
         (cylinder ? "\"plane\" or \"auto\")" : "\"bem\" or \"auto\")"));
  if (is_axial_profile(scene.roller)) {
    const std::string profile = "roller.profile = \"" + roller_profile_name(scene.roller) + "\"";
    if (method == Method::plane)
      fail(profile + " suits the line and bem methods, not plane (docs/rollers.md)");
  }
  if (std::holds_alternative<CylinderProfile>(scene.roller) && method != Method::plane &&
      method != Method::automatic)
    fail("roller.profile = \"cylinder\" suits the plane method only, not " + m +
         " (the line and bem methods need \"ellipsoid\" with c1 and c2, or a roller of finite "
         "length: crowned, logarithmic, table)");
  if (const auto* e = std::get_if<EllipsoidProfile>(&scene.roller)) {
    const double ratio = e->c2 / e->c1;
    const double max_ratio = 8 * std::exp(-3.0);
    if (method == Method::line && !(ratio < max_ratio))
      fail("roller.c2 = " + scene_detail::shortest(e->c2) +
           " is outside the valid range 0 < c2 < 8 e^-3 c1 = " +
           scene_detail::shortest(max_ratio * e->c1) +
           " for the line method (a contact longer in y than in x; the bem method has no such "
           "limit)");
    if (method == Method::bem && !(ratio >= 1e-10 && ratio <= 1e10))
      fail("roller.c2 = " + scene_detail::shortest(e->c2) +
           " is outside the valid range 1e-10 <= c2/c1 <= 1e10 for the bem method (c2/c1 = " +
           scene_detail::shortest(ratio) + ")");
  }
  if (scene.grid && method == Method::automatic && !cylinder)
    fail("grid = " + std::to_string(*scene.grid) +
         " needs a method: the auto method picks line or bem per result, each at its own "
         "default (give \"method\": \"line\" or \"bem\" with a grid)");
  if (method == Method::automatic && std::get_if<EllipsoidProfile>(&scene.roller)) {
    const auto& e = std::get<EllipsoidProfile>(scene.roller);
    if (!(e.c2 / e.c1 >= 1e-10 && e.c2 / e.c1 <= 1e10))
      fail("roller.c2 = " + scene_detail::shortest(e.c2) +
           " is outside the valid range 1e-10 <= c2/c1 <= 1e10 (c2/c1 = " +
           scene_detail::shortest(e.c2 / e.c1) + ")");
  }
  if (scene.grid) {
    const long n = *scene.grid;
    if (method == Method::line && n > 64)
      fail("grid = " + std::to_string(n) +
           " is outside the valid range 1 <= grid <= 64 for the line method (Chebyshev terms)");
    if (method == Method::bem && (n < 2 || n > 512))
      fail("grid = " + std::to_string(n) +
           " is outside the valid range 2 <= grid <= 512 for the bem method (elements per "
           "semi-axis)");
  }
  // The tolerance of the method that takes it: the plane method's on a layer or a bed, else the
  // bem's (the bem, the auto method off the cylinder); the others ignore it.
  const bool plane_substrate = solves_plane_substrate(scene.substrate.model, method, cylinder);
  if (scene.tolerance &&
      (plane_substrate || method == Method::bem || (method == Method::automatic && !cylinder)) &&
      !tolerance_in_range(*scene.tolerance, plane_substrate))
    fail("tolerance = " + scene_detail::shortest(*scene.tolerance) +
         " is outside the valid range " + tolerance_range("tolerance", plane_substrate));
}

/// The text of the scene file `path`: an error if it is missing, a directory or another file
/// that is not a regular one (a FIFO, /dev/zero), larger than max_scene_bytes, or empty
/// (viscoroll::detail::read_bounded_file).
inline std::string read_scene_file(const std::string& path) {
  const auto fail = [&](const std::string& message) {
    throw std::invalid_argument("viscoroll-solve: " + path + ": " + message);
  };
  std::string text =
      viscoroll::detail::read_bounded_file(path, max_scene_bytes, "scene file", fail);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    fail("is empty; a scene file is a JSON object (docs/cli.md)");
  return text;
}

}  // namespace viscoroll::cli
