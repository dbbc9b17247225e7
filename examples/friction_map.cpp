// friction_map: the rolling friction of a measured-like rubber over speed and temperature.
//
//   friction_map [dma.csv] [output-directory]
//     dma.csv           DMA data with a temperature column (default: the shipped
//                       examples/data/dma_known_spectrum_wlf.csv, 0.01-100 Hz at -30 ... 80 degC)
//     output-directory  default out/friction_map
//
// 1. Fits a Prony series to the data (fit_prony, WLF shift c1 = 8.86, c2 = 101.6 K,
//    t_ref = 20 degC: the master curve first, then non-negative least squares on two relaxation
//    times per decade), and prints the fit's report.
// 2. For a steel cylinder of radius 50 mm (C1 = 20 /m) pressed with 2 kN per metre of length
//    into the fitted rubber, solves the plane problem (PlaneSolver over the spectrum: the closed
//    form of docs/theory.md, section 12) at 23 temperatures (-30 ... 80 degC) and 41 speeds
//    (1e-8 ... 1e2 m/s), each temperature's material shifted by a_T (R13).
// 3. Writes <dir>/friction_map.csv (temperature_c, speed_m_s, chi, a_m, b_m, pmax_pa,
//    active_terms, converged) and, if gnuplot is on PATH, <dir>/friction_map.png: log10 chi
//    over log10 V and T, and chi(V) at five temperatures.
// The friction coefficient chi = C1 x_bar (Eq. 51) is the rolling resistance per unit load.
// Exit status 0, or 1 if a solve did not converge or the fit is poor.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <viscoroll/material/dma_fit.hpp>
#include <viscoroll/material/temperature_shift.hpp>
#include <viscoroll/plane/plane_solver.hpp>

namespace fs = std::filesystem;

namespace {

const char* gnuplot_script = R"(set terminal pngcairo size 1400,560 font ',11'
set output 'friction_map.png'
set datafile separator ','
set multiplot layout 1,2 title 'Rolling friction of a rubber fitted to DMA data (Prony series, WLF shift): steel cylinder R = 50 mm, 2 kN/m'
set view map
set xlabel 'log_{10} speed (m/s)'
set ylabel 'temperature (°C)'
set cblabel 'log_{10} {/Symbol c}'
set palette rgbformulae 33,13,10
set yrange [-32.5:82.5]
set xrange [-8.125:2.125]
set title 'log_{10} {/Symbol c} = log_{10}(C_1 x_{bar})'
splot 'friction_map.csv' every ::1 using (log10($2)):1:(log10($3)) with image notitle
unset view
set autoscale
set title '{/Symbol c} against speed'
set logscale x
set logscale y
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'speed (m/s)'
set ylabel '{/Symbol c}'
set key left top
plot for [T in '-30 0 20 50 80'] 'friction_map.csv' every ::1 using (($1 == T+0) ? $2 : 1/0):3 with lines lw 2 title sprintf('%s °C', T)
unset multiplot
)";

}  // namespace

int main(int argc, char** argv) {
  const fs::path data =
      argc > 1 ? fs::path(argv[1])
               : fs::path(__FILE__).parent_path() / "data" / "dma_known_spectrum_wlf.csv";
  const fs::path dir = argc > 2 ? fs::path(argv[2]) : fs::path("out/friction_map");
  try {
    const auto measured = viscoroll::read_dma_csv_file<double>(data);
    viscoroll::DmaFitOptions<double> fit_options;
    const viscoroll::WlfShift<double> wlf(8.86, 101.6, 20.0);
    fit_options.shift = wlf;
    const auto fit = viscoroll::fit_prony(measured, fit_options);
    std::printf("fit of %s: %s\n", data.string().c_str(), fit.report.summary.c_str());
    std::printf("material: G_inf = %.4g Pa, glassy modulus %.4g Pa, %zu relaxation terms\n",
                fit.material.g_inf(), fit.material.glassy_modulus(), fit.report.nonzero_terms);
    fs::create_directories(dir);
    std::ofstream csv(dir / "friction_map.csv");
    csv << "temperature_c,speed_m_s,chi,a_m,b_m,pmax_pa,active_terms,converged\n";
    csv.precision(10);
    const double c1 = 20.0, load = 2000.0;
    int failures = 0, solves = 0;
    double chi_max = 0, v_at_max = 0, t_at_max = 0;
    for (int it = 0; it <= 22; ++it) {
      const double temperature = -30.0 + 5.0 * it;
      const viscoroll::PlaneSolver solver(
          viscoroll::at_temperature(fit.material, wlf, temperature));
      for (int iv = 0; iv <= 40; ++iv) {
        const double speed = std::pow(10.0, -8.0 + 0.25 * iv);
        const auto s = solver.solve({.c1 = c1, .load = load, .speed = speed});
        ++solves;
        if (!s.converged) ++failures;
        if (s.chi > chi_max) chi_max = s.chi, v_at_max = speed, t_at_max = temperature;
        csv << temperature << ',' << speed << ',' << s.chi << ',' << s.a << ',' << s.b << ','
            << s.peak().pressure << ',' << s.active_terms << ',' << s.converged << '\n';
      }
    }
    csv.close();
    std::printf("%d solves, %d not converged; largest chi %.4g at %.3g m/s, %.0f degC\n", solves,
                failures, chi_max, v_at_max, t_at_max);
    std::printf("wrote %s\n", (dir / "friction_map.csv").string().c_str());
    if (std::system("command -v gnuplot > /dev/null 2>&1") == 0) {
      std::ofstream(dir / "friction_map.gp") << gnuplot_script;
      const std::string command = "cd '" + dir.string() + "' && gnuplot friction_map.gp";
      if (std::system(command.c_str()) == 0)
        std::printf("wrote %s\n", (dir / "friction_map.png").string().c_str());
      else
        std::fprintf(stderr, "friction_map: gnuplot failed\n");
    } else {
      std::printf("gnuplot not on PATH: no plot (the CSV is written)\n");
    }
    return failures == 0 && !fit.report.poor ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "friction_map: %s\n", e.what());
    return 2;
  }
}
