// The umbrella header brings in only what every scene needs: not the boundary-element reference
// solver (whose headers need Eigen's unsupported FFT module), not the FFT, not
// boost::multiprecision ("Only what a scene needs"; docs/performance.md). This file
// includes nothing of viscoroll but the umbrella header; bem_header.test.cpp checks that the same
// probes do see the optional parts when they are included, so these checks can fail.
#include <viscoroll/viscoroll.hpp>
// The probe goes after the headers under test.
#include <catch2/catch.hpp>

#include "optional_parts_probe.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_umbrella_header {

static_assert(!viscoroll_needs::bem_declared, "viscoroll.hpp declares the BEM solver");
static_assert(!viscoroll_needs::eigen_fft_included,
              "viscoroll.hpp includes <unsupported/Eigen/FFT>");
static_assert(!viscoroll_needs::multiprecision_included,
              "viscoroll.hpp includes boost::multiprecision");

TEST_CASE("needs: the umbrella header leaves out the BEM, the FFT and multiprecision", "[needs]") {
  CHECK_FALSE(viscoroll_needs::bem_declared);
  CHECK_FALSE(viscoroll_needs::eigen_fft_included);
  CHECK_FALSE(viscoroll_needs::multiprecision_included);
  // The probe names the fallback, which the umbrella header's solvers do not disturb.
  CHECK(viscoroll::bem::InfluenceTable<double>::fallback);
}

}  // namespace test_umbrella_header
