// Stability of the line solver in cpp_bin_float_50 (docs/stability.md): the closed forms and one
// iterated cell; scenes and checks in line_stability_support.hpp. A file of its own: the
// multiprecision instantiations are the costliest to compile (docs/building.md).
#include <catch2/catch.hpp>

#include "line_stability_support.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_line_stability_multiprecision {

TEST_CASE("stability: line solver closed forms in cpp_bin_float_50",
          "[stability][line][multiprecision]") {
  using mp = boost::multiprecision::cpp_bin_float_50;
  closed_form_matrix<mp, GaussLegendre<mp, 24>>();
}

TEST_CASE("stability: line solver, one iterated cell in cpp_bin_float_50",
          "[stability][line][multiprecision][slow]") {
  // The paper's cell (V tau = a0, f = 9, l0/a0 = 5) at terms = 2, GaussLegendre<mp, 24>: 101 s in
  // a Release build (68 s before the panels followed the scalar's epsilon, theory.md section 7;
  // 294 s with a difference Jacobian at every iteration), far longer under the sanitizers or
  // without optimisation, where it is not run.
#if defined(NDEBUG)
  constexpr bool optimised = !stability::sanitized;
#else
  constexpr bool optimised = false;
#endif
  if (!optimised) {
    WARN("cpp_bin_float_50 iterated line solve skipped: not an optimised, unsanitized build");
    return;
  }
  using mp = boost::multiprecision::cpp_bin_float_50;
  const Cell<mp> cell{1, 9, 5};
  const auto s = Solver<mp, GaussLegendre<mp, 24>>(cell.material(), LineOptions{.terms = 2})
                     .solve(cell.scene(mp(1)));
  INFO(s.reason << ", residual " << s.residual << ", iterations " << s.iterations);
  REQUIRE(s.converged);
  CHECK(s.residual <= 64 * sqrt(eps<mp>()));
  check_fields(s, mp(0));
  // The same discrete equations in long double (GaussLegendre<long double, 12>: its panels are
  // exact to long double rounding). A residual r moves the unknowns by up to ~50 r (the
  // Jacobian's smallest singular value ~2e-2 at V = a0), so they agree to 50 r + 64 eps of long
  // double (measured: 1-3 eps).
  const Cell<long double> ldc{1, 9, 5};
  const auto ld =
      Solver<long double, GaussLegendre<long double, 12>>(ldc.material(), LineOptions{.terms = 2})
          .solve(ldc.scene(1.0L));
  REQUIRE(ld.converged);
  const long double tol = 50 * ld.residual + 64 * eps<long double>();
  CHECK(rel(s.a(mp(0)), ld.a(0.0L)) <= tol);
  CHECK(rel(s.l(), ld.l()) <= tol);
  CHECK(rel(s.d, ld.d) <= tol);
  CHECK(rel(s.chi, ld.chi) <= tol);
  report("line cpp_bin_float_50 " + cell.name() + " terms 2: residual " + str(s.residual) +
         ", iterations " + std::to_string(s.iterations));
}

}  // namespace test_line_stability_multiprecision
