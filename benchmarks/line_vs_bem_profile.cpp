// line_vs_bem_profile: the rolling line solver for a roller profile (docs/theory.md section 16)
// against the BEM on the proportions of the static validation (docs/validation.md, "Crowned
// rollers": C1 = 1, crown radius 20, flat part 0, 10, 20; a logarithmic crown of length 16), on a
// standard linear solid (f = 2, tau = 1) under the long-term compliance load (1 + f) c P = 0.3,
// at V tau/a0 = 0 (the long-term static limit), 0.1, 1, 10 and the glassy limit (10^4), a0 the
// long-term static a(0); then the flat part 10 on the two- and the twenty-term spectra of the
// spectrum validation (sum of f = 9, under (1 + F) c P = 0.3) at V = 0.01 ... 100; then the flat
// part 10 and the logarithmic crown tilted by theta = 0.003 on the standard linear solid, and the
// flat part 10 so tilted on the two- and the twenty-term spectra; last, whether the BEM limits the
// F0 comparison: its rows at the grid and at twice the grid against each other and the line's
// (flat parts 10 and 20, V tau/a0 = 0 and 10, the rows inside the contact). Prints
// the tables of docs/validation.md ("Rolling rollers of any profile"): d, chi, a(0), b(0), the
// contact's end y+, F0(0) and the edge peak f0_max/F0(0) of both, the largest difference of F0(y)
// over the BEM's rows in units of its peak, and the line solve's wall time (for the tilted
// rollers both ends, the load's line of action y_bar = int y F0 / int F0 and the edge peak's
// position in place of a(0), b(0), F0(0)); with an output
// directory, the F0(y) of both at the BEM's rows (standard linear solid),
// out_dir/<roller>_v<V tau/a0>.csv (columns y, f0_bem, f0_line), which
// benchmarks/line_vs_bem_profile.gp draws as docs/figures/line_vs_bem_profile.png.
//   line_vs_bem_profile [grid [terms [out_dir]]]   (defaults 24, 8)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>
#include <viscoroll/bem/bem_profile.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/material/prony.hpp>

namespace {

/// The line's F0/((1 + F) c) at y, as along_roller (the standard linear solid's solution) or from
/// f0(y) and the compliance of the terms solved for (a spectrum's).
double load_per_length(const viscoroll::LineSolverD::Solution& s, double, double y) {
  return std::abs(y - s.shape.centre) < s.shape.l ? s.functions(y).f0 / (s.compliance * (1 + s.f))
                                                  : 0.0;
}
template <class Solution>
double load_per_length(const Solution& s, double long_term_compliance, double y) {
  return std::abs(y - s.shape.centre) < s.shape.l ? s.f0(y) / long_term_compliance : 0.0;
}

/// y_bar = sum y F0 / sum F0 over rows y (the load's line of action).
double line_of_action(const std::vector<double>& y, const std::vector<double>& f0) {
  double m0 = 0, m1 = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    m0 += f0[i];
    m1 += f0[i] * y[i];
  }
  return m1 / m0;
}

/// Speeds in units of a0/tau (a0 the long-term static a(0)) for the standard linear solid, of the
/// speed itself for a spectrum (tau_k from 1e-3 to 1e3).
template <class Material, class Profile>
void compare(const char* name, const Material& m, double creep_ratio, const Profile& roller,
             const std::vector<double>& speeds, bool in_a0, int grid, int terms,
             const std::string& out) {
  const double c = m.instantaneous_compliance(), load = 0.3 / ((1 + creep_ratio) * c);
  const viscoroll::LineSolver<double, Material> line(m, viscoroll::LineOptions{.terms = terms});
  const auto still = line.solve(viscoroll::LineProfileScene<Profile>{roller, load, 0.0});
  const double a0 = in_a0 ? still.shape.a(still.shape.centre) : 1.0;
  const bool tilted = !roller.symmetric();
  for (const double v : speeds) {
    const auto start = std::chrono::steady_clock::now();
    const auto s = line.solve(viscoroll::LineProfileScene<Profile>{roller, load, v * a0});
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    viscoroll::BemOptions options;
    options.grid = grid;
    const auto e =
        viscoroll::BemSolver(m, options).solve(viscoroll::bem_scene(roller, m, load, v * a0));
    const auto along = e.along_roller();
    // The line's load per length at the BEM's rows. A spectrum's F0 carries the compliance of
    // the terms solved for: at these speeds every term is active or none (static), so (1 + F) c.
    const auto line_f0 = [&](double y) { return load_per_length(s, (1 + creep_ratio) * c, y); };
    double worst = 0, centre_row = 0, bem_a0 = 0, bem_b0 = 0;
    for (std::size_t i = 0; i < along.y.size(); ++i) {
      worst = std::max(worst, std::abs(line_f0(along.y[i]) - along.f0[i]));
      if (std::abs(along.y[i]) < 1e-12) {
        centre_row = along.f0[i];
        bem_a0 = along.a[i];
        bem_b0 = along.b[i];
      }
    }
    double line_peak = 0, line_peak_y = 0;
    for (int k = 1; k < 800; ++k) {
      const double y = s.shape.centre + s.shape.l * (k / 400.0 - 1);
      if (line_f0(y) > line_peak) line_peak = line_f0(y), line_peak_y = y;
    }
    const double line_centre = line_f0(0.0);
    if (tilted) {
      // The line's F0 on 801 stations for its line of action (the BEM's on its rows).
      std::vector<double> ys, fs;
      for (int k = 1; k <= 801; ++k) {
        ys.push_back(s.shape.centre + s.shape.l * (k / 401.0 - 1));
        fs.push_back(line_f0(ys.back()));
      }
      std::printf(
          "| %s | %g | %.5f / %.5f | %.5f / %.5f | %.3f / %.3f | %.3f / %.3f | "
          "%.4f / %.4f | %.3f / %.3f | %.2f / %.2f | %.1f%% | %.3f |%s%s\n",
          name, v, e.d, s.d, e.chi, s.chi, along.y_minus, s.shape.centre - s.shape.l, along.y_plus,
          s.shape.centre + s.shape.l, line_of_action(along.y, along.f0), line_of_action(ys, fs),
          along.f0_max / centre_row, line_peak / line_centre, along.f0_max_y, line_peak_y,
          100 * worst / along.f0_max, seconds, s.converged && e.converged ? "" : " NOT CONVERGED",
          s.root ? "" : " (minimum)");
    } else {
      std::printf(
          "| %s | %g | %.5f / %.5f | %.5f / %.5f | %.4f / %.4f | %.4f / %.4f | %.3f / %.3f | "
          "%.5f / %.5f | %.3f / %.3f | %.1f%% | %.3f |%s%s\n",
          name, v, e.d, s.d, e.chi, s.chi, bem_a0, s.shape.a(0.0), bem_b0, s.shape.b(0.0),
          along.y_plus, s.shape.l, centre_row, line_centre, along.f0_max / centre_row,
          line_peak / line_centre, 100 * worst / along.f0_max, seconds,
          s.converged && e.converged ? "" : " NOT CONVERGED", s.root ? "" : " (minimum)");
    }
    if (!out.empty()) {
      char file[64];
      std::snprintf(file, sizeof file, "/%s_v%g.csv", name, v);
      std::ofstream csv(out + file);
      csv << "y,f0_bem,f0_line\n";
      for (std::size_t i = 0; i < along.y.size(); ++i)
        csv << along.y[i] << ',' << along.f0[i] << ',' << line_f0(along.y[i]) << '\n';
    }
  }
}

/// The largest |F0| differences over the rows inside the contact (not the first and last) of the
/// BEM at `grid`, in units of its peak: against the BEM at 2 grid (its rows interpolated linearly
/// to the same y) and the line's against the latter.
void grid_check(const char* name, double flat, double v, int grid, int terms) {
  const viscoroll::StandardLinearSolid<double> m(1.0, 0.5, 2.0, 1.0);
  const double load = 0.3 / (3 * m.instantaneous_compliance());
  const viscoroll::CrownedCylinder<double> roller(1.0, flat, 20.0);
  using Scene = viscoroll::LineProfileScene<viscoroll::CrownedCylinder<double>>;
  const viscoroll::LineSolverD line(m, viscoroll::LineOptions{.terms = terms});
  const double a0 = line.solve(Scene{roller, load, 0.0}).shape.a(0.0);
  const auto s = line.solve(Scene{roller, load, v * a0});
  const auto bem = [&](int g) {
    viscoroll::BemOptions options;
    options.grid = g;
    return viscoroll::BemSolver(m, options)
        .solve(viscoroll::bem_scene(roller, m, load, v * a0))
        .along_roller();
  };
  const auto coarse = bem(grid), fine = bem(2 * grid);
  const auto at = [&](double y) {
    for (std::size_t i = 0; i + 1 < fine.y.size(); ++i)
      if (fine.y[i] <= y && y <= fine.y[i + 1]) {
        const double w = (y - fine.y[i]) / (fine.y[i + 1] - fine.y[i]);
        return fine.f0[i] * (1 - w) + fine.f0[i + 1] * w;
      }
    return 0.0;
  };
  double bem_change = 0, line_error = 0, where = 0;
  for (std::size_t i = 1; i + 1 < coarse.y.size(); ++i) {
    const double y = coarse.y[i], reference = at(y);
    bem_change = std::max(bem_change, std::abs(coarse.f0[i] - reference));
    const double e = std::abs(load_per_length(s, 0.0, y) - reference);
    if (e > line_error) line_error = e, where = y;
  }
  std::printf("| %s | %g | %.2f%% | %.2f%% | %.2f |\n", name, v, 100 * bem_change / coarse.f0_max,
              100 * line_error / coarse.f0_max, where);
}

}  // namespace

int main(int argc, char** argv) {
  const int grid = argc > 1 ? std::atoi(argv[1]) : 24;
  const int terms = argc > 2 ? std::atoi(argv[2]) : 8;
  const std::string out = argc > 3 ? argv[3] : "";
  std::printf(
      "| roller | V tau/a0 | d: BEM / line | chi: BEM / line | a(0) | b(0) | y+ | F0(0) | "
      "f0_max/F0(0) | max dF0 | line s |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  const viscoroll::StandardLinearSolid<double> sls(1.0, 0.5, 2.0, 1.0);
  const std::vector<double> in_a0{0.0, 0.1, 1.0, 10.0, 1e4};
  const viscoroll::CrownedCylinder<double> flat10(1.0, 10.0, 20.0);
  compare("barrel", sls, 2.0, viscoroll::CrownedCylinder<double>(1.0, 0.0, 20.0), in_a0, true, grid,
          terms, out);
  compare("flat10", sls, 2.0, flat10, in_a0, true, grid, terms, out);
  compare("flat20", sls, 2.0, viscoroll::CrownedCylinder<double>(1.0, 20.0, 20.0), in_a0, true,
          grid, terms, out);
  compare("log16", sls, 2.0, viscoroll::LogarithmicCrown<double>(1.0, 16.0, 0.2), in_a0, true, grid,
          terms, out);
  std::vector<viscoroll::PronyTerm<double>> twenty;
  for (int k = 0; k < 20; ++k) twenty.push_back({0.45, std::pow(10.0, -3 + 6.0 * k / 19)});
  const std::vector<double> speeds{0.01, 0.1, 1.0, 10.0, 100.0};
  std::printf(
      "\nSpectra (V = V tau_1/a0 scale: speeds in units of 1/tau's unit), flat part 10:\n\n");
  compare("two terms", viscoroll::PronyCreep<double>(1.0, 0.5, {{3.0, 0.05}, {6.0, 5.0}}), 9.0,
          flat10, speeds, false, grid, terms, "");
  compare("twenty terms", viscoroll::PronyCreep<double>(1.0, 0.5, twenty), 9.0, flat10, speeds,
          false, grid, terms, "");
  std::printf(
      "\nTilted by theta = 0.003 (standard linear solid):\n\n| roller | V tau/a0 | "
      "d: BEM / line | chi: BEM / line | y- | y+ | y_bar | f0_max/F0(0) | f0_max at y | "
      "max dF0 | line s |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  const double theta = 0.003;
  compare("flat10_tilted", sls, 2.0, viscoroll::Tilted(flat10, theta), in_a0, true, grid, terms,
          out);
  compare("log16_tilted", sls, 2.0,
          viscoroll::Tilted(viscoroll::LogarithmicCrown<double>(1.0, 16.0, 0.2), theta), in_a0,
          true, grid, terms, "");
  compare("two terms tilted", viscoroll::PronyCreep<double>(1.0, 0.5, {{3.0, 0.05}, {6.0, 5.0}}),
          9.0, viscoroll::Tilted(flat10, theta), speeds, false, grid, terms, "");
  compare("twenty terms tilted", viscoroll::PronyCreep<double>(1.0, 0.5, twenty), 9.0,
          viscoroll::Tilted(flat10, theta), speeds, false, grid, terms, "");
  std::printf(
      "\nThe BEM's rows at grid %d against grid %d (interior rows, units of the peak):\n\n"
      "| roller | V tau/a0 | BEM change | line against the finer BEM | at y |\n"
      "|---|---|---|---|---|\n",
      grid, 2 * grid);
  for (const double v : {0.0, 10.0}) {
    grid_check("flat10", 10.0, v, grid, terms);
    grid_check("flat20", 20.0, v, grid, terms);
  }
}
