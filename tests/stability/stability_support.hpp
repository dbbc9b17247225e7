// Shared helpers of the stability matrix (docs/stability.md): finiteness, the scalar's epsilon,
// scenes normalised to a0 = 1, and the optional report of the measured errors
// (VISCOROLL_STABILITY_REPORT=1 viscoroll_tests "[stability]" prints one line per cell).
#pragma once

#include <boost/math/special_functions/fpclassify.hpp>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

namespace stability {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool sanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool sanitized = true;
#else
constexpr bool sanitized = false;
#endif
#else
constexpr bool sanitized = false;
#endif

template <class Real>
Real eps() {
  return std::numeric_limits<Real>::epsilon();
}

template <class Real>
bool finite(const Real& x) {
  return (boost::math::isfinite)(x);
}

/// |x - ref| / |ref| in long double (enough for every comparison made in double or narrower).
template <class Real>
long double rel(const Real& x, long double ref) {
  return std::abs(static_cast<long double>(x) / ref - 1);
}

inline bool reporting() {
  const char* v = std::getenv("VISCOROLL_STABILITY_REPORT");
  return v != nullptr && *v != '\0' && *v != '0';
}

/// One line of the measured-error report (docs/stability.md), only when reporting() is set.
inline void report(const std::string& line) {
  if (reporting()) std::cout << "[stability] " << line << '\n';
}

template <class T>
std::string str(const T& x) {
  std::ostringstream out;
  out.precision(3);
  out << static_cast<long double>(x);
  return out.str();
}

template <class Real>
std::string type_name() {
  if constexpr (std::numeric_limits<Real>::digits == 24) return "float";
  if constexpr (std::numeric_limits<Real>::digits == 53) return "double";
  if constexpr (std::numeric_limits<Real>::digits == 64) return "long double";
  return "mp" + std::to_string(std::numeric_limits<Real>::digits10);
}

}  // namespace stability
