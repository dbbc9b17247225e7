// viscoroll: input validation shared by every public entry point.
//
// A violation throws std::invalid_argument whose message names the parameter, its value and the
// valid range, e.g. "viscoroll: nu = 0.7 is outside the valid range -1 < nu <= 0.5".
#pragma once

#include <boost/math/special_functions/fpclassify.hpp>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace viscoroll::detail {

template <class Real>
std::string format_value(const Real& value) {
  std::ostringstream out;
  // digits10 prints 0.7 as 0.7, not as its binary expansion.
  out.precision(std::numeric_limits<Real>::is_specialized ? std::numeric_limits<Real>::digits10
                                                          : 17);
  out << value;
  return out.str();
}

/// Throws unless `ok`; `range` is the valid range written as a condition ("mu_d > 0").
template <class Real>
void require(bool ok, std::string_view name, const Real& value, std::string_view range) {
  if (!ok) {
    std::ostringstream out;
    out << "viscoroll: " << name << " = " << format_value(value) << " is outside the valid range "
        << range;
    throw std::invalid_argument(out.str());
  }
}

template <class Real>
void require_finite(std::string_view name, const Real& value, std::string_view range) {
  require((boost::math::isfinite)(value), name, value, range);
}

/// value > 0 and finite.
template <class Real>
void require_positive(std::string_view name, const Real& value) {
  std::string range = std::string(name) + " > 0 (finite)";
  require((boost::math::isfinite)(value) && value > 0, name, value, range);
}

/// value >= 0 and finite.
template <class Real>
void require_non_negative(std::string_view name, const Real& value) {
  std::string range = std::string(name) + " >= 0 (finite)";
  require((boost::math::isfinite)(value) && value >= 0, name, value, range);
}

/// -1 < nu <= 0.5 and finite: the range of Poisson's ratio for a stable isotropic solid.
template <class Real>
void require_poisson_ratio(const Real& nu) {
  require((boost::math::isfinite)(nu) && nu > -1 && nu <= Real(1) / 2, "nu", nu, "-1 < nu <= 0.5");
}

}  // namespace viscoroll::detail
