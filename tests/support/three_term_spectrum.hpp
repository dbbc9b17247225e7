// The three-term creep spectrum of the line residuals' Jacobian tests (tests/line/
// line_spectrum_jacobian.test.cpp, line_tilt_jacobian.test.cpp): (f, tau) = (2, 0.05), (3, 0.5),
// (4, 5) at speed v, as the lengths of a spectrum's LineProblem.
#pragma once

#include <vector>
#include <viscoroll/core/spectrum_strip.hpp>
#include <viscoroll/material/detail/prony_spectrum.hpp>

namespace viscoroll_test {

/// The spectrum at speed v: retardation lengths v tau_k and the relaxation lengths from the exact
/// conversion.
inline viscoroll::plane::SpectrumLengths<double> three_term_lengths(double v) {
  const std::vector<viscoroll::detail::SpectrumTerm<double>> creep{
      {2.0, 0.05 * v}, {3.0, 0.5 * v}, {4.0, 5 * v}};
  viscoroll::plane::SpectrumLengths<double> out;
  for (const auto& t : creep) {
    out.retardation.push_back(t.q);
    out.creep_ratio += t.w;
  }
  for (const auto& t : viscoroll::detail::convert_spectrum(
           creep, viscoroll::detail::SpectrumDirection::creep_to_relaxation, 1.0, 1.0))
    out.relaxation.push_back(t.q);
  return out;
}

}  // namespace viscoroll_test
