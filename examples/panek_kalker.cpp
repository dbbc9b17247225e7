// panek_kalker: the paper's 3-D scene (Panek & Kalker 1980, Section 7) over speed, by the line
// solver. f = 9, nu = 0.5, mu_D = 1, tau = 1, C1 = 1, C2 = (ln 20 - 1)/25 (a 5:1 static contact
// ellipse) and the load P = 5 C1 / (3 (1 + f) c), c = (1 - nu)/(2 pi mu_D), so that the static
// long-term half width a0 = a(0)|_{V tau = 0} = 1 (l0 = 5 a0). Speeds V tau/a0 log-spaced over
// 1e-3 ... 1e3, solved in increasing order, each seeded with the previous converged solution.
// Writes
//   <dir>/panek_kalker_sweep.csv     Fig. 3 and 4: vtau (= V tau/a0), a0_ratio = a(0)/a0,
//                                    b0_ratio = b(0)/a0, l_ratio = l/l0, d_over_c1a0sq = d/(C1
//                                    a0^2), chi, converged, iterations, seconds (wall time of that
//                                    solve), residual (max |r| of the scaled equations; empty if
//                                    undefined), root (1: a root of the line equations; 0 with
//                                    converged = 1: their least-squares minimum, where they have no
//                                    root)
//   <dir>/panek_kalker_zones.csv     Fig. 5: the contact outline x = b(y) +- a(y), y in [-l, l]
//                                    (units of a0), for V tau/a0 in {0.01, 0.1, 0.3, 1, 3, 10,
//                                    100}: vtau, y, x_lead = b + a, x_trail = b - a
//   <dir>/panek_kalker_pressure.csv  Fig. 6: the pressure along y = 0 for the same speeds, rescaled
//                                    as we read the paper's "rescaled for comparison": the contact
//                                    mapped onto xi = (x - b(0))/a(0) in [-1, 1] (trailing edge
//                                    -1, leading edge +1) and p divided by its peak on y = 0;
//                                    columns vtau, xi, p_over_pmax, x (units of a0), p a0^2 / P
// and prints a summary table and the glassy (V tau -> infinity) limits.
// usage: panek_kalker [output-directory] [--speeds N] [--terms N]
//        (defaults out/panek_kalker, 61 speeds, 6 Chebyshev terms)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/sweep.hpp>

namespace {

using Solver = viscoroll::LineSolverD;
using Solution = Solver::Solution;

struct Arguments {
  std::filesystem::path dir = "out/panek_kalker";
  int speeds = 61;
  int terms = 6;
};

int parse_count(std::string_view option, const char* text, int lo, int hi) {
  char* end = nullptr;
  const long n = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || n < lo || n > hi)
    throw std::invalid_argument("panek_kalker: " + std::string(option) +
                                " expects an integer in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "], got '" + text + "'");
  return static_cast<int>(n);
}

Arguments parse(int argc, char** argv) {
  Arguments args;
  bool have_dir = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    if ((a == "--speeds" || a == "--terms") && i + 1 < argc) {
      if (a == "--speeds")
        args.speeds = parse_count(a, argv[++i], 2, 100000);
      else
        args.terms = parse_count(a, argv[++i], 1, 64);
    } else if (!a.starts_with("--") && !have_dir) {
      args.dir = a;
      have_dir = true;
    } else {
      throw std::invalid_argument(
          "usage: panek_kalker [output-directory] [--speeds N] [--terms N]");
    }
  }
  return args;
}

}  // namespace

int main(int argc, char** argv) {
  Arguments args;
  try {
    args = parse(argc, argv);
  } catch (const std::invalid_argument& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  std::filesystem::create_directories(args.dir);

  const double f = 9, nu = 0.5, mu_d = 1, tau = 1, c1 = 1;
  const double c2 = (std::log(20.0) - 1) / 25;
  const viscoroll::StandardLinearSolid<double> material(mu_d, nu, f, tau);
  const double load = c1 * 5 / (3 * (1 + f) * material.instantaneous_compliance());
  viscoroll::LineOptions options;
  options.terms = args.terms;
  const Solver solver(material, options);
  auto solve = [&](double vtau, const Solution* start) {
    return solver.solve(
        viscoroll::LineScene<double>{.c1 = c1, .c2 = c2, .load = load, .speed = vtau / tau}, start);
  };
  // Continuation from the previous speed.
  std::optional<Solution> last;
  // The previous speed's solution where it seeds by viscoroll::sweep's rule (usable_as_seed,
  // which vr.sweep follows too: a least-squares minimum seeds nothing).
  auto seed = [&]() -> const Solution* {
    return last && viscoroll::usable_as_seed(*last) ? &*last : nullptr;
  };

  // Fig. 3 and 4: the sweep.
  std::ofstream sweep(args.dir / "panek_kalker_sweep.csv");
  sweep << "vtau,a0_ratio,b0_ratio,l_ratio,d_over_c1a0sq,chi,converged,iterations,seconds,residual,"
           "root\n";
  sweep.precision(17);
  std::vector<double> speeds;
  std::vector<Solution> solutions;
  int failures = 0;
  double a0 = 1, l0 = 5, d0 = 0;
  const auto sweep_start = std::chrono::steady_clock::now();
  std::printf("%12s %10s %10s %10s %12s %11s %5s %4s %8s %9s\n", "Vtau/a0", "a(0)/a0", "b(0)/a0",
              "l/l0", "d/(C1a0^2)", "chi", "conv", "it", "s", "residual");
  for (int i = 0; i < args.speeds; ++i) {
    const double vtau = std::pow(10.0, -3 + 6.0 * i / (args.speeds - 1));
    const auto t0 = std::chrono::steady_clock::now();
    Solution s = solve(vtau, seed());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    a0 = s.a_long_term;
    l0 = s.l_long_term;
    d0 = s.d_long_term;
    const double d_scaled = s.d / (c1 * a0 * a0);
    sweep << vtau << ',' << s.a(0.0) / a0 << ',' << s.b(0.0) / a0 << ',' << s.l() / l0 << ','
          << d_scaled << ',' << s.chi << ',' << (s.converged ? 1 : 0) << ',' << s.iterations << ','
          << seconds << ',';
    if (std::isfinite(s.residual)) sweep << s.residual;
    sweep << ',' << (s.root ? 1 : 0) << '\n';
    std::printf("%12.5g %10.6f %10.6f %10.6f %12.8f %11.8f %5s %4d %8.3f %9.2g%s%s\n", vtau,
                s.a(0.0) / a0, s.b(0.0) / a0, s.l() / l0, d_scaled, s.chi,
                s.converged ? "yes" : "NO", s.iterations, seconds, s.residual, s.root ? "" : "  ",
                s.root ? "" : s.reason.c_str());
    if (!s.converged) ++failures;
    speeds.push_back(vtau);
    solutions.push_back(s);
    last = std::move(s);
  }
  const double sweep_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - sweep_start).count();
  std::printf("sweep: %d speeds, terms = %d, %.1f s, %d not converged\n", args.speeds, args.terms,
              sweep_seconds, failures);
  const double glassy = std::pow(1 + f, -1.0 / 3);
  std::printf("static (V tau = 0): a0 = %.12g, l0 = %.12g (l0/a0 = %.6g), d0/(C1 a0^2) = %.10g\n",
              a0, l0, l0 / a0, d0 / (c1 * a0 * a0));
  std::printf(
      "glassy limits (V tau -> inf): a(0)/a0 = l/l0 = (1+f)^(-1/3) = %.6f, d/d0 = (1+f)^(-2/3) = "
      "%.6f, "
      "d/(C1 a0^2) = %.8f\n",
      glassy, glassy * glassy, glassy * glassy * d0 / (c1 * a0 * a0));

  // Fig. 5 and 6: the zones and the pressure on y = 0 at a few speeds, each seeded with the
  // converged sweep solution nearest below it (reused when the speed is on the sweep's grid).
  std::ofstream zones(args.dir / "panek_kalker_zones.csv");
  std::ofstream pressure(args.dir / "panek_kalker_pressure.csv");
  zones << "vtau,y,x_lead,x_trail\n";
  pressure << "vtau,xi,p_over_pmax,x,p_a0sq_over_P\n";
  zones.precision(17);
  pressure.precision(17);
  const double pi = std::acos(-1.0);
  for (double vtau : {0.01, 0.1, 0.3, 1.0, 3.0, 10.0, 100.0}) {
    std::optional<Solution> s;
    const Solution* start = nullptr;
    for (std::size_t i = 0; i < speeds.size(); ++i) {
      if (std::abs(speeds[i] - vtau) <= 1e-9 * vtau) s = solutions[i];
      if (speeds[i] <= vtau && solutions[i].converged) start = &solutions[i];
    }
    if (!s) s = solve(vtau, start);
    if (!s->converged) {
      ++failures;
      std::printf("V tau/a0 = %g: not converged (%s)\n", vtau, s->reason.c_str());
    }
    // Outline: y = -l cos(theta), clustered at the tips where a ~ sqrt(l - |y|).
    const int n = 400;
    for (int i = 0; i <= n; ++i) {
      const double y = -s->l() * std::cos(pi * i / n);
      const double a = s->a(y), b = s->b(y);
      zones << vtau << ',' << y / a0 << ',' << (b + a) / a0 << ',' << (b - a) / a0 << '\n';
    }
    const auto strip = s->strip(0.0);
    const auto peak = strip.peak();
    const double a = s->a(0.0), b = s->b(0.0);
    for (int i = 0; i <= n; ++i) {
      const double x = b - a * std::cos(pi * i / n);
      const double p = strip.pressure(x);
      pressure << vtau << ',' << (x - b) / a << ',' << p / peak.pressure << ',' << x / a0 << ','
               << p * a0 * a0 / load << '\n';
    }
    std::printf(
        "V tau/a0 = %-6g a(0)/a0 = %.6f  b(0)/a0 = %+.6f  l/l0 = %.6f  pmax a0^2/P = %.6f at xi = "
        "%+.4f\n",
        vtau, a / a0, b / a0, s->l() / l0, peak.pressure * a0 * a0 / load, (peak.x - b) / a);
  }
  std::cout << "panek_kalker: wrote " << (args.dir / "panek_kalker_sweep.csv").string() << ", "
            << (args.dir / "panek_kalker_zones.csv").string() << ", "
            << (args.dir / "panek_kalker_pressure.csv").string()
            << (failures ? " (some solutions did not converge)" : "") << "\n";
  return failures ? 1 : 0;
}
