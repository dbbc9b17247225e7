// The relaxation form goes to the boundary-element solver as it is: its memory terms are its
// creep form (docs/materials.md; docs/theory.md (R6a)).
#include <catch2/catch.hpp>
#include <viscoroll/bem/influence_operator.hpp>
#include <viscoroll/material/prony.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_prony_bem {

static_assert(viscoroll::ConstitutiveModel<viscoroll::PronyRelaxation<double>>);
static_assert(viscoroll::ConstitutiveModel<viscoroll::PronyCreep<double>>);

TEST_CASE(
    "prony: a relaxation spectrum's memory terms are its creep form, one term the standard linear "
    "solid",
    "[material][prony][bem]") {
  const viscoroll::StandardLinearSolid<double> sls(1.0, 0.3, 9.0, 2.0);
  // (R6a): G_inf = mu_D / (1 + f), g = mu_D f / (1 + f), rho = tau / (1 + f).
  const viscoroll::PronyRelaxation<double> relax(0.1, 0.3, {{0.9, 0.2}});
  const auto a = viscoroll::bem::memory_terms_of(sls);
  const auto b = viscoroll::bem::memory_terms_of(relax);
  REQUIRE(b.size() == 1);
  CHECK(b[0].f == Approx(a[0].f).epsilon(1e-15));
  CHECK(b[0].tau == Approx(a[0].tau).epsilon(1e-15));
  CHECK(relax.instantaneous_compliance() == Approx(sls.instantaneous_compliance()).epsilon(1e-15));
  CHECK(relax.creep_ratio() == Approx(9.0).epsilon(1e-15));
  const viscoroll::BemGrid<double> grid{5, 3, 0.1, 0.3};
  const double c = sls.instantaneous_compliance();
  const viscoroll::bem::InfluenceTable<double> ta(grid, c, a, 0.7), tb(grid, c, b, 0.7);
  for (int i = -4; i <= 4; ++i)
    for (int j = 0; j < 3; ++j) CHECK(tb(i, j) == Approx(ta(i, j)).epsilon(1e-14));
}

}  // namespace test_prony_bem
