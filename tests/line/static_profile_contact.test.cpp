// The static line contact of any roller profile (line/static_profile_contact.hpp; docs/theory.md,
// "Line contact for any roller profile (static)").
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>
#include <viscoroll/line/line_operators.hpp>
#include <viscoroll/line/static_line_contact.hpp>
#include <viscoroll/line/static_profile_contact.hpp>
#include <viscoroll/roller/profile.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_static_profile_contact {

using namespace viscoroll;

namespace {

template <class S>
double rel(double x, double ref) {
  return std::abs(x - ref) / std::abs(ref);
}

/// int F0 dy by composite Gauss-Legendre (64 panels of 16 points), independent of (G2)'s
/// Clenshaw-Curtis weights.
template <class S>
double load_of(const S& s) {
  using Rule = GaussLegendre<double, 16>;
  const int panels = 64;
  const double w = (s.y_plus - s.y_minus) / panels;
  double sum = 0;
  for (int p = 0; p < panels; ++p)
    for (int j = 0; j < Rule::points; ++j)
      sum += Rule::weights()[j] * s.f0(s.y_minus + w * (p + (Rule::nodes()[j] + 1) / 2));
  return sum * w / 2;
}

}  // namespace

TEST_CASE("static profile contact: the ellipsoid is Kalker's closed form (48)") {
  for (const double c2 : {0.02, 0.1, 0.3}) {
    const double c1 = 1.5, cl = 0.3;
    const auto k = static_line_contact(c1, c2, cl);
    for (const int n : {4, 12}) {
      const auto s = static_profile_contact(EllipsoidProfile<double>(c1, c2), cl, n);
      INFO("c2 = " << c2 << ", N = " << n << ": " << s.reason);
      REQUIRE(s.converged);
      // l/a0 = 2.9 at C2/C1 = 0.2: outside the slender domain, said so.
      CHECK(s.warnings.empty() == (k.l >= 3 * k.a0));
      CHECK(viscoroll::has_warning(s, viscoroll::WarningCode::short_contact) == !(k.l >= 3 * k.a0));
      CHECK(rel<double>(s.d, k.d) < 1e-12);
      CHECK(rel<double>(s.half_length(), k.l) < 1e-12);
      CHECK(std::abs(s.centre()) < 1e-12 * k.l);
      CHECK(rel<double>(s.a(0.0), k.a0) < 1e-12);
      CHECK(rel<double>(s.a(0.6 * k.l), k.a0 * std::sqrt(1 - 0.36)) < 1e-12);
    }
  }
}

TEST_CASE(
    "static profile contact: a tilted ellipsoid is the ellipsoid shifted (the log term on [y_-, "
    "y_+])") {
  // h = C2 y^2/2 + theta y = C2 (y + theta/C2)^2/2 - theta^2/(2 C2): the contact is Kalker's,
  // centred at -theta/C2, with d lowered by theta^2/(2 C2); only (G1)'s 16 (y_+ - y)(y - y_-)
  // gives that, since t is no longer y/l.
  const double c1 = 1, c2 = 0.1, cl = 0.3, theta = 0.02;
  const auto k = static_line_contact(c1, c2, cl);
  const auto s = static_profile_contact(Tilted(EllipsoidProfile<double>(c1, c2), theta), cl);
  REQUIRE(s.converged);
  CHECK(std::abs(s.centre() + theta / c2) < 1e-12 * k.l);
  CHECK(rel<double>(s.half_length(), k.l) < 1e-12);
  CHECK(rel<double>(s.d, k.d - theta * theta / (2 * c2)) < 1e-12);
  CHECK(rel<double>(s.a(-theta / c2), k.a0) < 1e-12);
}

TEST_CASE("static profile contact: the load (47) holds and tilt -theta mirrors tilt theta") {
  const CrownedCylinder<double> roller(1.0, 10.0, 20.0);
  const double cl = 0.3, theta = 0.003;
  const auto p = static_profile_contact(Tilted(roller, theta), cl);
  const auto m = static_profile_contact(Tilted(roller, -theta), cl);
  REQUIRE(p.converged);
  REQUIRE(m.converged);
  // The contact shifts towards the side pressed harder (y < 0 for theta > 0).
  CHECK(p.centre() < -0.05);
  CHECK(std::abs(p.y_minus + m.y_plus) < 1e-11 * p.half_length());
  CHECK(std::abs(p.y_plus + m.y_minus) < 1e-11 * p.half_length());
  CHECK(rel<double>(p.d, m.d) < 1e-12);
  CHECK(rel<double>(p.f0(-3.0), m.f0(3.0)) < 1e-10);
  for (const auto* s : {&p, &m}) CHECK(rel<double>(load_of(*s), cl) < 1e-12);
}

TEST_CASE("static profile contact: a barrel (L_f = 0) is the ellipsoid C2 = 1/R_c to (l/R_c)^2") {
  // h = y^2/(2 R_c) (1 + y^2/(4 R_c^2) + ...): the relative difference is of order (l/R_c)^2.
  const double c1 = 1, cl = 0.3;
  for (const double rc : {10.0, 40.0}) {
    const auto b = static_profile_contact(CrownedCylinder<double>(1 / c1, 0.0, rc), cl);
    const auto k = static_line_contact(c1, 1 / rc, cl);
    REQUIRE(b.converged);
    const double small = (k.l / rc) * (k.l / rc);
    INFO("R_c = " << rc << ", (l/R_c)^2 = " << small);
    CHECK(rel<double>(b.half_length(), k.l) < small);
    CHECK(rel<double>(b.half_length(), k.l) > small / 100);  // the crown is not a parabola
    CHECK(rel<double>(b.d, k.d) < small);
    CHECK(rel<double>(b.a(0.0), k.a0) < small);
  }
}

TEST_CASE("static profile contact: a long flat part carries the strip of (G1) at its local load") {
  // On the flat part (h = 0) far from its ends, (G1) reads
  //   d = F0 [1 + ln(16 (y_+ - y)(y - y_-)/a^2)] + FP[F0](y),  a^2 = 4 F0/C1 (2-D Hertz),
  // the plane strip whose far field is referred to the contact's ends; FP[F0] is the ends'
  // share, small when the flat part is long. Checked off the collocation points with FP by
  // LineOperators (an independent quadrature), and F0 nearly constant there.
  const CrownedCylinder<double> roller(1.0, 40.0, 20.0);
  const double cl = 0.3;
  const auto s = static_profile_contact(roller, cl);
  REQUIRE(s.converged);
  CHECK(s.warnings.empty());
  CHECK(s.warning_codes.empty());
  CHECK(s.y_plus > 20);  // the ends lie on the crowns
  CHECK(s.half_length() > 50 * s.a(0.0));
  const double l = s.half_length(), c = s.centre();
  const line::LineOperators<double, GaussLegendre<double, 16>> ops(l);
  const auto f0 = [&](double u) { return s.f0(u + c); };
  for (const double y : {0.0, 3.3, 7.1, -11.0}) {
    const double a = s.a(y), f = s.f0(y);
    const double fp = ops.finite_part(f0, y - c);
    const double strip = f * (1 + std::log(16 * (s.y_plus - y) * (y - s.y_minus) / (a * a)));
    INFO("y = " << y << ": FP/d = " << fp / s.d);
    CHECK(std::abs(strip + fp - s.d) < 2e-3 * s.d);  // (G1) between the points: discretisation
    CHECK(std::abs(fp) < 0.1 * s.d);
    CHECK(rel<double>(f, s.f0(0.0)) < 0.05);
  }
  // ... and peaks near the flat part's ends, above its centre value.
  CHECK(s.f0(19.5) > 1.1 * s.f0(0.0));
  CHECK(rel<double>(load_of(s), cl) < 1e-12);
}

TEST_CASE("static profile contact: logarithmic crown, body ends and bad input") {
  const double cl = 0.3;
  const auto lg = static_profile_contact(LogarithmicCrown<double>(1.0, 12.0, 0.1), cl);
  REQUIRE(lg.converged);
  CHECK(std::abs(lg.centre()) < 1e-12 * lg.half_length());
  CHECK(lg.y_plus < 6);
  CHECK(rel<double>(load_of(lg), cl) < 1e-12);
  // A roller whose crown ends at +-5.5: the contact would run beyond its body, which the line
  // theory does not describe: reported, not clipped.
  const auto e = static_profile_contact(CrownedCylinder<double>(1.0, 10.0, 20.0, 11.0), 3.0);
  CHECK_FALSE(e.converged);
  CHECK(e.code == viscoroll::StopCode::contact_reaches_body_end);
  REQUIRE(e.warnings.size() == 1);
  REQUIRE(e.warning_codes.size() == 1);
  CHECK(e.warning_codes[0] == viscoroll::WarningCode::contact_at_roller_end);
  // The warning prints where the body ends.
  CHECK(e.warnings[0].find("y_max = 5.5") != std::string::npos);
  const EllipsoidProfile<double> ell(1.0, 0.1);
  CHECK_THROWS_WITH(static_profile_contact(ell, -1.0),
                    Catch::Contains("compliance * load") && Catch::Contains("> 0"));
  CHECK_THROWS_WITH(static_profile_contact(ell, 0.3, 0), Catch::Contains("terms"));
  CHECK_THROWS_AS(static_profile_contact(ell, std::nan("")), std::invalid_argument);
}

TEST_CASE("static profile contact: off the roller's centre, and a short contact named as such") {
  // A crown of radius 2 about y = 0.04 on a body y = -0.08 ... 0.08, tabulated at 65 points (the
  // table symmetric about 0.04 on the contact): the contact sits about 0.04, clear of y = 0.
  std::vector<double> y, h;
  for (int i = 0; i <= 64; ++i) {
    y.push_back(-0.08 + 0.0025 * i);
    h.push_back((y.back() - 0.04) * (y.back() - 0.04) / 4);
  }
  const auto off = static_profile_contact(TabulatedProfile<double>(0.05, y, h), 1e-6);
  REQUIRE(off.converged);
  CHECK(std::abs(off.centre() - 0.04) <= 1e-12 * off.half_length());  // measured 5e-16
  CHECK(off.y_minus > 0);
  CHECK(off.half_length() > 3 * off.a_ref);
  // A table whose contact is about as long as it is wide (half length 1.09 half widths, far from
  // the body's ends): the line equations have no root there, which is reported as the contact's
  // shortness, not as reaching the body end.
  const auto shortc = static_profile_contact(
      TabulatedProfile<double>(0.05, {-0.08, 0, 0.01, 0.02, 0.04, 0.06, 0.07, 0.08},
                               {0.05, 0.02, 0.01, 0.003, 0, 0.003, 0.01, 0.02}),
      3.98e-6);
  INFO(shortc.reason);
  CHECK_FALSE(shortc.converged);
  CHECK(shortc.code == viscoroll::StopCode::tolerance_not_met);
  // No code says "short": the reason names the shortness (the test's point), not the body end.
  CHECK(shortc.reason.find("not slender") != std::string::npos);
  CHECK(shortc.code != viscoroll::StopCode::contact_reaches_body_end);
  CHECK(shortc.warnings.empty());
  CHECK(shortc.warning_codes.empty());
}

}  // namespace test_static_profile_contact
