// libFuzzer target over viscoroll-solve's command-line parser (issue 6). The input bytes are split
// at NUL and newline into arguments. Every input must either parse or throw
// std::invalid_argument with a message that names viscoroll-solve; any other exception, crash,
// sanitizer report or hang is a finding. Parsed options are then validated the way the program
// does (materials and scene), which must likewise throw only std::invalid_argument.
// Build and run: scripts/fuzz.sh [seconds]
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include <viscoroll/material/standard_linear_solid.hpp>
#include <viscoroll/plane/plane_solver.hpp>

#include "cli/solve_options.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
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
  try {
    const auto o = viscoroll::cli::parse_solve_options(args);
    const viscoroll::PlaneScene<double> scene{o.c1, o.load, o.speed};
    scene.validate();
    for (double tau : o.tau) (void)viscoroll::StandardLinearSolid<double>(o.mu_d, o.nu, o.f, tau);
  } catch (const std::invalid_argument& e) {
    const std::string_view what = e.what();
    if (!what.starts_with("viscoroll")) std::abort();  // every message names its source
  }
  return 0;
}
