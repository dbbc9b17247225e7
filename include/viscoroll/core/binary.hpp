// viscoroll: numbers apart from their binary exponents, for computing in units in which nothing
// overflows or underflows.
//
// A quantity x is held as m 2^e (Binary). Multiplying or dividing by a power of two is exact, so
// a product or quotient of significands rounds exactly as the product or quotient of the numbers
// does wherever that is a normal number: a computation carried out in units that are powers of
// two gives the bits of the same computation in the caller's units where those neither overflow
// nor underflow, and gives the answer where they do (docs/theory.md, "Scaling"). A result is
// converted back with times_power_of_two and checked with detail::representable, which names the
// quantity, its value and the inputs when it is not representable.
#pragma once

#include <bit>
#include <boost/math/special_functions/fpclassify.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>

namespace viscoroll::detail {

/// x = m 2^e with 1 <= |m| < 2 (m = e = 0 for x = 0): a number apart from its binary exponent,
/// so that products and quotients of numbers near the ends of the range neither overflow nor
/// underflow. Scaling by a power of two is exact, so m1 m2 rounds as x1 x2 does wherever x1 x2 is
/// a normal number.
template <RealScalar Real>
struct Binary {
  Real m;  ///< significand, 1 <= |m| < 2, or 0
  int e;   ///< binary exponent
};

/// The biased exponent field of an IEEE binary32 or binary64 Real, or of the x87 80-bit long
/// double, read (get) and written (set) inline: frexp and ldexp are library calls, which would
/// double the cost of an elastic plane solution. `available` is false for other types (128-bit
/// long double, multiprecision), which use frexp and ldexp.
template <class Real>
struct exponent_field {
  static constexpr bool available = false;
};

/// sign | exponent | fraction in one unsigned word Bits.
template <class Real, class Bits>
struct packed_exponent_field {
  static constexpr bool available = std::numeric_limits<Real>::is_iec559;
  static constexpr int shift = std::numeric_limits<Real>::digits - 1;
  static constexpr Bits mask = Bits(2 * std::numeric_limits<Real>::max_exponent - 1) << shift;
  static int get(Real x) { return static_cast<int>((std::bit_cast<Bits>(x) & mask) >> shift); }
  static Real set(Real x, int field) {
    return std::bit_cast<Real>((std::bit_cast<Bits>(x) & ~mask) | (Bits(field) << shift));
  }
};
template <>
struct exponent_field<float> : packed_exponent_field<float, std::uint32_t> {};
template <>
struct exponent_field<double> : packed_exponent_field<double, std::uint64_t> {};

/// The x87 layout: 64-bit significand with its integer bit, then sign and 15-bit exponent.
struct x87_long_double {
  std::uint64_t significand;
  std::uint16_t sign_exponent;
  std::uint16_t padding[3];
};
template <>
struct exponent_field<long double> {
  using limits = std::numeric_limits<long double>;
  static constexpr bool available = limits::digits == 64 && limits::max_exponent == 16384 &&
                                    sizeof(long double) == sizeof(x87_long_double);
  template <class L = long double>  // a template: bit_cast is checked only where available
  static int get(L x) {
    return std::bit_cast<x87_long_double>(x).sign_exponent & 0x7fff;
  }
  template <class L = long double>
  static L set(L x, int field) {
    auto bits = std::bit_cast<x87_long_double>(x);
    bits.sign_exponent = static_cast<std::uint16_t>((bits.sign_exponent & 0x8000) | field);
    return std::bit_cast<L>(bits);
  }
};

/// binary() by frexp: for zero, subnormal numbers and types without an exponent_field.
template <RealScalar Real>
Binary<Real> binary_by_frexp(Real x) {
  using std::frexp;
  if (x == 0) return {Real(0), 0};
  int e = 0;
  const Real m = frexp(x, &e);  // 1/2 <= |m| < 1
  return {2 * m, e - 1};
}

/// x as m 2^e (Binary), exactly (a subnormal x too); x finite.
template <RealScalar Real>
Binary<Real> binary(Real x) {
  using limits = std::numeric_limits<Real>;
  using field = detail::exponent_field<Real>;
  using std::abs;
  if constexpr (field::available) {
    if (abs(x) >= (limits::min)() && abs(x) <= (limits::max)()) {  // normal
      constexpr int bias = limits::max_exponent - 1;
      return {field::set(x, bias), field::get(x) - bias};
    }
  }
  return detail::binary_by_frexp(x);
}

/// x 2^n, as std::ldexp (one rounding where the result is subnormal, inf where it overflows).
template <RealScalar Real>
Real times_power_of_two(Real x, int n) {
  using limits = std::numeric_limits<Real>;
  using field = detail::exponent_field<Real>;
  if constexpr (field::available) {
    // 2^n normal: x times it rounds once, as ldexp does.
    if (n >= limits::min_exponent - 1 && n < limits::max_exponent)
      return x * field::set(Real(1), n + limits::max_exponent - 1);
  }
  using std::ldexp;
  return ldexp(x, n);
}

/// sqrt(m 2^e), m >= 0, as a Binary: the exponent made even first, so that the root is the one
/// sqrt forms (correctly rounded) wherever m 2^e is a normal number, and is formed where it is not.
template <RealScalar Real>
Binary<Real> binary_sqrt(Real m, int e) {
  using std::sqrt;
  if (e % 2 != 0) m *= 2, e -= 1;
  const Binary<Real> root = binary(sqrt(m));
  return {root.m, root.e + e / 2};
}

/// m 2^e in decimal with three significant digits, also where it is outside Real's range.
template <RealScalar Real>
std::string format_binary(Real m, int e) {
  if (m == 0 || !(boost::math::isfinite)(m)) return format_value(m);
  const Binary<Real> x = binary(m);
  const double digits = std::log10(std::abs(static_cast<double>(x.m))) +
                        (x.e + e) * 0.301029995663981195;  // log10(2)
  int exponent = static_cast<int>(std::floor(digits));
  double significand = std::round(std::pow(10.0, digits - exponent) * 100) / 100;
  if (significand >= 10) significand /= 10, ++exponent;
  std::ostringstream out;
  out << (m < 0 ? "-" : "") << significand << (exponent < 0 ? "e-" : "e+") << std::abs(exponent);
  return out.str();
}

/// The error of representable(): "viscoroll: <what> = <value> is below the smallest normal number
/// <min> (<inputs()>): rescale the units", or beyond the largest finite number.
template <RealScalar Real, class Inputs>
[[noreturn]] void throw_unrepresentable(Real value, int exponent, std::string_view what,
                                        const Inputs& inputs) {
  using limits = std::numeric_limits<Real>;
  std::ostringstream out;
  out << "viscoroll: " << what << " = " << format_binary(value, exponent) << " is ";
  if ((boost::math::isfinite)(times_power_of_two(value, exponent)))
    out << "below the smallest normal number " << format_binary((limits::min)(), 0);
  else
    out << "beyond the largest finite number " << format_binary((limits::max)(), 0);
  out << " (" << inputs() << "): rescale the units";
  throw std::invalid_argument(out.str());
}

/// value 2^exponent, a quantity `what` of a result, which must be a normal finite number (or zero
/// where `zero_allowed`); else throw_unrepresentable, with the inputs named by inputs().
template <RealScalar Real, class Inputs>
Real representable(Real value, int exponent, std::string_view what, const Inputs& inputs,
                   bool zero_allowed = true) {
  using std::abs;
  const Real x = times_power_of_two(value, exponent);
  if ((value == 0 && zero_allowed) ||
      ((boost::math::isfinite)(x) && abs(x) >= (std::numeric_limits<Real>::min)()))
    return x;
  throw_unrepresentable(value, exponent, what, inputs);
}

}  // namespace viscoroll::detail
