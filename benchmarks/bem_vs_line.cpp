// bem_vs_line: the line-contact theory (Panek & Kalker 1980, LineSolverD) against the exact 3-D
// boundary-element solver (BemSolverD) on the paper's scene: f = 9, nu = 0.5, mu_D = 1, tau = 1,
// C1 = 1, C2 = (ln 20 - 1)/25, load P = 5 C1 / (3 (1 + f) c), so that the line theory's static
// a0 = 1 and l0 = 5 (examples/panek_kalker.cpp). Lengths are in units of that a0.
// Writes
//   <dir>/bem_vs_line.csv    for V tau / a0 in 0.01 ... 100: the line solution (line_*) and the
//                            BEM at each grid N (bem<N>_*: a0 = a(0), b0 = b(0), l, d, chi,
//                            converged, seconds), and the first-order Richardson extrapolation
//                            2 X(N2) - X(N1) of the two finest grids (rich_*; docs/bem.md B13)
//   <dir>/bem_convergence.csv the BEM at V tau / a0 = 1 for N = 8 ... 64: a0, b0, l, d, chi,
//                            active-set and GMRES iterations, seconds
// and prints both tables. usage: bem_vs_line [output-directory] [--grids N1,N2,...]
// [--no-convergence] (defaults docs/figures, grids 8,16,32).
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
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/line/line_solver.hpp>

namespace {

constexpr double f = 9, nu = 0.5, mu = 1, c1 = 1;
const double c = (1 - nu) / (2 * std::acos(-1.0) * mu);
const double c2 = (std::log(20.0) - 1) / 25;
const double load = 5 * c1 / (3 * (1 + f) * c);

struct Row {
  double a0, b0, l, d, chi;
  bool converged;
  double seconds;
  int iterations, krylov;
};

Row bem(int n, double vtau) {
  viscoroll::BemOptions o;
  o.grid = n;
  const viscoroll::BemSolverD solver(viscoroll::StandardLinearSolid<double>(mu, nu, f, 1.0), o);
  const auto start = std::chrono::steady_clock::now();
  const auto s =
      solver.solve(viscoroll::BemScene<double>{.c1 = c1, .c2 = c2, .load = load, .speed = vtau});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!s.converged)
    std::fprintf(stderr, "bem N = %d, V tau = %g: not converged (%s)\n", n, vtau, s.reason.c_str());
  return {s.a0, s.b0, s.l, s.d, s.chi, s.converged, seconds, s.iterations, s.krylov_iterations};
}

std::vector<int> parse_grids(std::string_view text) {
  std::vector<int> out;
  while (!text.empty()) {
    const auto comma = text.find(',');
    const std::string item(text.substr(0, comma));
    char* end = nullptr;
    const long n = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || n < 2 || n > 512)
      throw std::invalid_argument("bem_vs_line: --grids expects integers in [2, 512], got '" +
                                  item + "'");
    out.push_back(static_cast<int>(n));
    if (comma == std::string_view::npos) break;
    text = text.substr(comma + 1);
  }
  if (out.size() < 2) throw std::invalid_argument("bem_vs_line: --grids needs at least two grids");
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path dir = "docs/figures";
  std::vector<int> grids{8, 16, 32};
  bool convergence = true;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string_view a = argv[i];
      if (a == "--grids" && i + 1 < argc)
        grids = parse_grids(argv[++i]);
      else if (a == "--no-convergence")
        convergence = false;
      else if (!a.starts_with("--"))
        dir = a;
      else
        throw std::invalid_argument(
            "usage: bem_vs_line [output-directory] [--grids N1,N2,...] [--no-convergence]");
    }
  } catch (const std::invalid_argument& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  std::filesystem::create_directories(dir);
  const std::vector<double> speeds{0.01, 0.03, 0.1, 0.3, 1, 2, 3, 4, 5, 7, 10, 30, 100};

  // Line solver with continuation over increasing speed (as examples/panek_kalker.cpp).
  using LineSolution = viscoroll::LineSolverD::Solution;
  viscoroll::LineOptions lo;
  lo.terms = 6;
  const viscoroll::LineSolverD line(viscoroll::StandardLinearSolid<double>(mu, nu, f, 1.0), lo);
  std::optional<LineSolution> last;
  int failures = 0;

  std::ofstream csv(dir / "bem_vs_line.csv");
  csv << "vtau,line_a0,line_b0,line_l,line_d,line_chi,line_converged";
  for (int n : grids)
    csv << ",bem" << n << "_a0,bem" << n << "_b0,bem" << n << "_l,bem" << n << "_d,bem" << n
        << "_chi,bem" << n << "_converged,bem" << n << "_seconds";
  csv << ",rich_a0,rich_b0,rich_l,rich_d,rich_chi\n";
  csv.precision(10);
  std::printf("%8s | %-38s | %-38s | %s\n", "Vtau/a0", "line: a(0) b(0) l d chi",
              "BEM finest: a(0) b(0) l d chi", "Richardson a(0) b(0) l d chi");
  for (const double vtau : speeds) {
    const LineSolution* seed = last && last->converged ? &*last : nullptr;
    LineSolution ls = line.solve(
        viscoroll::LineScene<double>{.c1 = c1, .c2 = c2, .load = load, .speed = vtau}, seed);
    if (!ls.converged) ++failures;
    csv << vtau << ',' << ls.a(0.0) << ',' << ls.b(0.0) << ',' << ls.l() << ',' << ls.d << ','
        << ls.chi << ',' << ls.converged;
    std::vector<Row> rows;
    for (int n : grids) {
      rows.push_back(bem(n, vtau));
      const Row& r = rows.back();
      if (!r.converged) ++failures;
      csv << ',' << r.a0 << ',' << r.b0 << ',' << r.l << ',' << r.d << ',' << r.chi << ','
          << r.converged << ',' << r.seconds;
    }
    const Row& fine = rows[rows.size() - 1];
    const Row& coarse = rows[rows.size() - 2];
    // First-order Richardson in h = 1/N: X + (X_fine - X_coarse) N_coarse / (N_fine - N_coarse).
    const double w =
        double(grids[grids.size() - 2]) / double(grids.back() - grids[grids.size() - 2]);
    const auto rich = [&](double xf, double xc) { return xf + (xf - xc) * w; };
    const Row r{rich(fine.a0, coarse.a0),
                rich(fine.b0, coarse.b0),
                rich(fine.l, coarse.l),
                rich(fine.d, coarse.d),
                rich(fine.chi, coarse.chi),
                true,
                0,
                0,
                0};
    csv << ',' << r.a0 << ',' << r.b0 << ',' << r.l << ',' << r.d << ',' << r.chi << '\n';
    std::printf(
        "%8.3g | %6.4f %6.4f %6.4f %6.4f %6.4f | %6.4f %6.4f %6.4f %6.4f %6.4f | %6.4f %6.4f %6.4f "
        "%6.4f %6.4f\n",
        vtau, ls.a(0.0), ls.b(0.0), ls.l(), ls.d, ls.chi, fine.a0, fine.b0, fine.l, fine.d,
        fine.chi, r.a0, r.b0, r.l, r.d, r.chi);
    std::fflush(stdout);
    last = std::move(ls);
  }

  if (convergence) {
    std::ofstream conv(dir / "bem_convergence.csv");
    conv.precision(10);
    conv << "N,a0,b0,l,d,chi,converged,active_set_iterations,gmres_iterations,seconds\n";
    std::printf("\nV tau / a0 = 1, grid convergence\n%4s %9s %9s %9s %10s %10s %6s %6s %8s\n", "N",
                "a(0)", "b(0)", "l", "d", "chi", "AS", "GMRES", "seconds");
    for (int n : {8, 12, 16, 24, 32, 48, 64}) {
      const Row r = bem(n, 1.0);
      if (!r.converged) ++failures;
      conv << n << ',' << r.a0 << ',' << r.b0 << ',' << r.l << ',' << r.d << ',' << r.chi << ','
           << r.converged << ',' << r.iterations << ',' << r.krylov << ',' << r.seconds << '\n';
      std::printf("%4d %9.5f %9.5f %9.5f %10.6f %10.6f %6d %6d %8.3f\n", n, r.a0, r.b0, r.l, r.d,
                  r.chi, r.iterations, r.krylov, r.seconds);
      std::fflush(stdout);
    }
  }
  return failures == 0 ? 0 : 1;
}
