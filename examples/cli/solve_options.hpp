// viscoroll-solve: command-line parsing, kept apart from main() so that tests and a fuzzer can
// drive it. Every error throws std::invalid_argument with a one-line message naming the option.
#pragma once

#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace viscoroll::cli {

enum class Method { plane, line, bem };

struct SolveOptions {
  Method method = Method::plane;
  double mu_d = 0, nu = 0, f = 0, speed = 0, c1 = 0, load = 0;
  std::optional<double> c2;
  std::vector<double> tau;   ///< one solution per value
  std::optional<long> grid;  ///< discretisation size (line: terms; bem: elements per semi-axis)
};

inline std::string usage() {
  return "usage: viscoroll-solve --method plane|line|bem --mu-d M --nu N --f F --tau T[,T...] "
         "--speed V --c1 C1 [--c2 C2] --load P [--grid N]";
}

/// A finite number, the whole of `text`.
inline double parse_number(std::string_view option, std::string_view text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value))
    throw std::invalid_argument("viscoroll-solve: " + std::string(option) + " expects a finite number, got '" +
                                std::string(text) + "'");
  return value;
}

/// Parses argv[1..]; throws std::invalid_argument on unknown, repeated, missing or malformed
/// options. Physical ranges are checked later by the library, which names the parameter.
inline SolveOptions parse_solve_options(const std::vector<std::string_view>& args) {
  static const std::set<std::string_view> known = {"--method", "--mu-d", "--nu",  "--f",    "--tau",
                                                   "--speed",  "--c1",   "--c2",  "--load", "--grid"};
  std::map<std::string_view, std::string_view> given;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string_view key = args[i], value;
    if (const auto eq = key.find('='); key.starts_with("--") && eq != std::string_view::npos) {
      value = key.substr(eq + 1);
      key = key.substr(0, eq);
    } else {
      if (!known.count(key)) throw std::invalid_argument("viscoroll-solve: unknown option '" + std::string(key) + "'; " + usage());
      if (i + 1 >= args.size()) throw std::invalid_argument("viscoroll-solve: " + std::string(key) + " needs a value");
      value = args[++i];
    }
    if (!known.count(key)) throw std::invalid_argument("viscoroll-solve: unknown option '" + std::string(key) + "'; " + usage());
    if (!given.emplace(key, value).second)
      throw std::invalid_argument("viscoroll-solve: " + std::string(key) + " given twice");
  }
  auto required = [&](std::string_view key) {
    const auto it = given.find(key);
    if (it == given.end()) throw std::invalid_argument("viscoroll-solve: missing " + std::string(key) + "; " + usage());
    return it->second;
  };
  SolveOptions o;
  const std::string_view method = required("--method");
  if (method == "plane") o.method = Method::plane;
  else if (method == "line") o.method = Method::line;
  else if (method == "bem") o.method = Method::bem;
  else throw std::invalid_argument("viscoroll-solve: --method expects plane, line or bem, got '" + std::string(method) + "'");
  o.mu_d = parse_number("--mu-d", required("--mu-d"));
  o.nu = parse_number("--nu", required("--nu"));
  o.f = parse_number("--f", required("--f"));
  o.speed = parse_number("--speed", required("--speed"));
  o.c1 = parse_number("--c1", required("--c1"));
  o.load = parse_number("--load", required("--load"));
  if (given.count("--c2")) o.c2 = parse_number("--c2", given["--c2"]);
  std::string_view taus = required("--tau");
  while (true) {
    const auto comma = taus.find(',');
    o.tau.push_back(parse_number("--tau", taus.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    taus = taus.substr(comma + 1);
  }
  if (given.count("--grid")) {
    const std::string_view text = given["--grid"];
    long n = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || n < 1)
      throw std::invalid_argument("viscoroll-solve: --grid expects a positive integer, got '" + std::string(text) + "'");
    o.grid = n;
  }
  return o;
}

}  // namespace viscoroll::cli
