// The C++ side of docs/python.md's overhead measurement: viscoroll::sweep of the line solver over
// N speeds (default 100, log-spaced V tau/a0 = 1e-2 ... 1e2 of the paper's nondimensional scene,
// terms 6, chunk 16), repeated R times (default 5); prints each wall time and the median.
// python/bench/bench_sweep.py times the same sweep from Python.
// usage: sweep_timing [--speeds N] [--repeats R] [--threads T]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string_view>
#include <vector>
#include <viscoroll/line/line_solver.hpp>
#include <viscoroll/sweep.hpp>

int main(int argc, char** argv) {
  int speeds = 100, repeats = 5;
  unsigned threads = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string_view a = argv[i];
    const long v = std::strtol(argv[i + 1], nullptr, 10);
    if (a == "--speeds")
      speeds = static_cast<int>(std::max(1L, v));
    else if (a == "--repeats")
      repeats = static_cast<int>(std::max(1L, v));
    else if (a == "--threads")
      threads = static_cast<unsigned>(std::max(0L, v));
    else {
      std::fprintf(stderr, "usage: sweep_timing [--speeds N] [--repeats R] [--threads T]\n");
      return 2;
    }
  }
  const double f = 9, nu = 0.5, mu_d = 1, tau = 1, c1 = 1;
  const double c2 = (std::log(20.0) - 1) / 25;
  const viscoroll::StandardLinearSolid<double> material(mu_d, nu, f, tau);
  const double load = c1 * 5 / (3 * (1 + f) * material.instantaneous_compliance());
  viscoroll::LineOptions line;
  line.terms = 6;
  const viscoroll::LineSolverD solver(material, line);
  std::vector<double> v(static_cast<std::size_t>(speeds));
  for (int i = 0; i < speeds; ++i)
    v[static_cast<std::size_t>(i)] = std::pow(10.0, -2 + 4.0 * i / std::max(1, speeds - 1)) / tau;
  viscoroll::SweepOptions options;
  options.threads = threads;
  std::vector<double> times, cpu;
  int converged = 0;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    const auto out = viscoroll::sweep(
        solver, viscoroll::LineScene<double>{.c1 = c1, .c2 = c2, .load = load, .speed = 0.0}, v,
        options);
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    cpu.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
    converged = static_cast<int>(
        std::count_if(out.begin(), out.end(), [](const auto& s) { return s.converged; }));
    std::printf("run %d: %.4f s (cpu %.4f s)\n", r + 1, times.back(), cpu.back());
  }
  std::sort(times.begin(), times.end());
  std::sort(cpu.begin(), cpu.end());
  std::printf(
      "C++ sweep: %d speeds, threads %u (effective %u), chunk %zu: median %.4f s (cpu "
      "%.4f s), %d converged\n",
      speeds, threads, options.effective_threads((v.size() + 15) / 16), options.chunk,
      times[times.size() / 2], cpu[cpu.size() / 2], converged);
  return 0;
}
