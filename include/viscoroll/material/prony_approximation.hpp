// viscoroll: a Prony series (relaxation form, material/prony.hpp) approximating any linear
// viscoelastic solid given by its complex shear modulus G*(omega), so that a material written
// outside the library (a fractional model, a measured master curve in closed form) can be
// solved by every solver (docs/materials.md).
//
// The approximation is the DMA fit of material/dma_fit.hpp (docs/theory.md (R14)) applied to
// G*(omega) sampled log-uniformly over the frequency range: the fitted series is
//   G(t) = G_inf + sum_j g_j exp(-t / rho_j)                                               (R1)
// whose complex modulus is
//   G*(omega) = G_inf + sum_j g_j i omega rho_j / (1 + i omega rho_j)                      (R10)
// (storage part G', loss part G'' of (R10)). The fit is exact only on the range and only to its
// reported error there: outside the range the series tends to G_inf and G_inf + sum g_j, which
// are the given solid's limits only if the range reaches its plateaus.
#pragma once

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <complex>
#include <concepts>
#include <cstddef>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/material/dma_fit.hpp>
#include <viscoroll/material/prony.hpp>

namespace viscoroll {

/// Settings of prony_approximation.
template <RealScalar Real>
struct PronyApproximationOptions {
  /// Samples of G* per decade of frequency, fitted (log-uniform, both ends included);
  /// 1 <= samples_per_decade <= 1000.
  int samples_per_decade = 10;
  /// Relaxation times per decade of the fit's grid, 10^(k / times_per_decade) s (dma_fit_times);
  /// 1 <= times_per_decade <= 100.
  int times_per_decade = 2;
  /// Decades the grid of times extends beyond 1/(2 pi f) of the range at each end; >= 0.
  Real margin_decades = 1;
  /// The fit is flagged poor (PronyApproximation::poor) if the largest relative error of |G*|
  /// or of the loss tangent over the range exceeds this; > 0.
  Real poor_fit_threshold = Real(0.01);
};

/// The Prony series fitted to G*(omega) and its error over the range.
template <RealScalar Real>
struct PronyApproximation {
  /// The fitted solid, (R1); its Poisson's ratio is the one given.
  PronyRelaxation<Real> material;
  /// max over the check frequencies of | |G*_fit| / |G*| - 1 |, G*_fit of (R10).
  Real max_modulus_error;
  /// max over the check frequencies of | tan delta_fit / tan delta - 1 |, tan delta = G''/G'.
  Real max_loss_tangent_error;
  /// The check frequencies: the fitted samples and the geometric midpoints between them (the
  /// error between samples is what the fit does not see), f_min ... f_max in Hz.
  std::size_t checked_frequencies;
  /// max(max_modulus_error, max_loss_tangent_error) > poor_fit_threshold, or the fit's NNLS did
  /// not converge.
  bool poor;
  /// The DMA fit's own report at the fitted samples (relative errors of G' and G'', (R14)).
  DmaFitReport<Real> fit;
  /// One line with the numbers above.
  std::string summary;
};

/// Fits a PronyRelaxation (R1) to the solid whose complex shear modulus is `modulus`, over the
/// frequencies f_min_hz <= f <= f_max_hz (Hz): `modulus(omega)` is called with the angular
/// frequency omega = 2 pi f (rad/s), as PronyRelaxation::storage_modulus, and returns
/// std::complex<Real> G*(omega) = G'(omega) + i G''(omega) (Pa). Samples at samples_per_decade
/// log-uniform frequencies are fitted by fit_prony (R14) on the grid of times dma_fit_times; the
/// result's |G*| and loss tangent (R10) are compared with the given ones at the samples and
/// between them. Throws std::invalid_argument naming the parameter and its valid range unless
/// -1 < nu <= 0.5, 0 < f_min_hz < f_max_hz (finite), f_max_hz / f_min_hz <= 1e40, the options in
/// their ranges and, at every sample, G' > 0 and G'' > 0 (finite): a solid with loss at every
/// frequency, which a Prony series with g_j > 0 is. As fit_prony, throws if the fitted G_inf is 0
/// (the range shows no rubbery plateau). A poor fit is reported, not thrown.
template <RealScalar Real, class Modulus>
requires std::invocable<const Modulus&, Real> &&
    std::convertible_to<std::invoke_result_t<const Modulus&, Real>, std::complex<Real>>
        PronyApproximation<Real> prony_approximation(
            const Modulus& modulus, Real nu, Real f_min_hz, Real f_max_hz,
            const PronyApproximationOptions<Real>& options = {}) {
  using std::abs;
  using std::ceil;
  using std::log10;
  using std::pow;
  using std::sqrt;
  detail::require_poisson_ratio(nu);
  detail::require_positive("f_min_hz", f_min_hz);
  detail::require_positive("f_max_hz", f_max_hz);
  detail::require(f_max_hz > f_min_hz, "f_max_hz", f_max_hz, "f_max_hz > f_min_hz");
  detail::require(f_max_hz / f_min_hz <= Real(1e40), "f_max_hz / f_min_hz", f_max_hz / f_min_hz,
                  "f_max_hz / f_min_hz <= 1e40 (40 decades)");
  detail::require(options.samples_per_decade >= 1 && options.samples_per_decade <= 1000,
                  "samples_per_decade", options.samples_per_decade,
                  "1 <= samples_per_decade <= 1000");
  detail::require(options.times_per_decade >= 1 && options.times_per_decade <= 100,
                  "times_per_decade", options.times_per_decade, "1 <= times_per_decade <= 100");
  detail::require_non_negative("margin_decades", options.margin_decades);
  detail::require_positive("poor_fit_threshold", options.poor_fit_threshold);

  const Real two_pi = boost::math::constants::two_pi<Real>();
  const Real decades = log10(f_max_hz / f_min_hz);
  // Intervals between samples: at least one, samples_per_decade per decade rounded up.
  const long intervals =
      (std::max)(1L, long(ceil(decades * Real(options.samples_per_decade) - Real(1e-9))));
  // The k-th of the 2 intervals + 1 check frequencies; even k are the fitted samples.
  const auto frequency = [&](long k) {
    if (k == 0) return f_min_hz;
    if (k == 2 * intervals) return f_max_hz;
    return f_min_hz * pow(f_max_hz / f_min_hz, Real(k) / Real(2 * intervals));
  };
  const auto evaluate = [&](Real f) {
    const std::complex<Real> g = modulus(two_pi * f);
    const std::string at = "G*(omega) at f = " + detail::format_value(f) + " Hz";
    detail::require((boost::math::isfinite)(g.real()) && g.real() > 0, "storage modulus " + at,
                    g.real(), "G' > 0 (finite)");
    detail::require((boost::math::isfinite)(g.imag()) && g.imag() > 0, "loss modulus " + at,
                    g.imag(), "G'' > 0 (finite): a solid with loss at every frequency");
    return g;
  };

  DmaData<Real> data;
  data.points.reserve(std::size_t(intervals + 1));
  for (long k = 0; k <= 2 * intervals; k += 2) {
    const Real f = frequency(k);
    const auto g = evaluate(f);
    data.points.push_back({f, g.real(), g.imag(), std::numeric_limits<Real>::quiet_NaN()});
  }
  DmaFitOptions<Real> fit_options;
  fit_options.nu = nu;
  fit_options.times_per_decade = options.times_per_decade;
  fit_options.margin_decades = options.margin_decades;
  fit_options.poor_fit_threshold = options.poor_fit_threshold;
  auto fit = fit_prony(data, fit_options);

  // (R10) against G* at the samples and between them.
  Real modulus_error = 0, tangent_error = 0;
  for (long k = 0; k <= 2 * intervals; ++k) {
    const Real f = frequency(k);
    const auto g = evaluate(f);
    const Real omega = two_pi * f;
    const Real s = fit.material.storage_modulus(omega), l = fit.material.loss_modulus(omega);
    // |G*_fit| / |G*| as sqrt(G'_fit^2 + G''_fit^2) / |G*| (std::abs: no overflow).
    modulus_error = (std::max)(modulus_error, abs(abs(std::complex<Real>(s, l)) / abs(g) - 1));
    tangent_error = (std::max)(tangent_error, abs((l / s) / (g.imag() / g.real()) - 1));
  }
  const bool poor = !fit.report.nnls_converged ||
                    !((std::max)(modulus_error, tangent_error) <= options.poor_fit_threshold);
  std::string summary = std::string(poor ? "POOR PRONY APPROXIMATION" : "Prony approximation") +
                        ": " + std::to_string(fit.material.terms().size()) +
                        " terms over f = " + detail::format_value(f_min_hz) + " ... " +
                        detail::format_value(f_max_hz) + " Hz; max relative error |G*| " +
                        detail::format_value(modulus_error) + ", tan delta " +
                        detail::format_value(tangent_error) + " (threshold " +
                        detail::format_value(options.poor_fit_threshold) + ")";
  PronyRelaxation<Real> material = fit.material;
  return PronyApproximation<Real>{
      std::move(material),   modulus_error,     tangent_error, std::size_t(2 * intervals + 1), poor,
      std::move(fit.report), std::move(summary)};
}

}  // namespace viscoroll
