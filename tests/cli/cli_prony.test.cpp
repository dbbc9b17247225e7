// viscoroll-solve with a material of model "prony" (a Prony series in relaxation form): the
// shipped prony scenes run with the bem method, and the plane and line methods solve a
// spectrum; one term equals the standard linear solid of the same relaxation form; a temperature is
// the reference material with every time multiplied by a_T; one line per (temperature, speed);
// --temperature overrides the scene's; a DMA file is fitted with its report (and a poor fit's
// warning) on stderr; malformed prony keys, temperatures and methods exit 2 naming the key, nothing
// on stdout.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/material/temperature_shift.hpp>

#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_prony {

namespace {

using namespace viscoroll::cli_test;
using nlohmann::json;

/// A prony scene on the bem method's coarse grid: three relaxation terms and a WLF shift.
json prony_scene() {
  return json::parse(R"({
    "description": "a valid prony scene, changed by each case",
    "material": {"model": "prony", "nu": 0.5, "g_inf": 2.5e6,
                 "terms": [{"g": 3.0e7, "tau": 1e-4}, {"g": 6.0e6, "tau": 1e-2},
                           {"g": 1.0e6, "tau": 1.0}],
                 "shift": {"law": "wlf", "c1": 8.86, "c2": 101.6, "t_ref": 25}},
    "roller": {"profile": "ellipsoid", "c1": 20.0, "c2": 0.5},
    "load": 100.0,
    "speeds": [0.001, 0.1],
    "method": "bem",
    "grid": 4
  })");
}

fs::path write(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

/// Every number of two result lines equal to `tolerance` relative (`skip`: keys not compared),
/// and every other field identical.
void check_same(json a, json b, double tolerance, const std::vector<std::string>& skip) {
  for (const auto& key : skip) {
    a.erase(key);
    b.erase(key);
  }
  REQUIRE(a.size() == b.size());
  for (const auto& [key, value] : a.items()) {
    INFO(key << ": " << value << " vs " << b[key]);
    REQUIRE(b.contains(key));
    if (value.is_number_float()) {
      const double x = value.get<double>(), y = b[key].get<double>();
      CHECK(std::abs(x - y) <= tolerance * std::max(std::abs(x), std::abs(y)));
    } else {
      CHECK(value == b[key]);
    }
  }
}

/// The scene's lines with the one relaxation term (mu_d/(1 + f), mu_d f/(1 + f), tau/(1 + f))
/// and with the standard linear solid of its creep form (f_1, tau_1 after the conversion),
/// `speeds` each.
using Lines = decltype(json_lines(std::string()));

std::pair<Lines, Lines> one_term_and_its_solid(const fs::path& dir, json scene,
                                               std::size_t speeds) {
  const double mu_d = 3e6, f = 9, tau = 0.01;
  const viscoroll::PronyRelaxation<double> relaxation(mu_d / (1 + f), 0.5,
                                                      {{mu_d * f / (1 + f), tau / (1 + f)}});
  const auto creep = relaxation.memory_terms();
  scene["material"] = {
      {"model", "prony"},
      {"nu", 0.5},
      {"g_inf", mu_d / (1 + f)},
      {"terms", json::array({{{"g", mu_d * f / (1 + f)}, {"tau", tau / (1 + f)}}})}};
  const Run a = run({"--scene", write(dir, "one.json", scene.dump()).string()});
  INFO("prony: " << a.out << a.err);
  CHECK(a.status == 0);
  scene["material"] = {{"model", "standard_linear_solid"},
                       {"mu_d", relaxation.glassy_modulus()},
                       {"nu", 0.5},
                       {"f", creep[0].f},
                       {"tau", creep[0].tau}};
  const Run b = run({"--scene", write(dir, "sls.json", scene.dump()).string()});
  INFO("sls: " << b.out << b.err);
  CHECK(b.status == 0);
  auto x = json_lines(a.out), y = json_lines(b.out);
  REQUIRE(x.size() == speeds);
  REQUIRE(y.size() == speeds);
  return {std::move(x), std::move(y)};
}

}  // namespace

TEST_CASE(
    "cli prony: the shipped prony scenes run with the bem method, one line per "
    "(temperature, speed)",
    "[cli][prony]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const Run r = run({"--scene", (scenes_dir() / "rubber_prony_bem.json").string()});
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.status == 0);
  const auto lines = json_lines(r.out);
  const json scene = json::parse(slurp(scenes_dir() / "rubber_prony_bem.json"));
  const auto& temperatures = scene["temperature"];
  const auto& speeds = scene["speeds"];
  CHECK(scene["material"]["terms"].size() >= 10);
  CHECK(scene["material"]["terms"].size() <= 20);
  REQUIRE(lines.size() == temperatures.size() * speeds.size());
  const viscoroll::WlfShift<double> wlf(8.86, 101.6, 25.0);
  for (std::size_t i = 0; i < temperatures.size(); ++i)
    for (std::size_t k = 0; k < speeds.size(); ++k) {
      const auto& line = lines[i * speeds.size() + k];
      CHECK(line["method"] == "bem");
      CHECK(line["temperature"].get<double>() == temperatures[i].get<double>());
      CHECK(line["a_T"].get<double>() == wlf.factor(temperatures[i].get<double>()));
      CHECK(line["speed"].get<double>() == speeds[k].get<double>());
      CHECK(line["converged"] == true);
      CHECK(!line.contains("tau"));
      for (const char* key : {"a0", "b0", "l", "d", "chi", "a_long_term"})
        CHECK(line[key].is_number());
    }
  // Warmer is softer in time (a_T < 1): at the same speed the contact is nearer the long-term one.
  CHECK(lines.back()["d"].get<double>() > lines.front()["d"].get<double>());

  // --temperature replaces the scene's list.
  const Run t = run({"--scene", (scenes_dir() / "rubber_prony_bem.json").string(), "--temperature",
                     "10,40", "--speed", "0.01"});
  INFO("stderr: " << t.err);
  CHECK(t.status == 0);
  const auto two = json_lines(t.out);
  REQUIRE(two.size() == 2);
  CHECK(two[0]["temperature"].get<double>() == 10);
  CHECK(two[1]["temperature"].get<double>() == 40);

  // The table shows the temperature and a_T.
  const Run table = run({"--scene", (scenes_dir() / "rubber_prony_bem.json").string(),
                         "--temperature", "25", "--speed", "0.01", "--format", "table"});
  CHECK(table.status == 0);
  CHECK(table.out.starts_with("T_degC"));
}

TEST_CASE("cli prony: a DMA file is fitted, its report on stderr; a poor fit is a warning",
          "[cli][prony]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const fs::path shipped = scenes_dir() / "rubber_dma_bem.json";
  const Run r = run({"--scene", shipped.string()});
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.status == 0);
  CHECK(r.err.find("material.dma = ") != std::string::npos);
  CHECK(r.err.find("fit: relative error G' max") != std::string::npos);
  CHECK(r.err.find("POOR FIT") == std::string::npos);
  const auto lines = json_lines(r.out);
  REQUIRE(lines.size() == 3);
  for (const auto& line : lines) {
    CHECK(line["temperature"].is_null());
    CHECK(line["a_T"].get<double>() == 1);
    CHECK(line["converged"] == true);
  }

  // Data no Prony series fits (the storage modulus falls with frequency): reported, and solved.
  const TempDir dir("viscoroll_cli_prony_dma");
  std::string csv = "frequency_hz,storage_pa,loss_pa\n";
  for (int k = 0; k <= 20; ++k) {
    const double f = std::pow(10.0, -2 + 0.25 * k);
    csv += exact(f) + "," + exact(1e7 / (1 + k)) + "," + exact(1e5 * (1 + (k % 3))) + "\n";
  }
  write(dir.path(), "bad.csv", csv);
  json scene = prony_scene();
  scene["material"].erase("terms");
  scene["material"].erase("g_inf");
  scene["material"].erase("shift");
  scene["material"]["dma"] = "bad.csv";
  const fs::path path = write(dir.path(), "poor.json", scene.dump());
  const Run poor = run({"--scene", path.string()});
  INFO("stdout: " << poor.out << "\nstderr: " << poor.err);
  CHECK(poor.err.find("POOR FIT") != std::string::npos);
  CHECK(poor.err.find("viscoroll-solve: warning: material.dma") != std::string::npos);
}

TEST_CASE("cli prony: one term equals the standard linear solid of the same relaxation form",
          "[cli][prony]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // The paper's material: mu_d = 3 MPa, f = 9, tau = 10 ms; relaxation form (R6a)
  // g_inf = mu_d / (1 + f), g = mu_d f / (1 + f), rho = tau / (1 + f).
  const double mu_d = 3e6, f = 9, tau = 0.01;
  const viscoroll::PronyRelaxation<double> relaxation(mu_d / (1 + f), 0.5,
                                                      {{mu_d * f / (1 + f), tau / (1 + f)}});
  const auto creep = relaxation.memory_terms();
  REQUIRE(creep.size() == 1);
  // The conversion back to the creep form is exact to an ulp or so (here: f exact, tau 1 ulp).
  CHECK(relaxation.glassy_modulus() == mu_d);
  CHECK(std::abs(creep[0].f - f) <= 4 * std::numeric_limits<double>::epsilon() * f);
  CHECK(std::abs(creep[0].tau - tau) <= 4 * std::numeric_limits<double>::epsilon() * tau);
  const TempDir dir("viscoroll_cli_prony_one");
  json scene = prony_scene();
  scene["material"] = {
      {"model", "prony"},
      {"nu", 0.5},
      {"g_inf", mu_d / (1 + f)},
      {"terms", json::array({{{"g", mu_d * f / (1 + f)}, {"tau", tau / (1 + f)}}})}};
  scene["speeds"] = {0.001, 0.1, 10.0};
  scene["grid"] = 6;
  const fs::path prony = write(dir.path(), "prony.json", scene.dump());
  const Run a = run({"--scene", prony.string()});
  INFO("prony: " << a.out << a.err);
  CHECK(a.status == 0);
  const auto x = json_lines(a.out);
  REQUIRE(x.size() == 3);
  // (1) The standard linear solid of the converted creep form (glassy modulus, f_1, tau_1): the
  // same memory term, so the same numbers, through the prony and the standard linear solid paths.
  // (2) The nominal standard linear solid (tau = 10 ms, 1 ulp from tau_1): the bem iteration
  // stops at a relative residual of 1e-10, and its iterate moves by up to 1.3e-10 relative
  // (measured, b0 at V = 0.1) when an input moves by an ulp; so 1e-9 there.
  const std::vector<std::pair<double, double>> slss = {{creep[0].tau, 1e-12}, {tau, 1e-9}};
  for (const auto& [sls_tau, tolerance] : slss) {
    scene["material"] = {{"model", "standard_linear_solid"},
                         {"mu_d", relaxation.glassy_modulus()},
                         {"nu", 0.5},
                         {"f", creep[0].f},
                         {"tau", sls_tau}};
    const fs::path sls = write(dir.path(), "sls.json", scene.dump());
    const Run b = run({"--scene", sls.string()});
    INFO("tau = " << exact(sls_tau) << ", tolerance " << tolerance << "\nsls: " << b.out << b.err);
    CHECK(b.status == 0);
    const auto y = json_lines(b.out);
    REQUIRE(y.size() == 3);
    for (std::size_t k = 0; k < x.size(); ++k) {
      CHECK(x[k]["temperature"].is_null());
      CHECK(y[k]["tau"].get<double>() == sls_tau);
      // The warnings quote V tau / (1 + f) to 15 digits; the residual is the iteration's.
      check_same(x[k], y[k], tolerance,
                 {"seconds", "temperature", "a_T", "tau", "vtau", "residual", "warnings"});
      CHECK(x[k]["warnings"].size() == y[k]["warnings"].size());
    }
  }
}

TEST_CASE(
    "cli prony: the plane method solves a spectrum; one term equals the standard linear solid",
    "[cli][prony][plane]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_prony_plane");
  json scene = prony_scene();
  scene["roller"] = {{"profile", "cylinder"}, {"radius", 0.05}};
  scene["load"] = 2000.0;
  scene["method"] = "plane";
  scene.erase("grid");
  scene["temperature"] = {0, 25};
  const Run r = run({"--scene", write(dir.path(), "plane.json", scene.dump()).string()});
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.status == 0);
  const auto lines = json_lines(r.out);
  REQUIRE(lines.size() == 4);
  for (const auto& line : lines) {
    CHECK(line["method"] == "plane");
    CHECK(line["converged"] == true);
    CHECK(line["active_terms"].get<long long>() >= 1);
    for (const char* key : {"a0", "b0", "chi", "a_long_term", "pmax", "a_T"})
      CHECK(line[key].is_number());
  }
  // Colder is stiffer in time (a_T > 1): at the same speed the contact is smaller.
  CHECK(lines[0]["a0"].get<double>() < lines[2]["a0"].get<double>());

  // One relaxation term against the standard linear solid of its creep form (f_1, tau_1): the
  // plane solver's spectrum path and its single-time closed form, (S1)-(S10) against (P1)-(P7),
  // agree to rounding (theory.md section 12; 1e-13 covers the JSON's 17 digits and the paths).
  scene.erase("temperature");
  scene["speeds"] = {0.001, 0.1, 10.0};
  const auto [x, y] = one_term_and_its_solid(dir.path(), scene, 3);
  for (std::size_t k = 0; k < x.size(); ++k) {
    check_same(x[k], y[k], 1e-13,
               {"seconds", "temperature", "a_T", "tau", "vtau", "residual", "iterations",
                "active_terms", "spectrum_error", "pmax_x"});
    // The peak's location is the root of the slope (7), whose two terms cancel as V tau/a falls:
    // it moves by about eps a/(V tau) of a (theory.md, "The plane problem"; here a/V tau <= 1e3).
    CHECK(std::abs(x[k]["pmax_x"].get<double>() - y[k]["pmax_x"].get<double>()) <=
          1e-11 * x[k]["a0"].get<double>());
  }
}

TEST_CASE("cli prony: the line method solves a spectrum; one term equals the standard linear solid",
          "[cli][prony][line]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_prony_line");
  json scene = prony_scene();
  scene["method"] = "line";
  scene.erase("grid");  // a prony material's default: 4 Chebyshev terms
  scene["temperature"] = {0, 25};
  const Run r = run({"--scene", write(dir.path(), "line.json", scene.dump()).string()});
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.status == 0);
  const auto lines = json_lines(r.out);
  REQUIRE(lines.size() == 4);
  for (const auto& line : lines) {
    CHECK(line["method"] == "line");
    CHECK(line["converged"] == true);
    CHECK(line["terms"] == 4);
    for (const char* key : {"a0", "b0", "l", "d", "chi", "a_long_term", "l0", "d0", "a_T"})
      CHECK(line[key].is_number());
    CHECK(line["a0"].get<double>() > 0);
    CHECK(line["l"].get<double>() > 0);
    CHECK_FALSE(line.contains("pmax"));  // the spectrum's line solution has no pressure
    // The load's peak along the roller, inside the contact (at 0 degC, 0.1 m/s off y = 0: the
    // contact is shorter than wide there, outside the line theory, with its warning).
    CHECK(line["f0_max"].get<double>() > 0);
    CHECK(std::abs(line["f0_max_y"].get<double>()) < line["l"].get<double>());
  }
  // Colder is stiffer in time (a_T > 1): at the same speed the contact is smaller.
  CHECK(lines[0]["a_T"].get<double>() > 1);
  CHECK(lines[0]["a0"].get<double>() < lines[2]["a0"].get<double>());

  // One relaxation term against the standard linear solid of its creep form: the spectrum path
  // of LineSolver hands one active term to the paper's theory (theory.md section 14), so the two
  // records agree to the JSON's 17 digits (1e-13 relative) where both have the field (the
  // solid's has pmax besides), the load's peak along the roller, f0_max and f0_max_y, included.
  scene.erase("temperature");
  scene["speeds"] = {0.01, 1.0};
  scene["grid"] = 6;  // the standard linear solid's default, given to both
  const auto [x, y] = one_term_and_its_solid(dir.path(), scene, 2);
  for (std::size_t k = 0; k < x.size(); ++k) {
    CHECK(x[k]["active_terms"] == 1);
    CHECK(x[k]["spectrum_error"] == 0.0);
    check_same(x[k], y[k], 1e-13,
               {"seconds", "temperature", "a_T", "tau", "vtau", "active_terms", "spectrum_error",
                "pmax", "pmax_x"});
  }
}

TEST_CASE("cli prony: a temperature is the reference material with every time times a_T",
          "[cli][prony]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_prony_shift");
  for (const double temperature : {0.0, 25.0, 60.0}) {
    json shifted = prony_scene();
    shifted["temperature"] = temperature;
    const double a_t = viscoroll::WlfShift<double>(8.86, 101.6, 25.0).factor(temperature);
    json reference = prony_scene();
    reference["material"].erase("shift");
    for (auto& term : reference["material"]["terms"]) term["tau"] = term["tau"].get<double>() * a_t;
    const fs::path p = write(dir.path(), "shifted.json", shifted.dump());
    const fs::path q = write(dir.path(), "reference.json", reference.dump());
    const Run a = run({"--scene", p.string()}), b = run({"--scene", q.string()});
    INFO("T = " << temperature << "\nshifted: " << a.out << a.err << "\nreference: " << b.out
                << b.err);
    CHECK(a.status == 0);
    CHECK(b.status == 0);
    const auto x = json_lines(a.out), y = json_lines(b.out);
    REQUIRE(x.size() == 2);
    REQUIRE(y.size() == 2);
    for (std::size_t k = 0; k < x.size(); ++k) {
      CHECK(x[k]["temperature"].get<double>() == temperature);
      CHECK(x[k]["a_T"].get<double>() == a_t);
      CHECK(y[k]["temperature"].is_null());
      check_same(x[k], y[k], 1e-12, {"seconds", "temperature", "a_T", "residual", "warnings"});
    }
  }
}

TEST_CASE("cli prony: malformed prony keys, temperatures and methods exit 2 naming the key",
          "[cli][prony]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_prony_malformed");
  struct Case {
    std::string name;
    std::function<void(json&)> change;
    std::string message;
    std::vector<std::string> options = {};
  };
  const std::vector<Case> cases = {
      {"terms_empty", set_at("/material/terms", json::array()), "material.terms is empty"},
      {"terms_object", set_at("/material/terms", json::object()),
       "material.terms must be an array of objects"},
      {"g_negative", set_at("/material/terms/1/g", -1.0),
       "material.terms[1].g = -1 is outside the valid range g >= 0"},
      {"tau_zero", set_at("/material/terms/2/tau", 0.0),
       "material.terms[2].tau = 0 is outside the valid range tau > 0"},
      {"tau_negative", set_at("/material/terms/0/tau", -1e-3),
       "material.terms[0].tau = -0.001 is outside the valid range tau > 0"},
      {"term_unknown_key", set_at("/material/terms/0/rho", 1.0),
       "unknown key material.terms[0].rho"},
      {"g_inf_zero", set_at("/material/g_inf", 0.0),
       "material.g_inf = 0 is outside the valid range g_inf > 0"},
      {"g_inf_missing", drop_at("/material/g_inf"), "missing key material.g_inf"},
      {"nu_high", set_at("/material/nu", 0.6), "material.nu = 0.6 is outside the valid range"},
      {"no_terms", drop_at("/material/terms"), "missing key material.terms (or material.dma"},
      {"terms_and_dma", set_at("/material/dma", "x.csv"),
       "material.terms and material.dma are both given"},
      {"dma_missing_file",
       [](json& s) {
         s["material"].erase("terms");
         s["material"].erase("g_inf");
         s["material"]["dma"] = "none.csv";
       },
       "material.dma = \"none.csv\""},
      {"dma_with_g_inf",
       [](json& s) {
         s["material"].erase("terms");
         s["material"]["dma"] = "x.csv";
       },
       "unknown key material.g_inf with dma"},
      {"unknown_law", set_at("/material/shift/law", "vft"),
       "material.shift.law = \"vft\" is not one of wlf, arrhenius"},
      {"wlf_c2_zero", set_at("/material/shift/c2", 0.0),
       "material.shift.c2 = 0 is outside the valid range c2 > 0"},
      {"wlf_extra_key", set_at("/material/shift/activation_energy", 1.0),
       "unknown key material.shift.activation_energy"},
      {"arrhenius_energy",
       set_at("/material/shift",
              json{{"law", "arrhenius"}, {"activation_energy", -1.0}, {"t_ref", 25.0}}),
       "material.shift.activation_energy = -1 is outside the valid range activation_energy > 0"},
      {"below_wlf_singularity", set_at("/temperature", json::array({25.0, -80.0})),
       "temperature[1] = -80 is outside the valid range temperature > t_ref - c2 = -76.6"},
      {"at_wlf_singularity", set_at("/temperature", -76.6),
       "temperature = -76.6 is outside the valid range temperature > t_ref - c2"},
      {"below_absolute_zero",
       [](json& s) {
         s["material"]["shift"] = {
             {"law", "arrhenius"}, {"activation_energy", 1.5e5}, {"t_ref", 25.0}};
         s["temperature"] = -300.0;
       },
       "temperature = -300 is outside the valid range temperature > -273.15"},
      {"temperature_string", set_at("/temperature", "warm"), "temperature must be a number"},
      {"temperature_empty", set_at("/temperature", json::array()), "temperature is empty"},
      {"temperature_without_shift",
       [](json& s) {
         s["material"].erase("shift");
         s["temperature"] = 20.0;
       },
       "temperature is given but the material has no shift law"},
      {"temperature_with_sls",
       [](json& s) {
         s["material"] = {{"model", "standard_linear_solid"},
                          {"mu_d", 3e6},
                          {"nu", 0.5},
                          {"f", 9},
                          {"tau", 0.01}};
         s["temperature"] = 20.0;
       },
       "temperature is given but the material has no shift law"},
      {"option_below_singularity",
       {},
       "--temperature: viscoroll: temperature = -90",
       {"--temperature", "-90"}},
      {"option_without_shift",
       drop_at("/material/shift"),
       "--temperature is valid only with a material of model prony with a shift law",
       {"--temperature", "20"}},
      {"option_with_sls",
       set_at("/material", json{{"model", "standard_linear_solid"},
                                {"mu_d", 3e6},
                                {"nu", 0.5},
                                {"f", 9},
                                {"tau", 0.01}}),
       "--temperature is valid only with a material of model prony with a shift law",
       {"--temperature", "20"}},
  };
  for (const auto& c : cases) {
    json scene = prony_scene();
    if (c.change) c.change(scene);
    const fs::path path = write(dir.path(), c.name + ".json", scene.dump(2));
    std::vector<std::string> args = {"--scene", path.string()};
    args.insert(args.end(), c.options.begin(), c.options.end());
    const Run r = run(args);
    INFO(c.name << ": " << scene.dump() << "\nstdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK(r.err.starts_with("viscoroll-solve: "));
  }
  // --temperature with options (a standard linear solid).
  const Run r = run({"--method", "bem", "--mu-d",        "1", "--nu", "0.5", "--f",    "1",
                     "--tau",    "1",   "--c1",          "1", "--c2", "1",   "--load", "1",
                     "--speed",  "1",   "--temperature", "20"});
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find("--temperature is valid only with --scene") != std::string::npos);
}

}  // namespace test_cli_prony
