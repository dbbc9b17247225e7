// error_vs_time: discretisation error against wall-clock run time of the two solvers of the
// paper's scene (Panek & Kalker 1980, Section 7): the line-contact theory (LineSolverD) as its
// Chebyshev discretisation LineOptions::terms grows, and the 3-D boundary elements (BemSolverD)
// as BemOptions::grid grows. Scene as examples/panek_kalker.cpp and benchmarks/bem_vs_line.cpp:
// f = 9, nu = 0.5, mu_D = 1, tau = 1, C1 = 1, C2 = (ln 20 - 1)/25, load P = 5 C1 / (3 (1 + f) c)
// (Eq. 47 with Kalker's static solution: the line theory's static a0 = 1, l0 = 5); lengths in
// units of that a0, d in C1 a0^2.
//
// For every speed V tau/a0 and every discretisation it records a(0), b(0), l, d, chi (Eq. 54 for
// the line solver, Eq. 51 for the BEM), whether the solver certified convergence, and the wall
// seconds of a cold solve (median of 5 runs below 0.3 s, of 3 below 2 s, else one run). Errors
// are relative, |X - X_ref| / |X_ref|, against
//   self:  the same method's reference: the line solver's largest converged `terms`, the BEM's
//          finest converged grid (docs/performance.md says why not Richardson extrapolation);
//   cross: the other method's reference (the line theory's modelling error plus both methods'
//          discretisation errors).
//
// Line run times. A cold LineSolver::solve at `terms` = N runs the continuation stages
// {2, 4, 8, 16, 32 below N} and then N, each seeded by the previous one
// (docs/line-solver.md, "Continuation in N"); a solve seeded with a solution goes straight to its
// own N. So the program solves each stage once, seeded by the previous stage's solution, and a
// cold solve at N costs the sum of its stages' times: the same arithmetic, hence the same values
// bit for bit (checked with --check-cold N, which also times the cold solve itself).
//
// Writes
//   <dir>/error_vs_time.csv  one row per (method, speed, discretisation): method (line | bem),
//                            vtau, n (terms or grid), converged, seconds (wall), cpu_seconds,
//                            repetitions, the values
//                            a0 b0 l d chi, self_<q> and cross_<q> relative errors for
//                            q = a0 b0 l d chi (0 for the reference itself), is_reference
//   <dir>/error_vs_time.txt  the references, the cold-solve check, and the run time to reach
//                            1%, 0.1%, 0.01% self-convergence error per method and speed
// and prints the same. usage: error_vs_time [output-directory] [--speeds V1,V2,...]
// [--terms N1,N2,...] [--grids N1,N2,...] [--check-cold N] (defaults docs/figures,
// speeds 0.1,1,10, terms 2-8,10,12,14,16,20,24,32, grids 4,6,8,12,16,24,32,48,64, no check).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/line/line_solver.hpp>

namespace {

constexpr double f = 9, nu = 0.5, mu = 1, c1 = 1, tau = 1;
const double c = (1 - nu) / (2 * std::acos(-1.0) * mu);  // Eq. (3): instantaneous compliance
const double c2 = (std::log(20.0) - 1) / 25;             // the line theory's 5:1 static contact
const double load = 5 * c1 / (3 * (1 + f) * c);          // Eq. (47): static a0 = 1, l0 = 5

constexpr int quantities = 5;
constexpr const char* names[quantities] = {"a0", "b0", "l", "d", "chi"};
constexpr const char* labels[quantities] = {"a(0)", "b(0)", "l", "d", "chi"};

struct Values {
  double q[quantities];
};

struct Point {
  std::string method;
  double vtau;
  int n;
  bool converged;
  std::string reason;
  double seconds;
  double cpu_seconds;
  int repetitions;
  Values v;
  double self[quantities] = {};
  double cross[quantities] = {};
  bool is_reference = false;
};

struct Timed {
  double seconds;      // wall clock
  double cpu_seconds;  // process CPU time (the same on a quiet machine: one thread)
  int repetitions;
};

/// Runs `work` once; repeats it to 5 runs below 0.3 s and to 3 below 2 s; the median seconds.
Timed time_median(const std::function<void()>& work) {
  using clock = std::chrono::steady_clock;
  std::vector<double> wall, cpu;
  const auto once = [&] {
    const std::clock_t cpu_start = std::clock();
    const auto start = clock::now();
    work();
    wall.push_back(std::chrono::duration<double>(clock::now() - start).count());
    cpu.push_back(double(std::clock() - cpu_start) / CLOCKS_PER_SEC);
  };
  once();
  const int total = wall[0] < 0.3 ? 5 : wall[0] < 2 ? 3 : 1;
  while (static_cast<int>(wall.size()) < total) once();
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  return {wall[wall.size() / 2], cpu[cpu.size() / 2], total};
}

using LineSolution = viscoroll::LineSolverD::Solution;

Values values_of(const LineSolution& s) { return {{s.a(0.0), s.b(0.0), s.l(), s.d, s.chi}}; }

viscoroll::LineSolverD line_solver(int terms) {
  viscoroll::LineOptions o;
  o.terms = terms;
  return viscoroll::LineSolverD(viscoroll::StandardLinearSolid<double>(mu, nu, f, tau), o);
}

/// The continuation stages of a cold solve (LineSolver::continuation_stages, docs/line-solver.md).
const std::vector<int> chain{2, 4, 8, 16, 32};

/// The line solver at every N of `terms` for one speed, each point timed as a cold solve.
class LineSeries {
 public:
  explicit LineSeries(double vtau)
      : scene_{.c1 = c1, .c2 = c2, .load = load, .speed = vtau / tau} {}

  Point point(int n) {
    const Stage& s = n == 1 ? stage(1, nullptr, {0, 0}) : side(n);
    return {"line",
            scene_.speed * tau,
            n,
            s.solution.converged,
            s.solution.reason,
            s.cumulative,
            s.cumulative_cpu,
            s.repetitions,
            values_of(s.solution)};
  }

  /// Times a cold solve at N and compares its values with the chained stages.
  std::string check_cold(int n) {
    const Point chained = point(n);
    LineSolution cold;
    const Timed t = time_median([&] { cold = line_solver(n).solve(scene_); });
    const Values v = values_of(cold);
    bool same = cold.converged == chained.converged;
    for (int q = 0; q < quantities; ++q) same = same && v.q[q] == chained.v.q[q];
    std::ostringstream out;
    out << "cold-solve check, V tau/a0 = " << scene_.speed * tau << ", terms = " << n
        << ": cold solve " << t.seconds << " s (median of " << t.repetitions
        << "), sum of its stages " << chained.seconds << " s; values "
        << (same ? "identical" : "DIFFERENT") << "\n";
    return out.str();
  }

 private:
  struct Stage {
    LineSolution solution;
    double cumulative;  // seconds of a cold solve ending with this stage
    double cumulative_cpu;
    int repetitions;
  };

  const Stage& stage(int n, const Stage* from, std::pair<double, double> before) {
    LineSolution s;
    const auto solver = line_solver(n);
    const Timed t = time_median([&] {
      s = from != nullptr ? solver.solve(scene_, &from->solution) : solver.solve(scene_);
    });
    owned_.push_back(std::make_unique<Stage>(Stage{std::move(s), before.first + t.seconds,
                                                   before.second + t.cpu_seconds, t.repetitions}));
    return *owned_.back();
  }

  /// The chain's stage k (chain[k]), from chain[k - 1].
  const Stage& main(std::size_t k) {
    if (const auto it = main_.find(k); it != main_.end()) return *it->second;
    const Stage* from = k == 0 ? nullptr : &main(k - 1);
    const Stage& s = stage(chain[k], from, start_time(from));
    main_[k] = &s;
    return s;
  }

  /// A cold solve at n: the chain's stages below n, then n.
  const Stage& side(int n) {
    std::size_t below = 0;
    while (below < chain.size() && chain[below] < n) ++below;
    if (below < chain.size() && chain[below] == n) return main(below);
    if (below == 0) return stage(n, nullptr, {0, 0});
    const Stage& from = main(below - 1);
    return stage(n, &from, start_time(&from));
  }

  static std::pair<double, double> start_time(const Stage* from) {
    return from != nullptr ? std::make_pair(from->cumulative, from->cumulative_cpu)
                           : std::make_pair(0.0, 0.0);
  }

  viscoroll::LineScene<double> scene_;
  std::vector<std::unique_ptr<Stage>> owned_;
  std::map<std::size_t, const Stage*> main_;
};

Point bem_point(int n, double vtau) {
  viscoroll::BemOptions o;
  o.grid = n;
  const viscoroll::BemSolverD solver(viscoroll::StandardLinearSolid<double>(mu, nu, f, tau), o);
  viscoroll::BemSolverD::Solution s;
  const Timed t = time_median([&] {
    s = solver.solve(
        viscoroll::BemScene<double>{.c1 = c1, .c2 = c2, .load = load, .speed = vtau / tau});
  });
  return {"bem",         vtau,          n,
          s.converged,   s.reason,      t.seconds,
          t.cpu_seconds, t.repetitions, Values{{s.a0, s.b0, s.l, s.d, s.chi}}};
}

/// The reference of a series: its last converged point (the series is ordered by n).
const Point* reference(const std::vector<Point>& series) {
  for (auto it = series.rbegin(); it != series.rend(); ++it)
    if (it->converged) return &*it;
  return nullptr;
}

void fill_errors(std::vector<Point>& series, const Point* self, const Point* other) {
  for (Point& p : series)
    for (int q = 0; q < quantities; ++q) {
      p.self[q] = self ? std::abs(p.v.q[q] - self->v.q[q]) / std::abs(self->v.q[q]) : NAN;
      p.cross[q] = other ? std::abs(p.v.q[q] - other->v.q[q]) / std::abs(other->v.q[q]) : NAN;
    }
  if (self)
    for (Point& p : series) p.is_reference = &p == self;
}

/// Time to reach `eps` for the quantities in `which`: the cheapest converged point at and beyond
/// which (in n, excluding the reference) every converged point is within eps of the reference.
/// Returns that point, or nullptr when none (not reached short of the reference).
const Point* time_to(const std::vector<Point>& series, double eps, const std::vector<int>& which) {
  const Point* found = nullptr;
  for (auto it = series.rbegin(); it != series.rend(); ++it) {
    if (it->is_reference || !it->converged) continue;
    bool ok = true;
    for (int q : which) ok = ok && it->self[q] <= eps;
    if (!ok) break;
    found = &*it;
  }
  return found;
}

std::vector<double> parse_list(std::string_view option, std::string_view text, double lo,
                               double hi) {
  std::vector<double> out;
  while (!text.empty()) {
    const auto comma = text.find(',');
    const std::string item(text.substr(0, comma));
    char* end = nullptr;
    const double x = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !(x >= lo && x <= hi))
      throw std::invalid_argument("error_vs_time: " + std::string(option) +
                                  " expects numbers in [" + std::to_string(lo) + ", " +
                                  std::to_string(hi) + "], got '" + item + "'");
    out.push_back(x);
    if (comma == std::string_view::npos) break;
    text = text.substr(comma + 1);
  }
  if (out.empty()) throw std::invalid_argument("error_vs_time: empty " + std::string(option));
  return out;
}

std::vector<int> parse_counts(std::string_view option, std::string_view text, int lo, int hi) {
  std::vector<int> out;
  for (double x : parse_list(option, text, lo, hi)) {
    if (x != std::floor(x))
      throw std::invalid_argument("error_vs_time: " + std::string(option) + " expects integers");
    out.push_back(static_cast<int>(x));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::string describe(const Point* p) {
  if (p == nullptr) return "not reached";
  char buf[128];
  std::snprintf(buf, sizeof buf, "%.3g s wall, %.3g s CPU (%s %d)", p->seconds, p->cpu_seconds,
                p->method == "line" ? "terms" : "N =", p->n);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path dir = "docs/figures";
  std::vector<double> speeds{0.1, 1, 10};
  std::vector<int> terms{2, 3, 4, 5, 6, 7, 8, 10, 12, 14, 16, 20, 24, 32};
  std::vector<int> grids{4, 6, 8, 12, 16, 24, 32, 48, 64};
  int check = 0;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string_view a = argv[i];
      if (a == "--speeds" && i + 1 < argc)
        speeds = parse_list(a, argv[++i], 1e-3, 1e3);
      else if (a == "--terms" && i + 1 < argc)
        terms = parse_counts(a, argv[++i], 1, 64);
      else if (a == "--grids" && i + 1 < argc)
        grids = parse_counts(a, argv[++i], 2, 512);
      else if (a == "--check-cold" && i + 1 < argc)
        check = parse_counts(a, argv[++i], 1, 64).front();
      else if (!a.starts_with("--"))
        dir = a;
      else
        throw std::invalid_argument(
            "usage: error_vs_time [output-directory] [--speeds V1,V2,...] [--terms N1,N2,...] "
            "[--grids N1,N2,...] [--check-cold N]");
    }
  } catch (const std::invalid_argument& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  std::filesystem::create_directories(dir);
  std::ostringstream summary;
  summary.precision(4);
  summary << "# error_vs_time: paper's scene (f = 9, 5:1), relative errors, wall seconds of a cold "
             "solve on one core\n";

  std::vector<Point> all;
  int failures = 0;
  for (const double vtau : speeds) {
    LineSeries line_series(vtau);
    std::vector<Point> line, bem;
    for (int n : terms) {
      line.push_back(line_series.point(n));
      const Point& p = line.back();
      std::printf(
          "line V tau = %-5g terms = %2d %s %8.3f s (x%d) a0 %.7f b0 %.7f l %.7f d %.8f "
          "chi %.8f%s%s\n",
          vtau, n, p.converged ? "conv" : "NOT ", p.seconds, p.repetitions, p.v.q[0], p.v.q[1],
          p.v.q[2], p.v.q[3], p.v.q[4], p.converged ? "" : ": ",
          p.converged ? "" : p.reason.c_str());
      std::fflush(stdout);
    }
    if (check > 0 && std::abs(vtau - 1) < 1e-12) {
      const std::string text = line_series.check_cold(check);
      summary << text;
      std::cout << text;
    }
    for (int n : grids) {
      bem.push_back(bem_point(n, vtau));
      const Point& p = bem.back();
      std::printf(
          "bem  V tau = %-5g N = %2d %s %8.3f s (x%d) a0 %.7f b0 %.7f l %.7f d %.8f "
          "chi %.8f%s%s\n",
          vtau, n, p.converged ? "conv" : "NOT ", p.seconds, p.repetitions, p.v.q[0], p.v.q[1],
          p.v.q[2], p.v.q[3], p.v.q[4], p.converged ? "" : ": ",
          p.converged ? "" : p.reason.c_str());
      std::fflush(stdout);
    }
    const Point* line_ref = reference(line);
    const Point* bem_ref = reference(bem);
    // Copies: fill_errors compares addresses within its own series.
    const Point line_ref_copy = line_ref ? *line_ref : Point{};
    const Point bem_ref_copy = bem_ref ? *bem_ref : Point{};
    fill_errors(line, line_ref, bem_ref ? &bem_ref_copy : nullptr);
    fill_errors(bem, bem_ref, line_ref ? &line_ref_copy : nullptr);
    int line_failed = 0, bem_failed = 0;
    for (const Point& p : line) line_failed += !p.converged;
    for (const Point& p : bem) bem_failed += !p.converged;
    failures += bem_failed;  // the line solver's failures at V tau/a0 = 10 are documented

    summary << "\n## V tau/a0 = " << vtau << "\n";
    summary << "line reference: terms = " << (line_ref ? std::to_string(line_ref->n) : "none")
            << " (largest converged; " << line_failed << " of " << line.size()
            << " line points not converged";
    for (const Point& p : line)
      if (!p.converged) summary << ", terms " << p.n;
    summary << ")\n";
    summary << "bem reference: N = " << (bem_ref ? std::to_string(bem_ref->n) : "none")
            << " (finest converged; " << bem_failed << " of " << bem.size() << " not converged)\n";
    for (const auto* series : {&line, &bem}) {
      const std::string method = series->front().method;
      summary << method << " time to reach a self-convergence error (all five quantities; "
              << "governing quantity = the last to get there):\n";
      for (double eps : {1e-2, 1e-3, 1e-4}) {
        const Point* all5 = time_to(*series, eps, {0, 1, 2, 3, 4});
        std::string governing;
        double latest = -1;
        for (int q = 0; q < quantities; ++q) {
          const Point* p = time_to(*series, eps, {q});
          const double t = p ? p->seconds : INFINITY;
          if (t > latest) {
            latest = t;
            governing = labels[q];
          }
        }
        const Point* dchi = time_to(*series, eps, {3, 4});
        summary << "  " << eps << ": " << describe(all5) << ", governed by " << governing
                << "; d and chi only: " << describe(dchi) << "\n";
        summary << "    per quantity:";
        for (int q = 0; q < quantities; ++q)
          summary << " " << labels[q] << " " << describe(time_to(*series, eps, {q})) << ";";
        summary << "\n";
      }
    }
    all.insert(all.end(), line.begin(), line.end());
    all.insert(all.end(), bem.begin(), bem.end());
  }

  std::sort(all.begin(), all.end(), [](const Point& x, const Point& y) {
    return std::make_tuple(x.method == "bem", x.vtau, x.n) <
           std::make_tuple(y.method == "bem", y.vtau, y.n);
  });
  std::ofstream csv(dir / "error_vs_time.csv");
  csv.precision(10);
  csv << "method,vtau,n,converged,seconds,cpu_seconds,repetitions";
  for (const char* q : names) csv << ',' << q;
  for (const char* q : names) csv << ",self_" << q;
  for (const char* q : names) csv << ",cross_" << q;
  csv << ",is_reference\n";
  for (const Point& p : all) {
    csv << p.method << ',' << p.vtau << ',' << p.n << ',' << p.converged << ',' << p.seconds << ','
        << p.cpu_seconds << ',' << p.repetitions;
    for (double x : p.v.q) csv << ',' << x;
    for (double x : p.self) csv << ',' << x;
    for (double x : p.cross) csv << ',' << x;
    csv << ',' << p.is_reference << '\n';
  }
  std::ofstream(dir / "error_vs_time.txt") << summary.str();
  std::cout << summary.str();
  return failures == 0 ? 0 : 1;
}
