// The roller profiles (roller/profile.hpp, docs/rollers.md): values against their definitions,
// smoothness where the pieces meet, the limits that tie them to the paper's ellipsoid, the tilt's
// mirror symmetry and the errors that name a bad parameter.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>
#include <viscoroll/roller/profile.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_profile {

using viscoroll::CrownedCylinder;
using viscoroll::EllipsoidProfile;
using viscoroll::LogarithmicCrown;
using viscoroll::TabulatedProfile;
using viscoroll::Tilted;

namespace {
const double eps = std::numeric_limits<double>::epsilon();
static_assert(viscoroll::RollerProfile<EllipsoidProfile<double>>);
static_assert(viscoroll::RollerProfile<CrownedCylinder<float>>);
static_assert(viscoroll::RollerProfile<LogarithmicCrown<long double>>);
static_assert(viscoroll::RollerProfile<TabulatedProfile<double>>);
static_assert(viscoroll::RollerProfile<Tilted<CrownedCylinder<double>>>);
static_assert(!viscoroll::RollerProfile<double>);
}  // namespace

TEST_CASE("profile: crowned cylinder is flat, then the crown circle", "[profile]") {
  const CrownedCylinder<double> p(0.01, 0.02, 0.5, 0.03);
  CHECK(p.c1() == 100.0);
  CHECK(p.drop(0.0) == 0.0);
  CHECK(p.drop(0.01) == 0.0);
  CHECK(p.drop_slope(0.0099) == 0.0);
  for (double y : {0.0101, 0.012, 0.015}) {
    const double s = y - 0.01, direct = 0.5 - std::sqrt(0.5 * 0.5 - s * s);
    CHECK(std::abs(p.drop(y) - direct) <= 8 * eps * 0.5);  // the direct form loses ~eps R_c
    CHECK(p.drop(-y) == p.drop(y));
    CHECK(p.drop_slope(-y) == -p.drop_slope(y));
    // The slope is the derivative of the drop (central difference, error h^2 h''' / 6).
    const double h = 1e-6;
    CHECK(std::abs((p.drop(y + h) - p.drop(y - h)) / (2 * h) - p.drop_slope(y)) <= 1e-9);
  }
  CHECK(p.y_max() == 0.015);  // length / 2 < flat / 2 + crown radius
  CHECK(CrownedCylinder<double>(0.01, 0.02, 0.001).y_max() == Approx(0.011).epsilon(4 * eps));
}

TEST_CASE("profile: a crowned cylinder without flat part is the ellipsoid near the centre",
          "[profile]") {
  // h = R_c - sqrt(R_c^2 - y^2) = y^2/(2 R_c) (1 + y^2/(4 R_c^2) + ...).
  const CrownedCylinder<double> barrel(0.01, 0.0, 2.0);
  const EllipsoidProfile<double> ellipsoid(100.0, 0.5);
  for (double y : {1e-4, 1e-3, 1e-2}) {
    const double relative = y * y / (4 * 2.0 * 2.0);
    CHECK(std::abs(barrel.drop(y) / ellipsoid.drop(y) - 1 - relative) <=
          4 * relative * relative + 16 * eps);
  }
}

TEST_CASE("profile: logarithmic crown", "[profile]") {
  const double A = 2e-6, L = 0.02;
  const LogarithmicCrown<double> lundberg(0.01, L, A);
  const LogarithmicCrown<double> bounded(0.01, L, A, 5e-6);
  // The end drop is z_m; Lundberg's is infinite at the ends.
  CHECK(bounded.drop(L / 2) == Approx(5e-6).epsilon(8 * eps));
  CHECK(std::isinf(lundberg.drop(L / 2)));
  // Near the centre h ~ A k (2y/L)^2, k = 1 - exp(-z_m/A).
  const double k = 1 - std::exp(-5e-6 / A), u = 1e-4;
  CHECK(bounded.drop(u * L / 2) == Approx(A * k * u * u).epsilon(2 * k * u * u));
  CHECK(lundberg.drop(u * L / 2) == Approx(A * u * u).epsilon(2 * u * u));
  for (double y : {0.001, 0.005, 0.009}) {
    const double h = 1e-7;
    CHECK(std::abs((bounded.drop(y + h) - bounded.drop(y - h)) / (2 * h) - bounded.drop_slope(y)) <=
          1e-8 * std::abs(bounded.drop_slope(y)));
  }
  // Lundberg's scale for a design load.
  const double pi = std::acos(-1.0);
  CHECK(LogarithmicCrown<double>::lundberg_scale(1000.0, 2.1e11, 0.3, L) ==
        Approx(2 * 1000.0 * 0.91 / (pi * 2.1e11 * L)).epsilon(4 * eps));
}

TEST_CASE("profile: a table interpolates smoothly and knows its symmetry", "[profile]") {
  // A quartic h = 1e4 y^4 + y^2/2 on [-0.02, 0.02] sampled every dy: the spline does at least as
  // well as linear interpolation, |error| <= dy^2 max|h''| / 8, and halving dy divides the error
  // by at least 4 (second order or better).
  const auto quartic = [](double t) { return 1e4 * std::pow(t, 4) + 0.5 * t * t; };
  const auto table = [&](int n) {
    std::vector<double> ys, hs;
    for (int i = -n; i <= n; ++i) {
      ys.push_back(0.02 * i / n);
      hs.push_back(quartic(0.02 * i / n));
    }
    return TabulatedProfile<double>(0.01, ys, hs);
  };
  const auto error = [&](const TabulatedProfile<double>& t) {
    double worst = 0;
    for (int k = 0; k < 997; ++k) {
      const double x = -0.0199 + 0.0398 * k / 996;
      worst = std::max(worst, std::abs(t.drop(x) - quartic(x)));
    }
    return worst;
  };
  const double h2_max = 12e4 * 0.02 * 0.02 + 1;
  const double coarse = error(table(20)), fine = error(table(40));
  CHECK(coarse <= 1e-6 * h2_max / 8);
  CHECK(fine <= coarse / 4);
  const TabulatedProfile<double> p = table(20);
  CHECK(p.symmetric());
  std::vector<double> y = p.y(), h = p.h();
  h.back() += 1e-9;
  CHECK_FALSE(TabulatedProfile<double>(0.01, y, h).symmetric());
}

TEST_CASE("profile: tilt mirrors exactly with theta -> -theta", "[profile]") {
  const CrownedCylinder<double> base(0.01, 0.02, 0.5, 0.03);
  const Tilted<CrownedCylinder<double>> plus(base, 1e-3), minus(base, -1e-3);
  CHECK_FALSE(plus.symmetric());
  CHECK(Tilted<CrownedCylinder<double>>(base, 0.0).symmetric());
  for (double y : {0.0, 0.004, 0.012, 0.0149}) {
    CHECK(plus.drop(-y) == minus.drop(y));
    CHECK(plus.drop_slope(-y) == -minus.drop_slope(y));
  }
  // theta > 0 lowers h on the side y < 0, which is pressed harder.
  CHECK(plus.drop(-0.012) < plus.drop(0.012));
}

TEST_CASE("profile: bad parameters are errors naming them", "[profile]") {
  const auto message = [](auto make) {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THAT(message([] { CrownedCylinder<double>(0.01, 0.02, -1.0); }),
             Catch::Contains("crown_radius"));
  CHECK_THAT(message([] { CrownedCylinder<double>(0.01, 0.02, 1.0, 0.01); }),
             Catch::Contains("length"));
  CHECK_THAT(message([&] { LogarithmicCrown<double>(0.01, inf, 1e-6); }),
             Catch::Contains("length"));
  CHECK_THAT(message([] { LogarithmicCrown<double>(0.01, 0.02, 1e-6, 0.0); }),
             Catch::Contains("end_drop"));
  CHECK_THAT(message([] {
               TabulatedProfile<double>(0.01, {0, 1, 1, 2}, {0, 0, 0, 0});
             }),
             Catch::Contains("y[2]"));
  CHECK_THAT(message([] {
               TabulatedProfile<double>(0.01, {0, 1, 2}, {0, 0, 0});
             }),
             Catch::Contains("at least 4"));
  CHECK_THAT(message([] { Tilted<EllipsoidProfile<double>>(EllipsoidProfile<double>(1, 1), 0.2); }),
             Catch::Contains("tilt"));
  CHECK_THAT(message([] { EllipsoidProfile<double>(1, 0); }), Catch::Contains("c2"));
}

}  // namespace test_profile
