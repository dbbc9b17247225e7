// A crowned roller on a rubber of many relaxation times (docs/rollers.md): the exact
// 3-D contact (BemSolver over PronyRelaxation, the grid sized by bem_scene's (B14)) of a steel
// cylinder of radius 50 mm and length 80 mm whose middle 50 mm are flat and whose ends drop away
// in circular crowns, pressed with 100 N onto the 12-term rubber of
// examples/scenes/rubber_prony_bem.json at 25 degC (G_inf = 2.5 MPa, g_k = 3e8 10^(-0.45 k) Pa,
// tau_k = 1e-7 10^k s, k = 0 .. 11; the scene file rounds g_k to three digits).
//
//   crowned_roller [out_dir] [grid]
//
// writes, in out_dir (default "."):
//   crowned_roller_along.csv   per speed and station y: F0(y), a(y), b(y), the largest pressure
//                              (crown radius 50 mm, speeds 1e-4, 1e-2, 1 and 10 m/s)
//   crowned_roller_peaks.csv   per crown radius (25, 50, 100 mm) and speed (1e-4 ... 10 m/s, two
//                              per decade): d, chi, F0(0), f0_max, f0_max / F0(0), where
//   and, if gnuplot is on PATH, crowned_roller_contact.png (the contact's outline x = b -+ a
//   against y and F0(y) at the four speeds) and crowned_roller_edge_peak.png (the edge-peak
//   ratio f0_max / F0(0) against speed for each crown radius).
// grid: BemOptions::grid, elements per semi-axis (default 32). Against N = 24, d moves by 0.1%,
// chi by 0.5% and the edge-peak ratio by up to 3% (8% at 10 m/s with the 25 mm crown, where the
// peak is narrowest): on this stiffer rubber the peak is resolved to a few per cent
// (docs/rollers.md). Exit status 0 only if every solve converged.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>
#include <viscoroll/bem/bem_profile.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/material/prony.hpp>

namespace fs = std::filesystem;

namespace {

const char* gnuplot_script = R"(set datafile separator ','
set terminal pngcairo size 1400,560 font ',11'
set output 'crowned_roller_contact.png'
set multiplot layout 1,2 title 'Crowned steel roller (R = 50 mm, 50 mm flat, 50 mm crowns, 80 mm long) on a 12-term rubber, 100 N, 25 °C (BEM)'
set xlabel 'y along the roller (mm)'
set ylabel 'x in the rolling direction (mm)'
set title 'contact outline x = b(y) ± a(y) (rolling towards +x)'
set key outside right
speeds = '0.0001 0.01 1 10'
plot for [i=1:4] 'crowned_roller_along.csv' every ::1 using (($1 == word(speeds, i)+0) ? 1e3*$2 : 1/0):(1e3*($5+$4)) with lines lw 2 lc i title sprintf('%s m/s', word(speeds, i)), \
     for [i=1:4] 'crowned_roller_along.csv' every ::1 using (($1 == word(speeds, i)+0) ? 1e3*$2 : 1/0):(1e3*($5-$4)) with lines lw 2 lc i notitle
set title 'load per unit length F_0(y)'
set ylabel 'F_0 (N/mm)'
plot for [i=1:4] 'crowned_roller_along.csv' every ::1 using (($1 == word(speeds, i)+0) ? 1e3*$2 : 1/0):($3/1e3) with lines lw 2 lc i title sprintf('%s m/s', word(speeds, i))
unset multiplot
set terminal pngcairo size 800,560 font ',11'
set output 'crowned_roller_edge_peak.png'
set title 'Edge peak of the load along the crowned roller (BEM, 100 N, 25 °C)'
set logscale x
set format x '10^{%L}'
set xlabel 'speed (m/s)'
set ylabel 'f0_{max} / F_0(0)'
set key left top
plot for [r in '0.025 0.05 0.1'] 'crowned_roller_peaks.csv' every ::1 using (($1 == r+0) ? $2 : 1/0):7 with linespoints lw 2 title sprintf('crown radius %g mm', 1e3*r)
)";

/// The 12-term rubber of rubber_prony_bem.json at its reference temperature.
viscoroll::PronyRelaxation<double> rubber() {
  std::vector<viscoroll::RelaxationTerm<double>> terms;
  for (int k = 0; k < 12; ++k)
    terms.push_back({3e8 * std::pow(10.0, -0.45 * k), 1e-7 * std::pow(10.0, k)});
  return {2.5e6, 0.5, std::move(terms)};
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const fs::path dir = argc > 1 ? fs::path(argv[1]) : fs::path(".");
    viscoroll::BemOptions options;
    options.grid = argc > 2 ? std::atoi(argv[2]) : 32;
    fs::create_directories(dir);
    const auto material = rubber();
    const viscoroll::BemSolver<double, viscoroll::PronyRelaxation<double>> solver(material,
                                                                                  options);
    const double radius = 0.05, flat = 0.05, length = 0.08, load = 100;
    bool all_converged = true;
    int solves = 0, warned = 0;  // the warnings are alike (above all the leading-edge layer's,
                                 // usual with a spectrum: docs/cli.md); the first is printed
    const auto solve = [&](double crown_radius, double speed) {
      const viscoroll::CrownedCylinder<double> roller(radius, flat, crown_radius, length);
      auto s = solver.solve(viscoroll::bem_scene(roller, material, load, speed));
      ++solves;
      if (!s.warnings.empty() && warned++ == 0)
        std::cerr << "crowned_roller: warning: crown radius " << crown_radius << " m, speed "
                  << speed << " m/s: " << s.warnings.front() << "\n";
      if (!s.converged) {
        all_converged = false;
        std::cerr << "crowned_roller: crown radius " << crown_radius << " m, speed " << speed
                  << " m/s did not converge: " << s.reason << "\n";
      }
      return s;
    };

    std::ofstream along_csv(dir / "crowned_roller_along.csv");
    along_csv << "speed,y,f0,a,b,p_max\n";
    along_csv.precision(10);
    for (const double speed : {1e-4, 1e-2, 1.0, 10.0}) {
      const auto along = solve(0.05, speed).along_roller();
      for (std::size_t k = 0; k < along.y.size(); ++k)
        along_csv << speed << ',' << along.y[k] << ',' << along.f0[k] << ',' << along.a[k] << ','
                  << along.b[k] << ',' << along.p_max[k] << '\n';
    }

    std::ofstream peaks_csv(dir / "crowned_roller_peaks.csv");
    peaks_csv << "crown_radius,speed,d,chi,f0_centre,f0_max,edge_peak_ratio,f0_max_y\n";
    peaks_csv.precision(10);
    std::printf("%-12s %-10s %-12s %-12s %-10s\n", "R_c (m)", "V (m/s)", "chi", "d (m)",
                "f0max/F0(0)");
    for (const double crown_radius : {0.025, 0.05, 0.1}) {
      for (int e = -8; e <= 2; ++e) {
        const double speed = std::pow(10.0, 0.5 * e);
        const auto s = solve(crown_radius, speed);
        const auto along = s.along_roller();
        const double centre = along.f0_nearest(0.0);
        peaks_csv << crown_radius << ',' << speed << ',' << s.d << ',' << s.chi << ',' << centre
                  << ',' << along.f0_max << ',' << along.f0_max / centre << ',' << along.f0_max_y
                  << '\n';
        std::printf("%-12g %-10.3g %-12.5g %-12.5g %-10.4f\n", crown_radius, speed, s.chi, s.d,
                    along.f0_max / centre);
      }
    }
    if (warned > 1)
      std::cerr << "crowned_roller: " << warned << " of " << solves
                << " solves carry warnings (the first above)\n";
    along_csv.close();
    peaks_csv.close();
    if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
      std::ofstream(dir / "crowned_roller.gp") << gnuplot_script;
      const std::string command = "cd '" + dir.string() + "' && gnuplot crowned_roller.gp";
      if (std::system(command.c_str()) != 0) {
        std::cerr << "crowned_roller: gnuplot failed\n";
        return 1;
      }
    }
    return all_converged ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "crowned_roller: " << e.what() << "\n";
    return 2;
  }
}
