// viscoroll: a spectrum made ready for the closed-form strip (core/spectrum_strip.hpp) of the
// plane and line methods (docs/theory.md, sections 12 and 14): its terms sorted at one speed into
// relaxed, glassy and active ((S21) for the line method's budget), near-equal times merged where
// the strip would lose digits ((S19), (S20)), and the term count checked.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/spectrum_strip.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/material/detail/prony_spectrum.hpp>

namespace viscoroll::detail {

/// The memory terms (f_k, tau_k) of a spectrum at one speed, sorted as the solvers for a
/// spectrum sort them (docs/theory.md section 12, "Terms at their limits", and section 14):
/// relaxed (V tau_k <= relaxed_below, or no speed or time), folded into the compliance; not
/// started (strip_is_glassy at the width `width`), dropped; the others active, with
/// lambda_k = V tau_k in the unit 2^length and f_k / (1 + relaxed) (R6b). With a `budget` > 0
/// (the line method's, (S21)), also the fastest terms are relaxed and the slowest dropped while
/// their share of the dissipation and of the penetration stays within budget/2 at each end;
/// `error` is the larger share.
template <class Real>
struct SpectrumClasses {
  Real relaxed = 0, glassy = 0;
  std::vector<SpectrumTerm<Real>> active;
  Real error = 0;
};
template <class Real, class Terms>
SpectrumClasses<Real> classify_spectrum(const Terms& terms, Real speed, int length,
                                        Real relaxed_below, Real width, Real creep_ratio,
                                        Real budget = 0, Real reach = 0) {
  SpectrumClasses<Real> out;
  const auto v = detail::binary<Real>(speed);
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const Real f = terms[k].f, tau = terms[k].tau;
    if (!(f > 0)) continue;
    if (!(speed > 0) || !(tau > 0)) {
      out.relaxed += f;
      continue;
    }
    const auto t = detail::binary<Real>(tau);
    const Real lambda = detail::times_power_of_two(Real(v.m * t.m), v.e + t.e - length);
    if (lambda <= relaxed_below)
      out.relaxed += f;
    else if (plane::strip_is_glassy(lambda, creep_ratio, width))
      out.glassy += f;
    else
      out.active.push_back({f, lambda});
  }
  if (budget > 0 && !out.active.empty()) {
    // (S21): term k's share of the dissipation, f_k x_k / (1 + x_k^2) with x_k = lambda_k / width
    // against the total L, and of the penetration, f_k x_k (fast end) or f_k reach / lambda_k
    // (slow end), each end within budget/2 of both.
    std::sort(out.active.begin(), out.active.end(),
              [](const auto& x, const auto& y) { return x.q < y.q; });
    const auto loss = [width](const SpectrumTerm<Real>& t) {
      const Real x = t.q / width;
      return x <= 1 ? t.w * x / (1 + x * x) : t.w / (x + 1 / x);
    };
    Real total = 0;
    for (const auto& t : out.active) total += loss(t);
    std::size_t first = 0, last = out.active.size();
    Real fast_loss = 0, fast_d = 0, slow_loss = 0, slow_d = 0;
    for (; first < last; ++first) {
      const auto& t = out.active[first];
      const Real l = fast_loss + loss(t), d = fast_d + t.w * t.q / width;
      if (l > total * budget / 2 || d > budget / 2) break;
      fast_loss = l;
      fast_d = d;
      out.relaxed += t.w;
    }
    for (; last > first; --last) {
      const auto& t = out.active[last - 1];
      const Real l = slow_loss + loss(t), d = slow_d + t.w * reach / t.q;
      if (l > total * budget / 2 || d > budget / 2) break;
      slow_loss = l;
      slow_d = d;
      out.glassy += t.w;
    }
    out.active = std::vector<SpectrumTerm<Real>>(out.active.begin() + std::ptrdiff_t(first),
                                                 out.active.begin() + std::ptrdiff_t(last));
    out.error = std::max((fast_loss + slow_loss) / total, fast_d + slow_d);
  }
  for (auto& t : out.active) t.w /= 1 + out.relaxed;
  return out;
}

/// The amplification of rounding in the closed-form strip (docs/theory.md (S20)): the larger of
/// sum_i |A_i|, A_i = prod_{j != i} mu_i / (mu_i - mu_j), the weights of the pressure's partial
/// fractions (S4), (S9) (crowded relaxation lengths), and max_k lambda_{k+1} / (lambda_{k+1} -
/// lambda_k) (crowded retardation lengths: the relaxation length between them crowds both, and
/// the two leading-edge rows (S7) become parallel). Lengths ascending and interlacing. The sum is
/// formed in logarithms: +inf where it exceeds the largest finite value.
template <class Real>
Real spectrum_amplification(const plane::SpectrumLengths<Real>& lengths) {
  using std::abs;
  using std::exp;
  using std::log;
  const auto& mu = lengths.relaxation;
  const auto& lambda = lengths.retardation;
  const Real log_max = log(std::numeric_limits<Real>::max());
  Real sum = 0;
  for (std::size_t i = 0; i < mu.size(); ++i) {
    Real l = 0;
    for (std::size_t j = 0; j < mu.size(); ++j)
      if (j != i) l += log(abs(mu[i] / (mu[i] - mu[j])));
    if (!(l < log_max)) return std::numeric_limits<Real>::infinity();
    sum += exp(l);
  }
  Real rows = 0;
  for (std::size_t k = 0; k + 1 < lambda.size(); ++k)
    rows = std::max(rows, lambda[k + 1] / (lambda[k + 1] - lambda[k]));
  return std::max(sum, rows);
}

/// The amplification above which the closed form merges terms (S20): eps^(-1/3) (1.65e5 in
/// double), so that the rounding of the strip, measured to grow as eps times the amplification
/// to the power 3/2, stays below sqrt(eps) (1.5e-8).
template <class Real>
Real spectrum_amplification_limit() {
  using std::cbrt;
  return 1 / cbrt(std::numeric_limits<Real>::epsilon());
}

/// The largest merge bound (S19) accepted: the merged spectrum's complex compliance is within
/// 1e-6 of the given one's at every frequency, far below any measured spectrum's accuracy and
/// below every method's stated error except the plane method's rounding level.
template <class Real>
Real spectrum_merge_limit() {
  return Real(1e-6);
}

/// The most memory terms the plane and line methods take (their closed-form strip costs O(M^3)
/// a solve of (S5), and the merging of (S20) O(M^2) a step): 256, ten times a measured spectrum's
/// usual 10-40 terms. Checked on the material's terms before any work.
inline constexpr std::size_t max_spectrum_terms = 256;

/// Throws std::invalid_argument naming the term count unless count <= max_spectrum_terms.
inline void require_spectrum_terms(std::size_t count, std::string_view method) {
  require(count <= max_spectrum_terms, "terms", count,
          "terms <= 256 in the " + std::string(method) +
              " method (its cost grows as the cube of the terms): use the bem method, or a "
              "spectrum with fewer terms (one or two a decade describe a measured one)");
}

/// (S19) for one cluster (terms ascending in time): the bound on |J_merged - J| / |J| of merging
/// them into one term of the summed weight at the weighted mean time,
/// (2 / 3^(3/2)) sum_k f_k ((q_k - Q) / q_min)^2.
template <class Real>
Real cluster_merge_bound(const std::vector<SpectrumTerm<Real>>& cluster) {
  if (cluster.size() < 2) return 0;
  Real w = 0, first = 0;
  for (const auto& t : cluster) {
    w += t.w;
    first += t.w * t.q;
  }
  const Real q = first / w, q_min = cluster.front().q;
  Real e = 0;
  for (const auto& t : cluster) e += t.w * ((t.q - q) / q_min) * ((t.q - q) / q_min);
  using std::sqrt;
  return 2 / (3 * sqrt(Real(3))) * e;
}

/// The active terms of a spectrum ready for the closed form (docs/theory.md, (S19), (S20)): equal
/// times merged exactly (merge_spectrum), then, while the strip's amplification
/// (spectrum_amplification) exceeds spectrum_amplification_limit(), the two adjacent terms whose
/// merge adds least to the bound (S19) merged into one with their summed weight at their weighted
/// mean time. `spectrum_error` bounds the relative change of the complex compliance at every
/// frequency that the merging makes (S19); a spectrum that cannot be conditioned within
/// spectrum_merge_limit() is refused (std::invalid_argument naming the retardation times, each
/// length times `time_per_length`, and pointing to the BEM).
template <class Real>
struct ConditionedSpectrum {
  std::vector<SpectrumTerm<Real>> terms;  ///< (weight f_k, length lambda_k), ascending
  plane::SpectrumLengths<Real> lengths;   ///< their lengths (empty for no term)
  Real amplification = 1;                 ///< spectrum_amplification of the terms kept
  Real spectrum_error = 0;                ///< the bound (S19) of the merging
  int given_terms = 0;                    ///< active terms before merging near-equal times
};

template <class Real>
ConditionedSpectrum<Real> condition_spectrum(std::vector<SpectrumTerm<Real>> active,
                                             Real time_per_length) {
  ConditionedSpectrum<Real> out;
  out.given_terms = static_cast<int>(active.size());
  // Each kept term with the given terms merged into it (for the bound (S19)).
  std::vector<std::vector<SpectrumTerm<Real>>> members;
  for (const auto& t : merge_spectrum(std::move(active))) {
    out.terms.push_back(t);
    members.push_back({t});
  }
  const auto lengths_of = [](const std::vector<SpectrumTerm<Real>>& terms) {
    plane::SpectrumLengths<Real> lengths;
    for (const auto& t : terms) {
      lengths.retardation.push_back(t.q);
      lengths.creep_ratio += t.w;
    }
    for (const auto& t :
         convert_spectrum(terms, SpectrumDirection::creep_to_relaxation, Real(1), Real(1)))
      lengths.relaxation.push_back(t.q);
    return lengths;
  };
  while (!out.terms.empty()) {
    out.lengths = lengths_of(out.terms);
    out.amplification = spectrum_amplification(out.lengths);
    if (out.amplification <= spectrum_amplification_limit<Real>()) break;
    // (S20): merge the adjacent pair whose merge adds least to the bound (S19) (the first of
    // equals): near-equal times, or a term of tiny weight into its neighbour.
    std::size_t k = 0;
    Real cheapest = std::numeric_limits<Real>::infinity();
    for (std::size_t j = 0; j + 1 < out.terms.size(); ++j) {
      std::vector<SpectrumTerm<Real>> both = members[j];
      both.insert(both.end(), members[j + 1].begin(), members[j + 1].end());
      const Real cost = cluster_merge_bound(both) - cluster_merge_bound(members[j]) -
                        cluster_merge_bound(members[j + 1]);
      if (cost < cheapest) {
        cheapest = cost;
        k = j;
      }
    }
    auto& left = out.terms[k];
    const auto& right = out.terms[k + 1];
    const Real w = left.w + right.w;
    left = {w, (left.w / w) * left.q + (right.w / w) * right.q};
    members[k].insert(members[k].end(), members[k + 1].begin(), members[k + 1].end());
    out.terms.erase(out.terms.begin() + std::ptrdiff_t(k + 1));
    members.erase(members.begin() + std::ptrdiff_t(k + 1));
  }
  for (std::size_t j = 0; j < out.terms.size(); ++j) {
    if (members[j].size() < 2) continue;
    out.spectrum_error += cluster_merge_bound(members[j]);
    if (out.spectrum_error > spectrum_merge_limit<Real>())
      throw std::invalid_argument(
          "spectrum: " + std::to_string(members[j].size()) + " retardation times between tau = " +
          format_value(members[j].front().q * time_per_length) + " and " +
          format_value(members[j].back().q * time_per_length) +
          " are too close for the plane and line methods' closed form (its rounding grows as "
          "prod mu_i / (mu_i - mu_j)), and merging them changes the complex compliance by up "
          "to " +
          format_value(out.spectrum_error) + ", more than " +
          format_value(spectrum_merge_limit<Real>()) +
          ": merge or refit the spectrum, or use the bem method");
  }
  return out;
}

}  // namespace viscoroll::detail
