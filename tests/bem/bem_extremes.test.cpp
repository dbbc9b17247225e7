// The BEM at the ends of the floating-point range (docs/bem.md, "Scaling"):
// the solver computes in units of powers of two (lengths near the long-term Hertz semi-axis,
// pressures by the long-term compliance), so a scene whose answer is representable is solved
// whatever its inputs' magnitudes, with the bits of the same scene in moderate units; one whose
// answer is not is an error naming the inputs.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <viscoroll/bem/bem_solver.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_bem_extremes {

namespace {

using viscoroll::BemOptions;
using viscoroll::BemScene;
using viscoroll::BemSolution;
using viscoroll::BemSolverD;
using viscoroll::StandardLinearSolid;

/// The reproductions' scene: mu_D = 1, nu = 0.5, f = 9, tau = 1, C1 = 1, C2 = 0.0798291 C1.
constexpr double c2_ratio = 0.0798291;

BemSolverD solver(double mu_d, int grid = 8) {
  BemOptions o;
  o.grid = grid;
  return BemSolverD(StandardLinearSolid<double>(mu_d, 0.5, 9.0, 1.0), o);
}

double peak(const BemSolution<double>& s) {
  double m = 0;
  for (const double p : s.pressure) m = std::max(m, p);
  return m;
}

/// Every claimed quantity finite and the sizes positive.
void check_finite(const BemSolution<double>& s) {
  CHECK(s.converged);
  CHECK(std::isfinite(s.d));
  CHECK(std::isfinite(s.chi));
  CHECK(std::isfinite(s.b0));
  CHECK(s.a0 > 0);
  CHECK(s.l > 0);
  CHECK(s.d > 0);
  CHECK(peak(s) > 0);
  CHECK(std::isfinite(s.a0));
  CHECK(std::isfinite(s.l));
  CHECK(std::isfinite(peak(s)));
}

}  // namespace

TEST_CASE("bem extremes: speed 1e308 gives the glassy solution", "[bem]") {
  // The reproduction: --speed 1e308 --grid 8 ran 5000 GMRES steps to a NaN residual (ln(L/h)
  // overflowed, so the glassy term was kept with L = 1e308). Every memory length beyond the
  // grid's reach drops the term (bem_solver.hpp, effective_terms): the solution is the one of
  // V = 1e300 bit for bit, and that of V = DBL_MAX too.
  const auto s = solver(1.0);
  const auto glassy = s.solve(BemScene<double>{1.0, c2_ratio, 1.0, 1e300});
  for (const double speed : {1e308, std::numeric_limits<double>::max()}) {
    INFO("speed " << speed);
    const auto r = s.solve(BemScene<double>{1.0, c2_ratio, 1.0, speed});
    check_finite(r);
    CHECK(r.krylov_iterations < 1000);
    CHECK(r.a0 == glassy.a0);
    CHECK(r.d == glassy.d);
    CHECK(r.chi == glassy.chi);
  }
}

TEST_CASE("bem extremes: a memory length far under a cell is the long-term contact to rounding",
          "[bem]") {
  // M_L = K_e + O(L) (B3), and the contact's a0, l and d move at second order in L (the first
  // order is the shift b ~ L, measured a0 - 1.1e-2 (L/hx)^2, d - 5e-4 (L/hx)^2 at N = 8), so that
  // for L <= 1e-7 hx they are the V = 0 contact's to rounding: bound 64 eps + (L/hx)^2. The case
  // of docs/bem.md, B4: an offset t of (B4)'s weight e^(-t/L) formed from positions of order m hx
  // moves its argument by m hx eps/L (d 5.7% and a0 21% off at L = 1e-15 hx, 5.7e-7 at 1e-10 hx).
  const double eps = std::numeric_limits<double>::epsilon();
  const auto s = solver(1.0);
  const double load = 5.0 / (3 * 10 / (4 * std::acos(-1.0)));  // a0 = 1 (c = 1/(4 pi))
  const auto rest = s.solve(BemScene<double>{1.0, c2_ratio, load, 0.0});
  REQUIRE(rest.converged);
  const double hx = rest.grid.hx;
  for (const double q : {1e-15, 1e-13, 1e-11, 1e-9, 1e-7}) {
    const auto r = s.solve(BemScene<double>{1.0, c2_ratio, load, q * hx});  // tau = 1: L = V
    INFO("L/hx = " << q);
    REQUIRE(r.converged);
    REQUIRE(r.contact_cells == rest.contact_cells);
    const double bound = 64 * eps + q * q;
    CHECK(std::abs(r.d / rest.d - 1) <= bound);
    CHECK(std::abs(r.a0 / rest.a0 - 1) <= bound);
    CHECK(std::abs(r.l / rest.l - 1) <= bound);
    CHECK(r.chi > 0);
  }
}

TEST_CASE("bem extremes: solutions scale exactly under powers of two of length and force",
          "[bem]") {
  // Lengths x 2^j (C1, C2 / 2^j, V x 2^j) and loads x 2^(3j) ... with mu_D fixed, or the
  // compliance / 2^i (mu_D x 2^i) with the load x 2^i: the solve runs on the same numbers in its
  // units, so a(0), b(0), l, d scale by 2^j and the pressure by 2^i exactly (no rounding), up to
  // loads of 1e308 and moduli of 1e-300 (the reproductions: load 1e308 and mu_D 1e-308 reported
  // "compliance = -nan").
  const double load = 1.0, speed = 1.0;
  const auto base = solver(1.0).solve(BemScene<double>{1.0, c2_ratio, load, speed});
  check_finite(base);
  for (const int j : {-330, -200, -60, 60, 200, 340}) {
    INFO("length x 2^" << j);
    const double s = std::ldexp(1.0, j);
    // Load x 2^(2j) at fixed moduli keeps the pressure; x 2^(3j) with C1 / 2^j keeps the shape.
    const auto r =
        solver(1.0).solve(BemScene<double>{1.0 / s, c2_ratio / s, load * s * s, speed * s});
    check_finite(r);
    CHECK(r.a0 == base.a0 * s);
    CHECK(r.l == base.l * s);
    CHECK(r.d == base.d * s);
    CHECK(r.chi == base.chi);
    CHECK(peak(r) == peak(base));
    CHECK(r.iterations == base.iterations);
  }
  for (const int i : {-1000, -500, 500, 1000}) {
    INFO("mu_D x 2^" << i);
    const double m = std::ldexp(1.0, i);
    const auto r = solver(m).solve(BemScene<double>{1.0, c2_ratio, load * m, speed});
    check_finite(r);
    CHECK(r.a0 == base.a0);
    CHECK(r.d == base.d);
    CHECK(peak(r) == peak(base) * m);
  }
  // The reproductions themselves: finite, converged.
  check_finite(solver(1.0).solve(BemScene<double>{1.0, c2_ratio, 1e308, speed}));
  check_finite(solver(1e-308).solve(BemScene<double>{1.0, c2_ratio, 1.0, speed}));
  check_finite(solver(1.0).solve(BemScene<double>{1e-300, 1e-300 * c2_ratio, 1e300, speed}));
}

TEST_CASE("bem extremes: an answer that is not representable is an error naming the inputs",
          "[bem]") {
  const auto message = [](const auto& call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // mu_D = 1e308: the material's compliance (1 - nu)/(2 pi mu_D) underflows to 0 (the plane
  // solver rejects it with the same words).
  const std::string mu = message([] {
    return solver(1e308).solve(BemScene<double>{1.0, c2_ratio, 1.0, 1.0});
  });
  CHECK_THAT(mu, Catch::StartsWith("viscoroll: the instantaneous compliance c = 0 is below the "
                                   "smallest normal number"));
  CHECK_THAT(mu, Catch::Contains("load = 1"));
  // The smallest subnormal load: the load in the solution would be under the smallest normal
  // number.
  const std::string tiny = message([] {
    return solver(1.0).solve(BemScene<double>{1.0, c2_ratio, 4.9e-324, 1.0});
  });
  CHECK_THAT(tiny, Catch::StartsWith("viscoroll: the load = "));
  CHECK_THAT(tiny, Catch::Contains("below the smallest normal number"));
  CHECK_THAT(tiny, Catch::Contains("c1 = 1, c2 = 0.0798291, load = 4.94065645841247e-324"));
  // a(0) beyond the largest double (load 1e308 on mu_D 1e-300: a ~ 1e205 ... d ~ 1e410).
  const std::string huge = message([] {
    return solver(1e-300).solve(BemScene<double>{1.0, c2_ratio, 1e308, 1.0});
  });
  CHECK_THAT(huge, Catch::Contains("beyond the largest finite number"));
  CHECK_THAT(huge, Catch::Contains("rescale the units"));
}

TEST_CASE("bem extremes: the speed options are validated by name", "[bem]") {
  BemOptions o;
  o.coarse_tolerance = 0.5;
  CHECK_THROWS_WITH(o.validate(),
                    Catch::Contains("coarse_tolerance = 0.5") &&
                        Catch::Contains("0 (off) or 1e-15 <= coarse_tolerance <= 0.1"));
  o.coarse_tolerance = 0;
  CHECK_NOTHROW(o.validate());
  o.final_tolerance = 1e-2;
  CHECK_THROWS_WITH(o.validate(),
                    Catch::Contains("final_tolerance = 0.01") &&
                        Catch::Contains("0 (off) or 1e-15 <= final_tolerance <= 1e-3"));
  o.final_tolerance = 0;
  CHECK_NOTHROW(o.validate());
  o.threads = 0;
  CHECK_THROWS_WITH(o.validate(),
                    Catch::Contains("threads = 0") && Catch::Contains("1 <= threads <= 1024"));
  // Every active set solved to the tolerance (coarse 0), or the early ones coarsely (default), on
  // two table threads: the same contact to the GMRES tolerance's effect (docs/bem.md, B11), in
  // fewer GMRES steps.
  BemOptions tight;
  tight.grid = 8;
  tight.coarse_tolerance = 0;
  BemOptions fast;
  fast.grid = 8;
  fast.threads = 2;
  const StandardLinearSolid<double> sls(1.0, 0.5, 9.0, 1.0);
  const BemScene<double> scene{1.0, c2_ratio, 1.0, 1.0};
  const auto a = BemSolverD(sls, tight).solve(scene), b = BemSolverD(sls, fast).solve(scene);
  REQUIRE(a.converged);
  REQUIRE(b.converged);
  CHECK(b.krylov_iterations < a.krylov_iterations);
  // Both end with a final solve of the same set to 1e-13 (final_tolerance): the same answer to
  // 1e-10 (tests/bem/bem_final_solve.test.cpp; docs/bem.md, B11).
  CHECK(b.d == Approx(a.d).epsilon(1e-10));
  CHECK(b.chi == Approx(a.chi).epsilon(1e-10));
  CHECK(b.a0 == Approx(a.a0).epsilon(1e-10));
  CHECK(b.l == Approx(a.l).epsilon(1e-10));
}

}  // namespace test_bem_extremes
