// Probes for the optional parts of viscoroll, shared by the [needs] tests: whether the BEM's
// classes are declared and whether Eigen's FFT module, boost::multiprecision, Eigen itself and
// Boost's Bessel functions were included,
// in the translation unit that includes this header after the headers under test.
//
// The BEM probe: a fallback class of the same name is made visible in viscoroll and
// viscoroll::bem through a using-directive. Qualified lookup finds a real declaration first and
// searches the nominated namespace only when there is none ([namespace.qual]), so the fallback is
// what viscoroll::bem::InfluenceTable<double> names exactly when the BEM header was not included.
#pragma once

#include <viscoroll/material/standard_linear_solid.hpp>

namespace viscoroll_needs_fallback {
template <class...>
struct InfluenceTable {
  static constexpr bool fallback = true;
};
template <class...>
struct BemSolver {
  static constexpr bool fallback = true;
};
}  // namespace viscoroll_needs_fallback

namespace viscoroll {
using namespace ::viscoroll_needs_fallback;
namespace bem {
using namespace ::viscoroll_needs_fallback;
}  // namespace bem
}  // namespace viscoroll

namespace viscoroll_needs {

template <class T>
concept Fallback = T::fallback;

// The values differ between translation units, so they have internal linkage (const, not inline).

/// True when viscoroll::bem::InfluenceTable and viscoroll::BemSolver are declared.
constexpr bool bem_declared =
    !Fallback<viscoroll::bem::InfluenceTable<double>> &&
    !Fallback<viscoroll::BemSolver<double, viscoroll::StandardLinearSolid<double>>>;

/// Include guards: <unsupported/Eigen/FFT> and boost/multiprecision/number.hpp (every
/// multiprecision back end includes the latter).
#ifdef EIGEN_FFT_H
constexpr bool eigen_fft_included = true;
#else
constexpr bool eigen_fft_included = false;
#endif
#ifdef BOOST_MATH_EXTENDED_REAL_HPP
constexpr bool multiprecision_included = true;
#else
constexpr bool multiprecision_included = false;
#endif
/// Include guards of <Eigen/Core> and of Boost's Bessel functions (which line_shape.hpp needs
/// through special/bessel_ratio.hpp): what the line solver's configuration headers leave out.
#ifdef EIGEN_CORE_H
constexpr bool eigen_core_included = true;
#else
constexpr bool eigen_core_included = false;
#endif
#ifdef BOOST_MATH_BESSEL_HPP
constexpr bool boost_bessel_included = true;
#else
constexpr bool boost_bessel_included = false;
#endif

}  // namespace viscoroll_needs
