// viscoroll: the exact 3-D boundary-element reference solver of the rolling contact.
//
// Panek & Kalker (1980), Eqs. (2), (3), (12), (13), (27), (51) solved without the line-contact
// approximation: the surface is divided into rectangles of constant pressure whose viscoelastic
// influence coefficients (rectangle_influence.hpp, docs/bem.md B1-B5) make the displacement a
// non-symmetric 2-D convolution applied by FFT (influence_operator.hpp, B6-B7). The contact set,
// the pressure and the penetration d under the total load come from the primal-dual active-set
// iteration of numerics/active_set.hpp, whose linear systems, restricted to the active cells and
// bordered by the load equation, are solved by GMRES right-preconditioned with the continuum
// symbol (B11). Nothing of it assumes a symmetric operator. The scene, the options and the
// solution are in bem_scene.hpp, with the units and conventions.
// This header needs Eigen's unsupported FFT module; the umbrella header does not include it.
#pragma once

#include <algorithm>
#include <boost/math/special_functions/fpclassify.hpp>
#include <boost/math/tools/roots.hpp>
#include <chrono>
#include <cmath>
#include <complex>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include <viscoroll/bem/bem_scene.hpp>
#include <viscoroll/bem/hertz.hpp>
#include <viscoroll/bem/influence_operator.hpp>
#include <viscoroll/bem/rectangle_influence.hpp>
#include <viscoroll/core/binary.hpp>
#include <viscoroll/core/concepts.hpp>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/material/generalized_maxwell.hpp>
#include <viscoroll/material/prony.hpp>  // compiled mode: PronyRelaxation<double>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/numerics/active_set.hpp>
#include <viscoroll/substrate/substrate.hpp>

namespace viscoroll {

namespace detail {
/// What BemSolver asks of its arguments: a material over Real, and a nodal quadrature rule over the
/// influence coefficients' scalar (bem::coefficient_real_t).
template <class Real, class Material, class Quadrature>
concept BemSolverArguments = std::same_as<typename Material::real_type, Real> &&
    NodalQuadratureRule<Quadrature, bem::coefficient_real_t<Real>>;
}  // namespace detail

/// Boundary-element solver over a scalar, a material (any ConstitutiveModel: Elastic,
/// StandardLinearSolid, or a spectrum such as GeneralizedMaxwell, term by term (B10)) and the
/// NodalQuadratureRule of the memory coefficients' panels (B4)-(B5), bem::MemoryPanelRule
/// (16-point Gauss-Legendre) by default: GaussLegendre<double, 24> there measures the default's
/// quadrature error (rectangle_influence.hpp).
///   - BemSolver(material, options): throws std::invalid_argument for invalid options;
///   - solve(scene, start): the contact (B11) and its measures (B12), a BemSolution;
///   - grid_for(scene): the grid solve() uses; long_term_hertz(scene): Hertz's contact of the
///     long-term compliance (B8), which sizes it;
///   - material(), options(): what the solver was built with.
template <RealScalar Real, ConstitutiveModel Material,
          class Quadrature = bem::MemoryPanelRule<Real>>
requires detail::BemSolverArguments<Real, Material, Quadrature>
class BemSolver {
 public:
  /// The solution type.
  using Solution = BemSolution<Real>;
  /// A complex number of the scalar.
  using Complex = std::complex<Real>;
  /// The type the influence coefficients are computed in (at least double).
  using W = bem::coefficient_real_t<Real>;

  /// Throws std::invalid_argument for invalid options (BemOptions::validate).
  explicit BemSolver(Material material, BemOptions options = {})
      : material_(std::move(material)), options_(options) {
    options_.validate();
  }

  /// The solver on a substrate other than the half space (core/concepts.hpp, Substrate): a Layer,
  /// a SpringBed or a user's body, with the material's Poisson's ratio `material.nu()`. Its
  /// kernel (bem/substrate_kernel.hpp, (B15)) is tabulated here, once.
  template <Substrate S>
  requires std::same_as<typename S::real_type, Real> && requires(const Material& m) {
    { m.nu() } -> std::convertible_to<Real>;
  }
  BemSolver(Material material, BemOptions options, const S& substrate)
      : material_(std::move(material)), options_(options) {
    options_.validate();
    if constexpr (S::kind != SubstrateKind::half_space)
      substrate_ = std::make_shared<const bem::SubstrateKernel<W>>(
          bem::substrate_kernel<W>(substrate, W(material_.nu())));
  }

  /// The material.
  const Material& material() const { return material_; }
  /// The settings.
  const BemOptions& options() const { return options_; }

  /// The grid the solver uses for a scene: grid elements per semi-axis of the long-term static
  /// Hertz ellipse, odd counts covering `extent` semi-axes each way.
  BemGrid<Real> grid_for(const BemScene<Real>& scene) const;

  /// Solves the scene; `start` (a solution on the same grid) seeds the active set and the
  /// pressure. Throws std::invalid_argument for an invalid scene; a non-converged iteration is
  /// returned with converged == false and the reason.
  Solution solve(const BemScene<Real>& scene, const Solution* start = nullptr) const;

  /// Hertz's contact (B8) of the scene on the long-term compliance (1 + f) c: the V tau = 0
  /// solution, which sizes the grid and scales d.
  bem::HertzContact<Real> long_term_hertz(const BemScene<Real>& scene) const;

 private:
  /// The memory terms that act on the grid. A term whose memory length L = V tau_k is glassy on
  /// it is dropped (it leaves the instantaneous response, exactly the limit L -> inf). Its
  /// coefficients (B3) are at most (hx hy / L)(ln(L/h) + 10 + |ln(hx/hy)|), h = min(hx, hy)
  /// (docs/bem.md, "Glassy memory terms"; measured constant 7.2 for square cells, 8.8 at 5:1:
  /// tests/bem/rectangle_influence.test.cpp), against an elastic coefficient of at least about
  /// hx hy / R at the grid's diagonal R; the term goes when f_k times their ratio is <= eps. That
  /// covers L = +inf (speed x tau overflowed), where the recurrence (B4)-(B5) has no scale to
  /// step with. A term whose L is under eps hx takes L = 0 (the long-term limit, below).
  static std::vector<PronyTerm<Real>> effective_terms(const BemGrid<Real>& grid, Real speed,
                                                      const std::vector<PronyTerm<Real>>& all) {
    using std::abs;
    using std::log;
    using std::sqrt;
    const Real eps = std::numeric_limits<Real>::epsilon();
    const Real diagonal = sqrt(Real(grid.nx) * grid.hx * Real(grid.nx) * grid.hx +
                               Real(grid.ny) * grid.hy * Real(grid.ny) * grid.hy);
    const Real h = std::min(grid.hx, grid.hy), shape = 10 + abs(log(grid.hx / grid.hy));
    std::vector<PronyTerm<Real>> kept;
    for (const auto& t : all) {
      const Real length = speed * t.tau;
      if (length > diagonal) {
        const Real u = diagonal / length;
        // ln L - ln h, not ln(L/h): L/h overflows for L near the largest double (speed 1e308).
        if (!(u > 0) || t.f * u * (log(length) - log(h) + shape) <= eps) continue;
      }
      // A memory length under eps hx is the long-term limit M_L = K_e + O((L/hx) ln(hx/L))
      // (B3): the recurrence (B4) cannot step with it (its panels round to zero width), so the
      // term takes L = 0, which the table evaluates as K_e exactly.
      if (length > 0 && length < eps * grid.hx) {
        kept.push_back(PronyTerm<Real>{t.f, Real(0)});
        continue;
      }
      kept.push_back(t);
    }
    return kept;
  }

  /// A user profile must be finite at every cell centre: a NaN or infinite gap would enter the
  /// complementarity test unseen (a NaN gap is never negative) or the linear systems.
  static void validate_profile(const BemScene<Real>& scene, const BemGrid<Real>& grid) {
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const Real h = scene.gap_profile(grid.x(i), grid.y(j));
        if (!(boost::math::isfinite)(h))
          detail::require(
              false, "profile(x, y)", h,
              "finite at every cell centre; here x = " + detail::format_value(grid.x(i)) +
                  ", y = " + detail::format_value(grid.y(j)));
      }
  }

  /// The BEM's operator of the active-set iteration (numerics::ContactOperator): K of (B6)-(B7),
  /// preconditioned by the inverse continuum symbol of (B11), or by nothing when `symbol` is null.
  struct ActiveSetOperator {
    const bem::ConvolutionOperator<Real>& op;
    const std::vector<Complex>* symbol;

    void apply(const std::vector<Real>& p, std::vector<Real>& u) const { op.apply(p, u); }
    void precondition(const std::vector<Real>& v, std::vector<Real>& out) const {
      if (symbol != nullptr)
        op.apply_symbol(*symbol, v, out);
      else
        out = v;
    }
  };

  /// The active-set iteration's start: the contact and pressure of `start` (a solution on the
  /// same grid) scaled to the load, else the Hertz contact of an effective compliance between
  /// the long-term (V tau = 0) and the instantaneous (V tau -> inf) one, each memory term weighted
  /// by a/(a + V tau_k).
  numerics::ActiveSetState<Real> initial_state(const BemScene<Real>& scene,
                                               const BemGrid<Real>& grid,
                                               const bem::HertzContact<Real>& hertz,
                                               const std::vector<PronyTerm<Real>>& terms,
                                               Real compliance, const Solution* start) const;

  /// (B18): a local bed's contact, exactly. Its rows are independent and its operator is
  /// triangular along x (a cell sinks under its own pressure and, through the memory of Eq. (2),
  /// the pressures ahead of it): for a penetration d, the cells from the front back take
  ///   p_i = max(0, (d - h_i - sum_{k > i} K(i - k, 0) p_k) / K(0, 0)),
  /// the complementarity solution of the row; the load grows with d, and TOMS 748 meets it to
  /// the scalar's precision. The active-set iteration then starts from the right set and
  /// confirms it in one solve (the primal-dual iteration alone can cycle here: the memory
  /// couplings are positive, the operator is not an M-matrix).
  static numerics::ActiveSetState<Real> local_bed_state(
      const BemGrid<Real>& grid, const bem::InfluenceTable<Real, Quadrature>& table,
      const std::vector<Real>& h, Real load, Real d_scale);

  /// The contact of (B11): the active-set iteration (numerics/active_set.hpp) on the gap
  /// g = u - d + h of the cell centres (Eqs. 13, 27) under the load hx hy sum p = P, its load row
  /// and gap tolerance in units of the long-term Hertz penetration.
  Solution iterate(const BemScene<Real>& scene, const BemGrid<Real>& grid,
                   const bem::HertzContact<Real>& hertz, const bem::ConvolutionOperator<Real>& op,
                   const std::vector<Complex>& symbol, const std::vector<PronyTerm<Real>>& terms,
                   Real compliance, int length_exponent, const Solution* start,
                   const bem::InfluenceTable<Real, Quadrature>* local = nullptr) const;

  /// The solution of the last iterate: the gap, the load, chi (Eq. 51 on piecewise-constant
  /// cells), the edges (B12) and the residual, the largest violation of p >= 0, g >= 0, p g = 0
  /// or of the load relative to d of Hertz (B11). A contact cell on the grid's border fails it.
  static Solution measure(const BemScene<Real>& scene, const BemGrid<Real>& grid,
                          const bem::HertzContact<Real>& hertz,
                          const bem::ConvolutionOperator<Real>& op, const std::vector<Real>& h,
                          numerics::ActiveSetState<Real> state,
                          const numerics::ActiveSetReport& report);

  /// What a converged solution does not claim: a contact under three cells across, where (B13)
  /// gives no error bound, is not converged; a pressure front sharper than the grid leaves a(0)
  /// and b(0) unclaimed (a warning); a non-finite value makes the residual NaN and the solution
  /// not converged.
  void judge(Solution& sol, const BemScene<Real>& scene, const std::vector<PronyTerm<Real>>& terms,
             int length_exponent) const;

  struct Edges {
    Real a0, b0, l;
  };

  /// (B12): a(0), b(0) and l of the pressure p on grid g.
  static Edges locate_edges(const BemGrid<Real>& g, const std::vector<Real>& p);

  /// The scene in the units of the solve (docs/bem.md, "Scaling"): lengths in the surface
  /// plane in 2^length, displacements (d, the gap, the profile) in 2^displacement, pressures in
  /// 2^pressure, all powers of two, so that every product and quotient rounds as in the caller's
  /// units wherever those neither overflow nor underflow (core/binary.hpp). The displacement
  /// unit makes C1 lie in [1, 2) (displacement = 2 length + exponent of C1: d ~ C1 a^2); the
  /// pressure unit makes the long-term compliance (1 + f) c lie in [1, 4); the length unit makes
  /// the long-term Hertz semi-axis a_H of order one (a_H^3 ~ (1 + f) c P / C1, (B8)). The memory
  /// terms become (f_k, V tau_k / 2^length), their memory lengths in the units, at the speed 1:
  /// an overflowed length is +inf (the glassy limit, dropped by effective_terms), one under
  /// eps hx the long-term limit.
  struct Scaled {
    BemScene<Real> scene;
    Real compliance;                     ///< instantaneous c in the units
    std::vector<PronyTerm<Real>> terms;  ///< (f_k, V tau_k) in the units
    int length, displacement, pressure;  ///< binary exponents of the units
    std::string inputs;                  ///< the inputs, for an error message
    W thickness = 0;                     ///< the substrate's thickness in the units
    /// The substrate's factor T(kappa/a) at the long-term contact it gives (B19): the compliance
    /// that sizes the grid and starts the iteration is (1 + f) c times it; 1 on the half space.
    Real sizing = 1;
  };

  /// The scene in the units of the solve (Scaled); throws std::invalid_argument for an
  /// invalid scene.
  Scaled scaled(const BemScene<Real>& scene) const;

  /// The grid of `n` elements per semi-axis in the units of `u`: of the long-term Hertz ellipse,
  /// or across (x) of `across` when given (the refinement's, which sizes the cells by the contact
  /// the grid before found). A roller profile on a body stiffer than the half space (B19's
  /// F < 1) keeps the cells of the sized ellipse but covers along y what the half space's grid
  /// covers: bem_scene() sized C2 for the half space, and a profile's contact is as long as its
  /// drop allows (a flat roller's, its flat length), not shorter by F^(1/3) as an ellipsoid's.
  BemGrid<Real> grid_in_units(const Scaled& u, const bem::HertzContact<Real>& hertz, int n,
                              Real across = 0) const;

  /// Hertz's long-term contact (B8) in the units of `u`, on the compliance (1 + f) c times the
  /// substrate's sizing factor (B19).
  static bem::HertzContact<Real> hertz_in_units(const Scaled& u, Real creep_ratio) {
    return bem::hertz_contact(u.scene.c1, u.scene.c2, (1 + creep_ratio) * u.compliance * u.sizing,
                              u.scene.load);
  }

  /// (B19): the factor F = T(kappa / min(a, b)) of the Hertz contact (a, b) on the compliance
  /// (1 + f) c F, kappa = 2, by bisection in ln F (T(kappa/a(F)) falls as F grows).
  Real sizing_factor(const Scaled& u) const;

  /// A start solution in the caller's units, in the units of `u` (or null).
  static std::optional<Solution> start_in_units(const Solution* start, const Scaled& u);

  /// The solution of the units of `u` in the caller's units. A converged solution's d, a(0), l,
  /// peak pressure and load must be normal numbers there, else an error names them and the
  /// inputs.
  static void to_caller_units(Solution& s, const Scaled& u);

  /// One solve on the grid of `n` elements per semi-axis (across: of `across`, in the units of
  /// `u`, when given), in the caller's units.
  Solution solve_on(const Scaled& u, int n, const Solution* start, Real across = 0) const;

  /// The refinement of BemOptions::tolerance (docs/theory.md, "The boundary-element solver's
  /// error estimate").
  Solution refine(const Scaled& u, const Solution* start) const;

  Material material_;
  BemOptions options_;
  std::shared_ptr<const bem::SubstrateKernel<W>> substrate_;  ///< null: the half space
};

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires detail::BemSolverArguments<Real, Material, Quadrature>
auto BemSolver<Real, Material, Quadrature>::solve(const BemScene<Real>& scene,
                                                  const Solution* start) const -> Solution {
  const Scaled u = scaled(scene);
  if (options_.tolerance > 0) return refine(u, start);
  return solve_on(u, options_.grid, start);
}

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires detail::BemSolverArguments<Real, Material, Quadrature>
auto BemSolver<Real, Material, Quadrature>::grid_for(const BemScene<Real>& scene) const
    -> BemGrid<Real> {
  const Scaled u = scaled(scene);
  BemGrid<Real> g = grid_in_units(u, hertz_in_units(u, material_.creep_ratio()), options_.grid);
  const auto inputs = [&] { return u.inputs; };
  g.hx = detail::representable(g.hx, u.length, "the cell width hx", inputs, false);
  g.hy = detail::representable(g.hy, u.length, "the cell length hy", inputs, false);
  return g;
}

template <RealScalar Real, ConstitutiveModel Material, class Quadrature>
requires detail::BemSolverArguments<Real, Material, Quadrature>
auto BemSolver<Real, Material, Quadrature>::long_term_hertz(const BemScene<Real>& scene) const
    -> bem::HertzContact<Real> {
  const Scaled u = scaled(scene);
  const bem::HertzContact<Real> h = hertz_in_units(u, material_.creep_ratio());
  const auto inputs = [&] { return u.inputs; };
  return {
      detail::representable(h.a, u.length, "the long-term Hertz semi-axis a", inputs, false),
      detail::representable(h.b, u.length, "the long-term Hertz semi-axis b", inputs, false),
      detail::representable(h.d, u.displacement, "the long-term Hertz penetration", inputs, false),
      detail::representable(h.p0, u.pressure, "the long-term Hertz pressure", inputs, false)};
}

}  // namespace viscoroll

// The long members of BemSolver, defined out of the class before the explicit instantiation
// declarations below: the scene in the units of the solve, the contact of one grid and the
// refinement's loop over grids.
#include <viscoroll/bem/detail/bem_grid_loop.hpp>
#include <viscoroll/bem/detail/bem_iteration.hpp>
#include <viscoroll/bem/detail/bem_units.hpp>

namespace viscoroll {

/// The scalar deduced from the material: BemSolver solver(GeneralizedMaxwell<double>(...)).
template <ConstitutiveModel Material>
BemSolver(Material) -> BemSolver<typename Material::real_type, Material>;
template <ConstitutiveModel Material>
BemSolver(Material, BemOptions) -> BemSolver<typename Material::real_type, Material>;

/// The common case: double precision, standard linear solid.
using BemSolverD = BemSolver<double, StandardLinearSolid<double>>;

// Compiled mode (docs/building.md, "Compiled mode"; as PlaneSolver's in plane_solver.hpp): these
// are instantiated once in viscoroll::compiled (or compiled_double), not here.
#if defined(VISCOROLL_COMPILED)
extern template class BemSolver<float, StandardLinearSolid<float>>;
extern template class BemSolver<long double, StandardLinearSolid<long double>>;
#endif
#if defined(VISCOROLL_COMPILED) || defined(VISCOROLL_COMPILED_DOUBLE)
extern template class BemSolver<double, StandardLinearSolid<double>>;
extern template class BemSolver<double, PronyRelaxation<double>>;
#endif

}  // namespace viscoroll
