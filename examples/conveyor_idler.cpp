// A conveyor belt's indentation rolling resistance at one idler (docs/rollers.md, "Example: a
// conveyor idler on a belt cover"): a rigid steel idler roll pressing the belt's bottom cover, a rubber layer bonded to the
// belt's stiff carcass, solved three ways:
//   layer       the exact cover: a bonded layer of the rubber (docs/plane-substrate.md);
//   spring bed  the conveyor industry's Winkler model, u = h p / E (E = 2 (1 + nu) mu);
//   half space  the cover taken as infinitely thick (Hunter's problem).
// Each is the plane problem of the idler's flat length (PlaneSubstrateSolver, relative tolerance
// 1e-3 on chi), so the force per idler is chi P, the power chi P V. A handful of scenes are solved
// again by the exact 3-D boundary-element method on the layer, with the idler's 5 mm edge radii,
// to show what the plane problem leaves out at the roller's ends.
//
// The rubber is examples/scenes/conveyor_idler.json's: an eight-term Prony series (G_inf =
// 1.5 MPa, one relaxation time per decade 1e-7 ... 1 s, glassy modulus about 0.29 GPa) with the
// 'universal' WLF shift (c1 = 8.86, c2 = 101.6 K) at t_ref = 0 degC, nu = 0.5: representative of
// a belt cover, not a measurement. The idler roll is 380 mm long, flat over 370 mm (the centre
// roll of a troughed set under a 1 m belt).
//
//   conveyor_idler [out_dir] [--no-bem] [--quick]
//
// writes, in out_dir (default "."):
//   conveyor_idler_study.csv  per temperature (-30 ... 40 degC), cover thickness (3, 6, 9,
//                             12 mm), idler radius (50, 63.5, 90 mm), load per idler (0.5, 1.5,
//                             5 kN) and belt speed (1, 2, 4, 6, 8 m/s): the layer's contact
//                             (a, b), chi, force (N) and power (W) per idler on each of the three
//                             bodies, and the ratios bed / layer and half space / layer
//   conveyor_idler_thick.csv  the middle idler under 1.5 kN at -30, 0 and 40 degC, 1, 4 and 8 m/s,
//                             on covers 3 mm ... 3 m thick: where the half space comes within 10%
//   conveyor_idler_bem.csv    the 3-D check: chi of the BEM on the layer and on the half space
//                             against the plane problem's
//   conveyor_idler_summary.txt where the spring bed and the half space are within 10% of the layer
//   conveyor_idler_lines.csv  the force figure's curves
//   and, if gnuplot is on PATH, conveyor_idler_force.png (the force per idler against speed,
//   temperature and cover thickness on the three bodies) and conveyor_idler_ratio.png (the two
//   models' ratios to the layer against the contact's half width over the cover's thickness).
// The same text as conveyor_idler_summary.txt is printed. Exit status 0 only if every solve
// converged. Runs on every core (viscoroll::sweep_scenes): 1440 scenes and the thick covers in
// about 5 minutes on two cores, the 3-D check in 1.5 more.
// --quick solves two temperatures, thicknesses and speeds of the middle idler under 1.5 kN, the
// thick covers at 0 degC and 4 m/s, and one 3-D check, and draws no figure (the slow test
// example_conveyor_idler).
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>
#include <viscoroll/bem/bem_profile.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/material/temperature_shift.hpp>
#include <viscoroll/plane/plane_substrate_solver.hpp>
#include <viscoroll/sweep.hpp>

namespace fs = std::filesystem;
using viscoroll::HalfSpace;
using viscoroll::Layer;
using viscoroll::SpringBed;

namespace {

const char* gnuplot_script = R"(set datafile separator ','
set terminal pngcairo size 1500,520 font ',11'
set output 'conveyor_idler_force.png'
set multiplot layout 1,3 title 'Indentation rolling resistance per idler (R = 63.5 mm, 1.5 kN over 370 mm): bonded cover (solid), spring bed h/E (dashed), half space (dotted)'
set ylabel 'force per idler (N)'
set yrange [0:*]
set key top left
set xlabel 'belt speed (m/s)'
set title 'against speed, 6 mm cover'
# conveyor_idler_lines.csv: blocks 0-2 against speed (-20, 0, 20 degC), 3-5 against temperature
# (1, 4, 8 m/s), 6-8 against thickness (-20, 0, 20 degC); columns x, F_layer, F_bed, F_half.
lines = 'conveyor_idler_lines.csv'
temps = '-20 0 20'
plot for [i=1:3] lines index i-1 using 1:2 with linespoints lw 2 lc i title sprintf('%s °C', word(temps,i)), \
     for [i=1:3] lines index i-1 using 1:3 with lines dt 2 lw 2 lc i notitle, \
     for [i=1:3] lines index i-1 using 1:4 with lines dt 3 lw 2 lc i notitle
set xlabel 'temperature (°C)'
set title 'against temperature, 6 mm cover'
speeds = '1 4 8'
plot for [i=1:3] lines index i+2 using 1:2 with linespoints lw 2 lc i title sprintf('%s m/s', word(speeds,i)), \
     for [i=1:3] lines index i+2 using 1:3 with lines dt 2 lw 2 lc i notitle, \
     for [i=1:3] lines index i+2 using 1:4 with lines dt 3 lw 2 lc i notitle
set xlabel 'cover thickness (mm)'
set title 'against cover thickness, 4 m/s'
plot for [i=1:3] lines index i+5 using 1:2 with linespoints lw 2 lc i title sprintf('%s °C', word(temps,i)), \
     for [i=1:3] lines index i+5 using 1:3 with lines dt 2 lw 2 lc i notitle, \
     for [i=1:3] lines index i+5 using 1:4 with lines dt 3 lw 2 lc i notitle
unset multiplot
set terminal pngcairo size 1200,520 font ',11'
set output 'conveyor_idler_ratio.png'
set multiplot layout 1,2 title 'The models against the bonded cover, all 1440 scenes (-30 ... 40 °C, 1 ... 8 m/s, 3 ... 12 mm, R 50 ... 90 mm, 0.5 ... 5 kN)'
set logscale xy
set xrange [0.01:3]
set yrange [0.8:5]
set ytics (0.8, 0.9, 1, 1.1, 1.5, 2, 3, 4, 5)
set xlabel 'contact half width / cover thickness (layer)'
set key top left
set title 'spring bed h/E'
set ylabel 'F_{bed} / F_{layer}'
set arrow 1 from 0.01, 1.1 to 3, 1.1 nohead dt 2
set arrow 2 from 0.01, 0.9 to 3, 0.9 nohead dt 2
plot for [h in '0.003 0.006 0.009 0.012'] 'conveyor_idler_study.csv' every ::1 using (abs($2 - h) < 1e-9 ? $6/$2 : 1/0):14 with points pt 7 ps 0.5 title sprintf('%g mm', 1e3*h)
set title 'half space'
set ylabel 'F_{half space} / F_{layer}'
plot for [h in '0.003 0.006 0.009 0.012'] 'conveyor_idler_study.csv' every ::1 using (abs($2 - h) < 1e-9 ? $6/$2 : 1/0):15 with points pt 7 ps 0.5 title sprintf('%g mm', 1e3*h)
unset multiplot
)";

/// The cover rubber of conveyor_idler.json at its reference temperature (0 degC).
viscoroll::PronyRelaxation<double> cover_rubber() {
  return {1.5e6,
          0.5,
          {{2e8, 1e-7},
           {6e7, 1e-6},
           {1.8e7, 1e-5},
           {6e6, 1e-4},
           {2e6, 1e-3},
           {8e5, 1e-2},
           {4e5, 1e-1},
           {2e5, 1.0}}};
}

const viscoroll::WlfShift<double> wlf(8.86, 101.6, 0.0);
constexpr double flat_length = 0.37, roll_length = 0.38, edge_radius = 0.005;

/// One scene of the study.
struct Scene {
  double temperature, thickness, radius, load, speed;
};

/// One scene solved on the three bodies.
struct Row {
  viscoroll::PlaneSubstrateSolution<double> layer, bed, half;
  bool converged = false;  ///< all three (sweep_scenes reads it)
};

/// The study's "solver" for viscoroll::sweep_scenes: each scene on the three bodies.
struct ThreeBodies {
  using Solution = Row;
  viscoroll::PlaneSubstrateOptions options;

  Row solve(const Scene& s) const {
    const auto rubber = viscoroll::at_temperature(cover_rubber(), wlf, s.temperature);
    const viscoroll::PlaneScene<double> plane{
        .c1 = 1 / s.radius, .load = s.load / flat_length, .speed = s.speed};
    Row r{viscoroll::PlaneSubstrateSolver(rubber, Layer<double>(s.thickness), options).solve(plane),
          viscoroll::PlaneSubstrateSolver(rubber, SpringBed<double>(s.thickness), options)
              .solve(plane),
          viscoroll::PlaneSubstrateSolver(rubber, HalfSpace<double>{}, options).solve(plane)};
    r.converged = r.layer.converged && r.bed.converged && r.half.converged;
    return r;
  }
};

bool within(double ratio, double band) { return std::abs(ratio - 1) <= band; }

/// "n of m (range lo ... hi)" for the ratios of `rows` whose index passes `keep`.
template <class Keep>
std::string share_within(const std::vector<double>& ratio, Keep keep) {
  int n = 0, m = 0;
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < ratio.size(); ++i) {
    if (!keep(i)) continue;
    ++m;
    n += within(ratio[i], 0.1) ? 1 : 0;
    lo = std::min(lo, ratio[i]);
    hi = std::max(hi, ratio[i]);
  }
  char text[128];
  if (m == 0) return "   0 of    0";
  std::snprintf(text, sizeof text, "%4d of %4d within 10%% (ratio %.2f ... %.2f)", n, m, lo, hi);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    fs::path dir = ".";
    bool run_bem = true, quick = false;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--no-bem")
        run_bem = false;
      else if (arg == "--quick")
        quick = true;
      else
        dir = arg;
    }
    fs::create_directories(dir);

    using list = std::vector<double>;
    const list temperatures = quick ? list{-20, 20} : list{-30, -20, -10, 0, 10, 20, 30, 40};
    const list thicknesses = quick ? list{0.003, 0.012} : list{0.003, 0.006, 0.009, 0.012};
    const list radii = quick ? list{0.0635} : list{0.05, 0.0635, 0.09};
    const list loads = quick ? list{1500} : list{500, 1500, 5000};
    const list speeds = quick ? list{1, 8} : list{1, 2, 4, 6, 8};
    std::vector<Scene> scenes;
    for (double t : temperatures)
      for (double h : thicknesses)
        for (double r : radii)
          for (double p : loads)
            for (double v : speeds) scenes.push_back({t, h, r, p, v});

    ThreeBodies study;
    study.options.tolerance = 1e-3;
    viscoroll::SweepOptions sweep_options;
    sweep_options.chunk = 8;
    const auto rows = viscoroll::sweep_scenes(study, scenes, sweep_options);

    bool all_converged = true;
    std::vector<double> bed_ratio(rows.size()), half_ratio(rows.size()), a_over_h(rows.size());
    std::ofstream csv(dir / "conveyor_idler_study.csv");
    csv << "temperature_C,thickness_m,radius_m,load_N,speed_m_s,a_layer_m,b_layer_m,chi_layer,"
           "chi_bed,chi_half,F_layer_N,F_bed_N,F_half_N,bed_over_layer,half_over_layer,"
           "power_layer_W,power_bed_W,power_half_W,a_bed_m,a_half_m,error_chi_layer\n";
    csv.precision(8);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const auto& s = scenes[i];
      const auto& r = rows[i];
      for (const auto* sol : {&r.layer, &r.bed, &r.half})
        if (!sol->converged) {
          all_converged = false;
          std::cerr << "conveyor_idler: " << s.temperature << " degC, h " << s.thickness << " m, R "
                    << s.radius << " m, " << s.load << " N, " << s.speed
                    << " m/s did not converge: " << sol->reason << "\n";
        }
      bed_ratio[i] = r.bed.chi / r.layer.chi;
      half_ratio[i] = r.half.chi / r.layer.chi;
      a_over_h[i] = r.layer.a / s.thickness;
      const double f_layer = r.layer.chi * s.load, f_bed = r.bed.chi * s.load,
                   f_half = r.half.chi * s.load;
      csv << s.temperature << ',' << s.thickness << ',' << s.radius << ',' << s.load << ','
          << s.speed << ',' << r.layer.a << ',' << r.layer.b << ',' << r.layer.chi << ','
          << r.bed.chi << ',' << r.half.chi << ',' << f_layer << ',' << f_bed << ',' << f_half
          << ',' << bed_ratio[i] << ',' << half_ratio[i] << ',' << f_layer * s.speed << ','
          << f_bed * s.speed << ',' << f_half * s.speed << ',' << r.bed.a << ',' << r.half.a << ','
          << r.layer.error_chi << '\n';
    }
    csv.close();

    std::ostringstream summary;
    summary << "Indentation rolling resistance of a conveyor idler: " << rows.size()
            << " scenes, each on a bonded cover (the exact layer), a spring bed h/E and a half "
               "space (plane problem, chi to 1e-3).\n\n";
    {
      double f_lo = 1e300, f_hi = 0, w_lo = 1e300, w_hi = 0;
      for (std::size_t i = 0; i < rows.size(); ++i) {
        const double f = rows[i].layer.chi * scenes[i].load;
        f_lo = std::min(f_lo, f);
        f_hi = std::max(f_hi, f);
        w_lo = std::min(w_lo, f * scenes[i].speed);
        w_hi = std::max(w_hi, f * scenes[i].speed);
      }
      char line[200];
      std::snprintf(line, sizeof line,
                    "Bonded cover: %.3g ... %.3g N per idler, %.3g ... %.3g W per idler.\n\n", f_lo,
                    f_hi, w_lo, w_hi);
      summary << line;
    }
    const auto all = [](std::size_t) { return true; };
    summary << "spring bed / layer, all scenes:   " << share_within(bed_ratio, all) << "\n";
    summary << "half space / layer, all scenes:   " << share_within(half_ratio, all) << "\n\n";
    const auto by = [&](const char* name, const std::vector<double>& values, auto field) {
      for (double v : values) {
        const auto keep = [&](std::size_t i) { return field(scenes[i]) == v; };
        char label[64];
        std::snprintf(label, sizeof label, "%-12s %-7g", name, v);
        summary << label << " bed: " << share_within(bed_ratio, keep)
                << "   half: " << share_within(half_ratio, keep) << "\n";
      }
      summary << "\n";
    };
    by("T (degC)", temperatures, [](const Scene& s) { return s.temperature; });
    by("h (m)", thicknesses, [](const Scene& s) { return s.thickness; });
    by("R (m)", radii, [](const Scene& s) { return s.radius; });
    by("P (N)", loads, [](const Scene& s) { return s.load; });
    by("V (m/s)", speeds, [](const Scene& s) { return s.speed; });
    const std::array<double, 6> bands{0, 0.25, 0.5, 1, 2, 1e300};
    for (std::size_t k = 0; k + 1 < bands.size(); ++k) {
      const auto keep = [&](std::size_t i) {
        return a_over_h[i] >= bands[k] && a_over_h[i] < bands[k + 1];
      };
      char label[64];
      if (k + 2 < bands.size())
        std::snprintf(label, sizeof label, "a/h in [%g, %g)", bands[k], bands[k + 1]);
      else
        std::snprintf(label, sizeof label, "a/h >= %g", bands[k]);
      char padded[64];
      std::snprintf(padded, sizeof padded, "%-20s", label);
      summary << padded << " bed: " << share_within(bed_ratio, keep)
              << "   half: " << share_within(half_ratio, keep) << "\n";
    }

    // Beyond the covers of the study: how thick a cover must be for the half space to come
    // within 10% (the middle idler, 1.5 kN, at three temperatures and speeds).
    std::vector<Scene> thick;
    for (double t : quick ? list{0} : list{-30, 0, 40})
      for (double v : quick ? list{4} : list{1, 4, 8})
        for (int e = 0; e <= 12; ++e)
          thick.push_back({t, 0.003 * std::pow(10.0, e / 4.0), 0.0635, 1500, v});
    const auto thick_rows = viscoroll::sweep_scenes(study, thick, sweep_options);
    std::ofstream thick_csv(dir / "conveyor_idler_thick.csv");
    thick_csv << "temperature_C,thickness_m,radius_m,load_N,speed_m_s,a_layer_m,chi_layer,chi_bed,"
                 "chi_half,bed_over_layer,half_over_layer\n";
    thick_csv.precision(8);
    summary << "\nThe thinnest cover (of 3 mm x 10^(k/4)) from which on the half space is within "
               "10% of the layer (R 63.5 mm, 1.5 kN):\n";
    for (std::size_t i = 0; i < thick.size(); ++i) {
      const auto& s = thick[i];
      const auto& r = thick_rows[i];
      all_converged = all_converged && r.converged;
      thick_csv << s.temperature << ',' << s.thickness << ',' << s.radius << ',' << s.load << ','
                << s.speed << ',' << r.layer.a << ',' << r.layer.chi << ',' << r.bed.chi << ','
                << r.half.chi << ',' << r.bed.chi / r.layer.chi << ',' << r.half.chi / r.layer.chi
                << '\n';
      const bool last_of_row = (i + 1) % 13 == 0;
      if (!last_of_row) continue;
      double from = -1;  // the thinnest cover from which on every thicker one is within 10%
      for (std::size_t k = i + 1; k-- > i + 1 - 13;) {
        if (!within(thick_rows[k].half.chi / thick_rows[k].layer.chi, 0.1)) break;
        from = thick[k].thickness;
      }
      char line[160];
      std::snprintf(
          line, sizeof line, "  %4g degC, %g m/s: %s\n", s.temperature, s.speed,
          from > 0 ? (std::to_string(1e3 * from).substr(0, 5) + " mm").c_str() : "none up to 3 m");
      summary << line;
    }

    if (run_bem) {
      // The 3-D check: the whole idler (flat 370 mm, 5 mm edge radii) on the bonded cover and on
      // the half space, by the BEM, against the plane problem's layer and half space.
      std::ofstream bem_csv(dir / "conveyor_idler_bem.csv");
      bem_csv << "temperature_C,thickness_m,radius_m,load_N,speed_m_s,chi_bem_layer,"
                 "error_chi_bem_layer,chi_plane_layer,chi_bem_half,error_chi_bem_half,"
                 "chi_plane_half,seconds\n";
      bem_csv.precision(8);
      summary << "\nThe 3-D check (BEM, the idler's edge radii included, tolerance 1e-2) against "
                 "the plane problem: chi on the layer, chi on the half space, their ratio:\n";
      viscoroll::BemOptions bem_options;
      bem_options.tolerance = 1e-2;
      const std::vector<Scene> checks{{-20, 0.003, 0.0635, 1500, 1},
                                      {0, 0.006, 0.0635, 1500, 4},
                                      {20, 0.012, 0.0635, 1500, 8},
                                      {40, 0.003, 0.05, 1500, 2},
                                      {-30, 0.012, 0.09, 500, 6}};
      using Bem = viscoroll::BemSolver<double, viscoroll::PronyRelaxation<double>>;
      for (const auto& s : quick ? std::vector<Scene>{checks[1]} : checks) {
        const auto rubber = viscoroll::at_temperature(cover_rubber(), wlf, s.temperature);
        const auto start = std::chrono::steady_clock::now();
        const viscoroll::CrownedCylinder<double> idler(s.radius, flat_length, edge_radius,
                                                       roll_length);
        const auto scene = viscoroll::bem_scene(idler, rubber, s.load, s.speed);
        const auto layer = Bem(rubber, bem_options, Layer<double>(s.thickness)).solve(scene);
        const auto half = Bem(rubber, bem_options).solve(scene);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const auto plane = study.solve(s);
        for (const auto* b : {&layer, &half})
          if (!b->converged) {
            all_converged = false;
            std::cerr << "conveyor_idler: BEM at " << s.temperature
                      << " degC did not converge: " << b->reason << "\n";
          }
        bem_csv << s.temperature << ',' << s.thickness << ',' << s.radius << ',' << s.load << ','
                << s.speed << ',' << layer.chi << ',' << layer.error.chi << ',' << plane.layer.chi
                << ',' << half.chi << ',' << half.error.chi << ',' << plane.half.chi << ','
                << seconds << '\n';
        char line[240];
        std::snprintf(line, sizeof line,
                      "  %4g degC, h %4.1f mm, R %4.1f mm, %4g N, %g m/s: layer %.5f +- %.0e "
                      "(plane %.5f), half space %.5f +- %.0e (plane %.5f), half/layer %.3f "
                      "(plane %.3f), %.0f s\n",
                      s.temperature, 1e3 * s.thickness, 1e3 * s.radius, s.load, s.speed, layer.chi,
                      layer.error.chi, plane.layer.chi, half.chi, half.error.chi, plane.half.chi,
                      half.chi / layer.chi, plane.half.chi / plane.layer.chi, seconds);
        summary << line;
      }
    }

    std::cout << summary.str();
    std::ofstream(dir / "conveyor_idler_summary.txt") << summary.str();
    if (!quick) {
      // The force figure's curves, one block each (gnuplot's index), in the order of their x.
      const auto find = [&](double t, double h, double v) {
        for (std::size_t i = 0; i < scenes.size(); ++i)
          if (scenes[i].temperature == t && scenes[i].thickness == h &&
              scenes[i].radius == 0.0635 && scenes[i].load == 1500 && scenes[i].speed == v)
            return i;
        throw std::logic_error("conveyor_idler: no such scene in the study");
      };
      std::ofstream lines(dir / "conveyor_idler_lines.csv");
      lines.precision(8);
      const auto point = [&](double x, std::size_t i) {
        lines << x << ',' << rows[i].layer.chi * scenes[i].load << ','
              << rows[i].bed.chi * scenes[i].load << ',' << rows[i].half.chi * scenes[i].load
              << '\n';
      };
      for (double t : {-20.0, 0.0, 20.0}) {
        lines << "# against speed (m/s), " << t << " degC, 6 mm: F_layer, F_bed, F_half (N)\n";
        for (double v : speeds) point(v, find(t, 0.006, v));
        lines << "\n\n";
      }
      for (double v : {1.0, 4.0, 8.0}) {
        lines << "# against temperature (degC), " << v << " m/s, 6 mm\n";
        for (double t : temperatures) point(t, find(t, 0.006, v));
        lines << "\n\n";
      }
      for (double t : {-20.0, 0.0, 20.0}) {
        lines << "# against thickness (mm), " << t << " degC, 4 m/s\n";
        for (double h : thicknesses) point(1e3 * h, find(t, h, 4.0));
        lines << "\n\n";
      }
    }
    if (!quick && std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
      std::ofstream(dir / "conveyor_idler.gp") << gnuplot_script;
      const std::string command = "cd '" + dir.string() + "' && gnuplot conveyor_idler.gp";
      if (std::system(command.c_str()) != 0) {
        std::cerr << "conveyor_idler: gnuplot failed\n";
        return 1;
      }
    }
    return all_converged ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "conveyor_idler: " << e.what() << "\n";
    return 2;
  }
}
