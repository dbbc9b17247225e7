// The auto method (docs/cli.md, "The auto method"), shared by viscoroll-solve and the Python
// bindings: a scene is solved by the line method where its theory applies and its answer stands,
// by the bem method (to its default tolerance, 1% in d and chi) otherwise; a cylinder by the
// plane method, the only one it has (on a layer or a spring bed PlaneSubstrateSolver, to its
// tolerance); any other roller on a layer or a bed by the bem. The rules, from the measured model
// errors (docs/theory.md section 18):
//   - before any solve, the ellipsoid needs c2 < 8 e^-3 c1 (the line theory's domain), and the
//     line theory a slender long-term contact, l0/a0 >= 3.6 (V3: its error in d is below
//     0.13 (a0/l)^2, 1% there), that the line theory finds inside the roller and ending at least
//     2.8 a0 before its end (end_loaded), on a roller that curves along its axis inside that
//     contact by less than 8 e^-3 c1, the ellipsoid's limit (axial_curvature_precheck);
//   - the line method is asked for a root only (LineOptions::least_squares off: a least-squares
//     minimum would not answer, and its minimisation can take seconds);
//   - a line result stands if it converged to a root (not a least-squares minimum) without a
//     warning, its contact slender (V3; for two or more active memory terms, the spectrum path,
//     l/a0 >= 12, V3s) and inside the roller (V2).
// Every result of the auto method carries `method_reason`: why its method answered.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <variant>
#include <vector>
#include <viscoroll/core/validity.hpp>

#include "validity_record.hpp"

namespace viscoroll::cli {

/// Words a user can act on where the long-term static contact (half width a0, half length l0,
/// centred on y = 0) ends within 2.8 a0 of the roller's body end (facts): there the line theory
/// cannot describe the contact's end (its crown intrusion is under the 2.8 a(y) that an edge peak
/// needs, docs/theory.md section 16, "Edge peaks"); empty otherwise.
inline std::string end_loaded(double a0, double l0, const ValidityFacts& facts) {
  if (!(std::isfinite(a0) && std::isfinite(l0))) return {};
  const double reach = l0 + 2.8 * a0;
  const bool high = std::isfinite(facts.body_max) && reach >= facts.body_max;
  const bool low = std::isfinite(facts.body_min) && -reach <= facts.body_min;
  if (!high && !low) return {};
  std::ostringstream s;
  s.precision(4);
  s << "the long-term contact reaches y = " << (high ? l0 : -l0) << ", within 2.8 a0 = " << 2.8 * a0
    << " of the roller's end at y = " << (high ? facts.body_max : facts.body_min)
    << ": the line theory does not describe an end-loaded contact";
  return s.str();
}

/// A line result that did not converge on an end-loaded roller (end_loaded): its `reason` says
/// so and names the bem method, in words a user can act on.
template <class Record>
void add_end_hint(Record& record, const ValidityFacts& facts) {
  if (record_flag(record, "converged", true)) return;
  const std::string end =
      end_loaded(record_number(record, "a_long_term"), record_number(record, "l0"), facts);
  if (end.empty()) return;
  if (auto* text = record_value<std::string>(record, "reason"))
    *text += "; " + end + ": use the bem method";
}

/// The reason a plane record gives for a cylinder (the auto method's only choice there).
inline std::string plane_cylinder() {
  return "auto: plane (a cylinder: the plane problem, exact to rounding)";
}

/// The reason a plane record gives for a cylinder on a layer or a spring bed, `substrate` (its
/// SubstrateSpec::describe()): the plane problem on that body (PlaneSubstrateSolver,
/// docs/plane-substrate.md), to the relative `tolerance` in a, d and chi.
inline std::string plane_substrate_cylinder(const std::string& substrate, double tolerance) {
  return "auto: plane (a cylinder on a " + substrate +
         ": the plane problem on the substrate, to the tolerance " +
         scene_detail::shortest(tolerance) + " in a, d and chi)";
}

/// Why the line method does not apply to the ellipsoid of curvatures `c1` across and `c2` along
/// (its theory needs c2 < 8 e^-3 c1, LineScene::validate), or empty.
inline std::string ellipsoid_precheck(double c1, double c2) {
  if (c2 / c1 < 8 * std::exp(-3.0)) return {};
  return "c2/c1 >= 8 e^-3: the contact is longer across than along";
}

/// Why the line method does not apply to a scene whose long-term static contact (the line
/// theory's, or Hertz's for the ellipsoid) has half width `a0` and half length `l0` (NaN: the
/// line theory found none inside the roller), or empty.
inline std::string line_precheck(double a0, double l0, const ValidityFacts& facts) {
  if (!(std::isfinite(a0) && std::isfinite(l0) && a0 > 0))
    return "the line theory's long-term static contact reaches the roller's end";
  if (std::string end = end_loaded(a0, l0, facts); !end.empty()) return end;
  const double limit = ValidityLimits<double>::slenderness;
  if (!(l0 / a0 >= limit)) {
    std::ostringstream s;
    s.precision(3);
    s << "the long-term contact is not slender: l0/a0 = " << l0 / a0 << " < " << limit
      << " (the line theory's error in d would exceed 1%)";
    return s.str();
  }
  return {};
}

/// Why the line method does not apply to a roller of finite length whose `profile` (a
/// RollerProfile) curves along its axis, inside the long-term static contact |y| <= l0 of half
/// width a0, by more than the line theory's domain allows the ellipsoid (c2 < 8 e^-3 c1,
/// LineScene::validate), or empty. The curvature is the drop's slope difference over a0/2,
/// (h'(y + a0/4) - h'(y - a0/4))/(a0/2), the mean curvature on the contact's own scale, sampled
/// at 257 points of [-l0, l0]: a crown or edge radius that the long-term contact runs onto is
/// caught (a flat idler's edge radius of 0.4 R put the line method's d 1.4% off, one of 0.8 R
/// its chi 3.9%: docs/validation.md).
template <class Profile>
std::string axial_curvature_precheck(const Profile& profile, double a0, double l0) {
  if (!(std::isfinite(a0) && std::isfinite(l0) && a0 > 0 && l0 > 0)) return {};
  const double c1 = profile.c1(), limit = 8 * std::exp(-3.0) * c1, step = a0 / 4;
  const double lo = profile.y_min() + step, hi = profile.y_max() - step;
  double worst = 0, at = 0;
  constexpr int samples = 256;
  for (int k = 0; k <= samples; ++k) {
    const double y = std::clamp(-l0 + 2 * l0 * k / samples, lo, hi);
    const double c =
        std::abs(profile.drop_slope(y + step) - profile.drop_slope(y - step)) / (2 * step);
    if (c > worst) worst = c, at = y;
  }
  if (!(worst >= limit)) return {};
  std::ostringstream s;
  s.precision(3);
  s << "the roller's curvature along its axis reaches " << worst / c1
    << " times its curvature across (" << worst << " against " << c1 << ") at y = " << at
    << ", inside the long-term contact (|y| <= l0 = " << l0
    << "): the line theory needs less than 8 e^-3 = 0.398 times (the ellipsoid's c2 < 8 e^-3 c1)";
  return s.str();
}

/// Why the line method's `record` cannot answer for the auto method (empty: it stands).
template <class Record>
std::string line_rejection(const Record& record, const ValidityFacts& facts) {
  if (!record_flag(record, "converged", false)) {
    // The auto method solves for a root only (LineOptions::least_squares off): a stop at a
    // least-squares minimum says there is none.
    const auto* reason = record_value<std::string>(record, "reason");
    if (reason && reason->find("least-squares minimum") != std::string::npos)
      return "the line equations have no root here (a least-squares minimum)";
    return "the line method did not converge (" + (reason ? *reason : std::string()) + ")";
  }
  if (!record_flag(record, "root", true))
    return "the line equations have no root here (a least-squares minimum)";
  const auto* warnings = record_value<std::vector<std::string>>(record, "warnings");
  if (warnings && !warnings->empty()) return "the line method warned: " + warnings->front();
  for (const auto& b : record_breaches(record, facts))
    if (b.check == ValidityCheck::slenderness || b.check == ValidityCheck::roller_length)
      return b.message;
  return {};
}

/// The reason a line record that stands gives.
inline std::string line_accepted() {
  return "auto: line (the line theory applies: a slender contact inside the roller, a root, no "
         "warning)";
}

/// Why a scene on a layer or a bed goes to the bem (a roller other than the cylinder, which the
/// plane method answers): the line theory is the half space's.
inline std::string substrate_precheck(const std::string& substrate) {
  return "the substrate is a " + substrate + "; the line theory is the half space's";
}

/// The reason a bem record gives when the line method could not answer, `why`.
inline std::string bem_instead(const std::string& why) { return "auto: bem (" + why + ")"; }

/// `record` with the field `method_reason` after its `method`.
template <class Record>
Record with_method_reason(Record record, const std::string& reason) {
  for (auto it = record.begin(); it != record.end(); ++it) {
    const auto& [name, value] = *it;
    if (name == "method") {
      record.insert(it + 1, typename Record::value_type{"method_reason", reason});
      return record;
    }
  }
  record.insert(record.begin(), typename Record::value_type{"method_reason", reason});
  return record;
}

}  // namespace viscoroll::cli
