// A random creep spectrum for the property tests of the plane and line methods over spectra
// (docs/materials.md, "Which spectra each method takes").
#pragma once

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>
#include <viscoroll/core/concepts.hpp>

namespace viscoroll::testing {

/// `m` terms (f_k, tau_k): times log-uniform over a span of 0 to 20 decades from 1 s, a third of
/// them copied from an earlier term with a relative change of 1e-12 to 1e-2 (clusters and
/// repeats); weights log-uniform over 10 decades below a largest of 10^(-2..1).
inline std::vector<PronyTerm<double>> random_spectrum(std::mt19937_64& rng, int m) {
  std::uniform_real_distribution<double> unit(0, 1);
  const double span = 20 * unit(rng), top = -2 + 3 * unit(rng);
  std::vector<PronyTerm<double>> t;
  for (int k = 0; k < m; ++k) {
    const double f = std::pow(10.0, top - 10 * unit(rng));
    if (k > 0 && unit(rng) < 1.0 / 3) {
      const auto& other = t[std::size_t(unit(rng) * double(k))];
      t.push_back({f, other.tau * (1 + std::pow(10.0, -12 + 10 * unit(rng)))});
    } else {
      t.push_back({f, std::pow(10.0, span * unit(rng))});
    }
  }
  return t;
}

}  // namespace viscoroll::testing
