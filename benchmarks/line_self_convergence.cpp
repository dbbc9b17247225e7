// line_self_convergence: the line solver on the paper's scene (Panek & Kalker 1980, Section 7:
// f = 9, nu = 0.5, C2/C1 = (ln 20 - 1)/25, the load of a static a0 = C1 = 1) at one speed over a
// list of discretisations, one line per solve: N, converged, iterations, a(0), b(0), l, d, chi,
// residual, median wall seconds of `--repeat` solves, reason. The data behind
// docs/line-solver.md's and docs/validation.md's tables.
//
// usage: line_self_convergence <V tau/a0> <terms>... [--repeat R] [--basis t2|s|mapped]
//        [--oversampling K] [--max-iterations M]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include <viscoroll/viscoroll.hpp>

int main(int argc, char** argv) {
  try {
    std::vector<int> terms;
    int repeat = 1;
    int oversampling = 1;
    int max_iterations = viscoroll::LineOptions{}.max_iterations;
    double vtau = -1;
    viscoroll::LineBasis basis = viscoroll::LineBasis::t_squared;
    for (int i = 1; i < argc; ++i) {
      const std::string_view a = argv[i];
      if (a == "--basis" && i + 1 < argc) {
        const std::string_view b = argv[++i];
        if (b != "t2" && b != "s" && b != "mapped")
          throw std::invalid_argument("--basis expects t2, s or mapped");
        basis = b == "s"        ? viscoroll::LineBasis::s
                : b == "mapped" ? viscoroll::LineBasis::s_mapped
                                : viscoroll::LineBasis::t_squared;
      } else if (a == "--oversampling" && i + 1 < argc) {
        oversampling = std::stoi(argv[++i]);
      } else if (a == "--max-iterations" && i + 1 < argc) {
        max_iterations = std::stoi(argv[++i]);
      } else if (a == "--repeat" && i + 1 < argc) {
        repeat = std::stoi(argv[++i]);
        if (repeat < 1 || repeat > 1000) throw std::invalid_argument("--repeat expects 1..1000");
      } else if (vtau < 0) {
        vtau = std::stod(std::string(a));
        if (!(vtau >= 0) || !std::isfinite(vtau))
          throw std::invalid_argument("V tau/a0 must be finite, >= 0");
      } else {
        terms.push_back(std::stoi(std::string(a)));
      }
    }
    if (vtau < 0 || terms.empty()) throw std::invalid_argument("missing V tau/a0 or terms");
    const double f = 9, c1 = 1, c2 = (std::log(20.0) - 1) / 25;
    const viscoroll::StandardLinearSolid<double> material(1, 0.5, f, 1);
    const double load = c1 * 5 / (3 * (1 + f) * material.instantaneous_compliance());  // a0 = 1
    std::printf(
        "# V tau/a0 = %g, oversampling %d; N, converged, iterations, a(0), b(0), l, d (a0 = C1 = "
        "1), chi, residual, median seconds of %d, reason\n",
        vtau, oversampling, repeat);
    for (const int n : terms) {
      viscoroll::LineOptions options;
      options.terms = n;
      options.basis = basis;
      options.oversampling = oversampling;
      options.max_iterations = max_iterations;
      const viscoroll::LineSolverD solver(material, options);
      std::vector<double> seconds;
      viscoroll::LineSolverD::Solution s;
      for (int r = 0; r < repeat; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        s = solver.solve({.c1 = c1, .c2 = c2, .load = load, .speed = vtau});
        seconds.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      }
      std::nth_element(seconds.begin(), seconds.begin() + repeat / 2, seconds.end());
      std::printf(
          "V=%g N=%2d conv=%d it=%d a0=%.10f b0=%.10f l=%.10f d=%.10f chi=%.10f res=%.3e %.4fs "
          "%s\n",
          vtau, n, int(s.converged), s.iterations, s.a(0), s.b(0), s.l(), s.d, s.chi, s.residual,
          seconds[repeat / 2], s.reason.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr,
                 "line_self_convergence: %s\nusage: line_self_convergence <V tau/a0> <terms>... "
                 "[--repeat R] [--basis t2|s|mapped] [--oversampling K] [--max-iterations M]\n",
                 e.what());
    return 2;
  }
}
