// libFuzzer target over viscoroll-solve's command-line parser and scene-file reader (issues 6 and
// 19). An input whose first byte is '{' is a scene file's text, read by parse_scene; any other
// input is split at NUL and newline into arguments for parse_solve_options. Every input must
// either parse or throw std::invalid_argument with a message that names viscoroll-solve (or the
// library); any other exception, crash, sanitizer report or hang is a finding. What parses is then
// checked the way the program does (method, materials, scene), which must likewise throw only
// std::invalid_argument, and a parsed scene must hold only finite values in range.
// Build and run: scripts/fuzz.sh [seconds]
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>
#include <viscoroll/material/elastic.hpp>
#include <viscoroll/material/prony.hpp>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_solver.hpp>
#include <viscoroll/roller/profile.hpp>

#include "cli/scene_file.hpp"
#include "cli/solve_options.hpp"

namespace {

void require(bool ok) {
  if (!ok) std::abort();
}

/// A parsed scene holds what the reader promised, and the program's checks throw only
/// std::invalid_argument.
void check_scene(const viscoroll::cli::Scene& s) {
  using namespace viscoroll::cli;
  require(std::isfinite(s.load) && s.load > 0);
  require(!s.speeds.empty());
  for (double v : s.speeds) require(std::isfinite(v) && v >= 0);
  require(!s.grid || (*s.grid >= 1 && *s.grid <= 512));
  double c1 = 0;
  if (const auto* e = std::get_if<EllipsoidProfile>(&s.roller)) {
    require(std::isfinite(e->c1) && e->c1 > 0 && std::isfinite(e->c2) && e->c2 > 0);
    c1 = e->c1;
  } else if (const auto* cylinder = std::get_if<CylinderProfile>(&s.roller)) {
    require(std::isfinite(cylinder->radius) && cylinder->radius > 0);
    c1 = 1 / cylinder->radius;
  } else {
    // A roller of finite length: the reader checked each number; the program builds the
    // library's profile, which may reject only with std::invalid_argument.
    std::visit(
        [&](const auto& r) {
          using R = std::decay_t<decltype(r)>;
          if constexpr (!std::is_same_v<R, EllipsoidProfile> &&
                        !std::is_same_v<R, CylinderProfile>) {
            require(std::isfinite(r.radius) && r.radius > 0 && std::abs(r.tilt) < 0.1);
            c1 = 1 / r.radius;
            try {
              if constexpr (std::is_same_v<R, CrownedProfile>)
                (void)viscoroll::Tilted(viscoroll::CrownedCylinder<double>(
                                            r.radius, r.flat_length, r.crown_radius, r.length),
                                        r.tilt);
              else if constexpr (std::is_same_v<R, LogarithmicProfile>)
                (void)viscoroll::Tilted(
                    viscoroll::LogarithmicCrown<double>(r.radius, r.length, r.scale, r.end_drop),
                    r.tilt);
              else
                (void)viscoroll::Tilted(viscoroll::TabulatedProfile<double>(r.radius, r.y, r.h),
                                        r.tilt);
            } catch (const std::invalid_argument&) {
            }
          }
        },
        s.roller);
  }
  if (const auto* m = std::get_if<ElasticModel>(&s.material)) {
    (void)viscoroll::Elastic<double>(m->mu, m->nu);
  } else if (const auto* sls = std::get_if<StandardLinearSolidModel>(&s.material)) {
    (void)viscoroll::StandardLinearSolid<double>(sls->mu_d, sls->nu, sls->f, sls->tau);
  } else {
    const auto& prony = std::get<PronyModel>(s.material);
    if (prony.dma.empty()) {  // a DMA file is read and fitted by the program, not here
      std::vector<viscoroll::RelaxationTerm<double>> terms;
      for (const auto& t : prony.terms) terms.push_back({t.g, t.tau});
      (void)viscoroll::PronyRelaxation<double>(prony.g_inf, prony.nu, terms);
    }
  }
  // Temperatures only with a shift law (the reader's promise).
  const auto* prony = std::get_if<PronyModel>(&s.material);
  require(s.temperatures.empty() || (prony != nullptr && prony->shift.has_value()));
  for (double t : s.temperatures) require(std::isfinite(t));
  for (double v : s.speeds) {
    try {
      viscoroll::PlaneScene<double>{.c1 = c1, .load = s.load, .speed = v}.validate();
    } catch (const std::invalid_argument&) {
      require(!std::isfinite(c1));  // 1/radius overflowed: the library says so
    }
  }
  for (const Method m : {Method::plane, Method::line, Method::bem}) {
    try {
      check_scene_for_method(s, m, "fuzz.json");
    } catch (const std::invalid_argument& e) {
      require(std::string_view(e.what()).starts_with("viscoroll-solve: fuzz.json: "));
    }
  }
}

void run_options(const std::string& text) {
  std::vector<std::string> storage;
  std::string current;
  for (char ch : text) {
    if (ch == '\0' || ch == '\n') {
      storage.push_back(current);
      current.clear();
    } else {
      current.push_back(ch);
    }
  }
  storage.push_back(current);
  const std::vector<std::string_view> args(storage.begin(), storage.end());
  const auto o = viscoroll::cli::parse_solve_options(args);
  if (!o.scene.empty()) return;  // the file system is not the fuzzer's to read
  require(o.method.has_value());
  require(!o.tau.empty() && !o.speeds.empty());
  for (double speed : o.speeds) {
    const viscoroll::PlaneScene<double> scene{.c1 = o.c1, .load = o.load, .speed = speed};
    scene.validate();
  }
  for (double tau : o.tau) (void)viscoroll::StandardLinearSolid<double>(o.mu_d, o.nu, o.f, tau);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    if (!text.empty() && text[0] == '{')
      check_scene(viscoroll::cli::parse_scene(text, "fuzz.json"));
    else
      run_options(text);
  } catch (const std::invalid_argument& e) {
    const std::string_view what = e.what();
    if (!what.starts_with("viscoroll")) std::abort();  // every message names its source
  }
  return 0;
}
