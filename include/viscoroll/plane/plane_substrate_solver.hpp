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
#include <viscoroll/plane/detail/plane_substrate_functions.hpp>
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
  /// Whether d is measured from a fixed base (see d).
  bool d_absolute{};
  Real chi{};  ///< rolling-friction coefficient C1 int x p / int p (Eq. 51)
  ///@{
  Real error_a{}, error_d{}, error_chi{};  ///< estimated absolute errors (Q13)
  ///@}
  /// Estimated absolute error of the peak pressure (Q13), reported, not asked to meet the
  /// tolerance: a point value converges more slowly than a, d and chi.
  Real error_peak{};
  bool converged{};    ///< the estimates met the tolerance; see `reason`
  std::string reason;  ///< empty when converged, else why not (the returned values are the last)
  StopCode code = StopCode::converged;  ///< why it stopped, as a code (core/outcome.hpp)
  int terms{};           ///< Chebyshev terms N of the returned solution (0 for a spring bed)
  int iterations{};      ///< root-finder evaluations in all
  Real load_residual{};  ///< |int p dx / W - 1| of the returned solution
  /// The pressure peak, as peak() returns it.
  PressurePeak<Real> peak_{};
  /// The pressure p(x), as pressure() returns it.
  std::function<Real(Real)> pressure_function;

  /// The pressure at x (moving frame; the cylinder axis is x = 0), 0 outside the contact.
  Real pressure(Real x) const { return pressure_function(x); }
  /// The pressure peak and its location.
  PressurePeak<Real> peak() const { return peak_; }
};

namespace detail {
/// What PlaneSubstrateSolver asks of its arguments: a material and a body over Real, the material
/// with Poisson's ratio `nu()` (the substrate's T depends on it).
template <class Real, class Material, class Body>
concept PlaneSubstrateArguments = std::same_as<typename Material::real_type, Real> &&
    std::same_as<typename Body::real_type, Real> && requires(const Material& m) {
  { m.nu() } -> std::convertible_to<Real>;
};
}  // namespace detail

/// Solver of the plane rolling contact of a rigid cylinder on a substrate of a viscoelastic
/// material: PlaneSubstrateSolver<Real, Material, Body>. The material models ConstitutiveModel and
/// has Poisson's ratio `nu()` (the substrate's T depends on it); the body models Substrate.
template <RealScalar Real, ConstitutiveModel Material, Substrate Body>
requires detail::PlaneSubstrateArguments<Real, Material, Body>
class PlaneSubstrateSolver {
 public:
  /// The solution type.
  using Solution = PlaneSubstrateSolution<Real>;

  /// Throws std::invalid_argument naming the option outside its range.
  PlaneSubstrateSolver(Material material, Body body, PlaneSubstrateOptions options = {})
      : material_(std::move(material)), body_(std::move(body)), options_(options) {
    options_.validate();
    detail::require(
        options_.tolerance >= 64 * static_cast<double>(std::numeric_limits<Real>::epsilon()),
        "tolerance", options_.tolerance, "64 eps <= tolerance <= 0.1");
  }

  /// The material.
  const Material& material() const { return material_; }
  /// The substrate.
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

  /// (Q6), (Q7), (Q9): the System at half width a with N terms (the displacement rows when
  /// `with_d`), the substrate's remainder subtracted on a body (fourier_rows).
  System build(const Problem& pr, Real a, int n_terms, bool with_d) const;

  /// (Q7), (Q9): subtracts the remainder's slope E_n(s_j) and displacement D_n(s_j),
  ///   E_n(s) = (n+1) int_0^W (T - 1) Re[i (-i)^n Phi e^{i w s}] J_{n+1}(w)/w dw,
  ///   D_n(s) = int_0^W { (T - 1)(n+1) Re[(-i)^n Phi e^{i w s}] J_{n+1}(w)/w
  ///                      + [n = 0] (1 - T(0))(1 + F) e^-w / 2 } dw / w + [n = 0] (1 - T(0))(1+F)
  ///                      E1(W)/2,
  /// T and Phi at q = w / a; panels at most 2 wide (the phases w s and w of J), a/(2h) (T's scale)
  /// and half the distance to Phi's nearest pole a/L_k.
  void fourier_rows(const Problem& pr, Real a, int n_terms, bool with_d, System& sys) const;

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
  static void pressure_of(const Problem& pr, Level& l);

  /// (Q8): the load C1 a^2 gamma_0(a) / (4 c) = W, by TOMS 748 on a; bracketed around `guess`.
  Level level(const Problem& pr, int n_terms, Real guess, Real spread) const;

  /// A body (SubstrateKind::half_space or ::body): the levels of N = initial_terms, 2
  /// initial_terms, ... terms until the estimates (Q13) meet the tolerance.
  Solution solve_body(const Problem& pr) const;

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

  /// (Q10)-(Q11): the spring bed's modes, from the eigenvectors of M = L^-1 + u u^T.
  BedModes bed_modes(const Problem& pr) const;

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

  /// A spring bed (SubstrateKind::local): the leading edge x2 by TOMS 748 on the load, the
  /// trailing edge as the first zero of p behind it (Q12), the errors (Q13).
  Solution solve_bed(const Problem& pr) const;

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

// The long members of PlaneSubstrateSolver, defined out of the class: a body's collocation and
// its levels, and the spring bed's closed form.
#include <viscoroll/plane/detail/plane_substrate_bed.hpp>
#include <viscoroll/plane/detail/plane_substrate_levels.hpp>
