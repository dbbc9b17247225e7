// The fields of a line solution in the command line's JSON order (docs/cli.md, "Output"), shared
// by viscoroll-solve and the Python bindings so that both print the same record.
#pragma once

#include <cmath>
#include <string>
#include <utility>

#include "engineering.hpp"
#include "outcome_fields.hpp"

namespace viscoroll::cli {

/// The stations of LineSolution::along_roller behind the record's f0_max, f0_max_y and the rows
/// of --profile-out: 65 evenly spaced inside (-l, l), y = 0 among them.
inline constexpr int line_profile_stations = 65;

/// The peak of the load per unit length over the stations of along_roller(stations) (LineSolution)
/// and where it is (the first of equal peaks): F0(y)/f0_per_load() (the
/// long-term compliance, (1 + f) c of Eq. 47 with (52)) at y = l (2k/(stations + 1) - 1),
/// k = 1..stations, computed as along_roller computes them but without its strips' peak pressures
/// (about 5 us against 3-8 ms a solve on the paper's scene); cli_line_profile.test.cpp checks it
/// against --profile-out's rows, which are along_roller's.
/// Both are NaN (null in the record) where a station's value is not a finite double: the load per
/// unit length of a scene whose numbers lie near the ends of the range (load/length beyond it),
/// as vtau where speed * tau overflows (docs/cli.md).
template <class Solution>
std::pair<double, double> line_f0_peak(const Solution& s, int stations) {
  const double per_load = s.f0_per_load();
  double peak = 0, at = 0;
  for (int k = 1; k <= stations; ++k) {
    const double y = s.shape.centre + s.l() * (double(2 * k) / double(stations + 1) - 1);
    const double f0 = s.f0(y) / per_load;
    if (!std::isfinite(f0)) return {std::nan(""), std::nan("")};
    if (f0 > peak) {
      peak = f0;
      at = y;
    }
  }
  return {peak, at};
}

/// The fields of a line solution `s` (LineSolution, any material) after the record's
/// head (method, the material's keys, speed): the contact's shape up to chi (a0, b0 at y = 0,
/// both 0 where the contact does not reach y = 0) (with the peak of the
/// load per unit length along the roller, f0_max at f0_max_y, over
/// along_roller(line_profile_stations)'s stations: line_f0_peak; as the bem's record), chi's
/// engineering_fields for `duty`, then `middle` (the peak pressure pmax, pmax_x; a spectrum's
/// active_terms), then the iteration's fields. `Record` is a sequence of (key, value) fields
/// built from braces.
template <class Record, class Solution>
Record line_fields(const Solution& s, const Record& middle, const Duty& duty, int terms,
                   double seconds) {
  const auto [f0_max, f0_max_y] = line_f0_peak(s, line_profile_stations);
  // Where the contact does not reach y = 0 (a tilted roller pressed off the centre) there is no
  // strip at y = 0: a0 = 0 and b0 = 0 (b's series extrapolated there would mean nothing).
  const double a0 = s.a(0.0);
  Record out = {{"a0", a0},
                {"b0", a0 > 0 ? double(s.b(0.0)) : 0.0},
                {"l", s.l()},
                {"y_minus", s.shape.centre - s.l()},
                {"y_plus", s.shape.centre + s.l()},
                {"f0_max", f0_max},
                {"f0_max_y", f0_max_y}};
  const Record shape = {{"d", s.d},
                        {"a_long_term", s.a_long_term},
                        {"l0", s.l_long_term},
                        {"d0", s.d_long_term},
                        {"chi", s.chi}};
  out.insert(out.end(), shape.begin(), shape.end());
  const Record cost = engineering_fields<Record>(s.chi, duty);
  out.insert(out.end(), cost.begin(), cost.end());
  out.insert(out.end(), middle.begin(), middle.end());
  const Record tail = {
      {"seconds", seconds},     {"converged", s.converged},
      {"root", s.root},         {"iterations", static_cast<long long>(s.iterations)},
      {"residual", s.residual}, {"terms", static_cast<long long>(terms)}};
  out.insert(out.end(), tail.begin(), tail.end());
  const Record outcome = outcome_fields<Record>(s);
  out.insert(out.end(), outcome.begin(), outcome.end());
  return out;
}

}  // namespace viscoroll::cli
