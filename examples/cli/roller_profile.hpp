// The library's roller profile (roller/profile.hpp) of a scene file's roller of finite length,
// shared by viscoroll-solve and the Python bindings: the bem and line methods take it tilted
// (viscoroll::Tilted).
#pragma once

#include <utility>
#include <viscoroll/roller/profile.hpp>

#include "scene_file.hpp"

namespace viscoroll::cli {

/// The untilted profile of a roller of finite length. The library validates what the scene
/// reader has not (a table's spline) and throws std::invalid_argument naming the parameter.
inline viscoroll::CrownedCylinder<double> library_profile(const CrownedProfile& r) {
  return {r.radius, r.flat_length, r.crown_radius, r.length};
}
inline viscoroll::LogarithmicCrown<double> library_profile(const LogarithmicProfile& r) {
  return {r.radius, r.length, r.scale, r.end_drop};
}
inline viscoroll::TabulatedProfile<double> library_profile(const TableProfile& r) {
  return {r.radius, r.y, r.h};
}

/// f(profile, tilt) with the untilted library profile of `roller`, a roller of finite length
/// (is_axial_profile), and its tilt.
template <class F>
decltype(auto) visit_axial_profile(const RollerProfile& roller, F&& f) {
  if (const auto* c = std::get_if<CrownedProfile>(&roller))
    return std::forward<F>(f)(library_profile(*c), c->tilt);
  if (const auto* g = std::get_if<LogarithmicProfile>(&roller))
    return std::forward<F>(f)(library_profile(*g), g->tilt);
  const auto& t = std::get<TableProfile>(roller);
  return std::forward<F>(f)(library_profile(t), t.tilt);
}

}  // namespace viscoroll::cli
