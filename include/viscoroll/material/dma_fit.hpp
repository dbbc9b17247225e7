// viscoroll: a Prony series (relaxation form, material/prony.hpp) fitted to dynamic mechanical
// analysis (DMA) data: storage and loss modulus against frequency, optionally at several
// temperatures shifted to a master curve first (docs/materials.md; docs/theory.md (R10), (R14)).
//
// CSV format (read_dma_csv): a header line naming the columns, in any order,
//   frequency_hz,storage_pa,loss_pa[,temperature_c]
// then one row per measurement; blank lines and lines starting with '#' are skipped. The moduli
// are shear moduli G', G'' unless DmaCsvOptions::modulus is tensile (E', E'' converted by
// G = E / (2 (1 + nu))). Every frequency, storage and loss modulus must be > 0 and finite.
//
// fit_prony: the unknowns G_inf and g_j >= 0 on log-spaced relaxation times rho_j; each data
// point gives two rows, the relative residuals G'(w)/G'_data - 1 and G''(w)/G''_data - 1 (R14),
// so every decade weighs the same; non-negative least squares (detail/nnls.hpp).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <istream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/input_limits.hpp>
#include <viscoroll/material/detail/nnls.hpp>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/material/temperature_shift.hpp>

namespace viscoroll {

/// Which modulus the CSV's storage_pa and loss_pa columns hold.
enum class DmaModulus { shear, tensile };

template <RealScalar Real>
/// How read_dma_csv reads the moduli.
struct DmaCsvOptions {
  /// Whether the storage_pa and loss_pa columns are shear (G', G'') or tensile (E', E'') moduli.
  DmaModulus modulus = DmaModulus::shear;
  /// Poisson's ratio for the tensile -> shear conversion G = E / (2 (1 + nu)).
  Real nu = Real(0.5);
};

/// One measurement: frequency (Hz), shear storage and loss modulus (Pa), temperature (degrees
/// Celsius; NaN when the file has no temperature_c column).
template <RealScalar Real>
struct DmaPoint {
  /// The measurement's frequency f (Hz), > 0.
  Real frequency_hz;
  /// G' (Pa), > 0 (converted to shear if the file holds E').
  Real storage;
  /// G'' (Pa), > 0 (converted to shear if the file holds E'').
  Real loss;
  /// The temperature (degrees Celsius), NaN without a temperature_c column.
  Real temperature_c;
};

template <RealScalar Real>
/// The measurements read from a DMA CSV file (read_dma_csv), in file order.
struct DmaData {
  /// The measurements.
  std::vector<DmaPoint<Real>> points;
  /// Whether the file has a temperature_c column (fit_prony then needs a shift law).
  bool has_temperature = false;
};

namespace detail {
inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}
inline std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, ',')) out.push_back(trim(field));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}
template <class Real>
bool parse_real(const std::string& s, Real& value) {
  if (s.empty()) return false;
  char* end = nullptr;
  if constexpr (std::is_same_v<Real, float>)
    value = std::strtof(s.c_str(), &end);
  else if constexpr (std::is_same_v<Real, double>)
    value = std::strtod(s.c_str(), &end);
  else
    value = Real(std::strtold(s.c_str(), &end));
  return end == s.c_str() + s.size();
}
[[noreturn]] inline void dma_error(const std::string& source, int line, const std::string& what) {
  throw std::invalid_argument("viscoroll: DMA CSV " + source + " line " + std::to_string(line) +
                              ": " + what);
}
}  // namespace detail

/// Reads the CSV described at the top of this header. Throws std::invalid_argument naming the
/// source, the line and the column on a missing or unknown column, a malformed number or a value
/// out of range (frequency_hz, storage_pa, loss_pa > 0, temperature_c finite).
template <RealScalar Real>
DmaData<Real> read_dma_csv(std::istream& in, const DmaCsvOptions<Real>& options = {},
                           const std::string& source = "<stream>") {
  if (options.modulus == DmaModulus::tensile) detail::require_poisson_ratio(options.nu);
  const Real to_shear = options.modulus == DmaModulus::tensile ? 1 / (2 * (1 + options.nu)) : 1;
  DmaData<Real> data;
  std::string line;
  int number = 0;
  int col_f = -1, col_s = -1, col_l = -1, col_t = -1;
  std::size_t columns = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    const std::string t = detail::trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto fields = detail::split_csv(t);
    if (!header) {
      for (std::size_t c = 0; c < fields.size(); ++c) {
        const std::string& name = fields[c];
        int* slot = name == "frequency_hz"    ? &col_f
                    : name == "storage_pa"    ? &col_s
                    : name == "loss_pa"       ? &col_l
                    : name == "temperature_c" ? &col_t
                                              : nullptr;
        if (!slot)
          detail::dma_error(source, number,
                            "unknown column '" + name +
                                "' (the header names frequency_hz, storage_pa, loss_pa and "
                                "optionally temperature_c)");
        if (*slot >= 0) detail::dma_error(source, number, "column '" + name + "' named twice");
        *slot = int(c);
      }
      for (auto [col, name] : {std::pair{col_f, "frequency_hz"}, std::pair{col_s, "storage_pa"},
                               std::pair{col_l, "loss_pa"}})
        if (col < 0)
          detail::dma_error(source, number,
                            std::string("the header line lacks the column ") + name +
                                " (a header line frequency_hz,storage_pa,loss_pa[,temperature_c] "
                                "is required)");
      columns = fields.size();
      data.has_temperature = col_t >= 0;
      header = true;
      continue;
    }
    if (fields.size() != columns)
      detail::dma_error(
          source, number,
          std::to_string(fields.size()) + " fields, the header has " + std::to_string(columns));
    auto value = [&](int col, const char* name, bool positive) {
      Real v{};
      if (!detail::parse_real(fields[std::size_t(col)], v))
        detail::dma_error(
            source, number,
            std::string(name) + " '" + fields[std::size_t(col)] + "' is not a number");
      if (!(boost::math::isfinite)(v) || (positive && !(v > 0)))
        detail::dma_error(source, number,
                          std::string(name) + " = " + detail::format_value(v) +
                              " is outside the valid range " + name +
                              (positive ? " > 0 (finite)" : " finite"));
      return v;
    };
    DmaPoint<Real> p{};
    p.frequency_hz = value(col_f, "frequency_hz", true);
    p.storage = value(col_s, "storage_pa", true) * to_shear;
    p.loss = value(col_l, "loss_pa", true) * to_shear;
    p.temperature_c =
        col_t >= 0 ? value(col_t, "temperature_c", false) : std::numeric_limits<Real>::quiet_NaN();
    data.points.push_back(p);
  }
  if (!header) detail::dma_error(source, number, "no header line");
  if (data.points.empty()) detail::dma_error(source, number, "no data rows");
  return data;
}

/// read_dma_csv of a file of at most `max_bytes` (limits::dma_file_bytes, 1 MiB); throws
/// std::invalid_argument naming the file if it is missing, not a regular file (a directory, a
/// FIFO, /dev/zero), larger, or cannot be read. The type and size are checked before the file is
/// opened, and at most max_bytes + 1 bytes are read.
template <RealScalar Real>
DmaData<Real> read_dma_csv_file(const std::filesystem::path& path,
                                const DmaCsvOptions<Real>& options = {},
                                std::size_t max_bytes = limits::dma_file_bytes) {
  std::istringstream in(
      detail::read_bounded_file(path, max_bytes, "DMA CSV file", [&](const std::string& message) {
        throw std::invalid_argument("viscoroll: DMA CSV " + path.string() + ": " + message);
      }));
  return read_dma_csv<Real>(in, options, path.string());
}

template <RealScalar Real>
/// The settings of fit_prony.
struct DmaFitOptions {
  /// Poisson's ratio of the fitted material.
  Real nu = Real(0.5);
  /// Relaxation times per decade of the automatic grid: 10^(k / times_per_decade) s, k integer,
  /// spanning 1/(2 pi f) of the (reduced) data widened by margin_decades at each end.
  int times_per_decade = 2;
  /// Decades added to the automatic grid at each end.
  Real margin_decades = 1;
  /// Explicit relaxation times (s); if non-empty, used instead of the automatic grid.
  std::vector<Real> times;
  /// Required if the data carry temperature_c: each frequency is multiplied by a_T(T) (R13),
  /// giving the master curve at the law's t_ref. Ignored for data without temperatures.
  std::optional<ShiftLaw<Real>> shift;
  /// The fit is flagged poor if the largest relative error in G' or G'' exceeds this.
  Real poor_fit_threshold = Real(0.02);
};

template <RealScalar Real>
/// How well fit_prony's Prony series reproduces the data (relative errors).
struct DmaFitReport {
  Real max_storage_error;  ///< max_i |G'_fit / G'_data - 1|
  Real rms_storage_error;  ///< root mean square of the same
  Real max_loss_error;     ///< max_i |G''_fit / G''_data - 1|
  /// The root mean square of the loss modulus' relative errors.
  Real rms_loss_error;
  std::size_t nonzero_terms;    ///< relaxation terms with g_j > 0
  std::size_t candidate_terms;  ///< relaxation times offered to the fit
  /// The iterations of the non-negative least squares.
  int nnls_iterations;
  /// Whether the non-negative least squares converged.
  bool nnls_converged;
  /// max(max_storage_error, max_loss_error) > poor_fit_threshold, or NNLS did not converge.
  bool poor;
  std::vector<Real> reduced_frequency_hz;  ///< f a_T of each point (the master curve abscissa)
  std::string summary;                     ///< one line with the numbers above
};

template <RealScalar Real>
/// What fit_prony returns: the fitted material and how well it fits.
struct DmaFit {
  /// The fitted relaxation form: G_inf, nu and the terms with g_j > 0.
  PronyRelaxation<Real> material;
  /// The errors of the fit.
  DmaFitReport<Real> report;
};

/// The relaxation times of the automatic grid for reduced frequencies in [f_min, f_max].
template <RealScalar Real>
std::vector<Real> dma_fit_times(Real f_min, Real f_max, int per_decade, Real margin_decades) {
  using std::ceil;
  using std::floor;
  using std::log10;
  using std::pow;
  detail::require(per_decade > 0, "times_per_decade", per_decade, "times_per_decade > 0");
  detail::require_non_negative("margin_decades", margin_decades);
  const Real two_pi = 2 * boost::math::constants::pi<Real>();
  const Real lo = log10(1 / (two_pi * f_max)) - margin_decades;
  const Real hi = log10(1 / (two_pi * f_min)) + margin_decades;
  std::vector<Real> times;
  for (long k = long(floor(lo * Real(per_decade))); k <= long(ceil(hi * Real(per_decade))); ++k)
    times.push_back(pow(Real(10), Real(k) / Real(per_decade)));
  return times;
}

/// Fits a PronyRelaxation to `data` (see the top of this header). Throws std::invalid_argument
/// if the data have temperatures but no shift law is given, or if the fitted G_inf is 0 (the
/// data show no rubbery plateau: a solid is required). A poor fit is reported, not thrown.
template <RealScalar Real>
DmaFit<Real> fit_prony(const DmaData<Real>& data, const DmaFitOptions<Real>& options = {}) {
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  using std::abs;
  using std::sqrt;
  detail::require_poisson_ratio(options.nu);
  if (data.points.empty()) throw std::invalid_argument("viscoroll: fit_prony: no data points");
  if (data.has_temperature && !options.shift)
    throw std::invalid_argument(
        "viscoroll: fit_prony: the data have temperature_c but DmaFitOptions::shift is not set "
        "(a WLF or Arrhenius law builds the master curve)");
  const std::size_t np = data.points.size();
  std::vector<Real> freq(np);
  for (std::size_t i = 0; i < np; ++i) {
    const auto& p = data.points[i];
    freq[i] = p.frequency_hz;
    if (data.has_temperature) freq[i] *= shift_factor<Real>(*options.shift, p.temperature_c);
  }
  std::vector<Real> times = options.times;
  if (times.empty()) {
    const auto [lo, hi] = std::minmax_element(freq.begin(), freq.end());
    times = dma_fit_times<Real>(*lo, *hi, options.times_per_decade, options.margin_decades);
  }
  for (std::size_t j = 0; j < times.size(); ++j)
    detail::require_positive("times[" + std::to_string(j) + "]", times[j]);
  const Real two_pi = 2 * boost::math::constants::pi<Real>();
  const Eigen::Index nt = Eigen::Index(times.size());
  // (R14): rows 2i (storage) and 2i+1 (loss); column 0 is G_inf, column 1 + j is g_j.
  Matrix a = Matrix::Zero(Eigen::Index(2 * np), nt + 1);
  Vector b = Vector::Ones(Eigen::Index(2 * np));
  for (std::size_t i = 0; i < np; ++i) {
    const Real omega = two_pi * freq[i];
    const auto& p = data.points[i];
    const Eigen::Index r = Eigen::Index(2 * i);
    a(r, 0) = 1 / p.storage;
    for (Eigen::Index j = 0; j < nt; ++j) {
      const auto [s, l] = detail::maxwell_factors(omega * times[std::size_t(j)]);
      a(r, 1 + j) = s / p.storage;
      a(r + 1, 1 + j) = l / p.loss;
    }
  }
  const auto sol = detail::nnls<Real>(a, b);
  const Real g_inf = sol.x(0);
  std::vector<RelaxationTerm<Real>> terms;
  for (Eigen::Index j = 0; j < nt; ++j)
    if (sol.x(1 + j) > 0) terms.push_back({sol.x(1 + j), times[std::size_t(j)]});
  detail::require(g_inf > 0, "g_inf", g_inf,
                  "g_inf > 0: the fitted long-term modulus is 0, the data show no rubbery plateau "
                  "(a solid is required for rolling; measure to lower frequency or higher "
                  "temperature)");
  DmaFit<Real> fit{PronyRelaxation<Real>(g_inf, options.nu, std::move(terms)), {}};
  auto& rep = fit.report;
  rep.max_storage_error = rep.max_loss_error = 0;
  Real ss = 0, sl = 0;
  for (std::size_t i = 0; i < np; ++i) {
    const Real omega = two_pi * freq[i];
    const Real es = abs(fit.material.storage_modulus(omega) / data.points[i].storage - 1);
    const Real el = abs(fit.material.loss_modulus(omega) / data.points[i].loss - 1);
    rep.max_storage_error = (std::max)(rep.max_storage_error, es);
    rep.max_loss_error = (std::max)(rep.max_loss_error, el);
    ss += es * es;
    sl += el * el;
  }
  rep.rms_storage_error = sqrt(ss / Real(np));
  rep.rms_loss_error = sqrt(sl / Real(np));
  rep.nonzero_terms = fit.material.terms().size();
  rep.candidate_terms = times.size();
  rep.nnls_iterations = sol.iterations;
  rep.nnls_converged = sol.converged;
  rep.poor = !sol.converged ||
             (std::max)(rep.max_storage_error, rep.max_loss_error) > options.poor_fit_threshold ||
             !(boost::math::isfinite)(rep.max_storage_error + rep.max_loss_error);
  rep.reduced_frequency_hz = std::move(freq);
  std::ostringstream out;
  out << (rep.poor ? "POOR FIT" : "fit") << ": relative error G' max " << rep.max_storage_error
      << " rms " << rep.rms_storage_error << ", G'' max " << rep.max_loss_error << " rms "
      << rep.rms_loss_error << "; " << rep.nonzero_terms << " of " << rep.candidate_terms
      << " terms non-zero; G_inf " << g_inf << " Pa"
      << (sol.converged ? "" : "; NNLS did not converge") << " (threshold "
      << options.poor_fit_threshold << ")";
  rep.summary = out.str();
  return fit;
}

}  // namespace viscoroll
