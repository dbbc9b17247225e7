// PlaneSubstrateSolver on a layer on a rigid base (docs/plane-substrate.md): a thick layer tends
// to the half space, with the far-field compression (Q14) in d; a thin bonded incompressible
// layer to the lubrication-like limit of docs/theory.md (H4), P' = 2 G a^5/(15 R h^3),
// d = a^2/(6 R); a thin layer on a frictionless base to the spring bed of compliance
// (1 - nu^2) h / E. The thin limits are first order in h/a with large coefficients: they are
// compared by Richardson extrapolation over h, h/2, h/4, to the extrapolation's own error.
#include <algorithm>
#include <boost/math/quadrature/exp_sinh.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_substrate_solver.hpp>
#include <viscoroll/substrate/substrate.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_plane_substrate_layer {

using viscoroll::HalfSpace;
using viscoroll::Layer;
using viscoroll::LayerBase;
using viscoroll::PlaneScene;
using viscoroll::PlaneSubstrateSolver;
using viscoroll::SpringBed;

/// (Q14): C_T = int_0^inf [T(x) - 1 + e^-x] / x dx, by exp-sinh quadrature.
double far_field_constant(double nu, LayerBase base) {
  boost::math::quadrature::exp_sinh<double> rule;
  return rule.integrate(
      [&](double x) { return (viscoroll::layer_factor(x, nu, base) + std::expm1(-x)) / x; });
}

/// Second-order Richardson extrapolation of q(h), q(h/2), q(h/4) to h = 0, and its error
/// estimate, the distance to the first-order extrapolation of the two thinnest.
struct Extrapolated {
  double value, error;
};
Extrapolated richardson(double q1, double q2, double q4) {
  const double second = (8 * q4 - 6 * q2 + q1) / 3, first = 2 * q4 - q2;
  return {second, std::abs(second - first)};
}

/// The thin layers' limits are checked to their extrapolation error, >= 3e-5: a discretisation
/// error below 1e-7 of a and d cannot move them.
viscoroll::PlaneSubstrateOptions thin_options() {
  viscoroll::PlaneSubstrateOptions options;
  options.tolerance = 1e-7;
  return options;
}

TEST_CASE("plane substrate: a thick layer tends to the half space; d by the far field (Q14)",
          "[plane][substrate]") {
  const viscoroll::StandardLinearSolid<double> m(1.0, 0.3, 2.0, 1.0);
  const double c1 = 1.0, load = 0.1, c = m.instantaneous_compliance();
  const double a0 = std::sqrt(4 * c * 3 * load / c1);
  for (LayerBase base : {LayerBase::bonded, LayerBase::frictionless}) {
    const double ct = far_field_constant(m.nu(), base);
    for (double speed : {0.0, a0}) {
      const PlaneScene<double> scene{.c1 = c1, .load = load, .speed = speed};
      const auto hs = PlaneSubstrateSolver(m, HalfSpace<double>{}).solve(scene);
      REQUIRE(hs.converged);
      std::vector<double> da, db, dchi, dd;
      for (double h_a0 : {8.0, 16.0, 32.0}) {
        const auto s = PlaneSubstrateSolver(m, Layer<double>(h_a0 * a0, base)).solve(scene);
        REQUIRE(s.converged);
        CHECK(s.d_absolute);
        // (Q14): d = d_half space + 2 c (1 + F) W [ln(h / a) + C_T] + O(((a + V tau)/h)^2).
        const double far = 2 * c * 3 * load * (std::log(h_a0 * a0 / hs.a) + ct);
        da.push_back(s.a / hs.a - 1);
        db.push_back((s.b - hs.b) / hs.a);
        dchi.push_back((s.chi - hs.chi) / (c1 * hs.a));
        // On the scale of the far-field term's factor 2 c (1 + F) W (far itself grows as ln h).
        dd.push_back((s.d - hs.d - far) / (2 * c * 3 * load));
        INFO("h/a0 = " << h_a0 << ": a " << da.back() << ", b " << db.back() << ", chi "
                       << dchi.back() << ", d " << dd.back());
        CHECK(true);
      }
      INFO("base " << (base == LayerBase::bonded ? "bonded" : "frictionless") << ", V = " << speed
                   << ": relative differences at h/a0 = 8, 16, 32: a " << da[0] << ", " << da[1]
                   << ", " << da[2] << "; d " << dd[0] << ", " << dd[1] << ", " << dd[2]);
      // Second order in a/h (Q14): each doubling of h divides the difference by 4 (within 12%;
      // measured 3.85 to 4.05), so it tends to zero.
      for (const auto* q : {&da, &dd}) CHECK(std::abs((*q)[1] / (*q)[2] - 4) <= 0.5);
      if (speed > 0) {
        CHECK(std::abs(db[1] / db[2] - 4) <= 0.5);
        CHECK(std::abs(dchi[1] / dchi[2] - 4) <= 0.5);
      }
    }
  }
}

TEST_CASE("plane substrate: a thin bonded incompressible layer tends to (H4)",
          "[plane][substrate]") {
  // Long-term (V = 0) standard linear solid: G = mu_d / (1 + f); load for a = 1 in (H4).
  const viscoroll::StandardLinearSolid<double> m(3.0, 0.5, 2.0, 1.0);
  const double g = 1.0, c1 = 1.0;
  std::vector<double> a, d;
  for (double h : {0.2, 0.1, 0.05}) {
    const double load = 2 * g / (15 * h * h * h) * c1;
    const auto s = PlaneSubstrateSolver(m, Layer<double>(h), thin_options())
                       .solve(PlaneScene<double>{.c1 = c1, .load = load, .speed = 0.0});
    REQUIRE(s.converged);
    a.push_back(s.a);
    d.push_back(s.d / (s.a * s.a * c1 / 6));
  }
  const auto ea = richardson(a[0], a[1], a[2]), ed = richardson(d[0], d[1], d[2]);
  INFO("a / a_thin at h = 0.2, 0.1, 0.05: " << a[0] << ", " << a[1] << ", " << a[2] << " -> "
                                            << ea.value << " +- " << ea.error);
  INFO("d / (a^2/6R): " << d[0] << ", " << d[1] << ", " << d[2] << " -> " << ed.value << " +- "
                        << ed.error);
  CHECK(std::abs(ea.value - 1) <= ea.error);
  CHECK(std::abs(ed.value - 1) <= ed.error);
  CHECK(ea.error <= 0.01);
  CHECK(ed.error <= 0.01);
}

TEST_CASE("plane substrate: a thin layer on a frictionless base tends to the spring bed",
          "[plane][substrate]") {
  const viscoroll::Elastic<double> m(1.0, 0.3);
  const double nu = 0.3, c1 = 1.0, e = 2 * (1 + nu);
  std::vector<double> a, d;
  for (double h : {0.2, 0.1, 0.05}) {
    // The bed of compliance (1 - nu^2) h / E, (H4), loaded so that its half width is 1.
    const double compliance = (1 - nu * nu) * h / e, load = 2 * c1 / (3 * compliance);
    const PlaneScene<double> scene{.c1 = c1, .load = load, .speed = 0.0};
    const auto bed = PlaneSubstrateSolver(m, SpringBed<double>((1 - nu * nu) * h)).solve(scene);
    const auto s =
        PlaneSubstrateSolver(m, Layer<double>(h, LayerBase::frictionless), thin_options())
            .solve(scene);
    REQUIRE(bed.converged);
    REQUIRE(s.converged);
    CHECK(std::abs(bed.a - 1) <= 1e-12);  // the static bed's closed form, (Q12)
    a.push_back(s.a / bed.a);
    d.push_back(s.d / bed.d);
  }
  const auto ea = richardson(a[0], a[1], a[2]), ed = richardson(d[0], d[1], d[2]);
  INFO("a / a_bed at h = 0.2, 0.1, 0.05: " << a[0] << ", " << a[1] << ", " << a[2] << " -> "
                                           << ea.value << " +- " << ea.error);
  INFO("d / d_bed: " << d[0] << ", " << d[1] << ", " << d[2] << " -> " << ed.value << " +- "
                     << ed.error);
  CHECK(std::abs(ea.value - 1) <= ea.error);
  CHECK(std::abs(ed.value - 1) <= ed.error);
  CHECK(ea.error <= 0.01);
  CHECK(ed.error <= 0.01);
}

}  // namespace test_plane_substrate_layer
