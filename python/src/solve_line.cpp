// viscoroll's Python module: the line-contact solver (LineSolverD) behind solve_line and
// sweep_line. The fields are those of viscoroll-solve --method line (examples/viscoroll_solve.cpp).
#include <stdexcept>
#include <utility>
#include <viscoroll/line/line_solver.hpp>

#include "bindings.hpp"

namespace viscoroll::python {
namespace {

using Solver = LineSolverD;
using Solution = Solver::Solution;

class LineSolved final : public Solved {
 public:
  LineSolved(Solution s, double tau, double speed, int terms, double seconds)
      : Solved(Method::line), s_(std::move(s)) {
    const auto peak = s_.strip(0.0).peak();
    record_ = {{"method", std::string("line")},
               {"tau", tau},
               {"speed", speed},
               {"vtau", speed * tau},
               {"a0", s_.a(0.0)},
               {"b0", s_.b(0.0)},
               {"l", s_.l()},
               {"y_minus", -s_.l()},
               {"y_plus", s_.l()},
               {"d", s_.d},
               {"a_long_term", s_.a_long_term},
               {"l0", s_.l_long_term},
               {"d0", s_.d_long_term},
               {"chi", s_.chi},
               {"pmax", peak.pressure},
               {"pmax_x", peak.x},
               {"seconds", seconds},
               {"converged", s_.converged},
               {"root", s_.root},
               {"iterations", static_cast<long long>(s_.iterations)},
               {"residual", s_.residual},
               {"terms", static_cast<long long>(terms)},
               {"reason", s_.reason},
               {"warnings", s_.warnings}};
  }

  const Solution& solution() const { return s_; }
  double pressure(double x, double y) const override { return s_.pressure(x, y); }
  double a(double y) const override { return s_.a(y); }
  double b(double y) const override { return s_.b(y); }
  double f0(double y) const override { return s_.f0(y); }

 private:
  Solution s_;
};

Solver make_solver(const SceneSpec& scene, int terms) {
  LineOptions options;
  options.terms = terms;
  const auto& m = scene.material;
  return Solver(StandardLinearSolid<double>(m.mu_d, m.nu, m.f, m.tau), options);
}

LineScene<double> line_scene(const SceneSpec& scene, double speed) {
  LineScene<double> s{
      .c1 = scene.roller.c1, .c2 = scene.roller.c2, .load = scene.load, .speed = speed};
  s.validate();
  return s;
}

}  // namespace

SolvedPtr solve_line(const SceneSpec& scene, double speed, int terms, const Solved* start) {
  return solve_seeded<LineSolved>(make_solver(scene, terms), line_scene(scene, speed), Method::line,
                                  start, scene.material.tau, terms);
}

std::vector<SolvedPtr> sweep_line(const SceneSpec& scene, std::span<const double> speeds, int terms,
                                  const SweepOptions& options) {
  for (const double v : speeds) line_scene(scene, v);  // every speed checked before any work
  return sweep_seeded<LineSolved>(make_solver(scene, terms), line_scene(scene, 0.0), speeds,
                                  scene.material.tau, terms, options);
}

}  // namespace viscoroll::python
