// viscoroll: the 2-D real-to-complex transform of the boundary-element operator (docs/bem.md,
// (B7)): a real array of nfx x nfy values, zero outside its first `rows` rows, to its half
// spectrum (nfx/2 + 1 x nfy complex values, index m + (nfx/2 + 1) n), and back, unscaled.
//
// Two back ends with the same interface, PaddedTransform<Real>:
//   - FFTW 3 (float, double, long double) when VISCOROLL_HAVE_FFTW is defined (the CMake target
//     viscoroll defines it and links fftw3, fftw3f and fftw3l when it finds them: docs/bem.md,
//     "The transforms"). Its plans are made once per (scalar, nfx, nfy, rows) in a process, under
//     a mutex (FFTW's planner is not thread-safe), and executed on each operator's own arrays
//     with the new-array interface, which is;
//   - Eigen's FFT (kissfft back end, header-only) otherwise, and for any other scalar.
// Both are pruned to the zero padding: the forward transform runs the x direction over the
// `rows` non-zero rows only (real-to-complex), then the y direction over the nfx/2 + 1 columns;
// the inverse the y direction over every column, then the x direction (complex-to-real) over the
// first `rows` rows only, the only ones the operator reads.
#pragma once

#include <algorithm>
#include <complex>
#include <cstddef>
#include <type_traits>
#include <unsupported/Eigen/FFT>
#include <vector>

#if defined(VISCOROLL_HAVE_FFTW)
#include <fftw3.h>

#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <tuple>
#endif

namespace viscoroll::bem {

namespace fft_detail {

/// The Eigen (kissfft) back end, for every scalar.
///   - real_data(): the nfx x rows real array (row j at j nfx); spectrum_data(): the nfxh x nfy
///     half spectrum, nfxh = nfx/2 + 1;
///   - forward_in_place(): spectrum = F(real), real preserved;
///   - inverse_in_place(): real = nfx nfy F^-1(spectrum) (unscaled), spectrum overwritten.
template <class Real>
class EigenTransform {
 public:
  using Complex = std::complex<Real>;

  EigenTransform(int nfx, int nfy, int rows)
      : nfx_(nfx),
        nfy_(nfy),
        nfxh_(nfx / 2 + 1),
        rows_(rows),
        real_(static_cast<std::size_t>(nfx) * static_cast<std::size_t>(rows)),
        spec_(static_cast<std::size_t>(nfxh_) * static_cast<std::size_t>(nfy)),
        line_r_(static_cast<std::size_t>(nfx)),
        line_c_(static_cast<std::size_t>(nfxh_)),
        col_in_(static_cast<std::size_t>(nfy)),
        col_out_(static_cast<std::size_t>(nfy)) {
    fft_.SetFlag(Eigen::FFT<Real>::HalfSpectrum);
    fft_.SetFlag(Eigen::FFT<Real>::Unscaled);
  }

  Real* real_data() { return real_.data(); }
  Complex* spectrum_data() { return spec_.data(); }

  void forward_in_place() {
    for (int j = 0; j < rows_; ++j) {
      for (int i = 0; i < nfx_; ++i) line_r_[static_cast<std::size_t>(i)] = real_[at(i, j, nfx_)];
      fft_.fwd(line_c_, line_r_);
      for (int m = 0; m < nfxh_; ++m) spec_[at(m, j, nfxh_)] = line_c_[static_cast<std::size_t>(m)];
    }
    std::fill(spec_.begin() + static_cast<std::ptrdiff_t>(at(0, rows_, nfxh_)), spec_.end(),
              Complex(0));
    columns(false);
  }

  void inverse_in_place() {
    columns(true);
    for (int j = 0; j < rows_; ++j) {
      for (int m = 0; m < nfxh_; ++m) line_c_[static_cast<std::size_t>(m)] = spec_[at(m, j, nfxh_)];
      fft_.inv(line_r_, line_c_);
      for (int i = 0; i < nfx_; ++i) real_[at(i, j, nfx_)] = line_r_[static_cast<std::size_t>(i)];
    }
  }

 private:
  static std::size_t at(int i, int j, int stride) {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(stride) * static_cast<std::size_t>(j);
  }
  void columns(bool inverse) {
    for (int m = 0; m < nfxh_; ++m) {
      for (int n = 0; n < nfy_; ++n) col_in_[static_cast<std::size_t>(n)] = spec_[at(m, n, nfxh_)];
      if (inverse)
        fft_.inv(col_out_, col_in_);
      else
        fft_.fwd(col_out_, col_in_);
      for (int n = 0; n < nfy_; ++n) spec_[at(m, n, nfxh_)] = col_out_[static_cast<std::size_t>(n)];
    }
  }

  int nfx_, nfy_, nfxh_, rows_;
  std::vector<Real> real_;
  std::vector<Complex> spec_;
  std::vector<Real> line_r_;
  std::vector<Complex> line_c_, col_in_, col_out_;
  Eigen::FFT<Real> fft_;
};

#if defined(VISCOROLL_HAVE_FFTW)

/// FFTW's API for one scalar: fftw_ (double), fftwf_ (float), fftwl_ (long double).
template <class Real>
struct Fftw;

#define VISCOROLL_FFTW_API(REAL, P)                                                           \
  template <>                                                                                 \
  struct Fftw<REAL> {                                                                         \
    using plan = P##plan;                                                                     \
    using complex = P##complex;                                                               \
    static void* malloc(std::size_t n) { return P##malloc(n); }                               \
    static void free(void* p) { P##free(p); }                                                 \
    static void destroy(plan p) { P##destroy_plan(p); }                                       \
    static plan r2c(int n, int howmany, REAL* in, complex* out, int odist, unsigned flags) {  \
      return P##plan_many_dft_r2c(1, &n, howmany, in, nullptr, 1, n, out, nullptr, 1, odist,  \
                                  flags);                                                     \
    }                                                                                         \
    static plan c2r(int n, int howmany, complex* in, REAL* out, int idist, unsigned flags) {  \
      return P##plan_many_dft_c2r(1, &n, howmany, in, nullptr, 1, idist, out, nullptr, 1, n,  \
                                  flags);                                                     \
    }                                                                                         \
    /* Columns: n points at stride `howmany`, `howmany` of them at distance 1, in place. */   \
    static plan columns(int n, int howmany, complex* a, int sign, unsigned flags) {           \
      return P##plan_many_dft(1, &n, howmany, a, nullptr, howmany, 1, a, nullptr, howmany, 1, \
                              sign, flags);                                                   \
    }                                                                                         \
    static void execute_r2c(const plan p, REAL* in, complex* out) {                           \
      P##execute_dft_r2c(p, in, out);                                                         \
    }                                                                                         \
    static void execute_c2r(const plan p, complex* in, REAL* out) {                           \
      P##execute_dft_c2r(p, in, out);                                                         \
    }                                                                                         \
    static void execute_dft(const plan p, complex* in, complex* out) {                        \
      P##execute_dft(p, in, out);                                                             \
    }                                                                                         \
  };

VISCOROLL_FFTW_API(double, fftw_)
VISCOROLL_FFTW_API(float, fftwf_)
VISCOROLL_FFTW_API(long double, fftwl_)
#undef VISCOROLL_FFTW_API

/// The one mutex of FFTW's planners (inline: one object in the whole program).
inline std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

/// An array from FFTW's allocator (SIMD-aligned, as the plans were made for).
template <class T, class Real>
struct FftwArray {
  struct Free {
    void operator()(T* p) const { Fftw<Real>::free(p); }
  };
  std::unique_ptr<T, Free> data;
  explicit FftwArray(std::size_t n) : data(static_cast<T*>(Fftw<Real>::malloc(sizeof(T) * n))) {
    if (!data) throw std::bad_alloc();
  }
  T* get() const { return data.get(); }
};

/// The four plans of one (nfx, nfy, rows), made once per process and destroyed at its exit (with
/// the cache that holds them), so that a leak checker sees no plan outlive the program.
template <class Real>
struct FftwPlans {
  typename Fftw<Real>::plan rows_forward, columns_forward, columns_inverse, rows_inverse;

  static const FftwPlans& get(int nfx, int nfy, int rows) {
    using F = Fftw<Real>;
    // The mutex before the cache: statics die in reverse order, so ~Cache still has its mutex.
    std::mutex& mutex = fftw_planner_mutex();
    static Cache cache;
    const std::lock_guard<std::mutex> lock(mutex);
    const auto key = std::make_tuple(nfx, nfy, rows);
    const auto it = cache.plans.find(key);
    if (it != cache.plans.end()) return it->second;
    const int nfxh = nfx / 2 + 1;
    // FFTW_ESTIMATE: a plan in microseconds, without trial runs that would cost more than a
    // solve on a new grid; the arrays are only for the plans' alignment and strides.
    const unsigned flags = FFTW_ESTIMATE;
    FftwArray<Real, Real> real(static_cast<std::size_t>(nfx) * static_cast<std::size_t>(rows));
    FftwArray<typename F::complex, Real> spec(static_cast<std::size_t>(nfxh) *
                                              static_cast<std::size_t>(nfy));
    FftwPlans p{};
    p.rows_forward = F::r2c(nfx, rows, real.get(), spec.get(), nfxh, flags);
    p.columns_forward = F::columns(nfy, nfxh, spec.get(), FFTW_FORWARD, flags);
    p.columns_inverse = F::columns(nfy, nfxh, spec.get(), FFTW_BACKWARD, flags);
    p.rows_inverse = F::c2r(nfx, rows, spec.get(), real.get(), nfxh, flags);
    if (p.rows_forward == nullptr || p.columns_forward == nullptr || p.columns_inverse == nullptr ||
        p.rows_inverse == nullptr) {
      p.destroy();
      throw std::bad_alloc();
    }
    return cache.plans.emplace(key, p).first->second;
  }

 private:
  void destroy() const {
    for (const auto plan : {rows_forward, columns_forward, columns_inverse, rows_inverse})
      if (plan != nullptr) Fftw<Real>::destroy(plan);
  }
  /// The process's plans; destroyed after every operator that uses them (function-local
  /// statics are destroyed in the reverse order of their construction).
  struct Cache {
    std::map<std::tuple<int, int, int>, FftwPlans> plans;
    Cache() = default;
    Cache(const Cache&) = delete;
    Cache& operator=(const Cache&) = delete;
    ~Cache() {
      const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
      for (const auto& entry : plans) entry.second.destroy();
    }
  };
};

/// The FFTW back end: float, double and long double.
template <class Real>
class FftwTransform {
 public:
  using Complex = std::complex<Real>;
  using F = Fftw<Real>;

  FftwTransform(int nfx, int nfy, int rows)
      : nfx_(nfx),
        nfy_(nfy),
        nfxh_(nfx / 2 + 1),
        rows_(rows),
        plans_(&FftwPlans<Real>::get(nfx, nfy, rows)),
        real_(static_cast<std::size_t>(nfx) * static_cast<std::size_t>(rows)),
        spec_(static_cast<std::size_t>(nfxh_) * static_cast<std::size_t>(nfy)) {}

  /// As EigenTransform's.
  Real* real_data() { return real_.get(); }
  Complex* spectrum_data() { return reinterpret_cast<Complex*>(spec_.get()); }
  /// spectrum_data() = F(real_data()); real_data() is preserved.
  void forward_in_place() {
    F::execute_r2c(plans_->rows_forward, real_.get(), spec_.get());
    Complex* s = reinterpret_cast<Complex*>(spec_.get());
    std::fill(s + static_cast<std::size_t>(nfxh_) * static_cast<std::size_t>(rows_),
              s + static_cast<std::size_t>(nfxh_) * static_cast<std::size_t>(nfy_), Complex(0));
    F::execute_dft(plans_->columns_forward, spec_.get(), spec_.get());
  }
  /// real_data() = nfx nfy F^-1(spectrum_data()); the spectrum is overwritten.
  void inverse_in_place() {
    F::execute_dft(plans_->columns_inverse, spec_.get(), spec_.get());
    F::execute_c2r(plans_->rows_inverse, spec_.get(), real_.get());
  }

 private:
  int nfx_, nfy_, nfxh_, rows_;
  const FftwPlans<Real>* plans_;
  FftwArray<Real, Real> real_;
  FftwArray<typename F::complex, Real> spec_;
};

template <class Real>
inline constexpr bool has_fftw = std::is_same_v<Real, float> || std::is_same_v<Real, double> ||
                                 std::is_same_v<Real, long double>;

#else

template <class Real>
inline constexpr bool has_fftw = false;

#endif

}  // namespace fft_detail

/// The back end of scalar Real: FFTW where available, else Eigen's FFT.
template <class Real>
using PaddedTransform = std::conditional_t<fft_detail::has_fftw<Real>,
#if defined(VISCOROLL_HAVE_FFTW)
                                           fft_detail::FftwTransform<Real>,
#else
                                           fft_detail::EigenTransform<Real>,
#endif
                                           fft_detail::EigenTransform<Real>>;

/// The name of Real's back end, for reports: "FFTW" or "Eigen (kissfft)".
template <class Real>
constexpr const char* transform_backend() {
  return fft_detail::has_fftw<Real> ? "FFTW" : "Eigen (kissfft)";
}

}  // namespace viscoroll::bem
