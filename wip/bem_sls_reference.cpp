#include <viscoroll/viscoroll.hpp>
#include <viscoroll/bem/bem_solver.hpp>
#include <cstdio>
using namespace viscoroll; using R = double;
int main(int argc, char** argv) {
  const R c2 = (std::log(20.0) - 1) / 25;
  auto st1 = static_line_contact<R>(1.0, c2, 1.0);
  const R X = 1.0 / (st1.a0 * st1.a0 * st1.a0);
  const R v = atof(argv[1]);
  const R pi = boost::math::constants::pi<R>();
  for (int n : {16, 32, 48}) {
    BemOptions o; o.grid = n;
    const BemSolverD solver(StandardLinearSolid<R>(1 / (pi * X), 0.5, 3.0, 0.05), o);
    auto s = solver.solve(BemScene<R>{.c1 = 1.0, .c2 = c2, .load = 1.0, .speed = v});
    printf("BEM N=%d conv %d: a0 %.6f b0 %.6f l %.6f d %.6f chi %.6g\n", n, s.converged, s.a0, s.b0, s.l, s.d, s.chi);
  }
}
