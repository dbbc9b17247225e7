// user_extensions: a material, a roller profile and a substrate written here, outside the
// library, each run through the solvers that take it (docs/materials.md, "Any solid by its
// complex modulus"; core/concepts.hpp, roller/profile.hpp for the contracts).
//
//   material   a fractional Zener (Cole-Cole) rubber, known only by its complex modulus
//                G*(w) = G_0 + (G_g - G_0) (i w tau)^alpha / (1 + (i w tau)^alpha),
//              made a Prony series by prony_approximation (docs/theory.md (R1), (R10), (R14));
//   profile    a roller flat over its middle whose ends drop by a cosine blend,
//                h(y) = z (1 - cos(pi s / (2 w))),  s = |y| - L_f/2 in (0, w);
//   substrate  a rubber cover bonded to a rigid base, its factor T(qh) written from
//              docs/theory.md (H2) as printed.
//
// The scene: a steel roller of radius 50 mm, 100 mm long, under 1 kN at 1 m/s. Prints each
// solver's contact and rolling-friction coefficient chi; exits 1 if the fit is poor or a solve
// did not converge.
//
//   user_extensions
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <viscoroll/bem/bem_profile.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony_approximation.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/plane/plane_substrate_solver.hpp>

namespace {

const double pi = std::acos(-1.0);

/// The material: G*(omega) of the fractional Zener solid, omega in rad/s, moduli in Pa.
struct FractionalZener {
  double g_rubbery = 5e6, g_glassy = 1e8, tau = 1e-3, alpha = 0.4;
  std::complex<double> operator()(double omega) const {
    const auto z = std::polar(std::pow(omega * tau, alpha), alpha * pi / 2);  // (i omega tau)^alpha
    return g_rubbery + (g_glassy - g_rubbery) * z / (1.0 + z);
  }
};

/// The profile (a model of viscoroll::RollerProfile): radius R, flat over L_f, cosine-blended ends
/// of width w dropping by z.
struct CosineBlendRoller {
  using real_type = double;
  double radius = 0.05, flat = 0.06, blend = 0.02, end_drop = 1e-3;
  double c1() const { return 1 / radius; }
  double drop(double y) const {
    const double s = std::abs(y) - flat / 2;
    return s <= 0 ? 0.0 : end_drop * (1 - std::cos(pi * s / (2 * blend)));
  }
  double drop_slope(double y) const {
    const double s = std::abs(y) - flat / 2;
    const double slope =
        s <= 0 ? 0.0 : end_drop * pi / (2 * blend) * std::sin(pi * s / (2 * blend));
    return y < 0 ? -slope : slope;
  }
  double y_max() const { return flat / 2 + blend; }
  double y_min() const { return -y_max(); }
  bool symmetric() const { return true; }
};

/// The substrate (a model of viscoroll::Substrate): a cover of thickness h bonded to a rigid
/// base, T(x) of (H2) at x = q h, 1 where it is 1 to rounding.
struct BondedCover {
  using real_type = double;
  static constexpr viscoroll::SubstrateKind kind = viscoroll::SubstrateKind::body;
  double h = 0.006;
  double surface_factor(double q, double nu) const {
    const double x = q * h, k = 3 - 4 * nu;
    if (x > 25) return 1.0;
    return (k * std::sinh(2 * x) - 2 * x) /
           (k * std::cosh(2 * x) + 2 * x * x + 5 - 12 * nu + 8 * nu * nu);
  }
  double thickness() const { return h; }
};

}  // namespace

int main() {
  bool ok = true;
  const auto report = [&](const char* what, const auto& s, double a) {
    ok = ok && s.converged;
    std::string why;
    if constexpr (requires { s.reason; }) why = s.reason;
    std::printf("  %-44s a = %6.3f mm  chi = %.4e%s%s\n", what, a * 1e3, double(s.chi),
                s.converged ? "" : "  NOT CONVERGED: ", s.converged ? "" : why.c_str());
  };

  // 1. The material: a Prony series over 1e-4 ... 1e6 Hz, with the fit's error.
  const auto fit = viscoroll::prony_approximation(FractionalZener{}, 0.45, 1e-4, 1e6);
  std::printf("material: %s\n", fit.summary.c_str());
  ok = ok && !fit.poor;
  const auto& rubber = fit.material;  // a viscoroll::PronyRelaxation<double>

  const CosineBlendRoller roller;
  const BondedCover cover;
  const double load = 1000.0, speed = 1.0;  // N, m/s
  const double per_length = load / roller.flat;

  // 2. The material alone: the plane problem (Hunter) on the half space, load per flat length.
  std::printf("plane problem, %.0f N/m at %.1f m/s:\n", per_length, speed);
  const auto plane =
      viscoroll::PlaneSolver<double, viscoroll::PronyRelaxation<double>>(rubber).solve(
          {.c1 = roller.c1(), .load = per_length, .speed = speed});
  report("half space (PlaneSolver)", plane, plane.a);
  viscoroll::PlaneSubstrateOptions plane_options;
  plane_options.tolerance = 1e-4;  // relative, on a, d and chi (as examples/conveyor_idler.cpp)
  const auto on_cover = viscoroll::PlaneSubstrateSolver(rubber, cover, plane_options)
                            .solve({.c1 = roller.c1(), .load = per_length, .speed = speed});
  report("user's bonded cover (PlaneSubstrateSolver)", on_cover, on_cover.a);

  // 3. The user's roller: the line theory and the exact BEM, on the half space and on the cover.
  std::printf("the cosine-blended roller, %.0f N at %.1f m/s (a is a(0), the width at y = 0):\n",
              load, speed);
  const auto line = viscoroll::LineSolver<double, viscoroll::PronyRelaxation<double>>(rubber).solve(
      viscoroll::LineProfileScene<CosineBlendRoller>{roller, load, speed});
  report("half space (LineSolver)", line, line.a(0.0));
  viscoroll::BemOptions options;
  options.grid = 12;
  const auto scene = viscoroll::bem_scene(roller, rubber, load, speed);
  const auto bem = viscoroll::BemSolver(rubber, options).solve(scene);
  report("half space (BemSolver)", bem, bem.a0);
  const auto bem_cover =
      viscoroll::BemSolver<double, viscoroll::PronyRelaxation<double>>(rubber, options, cover)
          .solve(scene);
  report("user's bonded cover (BemSolver)", bem_cover, bem_cover.a0);
  std::printf("  contact length: line %.1f mm, BEM %.1f mm (the flat part is %.0f mm)\n",
              2e3 * line.l(), 1e3 * (bem.l + bem.l), 1e3 * roller.flat);

  std::printf(ok ? "user_extensions: every solve converged\n"
                 : "user_extensions: a fit or a solve FAILED\n");
  return ok ? 0 : 1;
}
