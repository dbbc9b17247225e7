#include <viscoroll/viscoroll.hpp>
#include <viscoroll/line/line_spectrum.hpp>
#include <viscoroll/material/detail/prony_spectrum.hpp>
#include <viscoroll/numerics/levenberg_marquardt.hpp>
#include <boost/math/tools/roots.hpp>
#include <cstdio>
#include <chrono>
using namespace viscoroll;
using R = double;
// SLS reference
struct Ref { Ref(int argc, char** argv) {
  const R c2 = (std::log(20.0) - 1) / 25;
  auto st1 = static_line_contact<R>(1.0, c2, 1.0);
  const R X = 1.0 / (st1.a0 * st1.a0 * st1.a0);
  const R v = argc > 1 ? atof(argv[1]) : 1.0;
  const int N = argc > 3 ? atoi(argv[3]) : 6;
  const R pi = boost::math::constants::pi<R>();
  LineSolver<R, StandardLinearSolid<R>> sls(StandardLinearSolid<R>(1 / (pi * X), 0.5, 3.0, 0.05), LineOptions{.terms = N});
  auto s = sls.solve({.c1 = 1.0, .c2 = c2, .load = 1.0, .speed = v});
  printf("SLS N=%d conv %d: a0 %.8f b0 %.8f l %.8f d %.8f chi %.8g\n", N, s.converged, s.a(0), s.b(0), s.l(), s.d, s.chi);
}};
int main(int argc, char** argv) { Ref rr(argc, argv);
  const R c2 = (std::log(20.0) - 1) / 25;
  auto st1 = static_line_contact<R>(1.0, c2, 1.0);
  const R X = 1.0 / (st1.a0 * st1.a0 * st1.a0);  // a0 = 1
  auto slow = static_line_contact<R>(1.0, c2, X);  // compliance (1+F) c * P
  const R v = argc > 1 ? atof(argv[1]) : 1.0;  // speed with tau units
  const R f2 = argc > 2 ? atof(argv[2]) : 6.0;
  const int N = argc > 3 ? atoi(argv[3]) : 6;
  std::vector<detail::SpectrumTerm<R>> terms{{3.0, 0.05 * v}}; if (f2 > 0) terms.push_back({f2, 5 * v});
  SpectrumLengths<R> L;
  for (auto& t : terms) { L.retardation.push_back(t.q); L.creep_ratio += t.w; }
  for (auto& t : detail::convert_spectrum(terms, detail::SpectrumDirection::creep_to_relaxation, R(1), R(1))) L.relaxation.push_back(t.q);
  
  LineSpectrumProblem<R> prob{1.0, c2, L, slow.a0, slow.l, slow.a0 * slow.a0 * slow.l / 3};
  // plane seed
  auto h = [&](R A) { auto s = spectrum_strip(A * slow.a0, L); return A * A + 2 * s.g0 / (slow.a0 * slow.a0) - 1; };
  std::uintmax_t it = 100;
  auto br = boost::math::tools::toms748_solve(h, 1 / std::sqrt(1 + L.creep_ratio), R(1), boost::math::tools::eps_tolerance<R>(50), it);
  R A = (br.first + br.second) / 2;
  auto ps = spectrum_strip(A * slow.a0, L);
  printf("plane A %g b %g g0 %g centroid %g\n", A, ps.b, ps.g0, ps.centroid);
  R ratio = std::pow(A, 2.0 / 3);
  LineShape<R> shape{slow.a0, slow.l * ratio, {std::log(ratio)}, {ps.b / slow.a0}, argc > 4 && atoi(argv[4]) ? LineBasis::s_mapped : LineBasis::t_squared, argc > 4 && atoi(argv[4]) ? L.relaxation[0]/slow.a0 : 0.0};
  LineSpectrumMoments<R> mo{{ps.g0 / (A * A * slow.a0 * slow.a0)}, {ps.centroid / slow.a0}};
  R d = slow.d * ratio * ratio;
  auto t0 = std::chrono::steady_clock::now();
  int total = 0;
  for (int n : {2, 4, N}) {
    if (n > N) continue;
    LineSpectrumResidual<R, GaussLegendre<R, 12>> res(prob, n, argc > 4 && atoi(argv[4]) ? LineBasis::s_mapped : LineBasis::t_squared);
    auto x = res.pack(shape, mo, d);
    Eigen::VectorXd r(res.equations());
    if (!res(x, r)) { printf("undefined start\n"); return 1; }
    numerics::LeastSquaresOptions<R> o{.max_iterations = 100, .analytic_jacobian = false};
    auto out = numerics::levenberg_marquardt(res, x, r, o);
    total += out.iterations;
    shape = res.shape(x); mo = res.moments(x); d = res.penetration(x);
    printf("N=%d conv %d it %d |r| %.3g : a0 %.8f b0 %.8f l %.8f d %.8f chi %.8g  (%s)\n", n, out.converged, out.iterations, r.cwiseAbs().maxCoeff(), shape.a(0), shape.b(0), shape.l, d, res.centroid(shape, mo), out.reason.c_str());
    if (n == N) break;
  }
  auto t1 = std::chrono::steady_clock::now();
  printf("time %.3f s, iterations %d\n", std::chrono::duration<double>(t1 - t0).count(), total);
}
