// viscoroll: the exact conversion between the relaxation and the creep (retardation) spectrum of
// a discrete linear viscoelastic solid (docs/theory.md, section 11, (R1)–(R8)).
//
// Both directions are one computation in the time variable. Given poles q_0 < ... < q_{n-1}
// (times) with weights w_i > 0, the new times x are the zeros of
//   relaxation -> creep (R4):  Phi(tau) = G_inf + sum_i g_i rho_i / (rho_i - tau)
//   creep -> relaxation (R7):  Psi(rho) = 1 + sum_k f_k rho / (rho - tau_k)
// one in each interval between consecutive poles and one in the outer interval, and the new
// weights the residues (R5), (R8):  out = G_g / (x sum_i w_i q_i / (x - q_i)^2).
// Every zero is found by toms748 in d, the distance from the nearer pole of its interval
// (x = q_p + sigma d), in which x - q_p = sigma d is exact and every other x - q_i =
// (q_p - q_i) + sigma d loses at most a factor 2 to cancellation, and the function is multiplied
// by d (R9) so that it is finite at d = 0.
#pragma once

#include <algorithm>
#include <boost/math/special_functions/next.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace viscoroll::detail {

/// A term of either spectrum: a time q > 0 and its weight w > 0 (g_i or f_k).
template <class Real>
struct SpectrumTerm {
  Real w;
  Real q;
};

/// Sorts by time, merges equal times (their weights add: identical exponentials) and drops
/// zero weights: the poles must be distinct for the zeros to interlace (R6).
template <class Real>
std::vector<SpectrumTerm<Real>> merge_spectrum(std::vector<SpectrumTerm<Real>> terms) {
  std::sort(terms.begin(), terms.end(), [](const auto& a, const auto& b) { return a.q < b.q; });
  std::vector<SpectrumTerm<Real>> out;
  for (const auto& t : terms) {
    if (!(t.w > 0)) continue;
    if (!out.empty() && out.back().q == t.q)
      out.back().w += t.w;
    else
      out.push_back(t);
  }
  return out;
}

enum class SpectrumDirection { relaxation_to_creep, creep_to_relaxation };

/// The zeros and residues of (R4)/(R7). `terms` merged (merge_spectrum); `c0` = G_inf
/// (relaxation -> creep) or unused; `glassy` = G_g. Returns the new terms sorted by time.
template <class Real>
std::vector<SpectrumTerm<Real>> convert_spectrum(const std::vector<SpectrumTerm<Real>>& terms,
                                                 SpectrumDirection direction, Real g_inf,
                                                 Real glassy) {
  using std::abs;
  const std::size_t n = terms.size();
  const bool to_creep = direction == SpectrumDirection::relaxation_to_creep;
  const Real c0 = to_creep ? g_inf : Real(1);
  std::vector<SpectrumTerm<Real>> out;
  out.reserve(n);
  if (n == 0) return out;

  // A point x = q[ref] + sigma d (ref >= 0) or x = d (ref < 0, the origin, not a pole).
  struct Frame {
    int ref;
    Real sigma;
  };
  auto position = [&](const Frame& fr, Real d) {
    return fr.ref < 0 ? d : terms[std::size_t(fr.ref)].q + fr.sigma * d;
  };
  auto distance = [&](const Frame& fr, Real d, std::size_t i) {  // x - q_i without cancellation
    if (fr.ref < 0) return d - terms[i].q;
    if (std::size_t(fr.ref) == i) return fr.sigma * d;
    return (terms[std::size_t(fr.ref)].q - terms[i].q) + fr.sigma * d;
  };
  // (R9): d times Phi or Psi about a pole (finite at d = 0); Phi or Psi itself about the origin.
  // The numerators: Phi's  g_i rho_i / (rho_i - tau) = -w_i q_i / (x - q_i);
  //                 Psi's  f_k rho / (rho - tau_k)   =  w_i x   / (x - q_i).
  auto scaled = [&](const Frame& fr, Real d) {
    const Real x = position(fr, d);
    Real s = fr.ref < 0 ? c0 : d * c0;
    for (std::size_t i = 0; i < n; ++i) {
      const Real num = to_creep ? -terms[i].w * terms[i].q : terms[i].w * x;
      if (fr.ref < 0)
        s += num / distance(fr, d, i);
      else if (std::size_t(fr.ref) == i)
        s += num * fr.sigma;  // d / (x - q_p) = sigma exactly
      else
        s += num * (d / distance(fr, d, i));
    }
    return s;
  };
  auto solve = [&](const Frame& fr, Real dmax) {
    const Real f0 = scaled(fr, Real(0)), f1 = scaled(fr, dmax);
    if (f1 == 0 || (f0 < 0) == (f1 < 0)) return dmax;  // the zero is at dmax to rounding
    std::uintmax_t iterations = 200;
    auto tol = [](const Real& a, const Real& b) { return boost::math::float_distance(a, b) <= 1; };
    // Normalised to O(1): toms748's interpolation multiplies values of the function, which would
    // overflow a float at the scale of G_g d.
    const Real norm = (std::max)(abs(f0), abs(f1));
    const auto r =
        boost::math::tools::toms748_solve([&](Real d) { return scaled(fr, d) / norm; }, Real(0),
                                          dmax, f0 / norm, f1 / norm, tol, iterations);
    return abs(scaled(fr, r.first)) <= abs(scaled(fr, r.second)) ? r.first : r.second;
  };
  auto brackets = [&](const Frame& fr, Real dmax) {
    const Real a = scaled(fr, Real(0)), b = scaled(fr, dmax);
    return (a < 0 && b >= 0) || (a > 0 && b <= 0);
  };

  for (std::size_t k = 0; k < n; ++k) {
    Frame fr{};
    Real d{};
    if (to_creep && k + 1 == n) {
      // Outer interval (rho_max, rho_max + sum g_i rho_i / G_inf]: about rho_max throughout,
      // every x - rho_i > 0 (R6).
      Real bound = 0;
      for (const auto& t : terms) bound += t.w * t.q;
      bound /= g_inf;
      fr = Frame{int(k), Real(1)};
      d = solve(fr, bound);
    } else {
      // (q_left, q_right); for creep -> relaxation the first interval is (0, tau_min).
      const int left = to_creep ? int(k) : int(k) - 1;
      const int right = to_creep ? int(k) + 1 : int(k);
      const Real ql = left < 0 ? Real(0) : terms[std::size_t(left)].q;
      const Real half = (terms[std::size_t(right)].q - ql) / 2;
      const Frame lf{left, Real(1)}, rf{right, Real(-1)};
      if (brackets(lf, half)) {
        fr = lf;
        d = solve(lf, half);
      } else if (brackets(rf, half)) {
        fr = rf;
        d = solve(rf, half);
      } else {  // the zero is the midpoint to rounding
        fr = lf;
        d = half;
      }
    }
    const Real x = position(fr, d);
    // (R5)/(R8): out = G_g / (x sum_i w_i q_i / (x - q_i)^2), with d^2 factored out about a pole:
    // out = (G_g / sum_i w_i q_i (d / (x - q_i))^2) (d / x) d.
    Real w;
    if (fr.ref < 0) {
      Real s = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const Real r = distance(fr, d, i);
        s += terms[i].w * terms[i].q / r / r;
      }
      w = glassy / (x * s);
    } else {
      Real s = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const Real r = std::size_t(fr.ref) == i ? Real(1) : d / distance(fr, d, i);
        s += terms[i].w * terms[i].q * r * r;
      }
      w = glassy / s * (d / x) * d;
    }
    out.push_back(SpectrumTerm<Real>{w, x});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.q < b.q; });
  return out;
}

}  // namespace viscoroll::detail
