// Property test of the boundary-element solver: random scenes, materials (standard
// linear solid, generalised Maxwell with 0-3 terms, elastic) and options, inside and outside the
// valid ranges. Each ends in
//   - std::invalid_argument whose message names one of the parameters drawn invalid (and a scene
//     drawn entirely valid is never rejected), or
//   - a converged solution that satisfies the invariants below, or
//   - a solution reported converged == false with a non-empty reason (no invariant claimed),
// none in NaN, a crash or a hang. Fixed seeds: reproducible (the trial number is in every
// failure message).
//
// Invariants of a converged solution:
//   - every reported number finite (d, a0, b0, l, chi, load, residual, every cell's p and g);
//   - p >= 0 in every cell (exactly: the active set is the set of cells with p > 0 when it stops
//     changing), and at least one cell in contact;
//   - the total load hx hy sum p equals the scene's load to the GMRES tolerance (the load is a row
//     of the bordered system, docs/bem.md B11);
//   - the gap: g >= 0 outside the contact and |g| small in it (BemSolution::residual, relative to
//     the Hertz penetration), to the same tolerance;
//   - l > 0, a0 > 0 (the trailing edge b0 - a0 behind the leading edge b0 + a0);
//   - d between the instantaneous (glassy) and the long-term Hertz penetrations, to the
//     discretisation error of the grid.
#include <boost/math/special_functions/fpclassify.hpp>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>
#include <viscoroll/bem/bem_solver.hpp>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/generalized_maxwell.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_bem_property {

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool sanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool sanitized = true;
#else
constexpr bool sanitized = false;
#endif
#else
constexpr bool sanitized = false;
#endif
#ifdef NDEBUG
constexpr bool optimised = !sanitized;
#else
constexpr bool optimised = false;
#endif

bool finite(double x) { return (boost::math::isfinite)(x); }

/// The exception names one of `bad` in the library's form "viscoroll: <name> = <value> ...".
bool names_one_of(const std::string& what, const std::vector<std::string>& bad) {
  for (const auto& name : bad)
    if (what.find("viscoroll: " + name + " = ") != std::string::npos) return true;
  return false;
}

struct Tally {
  int solved = 0, not_converged = 0, rejected = 0;
  double worst_seconds = 0, worst_load = 0, worst_residual = 0, worst_d_excess = 0;
  std::string failures;  ///< not converged with the default iteration limits: trial and reason
};

/// Solves and checks one case; `bad` lists the parameters drawn invalid.
template <class Material>
void solve_and_check(const Material& material, const viscoroll::BemOptions& options,
                     const viscoroll::BemScene<double>& scene, double instantaneous_compliance,
                     const std::vector<std::string>& bad, const std::string& description,
                     Tally& tally) {
  const double eps = std::numeric_limits<double>::epsilon();
  const auto t0 = std::chrono::steady_clock::now();
  const viscoroll::BemSolver<double, Material> solver(material, options);
  const auto s = solver.solve(scene);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  tally.worst_seconds = std::max(tally.worst_seconds, seconds);
  CHECK(seconds < 120);  // no hang: a solve at grid <= 8 takes a fraction of a second
  REQUIRE(bad.empty());  // a scene with an invalid parameter must have been rejected
  INFO("reason: " << s.reason << ", residual " << s.residual << ", iterations " << s.iterations
                  << ", krylov " << s.krylov_iterations << ", cells in contact "
                  << s.contact_cells);
  REQUIRE_FALSE(s.reason.empty());
  // The warnings and their codes, index for index (core/outcome.hpp); converged exactly when
  // the code says so.
  CHECK(s.warning_codes.size() == s.warnings.size());
  CHECK(s.converged == (s.code == viscoroll::StopCode::converged));
  if (!s.converged) {
    ++tally.not_converged;
    const viscoroll::BemOptions defaults;
    if (options.max_active_set_iterations == defaults.max_active_set_iterations &&
        options.max_krylov_iterations == defaults.max_krylov_iterations)
      tally.failures += "\n  not converged at the default limits: " + description + ": " + s.reason;
    return;
  }
  ++tally.solved;
  REQUIRE(finite(s.d));
  REQUIRE(finite(s.a0));
  REQUIRE(finite(s.b0));
  REQUIRE(finite(s.l));
  REQUIRE(finite(s.chi));
  REQUIRE(finite(s.load));
  REQUIRE(finite(s.residual));
  REQUIRE(s.contact_cells > 0);
  // p >= 0 everywhere, finite; the load, recomputed.
  REQUIRE(s.pressure.size() == s.grid.size());
  REQUIRE(s.gap.size() == s.grid.size());
  double sum = 0;
  int negative = 0, not_finite = 0;
  for (std::size_t q = 0; q < s.pressure.size(); ++q) {
    if (!finite(s.pressure[q]) || !finite(s.gap[q])) ++not_finite;
    if (s.pressure[q] < 0) ++negative;
    sum += s.pressure[q];
  }
  CHECK(not_finite == 0);
  CHECK(negative == 0);
  // The load row of the bordered system, d_ref area sum p / P = d_ref, is one of na + 1 rows whose
  // residual GMRES brings below tol ||b||, ||b|| <= sqrt(na + 1) max(max |h|, d_ref) with
  // max |h| over the contact ~ d_ref: relative error <= tol sqrt(na + 1) up to that factor of
  // order one; bound 4 tol sqrt(na + 1), tol = max(options.gmres_tolerance, 32 eps).
  const double tol = std::max(options.gmres_tolerance, 32 * eps);
  const double bound = 4 * tol * std::sqrt(s.contact_cells + 1.0);
  const double load_error = std::abs(s.grid.hx * s.grid.hy * sum / scene.load - 1);
  tally.worst_load = std::max(tally.worst_load, load_error / bound);
  CHECK(load_error <= bound);
  CHECK(std::abs(s.load / scene.load - 1) <= bound);
  // The complementarity violation (gap in and out of contact, relative to d) meets the same bound.
  tally.worst_residual = std::max(tally.worst_residual, s.residual / bound);
  CHECK(s.residual <= bound);
  // The contact: l > 0, a0 > 0, trailing edge behind leading edge.
  CHECK(s.l > 0);
  CHECK(s.a0 > 0);
  CHECK(s.b0 - s.a0 < s.b0 + s.a0);
  // d between the glassy and the long-term Hertz penetrations: the compliance acting lies between
  // the instantaneous c and the long-term (1 + f) c. Discretisation: |d - d_H| / d_H <= (h/a)^2 / 5
  // with h/a the cell over the semi-axis in contact (tests/bem/bem_solver.test.cpp), h/a <= 1/grid
  // for the long-term contact and <= (1 + f)^(1/3) / grid for the glassy one; bound (h/a)^2.
  const auto glassy =
      viscoroll::bem::hertz_contact(scene.c1, scene.c2, instantaneous_compliance, scene.load);
  const double n = options.grid;
  const double ha_long = 1 / n,
               ha_glassy = std::cbrt(s.long_term.a * s.long_term.b / (glassy.a * glassy.b)) / n;
  INFO("d " << s.d << ", long-term Hertz d " << s.long_term.d << ", glassy Hertz d " << glassy.d);
  CHECK(s.d <= s.long_term.d * (1 + ha_long * ha_long));
  CHECK(s.d >= glassy.d * (1 - ha_glassy * ha_glassy));
  tally.worst_d_excess =
      std::max({tally.worst_d_excess, (s.d / s.long_term.d - 1) / (ha_long * ha_long),
                (1 - s.d / glassy.d) / (ha_glassy * ha_glassy)});
}

void run_bem_cases(int count, std::uint64_t seed, int max_grid, Tally& tally) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const double nan = std::numeric_limits<double>::quiet_NaN(),
               inf = std::numeric_limits<double>::infinity();
  const double pi = std::acos(-1.0);
  auto log_uniform = [&](double lo_exp, double hi_exp) {
    return std::pow(10.0, lo_exp + (hi_exp - lo_exp) * unit(rng));
  };
  auto pick = [&](std::initializer_list<double> values) {
    const auto i = static_cast<std::size_t>(unit(rng) * static_cast<double>(values.size()));
    return *(values.begin() + std::min(i, values.size() - 1));
  };
  // Each parameter is drawn invalid with probability 1/20: about half the scenes are valid.
  auto invalid = [&] { return unit(rng) < 1.0 / 20; };

  for (int trial = 0; trial < count; ++trial) {
    std::vector<std::string> bad;
    // The material: 70% standard linear solid, 20% generalised Maxwell (0-3 terms), 10% elastic.
    const double kind = unit(rng);
    const double mu_d =
        invalid() ? (bad.push_back(kind < 0.9 ? "mu_d" : "mu"), pick({0.0, -1.0, nan, inf, -inf}))
                  : log_uniform(-6, 9);
    const double nu = invalid() ? (bad.push_back("nu"), pick({0.75, -1.0, 0.5000001, nan, inf}))
                                : (unit(rng) < 0.1 ? 0.5 : -0.99 + 1.49 * unit(rng));
    std::vector<viscoroll::PronyTerm<double>> terms;
    const int nterms = kind < 0.7 ? 1 : kind < 0.9 ? static_cast<int>(4 * unit(rng)) : 0;
    double tau_max = 0;
    for (int k = 0; k < nterms; ++k) {
      const std::string fk = kind < 0.7 ? "f" : "f[" + std::to_string(k) + "]";
      const std::string tk = kind < 0.7 ? "tau" : "tau[" + std::to_string(k) + "]";
      const double fv = invalid() ? (bad.push_back(fk), pick({-1e-3, -1.0, nan, inf, -inf}))
                                  : (unit(rng) < 0.1 ? 0.0 : log_uniform(-3, 4));
      const double tv = invalid() ? (bad.push_back(tk), pick({-1.0, nan, inf, -inf}))
                                  : (unit(rng) < 0.05 ? 0.0 : log_uniform(-6, 4));
      terms.push_back({fv, tv});
      if (tv > tau_max) tau_max = tv;
    }
    const double c1 =
        invalid() ? (bad.push_back("c1"), pick({0.0, -1.0, nan, inf})) : log_uniform(-3, 3);
    // C2/C1 mostly 1e-3 .. 1e3, one in ten over the whole supported range 1e-10 .. 1e10.
    double c2 = c1 * (unit(rng) < 0.1 ? log_uniform(-9.9, 9.9) : log_uniform(-3, 3));
    if (invalid()) {
      const double v = pick({0.0, -1.0, nan, inf, 1e-11, 1e11});
      bad.push_back(v > 0 && v < inf ? "c2/c1" : "c2");
      c2 = v > 0 && v < inf ? v * c1 : v;
    }
    const double load =
        invalid() ? (bad.push_back("load"), pick({0.0, -1.0, nan, inf})) : log_uniform(-6, 6);
    viscoroll::BemOptions options;
    options.grid = unit(rng) < 0.1 ? 2 + static_cast<int>(2 * unit(rng))
                                   : 4 + static_cast<int>((max_grid - 3) * unit(rng));
    if (invalid()) {
      bad.push_back("grid");
      options.grid = static_cast<int>(pick({1.0, 0.0, -4.0, 4097.0}));
    }
    options.extent = unit(rng) < 0.8 ? 1.6 : 1.6 + 1.4 * unit(rng);
    if (invalid()) {
      bad.push_back("extent");
      options.extent = pick({1.0, 1.59, 65.0, nan, inf});
    }
    options.gmres_tolerance = unit(rng) < 0.7 ? 1e-10 : log_uniform(-14, -4);
    if (invalid()) {
      bad.push_back("gmres_tolerance");
      options.gmres_tolerance = pick({0.0, 1e-16, 1e-2, nan, -1e-10});
    }
    options.max_active_set_iterations = unit(rng) < 0.9 ? 200 : 1 + static_cast<int>(3 * unit(rng));
    if (invalid()) {
      bad.push_back("max_active_set_iterations");
      options.max_active_set_iterations = static_cast<int>(pick({0.0, -1.0, 100001.0}));
    }
    options.max_krylov_iterations = unit(rng) < 0.9 ? 5000 : 1 + static_cast<int>(40 * unit(rng));
    if (invalid()) {
      bad.push_back("max_krylov_iterations");
      options.max_krylov_iterations = static_cast<int>(pick({0.0, -1.0}));
    }
    options.restart = unit(rng) < 0.9 ? 80 : 2 + static_cast<int>(10 * unit(rng));
    if (invalid()) {
      bad.push_back("restart");
      options.restart = static_cast<int>(pick({1.0, 0.0, 1001.0}));
    }
    options.precondition = unit(rng) < 0.9;
    // Speed: V tau_max / a_H from 1e-4 to 1e4 (a_H the long-term static Hertz semi-axis along x),
    // or 0.
    double speed = log_uniform(-3, 3);
    if (bad.empty() && tau_max > 0) {
      double f_total = 0;
      for (const auto& t : terms) f_total += t.f;
      const double c = (1 - nu) / (2 * pi * mu_d);
      speed = log_uniform(-4, 4) *
              viscoroll::bem::hertz_contact(c1, c2, (1 + f_total) * c, load).a / tau_max;
    }
    if (unit(rng) < 0.05) speed = 0;
    if (invalid()) {
      bad.push_back("speed");
      speed = pick({-1.0, -1e-300, nan, inf, -inf});
    }
    const viscoroll::BemScene<double> scene{c1, c2, load, speed};
    std::string terms_text;
    for (const auto& t : terms)
      terms_text += " (" + std::to_string(t.f) + ", " + std::to_string(t.tau) + ")";
    std::ostringstream description;
    description << "trial " << trial << ": "
                << (kind < 0.7   ? "sls"
                    : kind < 0.9 ? "maxwell"
                                 : "elastic")
                << " mu_d " << mu_d << " nu " << nu << " terms" << terms_text << " c1 " << c1
                << " c2 " << c2 << " load " << load << " speed " << speed << "; grid "
                << options.grid << " extent " << options.extent << " gmres_tolerance "
                << options.gmres_tolerance << " max_active_set "
                << options.max_active_set_iterations << " max_krylov "
                << options.max_krylov_iterations << " restart " << options.restart
                << " precondition " << options.precondition;
    INFO(description.str() << "; invalid: " << bad.size());
    try {
      const double c = (1 - nu) / (2 * pi * mu_d);
      if (kind < 0.7) {
        solve_and_check(viscoroll::StandardLinearSolid<double>(mu_d, nu, terms[0].f, terms[0].tau),
                        options, scene, c, bad, description.str(), tally);
      } else if (kind < 0.9) {
        solve_and_check(viscoroll::GeneralizedMaxwell<double>(mu_d, nu, terms), options, scene, c,
                        bad, description.str(), tally);
      } else {
        solve_and_check(viscoroll::Elastic<double>(mu_d, nu), options, scene, c, bad,
                        description.str(), tally);
      }
    } catch (const std::invalid_argument& e) {
      ++tally.rejected;
      INFO("message: " << e.what());
      CHECK_FALSE(bad.empty());  // a valid scene must not be rejected
      CHECK(names_one_of(e.what(), bad));
      CHECK(std::string(e.what()).find("outside the valid range") != std::string::npos);
    }
  }
}

void report(const Tally& t, int count) {
  WARN("bem property: " << count << " scenes: " << t.solved << " converged, " << t.not_converged
                        << " reported not converged, " << t.rejected << " rejected; slowest solve "
                        << t.worst_seconds << " s; worst load error / bound " << t.worst_load
                        << ", residual / bound " << t.worst_residual << ", d excess / (h/a)^2 "
                        << t.worst_d_excess << t.failures);
}

}  // namespace

TEST_CASE("bem: random scenes end in a valid solution, a reported failure or a clear error",
          "[bem][property]") {
  Tally tally;
  const int count = 30;
  run_bem_cases(count, 20261125, 8, tally);
  report(tally, count);
  CHECK(tally.solved > 5);
  CHECK(tally.rejected > 5);
}

TEST_CASE("bem: many random scenes end in a valid solution, a reported failure or a clear error",
          "[bem][property][slow]") {
  // 2000 scenes in an optimised build (about a minute on one core); 200 under the sanitizers or
  // without optimisation.
  Tally tally;
  const int count = optimised ? 2000 : 200;
  run_bem_cases(count, 20261126, 8, tally);
  report(tally, count);
  CHECK(tally.solved > count / 4);
  CHECK(tally.rejected > count / 4);
}

TEST_CASE("bem: a user profile that is not finite at a cell centre is rejected",
          "[bem][property]") {
  // A NaN gap is never negative, so before the check a profile NaN outside the contact gave a
  // converged solution with NaN gaps (and a residual that skipped them).
  const viscoroll::BemOptions options{.grid = 6};
  const viscoroll::BemSolverD solver(viscoroll::StandardLinearSolid<double>(1, 0.5, 9, 1), options);
  const double nan = std::numeric_limits<double>::quiet_NaN(),
               inf = std::numeric_limits<double>::infinity();
  for (const double bad : {nan, inf, -inf}) {
    viscoroll::BemScene<double> scene{1.0, 0.5, 1.0, 0.5};
    scene.profile = [bad](double x, double y) {
      const double h = x * x / 2 + y * y / 4;
      return h > 3 ? bad : h;
    };
    INFO("profile value " << bad << " where h > 3");
    CHECK_THROWS_WITH(solver.solve(scene),
                      Catch::Contains("viscoroll: profile(x, y) = ") &&
                          Catch::Contains("outside the valid range finite at every cell centre"));
  }
  viscoroll::BemScene<double> scene{1.0, 0.5, 1.0, 0.5};
  scene.profile = [](double x, double y) { return x * x / 2 + y * y / 4; };
  const auto s = solver.solve(scene);
  CHECK(s.converged);
}

}  // namespace test_bem_property
