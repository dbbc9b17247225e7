// The counterpart of umbrella_header.test.cpp and line_configuration.test.cpp: with the optional
// headers and the solvers included, the same probes report them, so those checks are not vacuous.
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/viscoroll.hpp>
// The probe goes after the headers under test.
#include <catch2/catch.hpp>

#include "optional_parts_probe.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_bem_header {

static_assert(viscoroll_needs::bem_declared);
static_assert(viscoroll_needs::eigen_fft_included);
static_assert(viscoroll_needs::multiprecision_included);
static_assert(viscoroll_needs::eigen_core_included);
static_assert(viscoroll_needs::boost_bessel_included);

TEST_CASE("needs: the probes see the BEM, the FFT and multiprecision when they are included",
          "[needs]") {
  CHECK(viscoroll_needs::bem_declared);
  CHECK(viscoroll_needs::eigen_fft_included);
  CHECK(viscoroll_needs::multiprecision_included);
  // The line solver (in the umbrella header) needs Eigen and Boost's Bessel functions.
  CHECK(viscoroll_needs::eigen_core_included);
  CHECK(viscoroll_needs::boost_bessel_included);
}

}  // namespace test_bem_header
