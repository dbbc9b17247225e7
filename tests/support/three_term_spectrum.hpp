// The three-term creep spectrum of the line residuals' Jacobian tests (tests/line/
// line_spectrum_jacobian.test.cpp, line_tilt_jacobian.test.cpp): (f, tau) = (2, 0.05), (3, 0.5),
// (4, 5) at speed v, as the lengths of a spectrum's LineProblem, and that problem.
#pragma once

#include <vector>
#include <viscoroll/core/spectrum_strip.hpp>
#include <viscoroll/line/line_residual.hpp>
#include <viscoroll/line/static_line_contact.hpp>
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

/// The residual's problem of the spectrum at speed v for curvatures c1, c2: lengths in units of
/// the long-term static contact of compliance load 1 (a_ref = a0, l_ref = l), its load target.
inline viscoroll::line::LineProblem<double> three_term_problem(double v, double c1, double c2) {
  const auto slow = viscoroll::static_line_contact(c1, c2, 1.0);
  return {.c1 = c1,
          .c2 = c2,
          .vtau = 0,
          .f = 0,
          .a_ref = slow.a0,
          .l_ref = slow.l,
          .load_target = c1 * slow.a0 * slow.a0 * slow.l / 3,
          .lengths = three_term_lengths(v)};
}

}  // namespace viscoroll_test
