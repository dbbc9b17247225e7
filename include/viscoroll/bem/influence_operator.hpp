// viscoroll: the boundary-element operator of the 3-D reference solver, a 2-D convolution of the
// cell pressures with the viscoelastic influence coefficients, applied by FFT on a zero-padded
// grid.
//
// On a uniform grid of nx x ny rectangles hx x hy with cell centres (x_i, y_j), the displacement
// at cell centre (i, j) due to constant pressures p_kl is (docs/bem.md, (B6))
//   u_ij = c sum_kl [K_e + sum_k f_k M_{V tau_k}](x_i - x_k, y_j - y_l) p_kl,
// K_e of (B1), M of (B3), c = (1 - nu)/(2 pi mu_D): Hunter's Eq. (2) with Boussinesq's Eq. (3).
// The coefficient depends only on the offset, so u = K * p is a discrete convolution; with p
// zero-padded to nfx >= 2 nx - 1 by nfy >= 2 ny - 1 the circular convolution equals it (B7).
// The kernel is even in y and, unless V tau = 0, not even in x: the operator is not symmetric.
// The inverse of its continuum symbol (B11), applied the same way, preconditions the solver's
// linear systems.
#pragma once

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <complex>
#include <cstddef>
#include <exception>
#include <memory>
#include <optional>
#include <thread>
#include <vector>
#include <viscoroll/bem/bem_scene.hpp>
#include <viscoroll/bem/fft_backend.hpp>
#include <viscoroll/bem/rectangle_influence.hpp>
#include <viscoroll/bem/substrate_kernel.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/material/generalized_maxwell.hpp>

namespace viscoroll {

namespace detail {

/// Smallest 2^a 3^b 5^c >= n (sizes kissfft transforms fastest).
inline int fft_size(int n) {
  int best = 1;
  while (best < n) best *= 2;
  for (int p2 = 1; p2 < 2 * n; p2 *= 2)
    for (int p3 = p2; p3 < 2 * n; p3 *= 3)
      for (int p5 = p3; p5 < 2 * n; p5 *= 5)
        if (p5 >= n && p5 < best) best = p5;
  return best;
}

}  // namespace detail

namespace bem {

/// The memory terms (f_k, tau_k) of Eq. (B10) that act: the material's spectrum
/// (ConstitutiveModel::memory_terms(), the single term (f, tau) of Eq. (1) for the standard linear
/// solid) without its zero weights; none for an elastic material.
template <ConstitutiveModel M>
std::vector<PronyTerm<typename M::real_type>> memory_terms_of(const M& m) {
  using Real = typename M::real_type;
  std::vector<PronyTerm<Real>> terms;
  if constexpr (M::is_viscoelastic) {
    for (const auto& t : m.memory_terms())
      if (t.f > 0) terms.push_back(PronyTerm<Real>{t.f, t.tau});
  }
  return terms;
}

/// (B6): the influence coefficients per unit pressure of every offset (di, dj), |di| < nx,
/// 0 <= dj < ny (even in dj), including the compliance c; memory lengths L_k = V tau_k. The memory
/// coefficients (B4)-(B5) are integrated by the rule Quadrature (MemoryPanelRule by default);
/// two or more terms share their panels' nodes (MemoryRows; docs/bem.md, "Many memory terms").
///   - InfluenceTable(grid, c, terms, V, threads = 1, substrate = nullptr, thickness = 0): the
///     table of the grid's offsets for the memory terms (f_k, tau_k) at speed V, computed in
///     coefficient_real_t<Real> and rounded once, its rows shared among `threads` threads (the
///     same table for any count); on a substrate (substrate_kernel.hpp) of `thickness` in the
///     grid's units, a body's correction (B16)-(B17) is added and a local bed's rows (B18)
///     replace the half space's;
///   - operator()(di, dj): the coefficient of offset (di, dj);
///   - nx(), ny(): the grid's cell counts.
template <RealScalar Real, class Quadrature = MemoryPanelRule<Real>>
requires NodalQuadratureRule<Quadrature, coefficient_real_t<Real>>
class InfluenceTable {
 public:
  /// The table of the grid's offsets for the memory terms at speed V (see the class comment).
  InfluenceTable(const BemGrid<Real>& grid, Real compliance,
                 const std::vector<PronyTerm<Real>>& terms, Real speed, int threads = 1,
                 const SubstrateKernel<coefficient_real_t<Real>>* substrate = nullptr,
                 coefficient_real_t<Real> thickness = 0)
      : nx_(grid.nx),
        ny_(grid.ny),
        k_(static_cast<std::size_t>(2 * grid.nx - 1) * static_cast<std::size_t>(grid.ny)),
        substrate_(substrate != nullptr && substrate->kind != SubstrateKind::half_space ? substrate
                                                                                        : nullptr),
        thickness_(thickness) {
    // Memory lengths L_k = V tau_k; those of at least hx/1024, when two or more, share their
    // panels' nodes (MemoryRows): a shorter one would add more shared panels per step,
    // log2(hx/(16 L)), than its own memory_row costs (about 6).
    using W = coefficient_real_t<Real>;
    std::vector<W> shared;
    for (const auto& t : terms) {
      if (substrate_ != nullptr && substrate_->kind == SubstrateKind::local) break;
      const W length = W(speed) * W(t.tau);
      if (length > 0 && length >= W(grid.hx) / 1024) shared.push_back(length);
    }
    if (shared.size() >= 2) shared_.emplace(grid.nx - 1, W(grid.hx), W(grid.hy), std::move(shared));
    // The rows dj are independent: `threads` threads take every threads-th row each, so the table
    // is the same for any thread count.
    const int workers = std::max(1, std::min(threads, ny_));
    if (workers == 1) {
      for (int j = 0; j < ny_; ++j) fill_row(grid, compliance, terms, speed, j);
      return;
    }
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(workers));
    {
      std::vector<std::jthread> pool;
      for (int w = 0; w < workers; ++w)
        pool.emplace_back([&, w] {
          try {
            for (int j = w; j < ny_; j += workers) fill_row(grid, compliance, terms, speed, j);
          } catch (...) {
            errors[static_cast<std::size_t>(w)] = std::current_exception();
          }
        });
    }
    for (const auto& e : errors)
      if (e) std::rethrow_exception(e);
  }

  /// The coefficient of offset (di, dj) = (i - k, j - l): displacement at cell (i, j) per unit
  /// pressure on cell (k, l).
  Real operator()(int di, int dj) const {
    const int j = dj < 0 ? -dj : dj;
    return k_[static_cast<std::size_t>(di + nx_ - 1) +
              static_cast<std::size_t>(2 * nx_ - 1) * static_cast<std::size_t>(j)];
  }
  /// The grid's cells per row.
  int nx() const { return nx_; }
  /// The grid's cells per column.
  int ny() const { return ny_; }

 private:
  /// Row dj = j of the table: Love's coefficients (B1)-(B2) plus each memory term's (B3)-(B5).
  void fill_row(const BemGrid<Real>& grid, Real compliance,
                const std::vector<PronyTerm<Real>>& terms, Real speed, int j) {
    using W = coefficient_real_t<Real>;
    const int m = nx_ - 1;
    const W hx = W(grid.hx), hy = W(grid.hy);
    const W y = W(j) * hy;
    const auto store = [&](const std::vector<W>& total) {
      for (int i = -m; i <= m; ++i)
        k_[static_cast<std::size_t>(i + m) +
           static_cast<std::size_t>(2 * m + 1) * static_cast<std::size_t>(j)] =
            Real(W(compliance) * total[static_cast<std::size_t>(i + m)]);
    };
    if (substrate_ != nullptr && substrate_->kind == SubstrateKind::local) {
      // (B18): the bed's own rows, no half space.
      const W l = substrate_->local_length / substrate_->thickness * thickness_;
      std::vector<W> total = local_row(m, j, hx, l, W(0));
      for (const auto& t : terms) {
        const std::vector<W> mem = local_row(m, j, hx, l, W(speed) * W(t.tau));
        for (std::size_t q = 0; q < total.size(); ++q) total[q] += W(t.f) * mem[q];
      }
      store(total);
      return;
    }
    // (B16)-(B17): a body adds its correction to the half space's rows.
    std::optional<BodyCorrection<W>> body;
    if (substrate_ != nullptr) {
      W longest = 0;
      for (const auto& t : terms) longest = std::max(longest, W(speed) * W(t.tau));
      body.emplace(*substrate_->radial, thickness_, hx, hy, m, y, longest);
    }
    std::vector<W> row(static_cast<std::size_t>(2 * m + 1));
    for (int i = -m; i <= m; ++i)
      row[static_cast<std::size_t>(i + m)] = rectangle_influence(W(i) * hx, y, hx, hy);
    std::vector<W> total = row;
    std::vector<W> elastic_correction;
    if (body) {
      elastic_correction = body->elastic(row);
      for (std::size_t q = 0; q < total.size(); ++q) total[q] += elastic_correction[q];
    }
    std::vector<std::vector<W>> shared;
    if (shared_) shared = (*shared_)(y);
    std::size_t next_shared = 0;
    for (const auto& t : terms) {
      const W length = W(speed) * W(t.tau);
      // V tau = 0: M = K_e (B3), the long-term compliance; otherwise the recurrence (B4), of the
      // shared rows in the terms' order (the constructor's selection) or of its own.
      const bool in_shared = shared_ && length > 0 && length >= hx / 1024;
      const std::vector<W> mem = !(length > 0) ? row
                                 : in_shared   ? std::move(shared[next_shared++])
                                               : memory_row<W, Quadrature>(m, y, hx, hy, length);
      for (std::size_t q = 0; q < total.size(); ++q) total[q] += W(t.f) * mem[q];
      if (body) {
        const std::vector<W> correction =
            length > 0 ? body->memory(length, mem) : elastic_correction;
        for (std::size_t q = 0; q < total.size(); ++q) total[q] += W(t.f) * correction[q];
      }
    }
    store(total);
  }

  int nx_, ny_;
  std::vector<Real> k_;
  const SubstrateKernel<coefficient_real_t<Real>>* substrate_;
  coefficient_real_t<Real> thickness_;
  std::optional<MemoryRows<coefficient_real_t<Real>, Quadrature>> shared_;
};

/// (B7): the operator u = K * p applied by real-to-complex FFT (fft_backend.hpp: FFTW where the
/// build found it, else Eigen's FFT) on the grid zero-padded to nfx x nfy. The spectra are half
/// spectra: nfx/2 + 1 x nfy values, index m + (nfx/2 + 1) n, for the x wavenumbers m = 0 ..
/// nfx/2 (the others are their complex conjugates, the data being real).
///   - ConvolutionOperator(table): the kernel's padded spectrum, from an InfluenceTable,
///     transformed once;
///   - apply(p, u): u = K * p, one forward and one inverse 2-D transform of the padded size;
///   - apply_symbol(symbol, p, u): the same with another half spectrum (the preconditioner of
///     (B11)), unscaled: the operator divides by nfx nfy;
///   - nx(), ny(): the grid; fft_nx(), fft_ny(): the padded transform's size; spectrum_nx():
///     nfx/2 + 1.
/// apply and apply_symbol share work arrays: one operator serves one thread (copies share the
/// kernel's spectrum and have their own work arrays).
template <RealScalar Real>
class ConvolutionOperator {
 public:
  /// A complex number of the scalar.
  using Complex = std::complex<Real>;

  /// The kernel's padded spectrum from an InfluenceTable, transformed once.
  template <class Quadrature>
  explicit ConvolutionOperator(const InfluenceTable<Real, Quadrature>& table)
      : nx_(table.nx()),
        ny_(table.ny()),
        nfx_(detail::fft_size(2 * table.nx() - 1)),
        nfy_(detail::fft_size(2 * table.ny() - 1)),
        fft_(nfx_, nfy_, ny_),
        kernel_(kernel_spectrum(table, nfx_, nfy_)) {}

  /// A copy shares the kernel's spectrum and has its own work arrays.
  ConvolutionOperator(const ConvolutionOperator& o)
      : nx_(o.nx_),
        ny_(o.ny_),
        nfx_(o.nfx_),
        nfy_(o.nfy_),
        fft_(o.nfx_, o.nfy_, o.ny_),
        kernel_(o.kernel_) {}
  ConvolutionOperator& operator=(const ConvolutionOperator&) = delete;

  /// The grid's cells per row.
  int nx() const { return nx_; }
  /// The grid's cells per column.
  int ny() const { return ny_; }
  /// nfx, the padded transform's size along x.
  int fft_nx() const { return nfx_; }
  /// nfy, the padded transform's size along y.
  int fft_ny() const { return nfy_; }
  /// nfx/2 + 1, the half spectrum's size along x.
  int spectrum_nx() const { return nfx_ / 2 + 1; }
  /// (nfx/2 + 1) nfy, the values of a half spectrum.
  std::size_t spectrum_size() const {
    return static_cast<std::size_t>(spectrum_nx()) * static_cast<std::size_t>(nfy_);
  }

  /// u = K * p on the nx x ny grid (flat index i + nx j); u and p have nx ny entries.
  template <class In, class Out>
  void apply(const In& p, Out& u) const {
    load(p);
    fft_.forward_in_place();
    Complex* s = fft_.spectrum_data();
    const std::vector<Complex>& k = *kernel_;
    for (std::size_t q = 0; q < k.size(); ++q) s[q] *= k[q];
    store(u);
  }

  /// Multiplies the padded half spectrum of p by `symbol` (spectrum_size() values, index
  /// m + spectrum_nx() n) instead of the kernel's: a circulant operator on the padded grid,
  /// restricted to the nx x ny grid.
  template <class In, class Out>
  void apply_symbol(const std::vector<Complex>& symbol, const In& p, Out& u) const {
    load(p);
    fft_.forward_in_place();
    Complex* s = fft_.spectrum_data();
    const Real scale = Real(1) / (Real(nfx_) * Real(nfy_));
    for (std::size_t q = 0; q < symbol.size(); ++q) s[q] *= symbol[q] * scale;
    store(u);
  }

 private:
  /// The kernel's half spectrum divided by nfx nfy (the inverse transform is unscaled). The
  /// kernel fills every row of the padded grid: its transform is not pruned (rows = nfy).
  template <class Quadrature>
  static std::shared_ptr<const std::vector<Complex>> kernel_spectrum(
      const InfluenceTable<Real, Quadrature>& table, int nfx, int nfy) {
    const int nx = table.nx(), ny = table.ny();
    PaddedTransform<Real> fft(nfx, nfy, nfy);
    Real* r = fft.real_data();
    std::fill(r, r + static_cast<std::size_t>(nfx) * static_cast<std::size_t>(nfy), Real(0));
    for (int dj = -(ny - 1); dj <= ny - 1; ++dj)
      for (int di = -(nx - 1); di <= nx - 1; ++di)
        r[static_cast<std::size_t>((di + nfx) % nfx) +
          static_cast<std::size_t>(nfx) * static_cast<std::size_t>((dj + nfy) % nfy)] =
            table(di, dj);
    fft.forward_in_place();
    const Real scale = Real(1) / (Real(nfx) * Real(nfy));
    const Complex* s = fft.spectrum_data();
    auto k = std::make_shared<std::vector<Complex>>(static_cast<std::size_t>(nfx / 2 + 1) *
                                                    static_cast<std::size_t>(nfy));
    for (std::size_t q = 0; q < k->size(); ++q) (*k)[q] = s[q] * scale;
    return k;
  }
  std::size_t at(int i, int j) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(nfx_) * static_cast<std::size_t>(j);
  }
  /// The first ny rows of the padded real array: p, then zeros to nfx.
  template <class In>
  void load(const In& p) const {
    Real* r = fft_.real_data();
    for (int j = 0; j < ny_; ++j) {
      for (int i = 0; i < nx_; ++i) r[at(i, j)] = Real(p[static_cast<std::size_t>(i + nx_ * j)]);
      std::fill(r + at(nx_, j), r + at(0, j + 1), Real(0));
    }
  }
  template <class Out>
  void store(Out& u) const {
    fft_.inverse_in_place();
    const Real* r = fft_.real_data();
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) u[static_cast<std::size_t>(i + nx_ * j)] = r[at(i, j)];
  }

  int nx_, ny_, nfx_, nfy_;
  mutable PaddedTransform<Real> fft_;
  std::shared_ptr<const std::vector<Complex>> kernel_;
};

/// (B11): the inverse continuum symbol |k| / (2 pi c T(|k|) (1 + sum f_k / (1 - i k_x V tau_k))) on
/// the padded grid, |k| the discrete (finite-difference) wavenumber; the zero mode gets the
/// value of the lowest non-zero one. c is the instantaneous compliance, (f_k, tau_k) the memory
/// terms, V the speed, T the substrate's factor (H1) at thickness `thickness` in the grid's units
/// (1 without a substrate); ConvolutionOperator::apply_symbol applies it.
template <RealScalar Real>
std::vector<std::complex<Real>> preconditioner_symbol(
    const BemGrid<Real>& grid, const ConvolutionOperator<Real>& op, Real c,
    const std::vector<PronyTerm<Real>>& terms, Real speed,
    const SubstrateKernel<coefficient_real_t<Real>>* substrate = nullptr,
    coefficient_real_t<Real> thickness = 0) {
  using Complex = std::complex<Real>;
  using std::sin;
  using std::sqrt;
  const Real pi = boost::math::constants::pi<Real>();
  const int nfx = op.fft_nx(), nfy = op.fft_ny(), nfxh = op.spectrum_nx();
  std::vector<Complex> s(op.spectrum_size());
  const Real kmin = std::min(2 * pi / (Real(nfx) * grid.hx), 2 * pi / (Real(nfy) * grid.hy));
  for (int n = 0; n < nfy; ++n)
    for (int m = 0; m < nfxh; ++m) {
      const int mm = m, nn = n <= nfy / 2 ? n : n - nfy;
      const Real kx = 2 * pi * Real(mm) / (Real(nfx) * grid.hx),
                 ky = 2 * pi * Real(nn) / (Real(nfy) * grid.hy);
      const Real qx = 2 * sin(kx * grid.hx / 2) / grid.hx, qy = 2 * sin(ky * grid.hy / 2) / grid.hy;
      const Real k = std::max(sqrt(qx * qx + qy * qy), kmin);
      Complex memory(1);
      for (const auto& t : terms) memory += t.f / Complex(1, -kx * speed * t.tau);
      // A substrate's factor T (H1) at the same wavenumber.
      if (substrate != nullptr)
        memory *= Real(substrate->surface_factor(coefficient_real_t<Real>(k), thickness));
      s[static_cast<std::size_t>(m) +
        static_cast<std::size_t>(nfxh) * static_cast<std::size_t>(n)] = k / (2 * pi * c * memory);
    }
  return s;
}

/// The direct O((nx ny)^2) sum u = K * p, for tests of the FFT apply.
template <RealScalar Real, class Quadrature, class In, class Out>
void apply_direct(const InfluenceTable<Real, Quadrature>& table, const In& p, Out& u) {
  const int nx = table.nx(), ny = table.ny();
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      Real s = 0;
      for (int l = 0; l < ny; ++l)
        for (int k = 0; k < nx; ++k)
          s += table(i - k, j - l) * p[static_cast<std::size_t>(k + nx * l)];
      u[static_cast<std::size_t>(i + nx * j)] = s;
    }
}

}  // namespace bem
}  // namespace viscoroll
