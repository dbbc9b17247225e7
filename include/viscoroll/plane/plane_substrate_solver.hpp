// viscoroll: the plane problem on any substrate, a rigid cylinder rolling on a viscoelastic
// half space, a layer on a rigid base, a spring bed or a user's body (the Substrate concept).
//
// Hunter (1961), J. Appl. Mech. 28, 611-617; Panek & Kalker (1980), J. Inst. Maths Applics 26,
// Eq. (2) (Hunter's memory superposition). Derivation, accuracy and speed: docs/plane-substrate.md,
// equations (Q1)-(Q14); the layer's factor T: docs/theory.md section 19, (H1)-(H5).
//
// A body (SubstrateKind::half_space or ::body) is solved by spectral collocation of the surface
// slope, as tests/support/hunter_collocation.hpp solves the half space: the pressure on the
// contact [b - a, b + a] is p(b + a s) = sqrt(1 - s^2) sum_{n<N} c_n U_n(s) (Q5), the slope
// u'(x) = -C1 x is imposed at the N + 1 Chebyshev points (Q7), which gives c_n and b; the load
// (Q8) fixes a by TOMS 748. The half space's part of the kernel, -ln|x/a| with its memory, is
// exact through Chebyshev identities (Q6); the substrate's smooth remainder (Q3) is a Fourier
// integral over the wavenumber with the material's complex compliance (Q4), done by Gauss-Legendre
// panels to rounding. N is doubled from `initial_terms` until successive solutions agree to the
// tolerance (Q13): the error falls exponentially in N.
//
// A spring bed (SubstrateKind::local) has a local kernel; its memory integrals obey first-order
// ODEs (Q10), solved in closed form through the eigenvectors of a symmetric matrix (Q11); the
// edges follow from p = 0 at both ends and the load by a root in the leading edge (Q12).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <boost/math/special_functions/expint.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <complex>
#include <concepts>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/outcome.hpp>
#include <viscoroll/core/strip.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/plane/detail/memory_integrals.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/substrate/substrate.hpp>

namespace viscoroll {

/// Runtime settings of PlaneSubstrateSolver.
struct PlaneSubstrateOptions {
  /// Relative accuracy asked of a, d and chi (Q13); at least 64 eps of the scalar.
  double tolerance = 1e-8;
  /// Chebyshev terms of the first collocation; each refinement doubles them (Q13).
  int initial_terms = 16;
  /// The most terms tried before the solution is returned as not converged.
  int max_terms = 512;
  /// Iterations allowed to each root finder (TOMS 748 for a; the spring bed's edge).
  int max_iterations = 100;

  /// Throws std::invalid_argument naming the setting outside its range.
  void validate() const {
    detail::require(tolerance > 0 && tolerance <= 0.1, "tolerance", tolerance,
                    "0 < tolerance <= 0.1");
    detail::require(initial_terms >= 4 && initial_terms <= 4096, "initial_terms", initial_terms,
                    "4 <= initial_terms <= 4096");
    detail::require(max_terms >= 2 * initial_terms && max_terms <= 8192, "max_terms", max_terms,
                    "2 initial_terms <= max_terms <= 8192");
    detail::require(max_iterations >= 1 && max_iterations <= 100000, "max_iterations",
                    max_iterations, "1 <= max_iterations <= 100000");
  }
};

/// The plane solution on a substrate: the contact, its pressure, the approach and the rolling
/// friction, with the estimated discretisation errors (Q13).
template <RealScalar Real>
struct PlaneSubstrateSolution {
  Real a{};  ///< contact half width
  Real b{};  ///< offset of the contact centre ahead of the cylinder axis (Eq. 29)
  /// The approach d of the profile S = d - C1 x^2 / 2 (u = S on the contact). On a body on a rigid
  /// base (T(0) = 0) and on a spring bed it is measured from the base (the surface far away);
  /// on the half space, or a body with T(0) > 0, the displacement has a free constant and d is
  /// reported for the kernel normalised as -ln|x / a| ((Q3) with l = a): `d_absolute` is false.
  Real d{};
  bool d_absolute{};
  Real chi{};  ///< rolling-friction coefficient C1 int x p / int p (Eq. 51)
  Real error_a{}, error_d{}, error_chi{};  ///< estimated absolute errors (Q13)
  /// Estimated absolute error of the peak pressure (Q13), reported, not asked to meet the
  /// tolerance: a point value converges more slowly than a, d and chi.
  Real error_peak{};
  bool converged{};    ///< the estimates met the tolerance; see `reason`
  std::string reason;  ///< empty when converged, else why not (the returned values are the last)
  StopCode code = StopCode::converged;  ///< why it stopped, as a code (core/outcome.hpp)
  int terms{};           ///< Chebyshev terms N of the returned solution (0 for a spring bed)
  int iterations{};      ///< root-finder evaluations in all
  Real load_residual{};  ///< |int p dx / W - 1| of the returned solution
  PressurePeak<Real> peak_{};
  std::function<Real(Real)> pressure_function;

  /// The pressure at x (moving frame; the cylinder axis is x = 0), 0 outside the contact.
  Real pressure(Real x) const { return pressure_function(x); }
  /// The pressure peak and its location.
  PressurePeak<Real> peak() const { return peak_; }
};

namespace detail::plane_substrate {

/// Composite Gauss-Legendre (20 points per panel): calls g(x, w) for every node of [lo, hi].
template <class Real, class G>
void gauss_panel(Real lo, Real hi, G&& g) {
  using rule = boost::math::quadrature::gauss<Real, 20>;
  const auto& x = rule::abscissa();
  const auto& w = rule::weights();
  const Real mid = (lo + hi) / 2, half = (hi - lo) / 2;
  for (std::size_t i = 0; i < x.size(); ++i) {
    g(mid - half * x[i], half * w[i]);
    g(mid + half * x[i], half * w[i]);
  }
}

using plane_memory::memory_integrals;
using plane_memory::MemoryQuadrature;  // (Q6): plane/detail/memory_integrals.hpp
using plane_memory::tail_integrals;

/// J_k(x), k = 0..n_max, x > 0: above x = n_max + 1 by the upward recurrence from J_0 and J_1;
/// below it by Miller's backward recurrence J_{k-1} = (2k/x) J_k - J_{k+1} normalised by
/// J_0 + 2 sum_k J_2k = 1 (A&S 9.1.27, 9.1.46), started far enough above max(n_max, x) for the
/// scalar's precision.
template <class Real>
void bessel_j_sequence(Real x, int n_max, std::vector<Real>& j, std::vector<Real>& buffer) {
  using std::abs;
  using std::ceil;
  using std::sqrt;
  j.resize(static_cast<std::size_t>(n_max + 1));
  if (x > Real(n_max + 1)) {
    // Upward recurrence from J_0, J_1: stable while k < x (A&S 9.12), O(n_max) work.
    j[0] = boost::math::cyl_bessel_j(0, x);
    if (n_max >= 1) j[1] = boost::math::cyl_bessel_j(1, x);
    for (int k = 1; k < n_max; ++k)
      j[static_cast<std::size_t>(k + 1)] =
          Real(2 * k) / x * j[static_cast<std::size_t>(k)] - j[static_cast<std::size_t>(k - 1)];
    return;
  }
  const int top = std::max(n_max, static_cast<int>(ceil(x)));
  int m = top + 24 + static_cast<int>(sqrt(Real(80 * top)));
  if (m % 2 != 0) ++m;
  buffer.assign(static_cast<std::size_t>(m + 2), Real(0));
  const Real big = sqrt(std::numeric_limits<Real>::max()) / 4;
  Real next = 0,
       current = std::numeric_limits<Real>::min() * Real(1) / std::numeric_limits<Real>::epsilon();
  buffer[static_cast<std::size_t>(m)] = current;
  for (int k = m; k >= 1; --k) {
    const Real below = Real(2 * k) / x * current - next;
    next = current;
    current = below;
    buffer[static_cast<std::size_t>(k - 1)] = below;
    if (abs(below) > big) {
      for (int i = k - 1; i <= m; ++i) buffer[static_cast<std::size_t>(i)] /= big;
      next /= big;
      current /= big;
    }
  }
  Real norm = buffer[0];
  for (int k = 2; k <= m; k += 2) norm += 2 * buffer[static_cast<std::size_t>(k)];
  for (int k = 0; k <= n_max; ++k)
    j[static_cast<std::size_t>(k)] = buffer[static_cast<std::size_t>(k)] / norm;
}

/// (Q6): G_n(s) = int_{-1}^{1} sqrt(1 - t^2) U_n(t) ln|s - t| dt for |s| <= 1:
/// (pi/2)(s^2 - 1/2 - ln 2) for n = 0, (pi/2)(T_{n+2}(s)/(n+2) - T_n(s)/n) for n >= 1.
template <class Real>
std::vector<Real> log_potentials(Real phi, int n_terms) {
  using std::cos;
  using std::log;
  const Real pi = boost::math::constants::pi<Real>();
  std::vector<Real> g(static_cast<std::size_t>(n_terms));
  const Real s = cos(phi);
  g[0] = pi / 2 * (s * s - Real(0.5) - log(Real(2)));
  for (int n = 1; n < n_terms; ++n)
    g[static_cast<std::size_t>(n)] =
        pi / 2 * (cos(Real(n + 2) * phi) / Real(n + 2) - cos(Real(n) * phi) / Real(n));
  return g;
}

/// phi_j(y) = int_0^1 u^j e^{-y u} du, j = 0, 1, 2, y >= 0: the series below y = 2, above it
/// phi_0 = -expm1(-y)/y and phi_j = (j phi_{j-1} - e^-y)/y (errors damped by j/y < 1).
template <class Real>
std::array<Real, 3> exponential_moments(Real y) {
  using std::exp;
  using std::expm1;
  std::array<Real, 3> out{};
  if (y < 2) {
    for (int j = 0; j < 3; ++j) {
      Real term = 1, sum = 0;
      for (int m = 0; m < 80; ++m) {
        const Real add = term / Real(m + j + 1);
        sum += add;
        if (std::abs(static_cast<double>(add)) <=
            static_cast<double>(std::numeric_limits<Real>::epsilon()) *
                std::abs(static_cast<double>(sum)) / 4)
          break;
        term *= -y / Real(m + 1);
      }
      out[static_cast<std::size_t>(j)] = sum;
    }
    return out;
  }
  const Real e = exp(-y);
  out[0] = -expm1(-y) / y;
  out[1] = (out[0] - e) / y;
  out[2] = (2 * out[1] - e) / y;
  return out;
}

}  // namespace detail::plane_substrate

/// Solver of the plane rolling contact of a rigid cylinder on a substrate of a viscoelastic
/// material: PlaneSubstrateSolver<Real, Material, Body>. The material models ConstitutiveModel and
/// has Poisson's ratio `nu()` (the substrate's T depends on it); the body models Substrate.
template <RealScalar Real, ConstitutiveModel Material, Substrate Body>
requires std::same_as<typename Material::real_type, Real> &&
    std::same_as<typename Body::real_type, Real> && requires(const Material& m) {
  { m.nu() } -> std::convertible_to<Real>;
}
class PlaneSubstrateSolver {
 public:
  using Solution = PlaneSubstrateSolution<Real>;

  /// Throws std::invalid_argument naming the option outside its range.
  PlaneSubstrateSolver(Material material, Body body, PlaneSubstrateOptions options = {})
      : material_(std::move(material)), body_(std::move(body)), options_(options) {
    options_.validate();
    detail::require(
        options_.tolerance >= 64 * static_cast<double>(std::numeric_limits<Real>::epsilon()),
        "tolerance", options_.tolerance, "64 eps <= tolerance <= 0.1");
  }

  const Material& material() const { return material_; }
  const Body& body() const { return body_; }

  /// Solves the scene; throws std::invalid_argument naming c1, load or speed outside their ranges.
  /// A solution whose estimated error exceeds the tolerance, or whose pressure is negative, has
  /// converged = false and a `reason`.
  Solution solve(const PlaneScene<Real>& scene) const {
    scene.validate();
    Problem pr = problem(scene);
    if constexpr (Body::kind == SubstrateKind::local) {
      return solve_bed(pr);
    } else {
      return solve_body(pr);
    }
  }

 private:
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  using Complex = std::complex<Real>;

  /// One memory term at the scene's speed: creep ratio f_k and length L_k = V tau_k.
  struct Term {
    Real f, length;
  };

  struct Problem {
    Real c1, load, c;  ///< curvature, load, instantaneous compliance (relaxed terms folded in)
    Real creep;        ///< F = sum f_k of the active terms
    std::vector<Term> terms;
    Real nu, t0, omega_scale;  ///< Poisson's ratio, T(0), thickness
    Real a0;                   ///< long-term half-space Hertz half width, sqrt(4 c (1 + F) W / C1)
  };

  /// The material at the scene's speed (Q2): terms with L_k = 0 are relaxed and folded into the
  /// compliance, c (1 + f_r), the others' f_k divided by 1 + f_r; terms with f_k = 0 dropped.
  Problem problem(const PlaneScene<Real>& scene) const {
    Problem pr{};
    pr.c1 = scene.c1;
    pr.load = scene.load;
    pr.nu = static_cast<Real>(material_.nu());
    Real relaxed = 0;
    std::vector<Term> active;
    if constexpr (Material::is_viscoelastic) {
      const auto& terms = material_.memory_terms();
      for (std::size_t k = 0; k < terms.size(); ++k) {
        const Real length = scene.speed * terms[k].tau;
        if (!(terms[k].f > 0)) continue;
        if (length > 0)
          active.push_back(Term{terms[k].f, length});
        else
          relaxed += terms[k].f;
      }
    }
    pr.c = material_.instantaneous_compliance() * (1 + relaxed);
    pr.creep = 0;
    for (auto& t : active) {
      t.f /= 1 + relaxed;
      pr.creep += t.f;
    }
    pr.terms = std::move(active);
    using std::sqrt;
    pr.a0 = sqrt(4 * pr.c * (1 + pr.creep) * pr.load / pr.c1);
    if constexpr (Body::kind != SubstrateKind::half_space) {
      pr.omega_scale = body_.thickness();
      pr.t0 = body_.surface_factor(Real(0), pr.nu);
      detail::require(pr.t0 >= 0 && pr.t0 < std::numeric_limits<Real>::infinity(),
                      "surface_factor(0, nu)", pr.t0, "0 <= T(0) < inf (the Substrate concept)");
    } else {
      pr.omega_scale = std::numeric_limits<Real>::infinity();
      pr.t0 = 1;
    }
    return pr;
  }

  // ----- a body: spectral collocation ------------------------------------------------------

  /// The wavenumber from which |T(q) - 1| is at rounding level, <= eps at three successive
  /// multiples of 1/thickness (Q3): the Fourier integrals stop there.
  Real q_max(const Problem& pr) const {
    using std::abs;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real h = pr.omega_scale;
    int below = 0;
    for (int m = 1; m <= 1000; ++m) {
      const Real q = Real(m) / h;
      below = abs(body_.surface_factor(q, pr.nu) - 1) <= eps ? below + 1 : 0;
      if (below == 3) return q;
    }
    detail::require(false, "surface_factor", body_.surface_factor(Real(1000) / h, pr.nu),
                    "|T(q) - 1| <= eps at q = 1000/thickness (T - 1 must decay as "
                    "exp(-q thickness))");
    return Real(0);
  }

  /// Phi(q) = 1 + sum_k f_k / (1 - i q L_k): the complex compliance over c (Q4).
  static Complex compliance_ratio(const Problem& pr, Real q) {
    Complex phi(1, 0);
    for (const auto& t : pr.terms) phi += t.f / Complex(1, -q * t.length);
    return phi;
  }

  /// The collocation at half width a with N terms (Q7): the matrix of slopes, and, when
  /// `with_d`, the rows of displacement (Q9) at the same points.
  struct System {
    Matrix slope;         ///< (N+1) x (N+1): M_n(s_j) - E_n(s_j), last column -1
    Matrix displacement;  ///< (N+1) x N: U_n(s_j)/pi - D_n(s_j) (Q9), when asked
    std::vector<Real> s;  ///< collocation points s_j
  };

  System build(const Problem& pr, Real a, int n_terms, bool with_d) const {
    using std::cos;
    using std::exp;
    using std::sin;
    const Real pi = boost::math::constants::pi<Real>();
    const int rows = n_terms + 1;
    System sys;
    sys.slope.setZero(rows, rows);
    if (with_d) sys.displacement.setZero(rows, n_terms);
    sys.s.resize(static_cast<std::size_t>(rows));
    namespace ps = detail::plane_substrate;
    const ps::MemoryQuadrature<Real> mq{};
    std::vector<std::vector<Real>> tails(pr.terms.size());
    for (std::size_t k = 0; k < pr.terms.size(); ++k)
      tails[k] = ps::tail_integrals(pr.terms[k].length / a, n_terms, mq);
    for (int j = 0; j < rows; ++j) {
      const Real phi = Real(2 * j + 1) * pi / Real(2 * rows);
      sys.s[static_cast<std::size_t>(j)] = cos(phi);
      // (Q6): the half space's slope H_n = T_{n+1} and its memory f_k m_n(s; L_k / a).
      Real t = cos(phi), t_sin = sin(phi);
      for (int n = 0; n < n_terms; ++n) {
        sys.slope(j, n) = t;
        const Real next = t * cos(phi) - t_sin * sin(phi);
        t_sin = t_sin * cos(phi) + t * sin(phi);
        t = next;
      }
      std::vector<Real> g;
      if (with_d) {
        g = ps::log_potentials(phi, n_terms);
        for (int n = 0; n < n_terms; ++n)
          sys.displacement(j, n) = (1 + pr.creep) * g[static_cast<std::size_t>(n)] / pi;
      }
      for (std::size_t k = 0; k < pr.terms.size(); ++k) {
        const Real v = pr.terms[k].length / a;
        const auto m = ps::memory_integrals(phi, v, tails[k], mq);
        for (int n = 0; n < n_terms; ++n) {
          sys.slope(j, n) += pr.terms[k].f * m[static_cast<std::size_t>(n)];
          // (Q9): int e^-eta G_n(s + v eta) d eta = G_n(s) + pi v m_n(s).
          if (with_d) sys.displacement(j, n) += pr.terms[k].f * v * m[static_cast<std::size_t>(n)];
        }
      }
      sys.slope(j, n_terms) = Real(-1);
    }
    if constexpr (Body::kind == SubstrateKind::body) fourier_rows(pr, a, n_terms, with_d, sys);
    return sys;
  }

  /// (Q7), (Q9): subtracts the remainder's slope E_n(s_j) and displacement D_n(s_j),
  ///   E_n(s) = (n+1) int_0^W (T - 1) Re[i (-i)^n Phi e^{i w s}] J_{n+1}(w)/w dw,
  ///   D_n(s) = int_0^W { (T - 1)(n+1) Re[(-i)^n Phi e^{i w s}] J_{n+1}(w)/w
  ///                      + [n = 0] (1 - T(0))(1 + F) e^-w / 2 } dw / w + [n = 0] (1 - T(0))(1+F)
  ///                      E1(W)/2,
  /// T and Phi at q = w / a; panels at most 2 wide (the phases w s and w of J), a/(2h) (T's scale)
  /// and half the distance to Phi's nearest pole a/L_k.
  void fourier_rows(const Problem& pr, Real a, int n_terms, bool with_d, System& sys) const {
    using std::exp;
    using std::min;
    const int rows = n_terms + 1;
    const Real w_max = q_max(pr) * a;
    Real pole = std::numeric_limits<Real>::infinity();  // a / max L_k
    for (const auto& t : pr.terms) pole = min(pole, a / t.length);
    const Real width_cap = min(Real(4), a / (2 * pr.omega_scale));
    std::vector<Real> j_seq, buffer, coef(static_cast<std::size_t>(n_terms));
    Real w_lo = 0;
    while (w_lo < w_max) {
      Real width = width_cap;
      if (pole < std::numeric_limits<Real>::infinity())
        width = min(width, std::max(w_lo, pole) / 2);
      const Real w_hi = min(w_max, w_lo + width);
      detail::plane_substrate::gauss_panel(w_lo, w_hi, [&](Real w, Real weight) {
        const Real q = w / a;
        const Real tm1 = body_.surface_factor(q, pr.nu) - 1;
        const Complex phi = compliance_ratio(pr, q);
        detail::plane_substrate::bessel_j_sequence(w, n_terms, j_seq, buffer);
        for (int n = 0; n < n_terms; ++n)
          coef[static_cast<std::size_t>(n)] =
              weight * tm1 * Real(n + 1) * j_seq[static_cast<std::size_t>(n + 1)] / w;
        for (int j = 0; j < rows; ++j) {
          const Complex e = phi * std::polar(Real(1), w * sys.s[static_cast<std::size_t>(j)]);
          const Complex z = Complex(0, 1) * e;                               // i Phi e^{i w s}
          const Real cycle[4] = {z.real(), z.imag(), -z.real(), -z.imag()};  // Re[(-i)^n z]
          for (int n = 0; n < n_terms; ++n)
            sys.slope(j, n) -= coef[static_cast<std::size_t>(n)] * cycle[n % 4];
          if (with_d) {
            const Real cd[4] = {e.real(), e.imag(), -e.real(), -e.imag()};
            for (int n = 0; n < n_terms; ++n)
              sys.displacement(j, n) -= coef[static_cast<std::size_t>(n)] * cd[n % 4] / w;
            sys.displacement(j, 0) -= weight * (1 - pr.t0) * (1 + pr.creep) * exp(-w) / (2 * w);
          }
        }
      });
      w_lo = w_hi;
    }
    if (with_d) {
      const Real tail = (1 - pr.t0) * (1 + pr.creep) * boost::math::expint(1, w_max) / 2;
      for (int j = 0; j < rows; ++j) sys.displacement(j, 0) -= tail;
    }
  }

  /// The collocation solved at half width a: gamma_n (c_n = C1 a gamma_n / (2 pi c)), beta = b/a.
  struct Collocation {
    Vector x;  ///< gamma_0 .. gamma_{N-1}, beta
    Real residual{};
    System sys;
  };

  Collocation collocate(const Problem& pr, Real a, int n_terms, bool with_d) const {
    Collocation out;
    out.sys = build(pr, a, n_terms, with_d);
    const int rows = n_terms + 1;
    Vector rhs(rows);
    for (int j = 0; j < rows; ++j) rhs(j) = out.sys.s[static_cast<std::size_t>(j)];  // (Q7)
    const Eigen::PartialPivLU<Matrix> lu(out.sys.slope);
    out.x = lu.solve(rhs);
    const Real scale =
        out.sys.slope.cwiseAbs().rowwise().sum().maxCoeff() * out.x.cwiseAbs().maxCoeff() +
        rhs.cwiseAbs().maxCoeff();
    out.residual = (out.sys.slope * out.x - rhs).cwiseAbs().maxCoeff() / scale;
    return out;
  }

  /// One level of the refinement: the solution with N terms.
  struct Level {
    Real a{}, b{}, d{}, chi{};
    bool root_ok{};
    int evaluations{};
    Collocation col;
    std::function<Real(Real)> pressure;
    PressurePeak<Real> peak{};
    Real lowest{};  ///< the least sampled pressure (negative: not one contact)
  };

  /// The pressure (Q5) of a level, its peak (samples uniform in theta, x = b + a cos theta, then
  /// Brent around the best one) and its least sampled value.
  static void pressure_of(const Problem& pr, Level& l) {
    using std::cos;
    const Real pi = boost::math::constants::pi<Real>();
    const int n_terms = static_cast<int>(l.col.x.size()) - 1;
    std::vector<Real> coeffs(static_cast<std::size_t>(n_terms));
    for (int k = 0; k < n_terms; ++k)
      coeffs[static_cast<std::size_t>(k)] = pr.c1 * l.a * l.col.x(k) / (2 * pi * pr.c);
    const Real a = l.a, b = l.b;
    l.pressure = [coeffs, a, b](Real x) {
      const Real t = (x - b) / a;
      if (!(t > -1 && t < 1)) return Real(0);
      Real u_prev = 0, u = 1, sum = 0;  // (Q5): U_{-1} = 0, U_0 = 1
      for (const Real c : coeffs) {
        sum += c * u;
        const Real next = 2 * t * u - u_prev;
        u_prev = u;
        u = next;
      }
      using std::sqrt;
      return sqrt((1 - t) * (1 + t)) * sum;
    };
    const int samples = 8 * n_terms + 64;
    const auto p_theta = [&](Real theta) { return l.pressure(b + a * cos(theta)); };
    int best = 0;
    Real best_p = -std::numeric_limits<Real>::infinity();
    l.lowest = std::numeric_limits<Real>::infinity();
    for (int k = 0; k < samples; ++k) {
      const Real p = p_theta((Real(k) + Real(0.5)) * pi / Real(samples));
      if (p > best_p) {
        best_p = p;
        best = k;
      }
      l.lowest = std::min(l.lowest, p);
    }
    const Real t_lo = Real(std::max(0, best - 1)) * pi / Real(samples);
    const Real t_hi = Real(std::min(samples, best + 2)) * pi / Real(samples);
    const auto brent = boost::math::tools::brent_find_minima(
        [&](Real theta) { return -p_theta(theta); }, t_lo, t_hi, std::numeric_limits<Real>::digits);
    l.peak = PressurePeak<Real>{b + a * cos(brent.first), -brent.second};
  }

  /// (Q8): the load C1 a^2 gamma_0(a) / (4 c) = W, by TOMS 748 on a; bracketed around `guess`.
  Level level(const Problem& pr, int n_terms, Real guess, Real spread) const {
    Level out;
    const auto load_gap = [&](Real a) {
      ++out.evaluations;
      const auto col = collocate(pr, a, n_terms, false);
      return pr.c1 * a * a * col.x(0) / (4 * pr.c * pr.load) - 1;
    };
    Real lo = guess / (1 + spread), hi = guess * (1 + spread);
    Real g_lo = load_gap(lo), g_hi = load_gap(hi);
    for (int k = 0; k < 60 && !(g_lo <= 0 && g_hi >= 0); ++k) {
      if (g_lo > 0) {
        hi = lo;
        g_hi = g_lo;
        lo /= 2;
        g_lo = load_gap(lo);
      } else {
        lo = hi;
        g_lo = g_hi;
        hi *= 2;
        g_hi = load_gap(hi);
      }
    }
    Real a = hi;
    out.root_ok = false;
    if (g_lo <= 0 && g_hi >= 0) {
      if (g_lo == 0 || g_hi == 0) {
        a = g_lo == 0 ? lo : hi;
        out.root_ok = true;
      } else {
        std::uintmax_t iterations = static_cast<std::uintmax_t>(options_.max_iterations);
        const auto r = boost::math::tools::toms748_solve(
            load_gap, lo, hi, g_lo, g_hi,
            boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 3),
            iterations);
        a = (r.first + r.second) / 2;
        out.root_ok = iterations < static_cast<std::uintmax_t>(options_.max_iterations);
      }
    }
    out.a = a;
    out.col = collocate(pr, a, n_terms, true);
    const Vector& x = out.col.x;
    out.b = x(n_terms) * a;
    out.chi = pr.c1 * (out.b + a * x(1) / (2 * x(0)));  // Eq. (51) with (Q5)
    // (Q9): d = u(x_j) + C1 x_j^2 / 2, averaged over the collocation points.
    const Vector u = -pr.c1 * a * a * (out.col.sys.displacement * x.head(n_terms));
    Real d = 0;
    for (int j = 0; j <= n_terms; ++j) {
      const Real xj = out.b + a * out.col.sys.s[static_cast<std::size_t>(j)];
      d += u(j) + pr.c1 * xj * xj / 2;
    }
    out.d = d / Real(n_terms + 1);
    pressure_of(pr, out);
    return out;
  }

  Solution solve_body(const Problem& pr) const {
    using std::abs;
    using std::max;
    using std::sqrt;
    const Real tol = Real(options_.tolerance);
    Solution s;
    s.d_absolute = Body::kind == SubstrateKind::body && pr.t0 == 0;
    std::vector<Level> levels;
    // The first bracket starts at the half space's width or, on a thin body, at 4 thicknesses
    // (the Fourier rows cost in proportion to a / thickness; the search doubles from there).
    Real guess = std::min(pr.a0 / sqrt(sqrt(1 + pr.creep)), 4 * pr.omega_scale);
    // [guess / (1 + spread), guess (1 + spread)]: first the glassy to long-term range.
    Real spread = sqrt(1 + pr.creep) - 1 + Real(1) / 64;
    int n = options_.initial_terms;
    bool met = false;
    for (; n <= options_.max_terms; n *= 2) {
      levels.push_back(level(pr, n, guess, spread));
      s.iterations += levels.back().evaluations;
      guess = levels.back().a;
      // The next bracket: four times the last change of a (at least 1e-12 of it).
      spread =
          levels.size() < 2
              ? Real(1) / 256
              : std::max(Real(4) * abs(guess - levels[levels.size() - 2].a) / guess, Real(1e-12));
      if (levels.size() < 2) continue;
      const Level& now = levels.back();
      const Level& before = levels[levels.size() - 2];
      // (Q13) = theory.md (E2), (E3): (5/4) of the last change, or of half the change before it
      // when that is larger (either can be small by coincidence, never both).
      const Level* earlier = levels.size() >= 3 ? &levels[levels.size() - 3] : nullptr;
      const auto estimate = [&](auto member) {
        Real e = abs(member(now) - member(before));
        if (earlier) e = max(e, abs(member(before) - member(*earlier)) / 2);
        return Real(5) / 4 * e;
      };
      s.error_a = estimate([](const Level& l) { return l.a; });
      s.error_d = estimate([](const Level& l) { return l.d; });
      s.error_chi = estimate([](const Level& l) { return l.chi; });
      s.error_peak = estimate([](const Level& l) { return l.peak.pressure; });
      const Real d_scale = max(abs(now.d), pr.c1 * now.a * now.a / 2);
      const Real chi_scale = max(abs(now.chi), Real(1e-6) * pr.c1 * now.a);
      if (s.error_a <= tol * now.a && s.error_d <= tol * d_scale &&
          s.error_chi <= tol * chi_scale) {
        met = true;
        break;
      }
    }
    const Level& last = levels.back();
    s.a = last.a;
    s.b = last.b;
    s.d = last.d;
    s.chi = last.chi;
    s.terms = static_cast<int>(last.col.x.size()) - 1;
    s.load_residual = abs(pr.c1 * s.a * s.a * last.col.x(0) / (4 * pr.c * pr.load) - 1);
    s.pressure_function = last.pressure;
    s.peak_ = last.peak;
    const Real lowest = last.lowest;
    // Converged: every level's root, the tolerance (Q13), and a pressure that is nowhere
    // negative beyond the tolerance (else the contact is not one interval with square-root edges).
    bool roots = true;
    for (const auto& l : levels) roots = roots && l.root_ok;
    s.converged = met && roots && lowest >= -tol * s.peak_.pressure;
    if (!roots)
      set_stop(s, StopCode::root_finder_failed,
               "the root finder for the half width a did not converge");
    else if (!met)
      set_stop(s, StopCode::tolerance_not_met,
               "the estimated errors (a " + detail::format_value(s.error_a) + ", d " +
                   detail::format_value(s.error_d) + ", chi " + detail::format_value(s.error_chi) +
                   ") exceed the tolerance at max_terms = " + std::to_string(options_.max_terms));
    else if (!s.converged)
      set_stop(s, StopCode::not_a_contact,
               "the pressure is negative (" + detail::format_value(lowest) +
                   "): the contact is not one interval with square-root edges");
    return s;
  }

  // ----- a spring bed: closed form of the memory ODEs ---------------------------------------

  /// The memory of a spring bed (Q10)-(Q11) for a leading edge x2: m = X^-1 V z,
  /// z_i(x) = sigma_i int_x^{x2} e^{-lambda_i (s - x)} g(s) ds, g(s) = (C1/2)(x2^2 - s^2).
  struct BedModes {
    Real kappa{};  ///< the bed's instantaneous compliance 2 pi c l (Q10)
    Real c1{};
    std::vector<Real> f;  ///< f_k
    Vector lambda;        ///< eigenvalues of M = L^-1 + u u^T (Q11)
    Matrix back;          ///< X^-1 V: m = back z
    Vector sigma;         ///< V^T X rho, rho_k = 1 / (kappa L_k)
    Real creep{};

    /// (Q12): p(x) = g(x)/kappa - sum_k f_k m_k(x) for x <= x2.
    Real pressure(Real x, Real x2) const {
      const Real g = c1 / 2 * (x2 - x) * (x2 + x);
      if (f.empty()) return g / kappa;
      const Real delta = x2 - x;
      const int k_count = static_cast<int>(f.size());
      Vector z(k_count);
      for (int i = 0; i < k_count; ++i) {
        const auto mu = detail::plane_substrate::exponential_moments(lambda(i) * delta);
        // int_0^delta e^{-lambda t} g(x + t) dt = delta^{j+1} phi_j moments of
        // (C1/2)[(x2^2 - x^2) - 2 x t - t^2].
        const Real m0 = delta * mu[0], m1 = delta * delta * mu[1],
                   m2 = delta * delta * delta * mu[2];
        z(i) = sigma(i) * c1 / 2 * ((x2 - x) * (x2 + x) * m0 - 2 * x * m1 - m2);
      }
      const Vector m = back * z;
      Real memory = 0;
      for (int k = 0; k < k_count; ++k) memory += f[static_cast<std::size_t>(k)] * m(k);
      return g / kappa - memory;
    }
  };

  BedModes bed_modes(const Problem& pr) const {
    const Real pi = boost::math::constants::pi<Real>();
    BedModes modes;
    // (Q10): T(q) = q l, so K = pi l delta(x) and u = 2 pi c l p.
    const Real h = body_.thickness();
    const Real l = body_.surface_factor(1 / h, pr.nu) * h;
    detail::require(l > 0 && l < std::numeric_limits<Real>::infinity(), "surface_factor(q)/q", l,
                    "0 < T(q)/q < inf for a local substrate");
    modes.kappa = 2 * pi * pr.c * l;
    modes.c1 = pr.c1;
    modes.creep = pr.creep;
    const int k_count = static_cast<int>(pr.terms.size());
    if (k_count == 0) return modes;
    Matrix m(k_count, k_count);
    Vector u(k_count), x(k_count);
    for (int k = 0; k < k_count; ++k) {
      const auto& t = pr.terms[static_cast<std::size_t>(k)];
      modes.f.push_back(t.f);
      using std::sqrt;
      u(k) = sqrt(t.f / t.length);
      x(k) = sqrt(t.f * t.length);
    }
    m = u * u.transpose();
    for (int k = 0; k < k_count; ++k) m(k, k) += 1 / pr.terms[static_cast<std::size_t>(k)].length;
    const Eigen::SelfAdjointEigenSolver<Matrix> eig(m);
    modes.lambda = eig.eigenvalues();
    modes.back = x.cwiseInverse().asDiagonal() * eig.eigenvectors();
    Vector rho(k_count);
    for (int k = 0; k < k_count; ++k)
      rho(k) = x(k) / (modes.kappa * pr.terms[static_cast<std::size_t>(k)].length);
    modes.sigma = eig.eigenvectors().transpose() * rho;
    return modes;
  }

  /// Integrals over the contact [x1, x2] of p(x) and x p(x): Gauss-Legendre panels graded
  /// geometrically towards x2 (the memory's boundary layer, of width 1/lambda_max), `refine`
  /// times halved.
  template <class F>
  static void bed_quadrature(const BedModes& modes, Real x1, Real x2, int refine, F&& g) {
    const Real span = x2 - x1;
    Real layer = span / 32;
    if (modes.lambda.size() > 0) layer = std::min(layer, 1 / modes.lambda.maxCoeff());
    layer /= Real(1 << refine);
    const Real uniform = span / Real(32 << refine);
    Real hi = x2, width = layer;
    while (hi > x1) {
      const Real lo = std::max(x1, hi - width);
      detail::plane_substrate::gauss_panel(lo, hi, g);
      hi = lo;
      width = std::min(2 * width, uniform);
    }
  }

  Solution solve_bed(const Problem& pr) const {
    using std::abs;
    using std::cbrt;
    const BedModes modes = bed_modes(pr);
    Solution s;
    s.d_absolute = true;
    int evaluations = 0;
    // (Q12): the trailing edge x1 < x2 is the first zero of p behind x2, bracketed by steps.
    const auto trailing = [&](Real x2) {
      const Real step = x2 / 128;
      Real hi = x2 - step / 1024, p_hi = modes.pressure(hi, x2);
      for (int k = 0; k < 1 << 16; ++k) {
        const Real lo = hi - step;
        const Real p_lo = modes.pressure(lo, x2);
        if (p_lo <= 0) {
          if (p_lo == 0) return lo;
          std::uintmax_t it = static_cast<std::uintmax_t>(options_.max_iterations);
          const auto r = boost::math::tools::toms748_solve(
              [&](Real x) { return modes.pressure(x, x2); }, lo, hi, p_lo, p_hi,
              boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 3), it);
          return (r.first + r.second) / 2;
        }
        hi = lo;
        p_hi = p_lo;
      }
      return hi;
    };
    const auto moments = [&](Real x1, Real x2, int refine) {
      std::array<Real, 2> out{};
      bed_quadrature(modes, x1, x2, refine, [&](Real x, Real w) {
        const Real p = modes.pressure(x, x2);
        out[0] += w * p;
        out[1] += w * x * p;
      });
      return out;
    };
    const auto load_gap = [&](Real x2) {
      ++evaluations;
      return moments(trailing(x2), x2, 0)[0] / pr.load - 1;
    };
    // Bracket: the glassy and the long-term static leading edges, (3 W kappa (1+f) / (2 C1))^(1/3).
    Real lo = cbrt(3 * pr.load * modes.kappa / (2 * pr.c1)) / 2;
    Real hi = cbrt(3 * pr.load * modes.kappa * (1 + pr.creep) / (2 * pr.c1)) * 2;
    Real g_lo = load_gap(lo), g_hi = load_gap(hi);
    for (int k = 0; k < 60 && g_lo > 0; ++k) g_lo = load_gap(lo /= 2);
    for (int k = 0; k < 60 && g_hi < 0; ++k) g_hi = load_gap(hi *= 2);
    bool root_ok = g_lo <= 0 && g_hi >= 0;
    Real x2 = hi;
    if (root_ok) {
      std::uintmax_t it = static_cast<std::uintmax_t>(options_.max_iterations);
      const auto r = boost::math::tools::toms748_solve(
          load_gap, lo, hi, g_lo, g_hi,
          boost::math::tools::eps_tolerance<Real>(std::numeric_limits<Real>::digits - 3), it);
      x2 = (r.first + r.second) / 2;
      root_ok = it < static_cast<std::uintmax_t>(options_.max_iterations);
    }
    const Real x1 = trailing(x2);
    const auto coarse = moments(x1, x2, 0), fine = moments(x1, x2, 1);
    s.a = (x2 - x1) / 2;
    s.b = (x2 + x1) / 2;
    s.d = pr.c1 * x2 * x2 / 2;  // (Q12): p(x2) = 0
    s.chi = pr.c1 * fine[1] / fine[0];
    s.load_residual = abs(fine[0] / pr.load - 1);
    // (Q13) for the closed form: the quadrature's change under halving its panels (rounding,
    // some eps C1 a in chi, is not included).
    s.error_chi = Real(5) / 4 * abs(s.chi - pr.c1 * coarse[1] / coarse[0]);
    s.error_a = Real(5) / 4 * abs(fine[0] - coarse[0]) / pr.load * s.a;
    s.error_d = 2 * s.error_a / s.a * s.d;
    s.iterations = evaluations;
    const auto m = modes;
    s.pressure_function = [m, x1, x2](Real x) {
      return (x > x1 && x < x2) ? std::max(Real(0), m.pressure(x, x2)) : Real(0);
    };
    // The peak: the best of the quadrature's nodes, then Brent around it.
    Real best_x = s.b, best_p = -1;
    bed_quadrature(modes, x1, x2, 1, [&](Real x, Real) {
      const Real p = modes.pressure(x, x2);
      if (p > best_p) {
        best_p = p;
        best_x = x;
      }
    });
    const Real reach = (x2 - x1) / 64;
    const auto brent = boost::math::tools::brent_find_minima(
        [&](Real x) { return -s.pressure_function(x); }, std::max(x1, best_x - reach),
        std::min(x2, best_x + reach), std::numeric_limits<Real>::digits / 2);
    s.peak_ = PressurePeak<Real>{brent.first, -brent.second};
    const Real tol = Real(options_.tolerance);
    const bool met = s.error_a <= tol * s.a &&
                     s.error_chi <= tol * std::max(abs(s.chi), Real(1e-6) * pr.c1 * s.a);
    s.converged = root_ok && met;
    if (!root_ok)
      set_stop(s, StopCode::root_finder_failed,
               "the root finder for the leading edge did not converge");
    else if (!met)
      set_stop(s, StopCode::tolerance_not_met,
               "the quadrature's estimated errors (a " + detail::format_value(s.error_a) +
                   ", chi " + detail::format_value(s.error_chi) + ") exceed the tolerance");
    return s;
  }

  Material material_;
  Body body_;
  PlaneSubstrateOptions options_;
};

/// The scalar deduced from the material: PlaneSubstrateSolver solver(material, Layer<double>(h)).
template <ConstitutiveModel Material, Substrate Body>
PlaneSubstrateSolver(Material, Body)
    -> PlaneSubstrateSolver<typename Material::real_type, Material, Body>;
template <ConstitutiveModel Material, Substrate Body>
PlaneSubstrateSolver(Material, Body, PlaneSubstrateOptions)
    -> PlaneSubstrateSolver<typename Material::real_type, Material, Body>;

}  // namespace viscoroll
