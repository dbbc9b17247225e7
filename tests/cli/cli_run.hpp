// Running the built viscoroll-solve from the tests of tests/cli: <build>/bin/viscoroll-solve, next
// to this executable's directory (<build>/tests). The viscoroll_cli_tests target depends on
// viscoroll_solve (examples/CMakeLists.txt); where the program is missing a test says so and does
// nothing.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace viscoroll::cli_test {

namespace fs = std::filesystem;

inline fs::path solve_program() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  return self.parent_path().parent_path() / "bin" / "viscoroll-solve";
}

/// The source tree's examples/scenes.
inline fs::path scenes_dir() { return fs::path(VISCOROLL_SOURCE_DIR) / "examples" / "scenes"; }

struct Run {
  int status;
  std::string out, err;
};

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A fresh directory under the system's temporary directory, removed with the object.
class TempDir {
 public:
  explicit TempDir(const std::string& name)
      : path_(fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

/// A shell word: `text` in single quotes.
inline std::string quote(const std::string& text) {
  std::string out = "'";
  for (const char ch : text) {
    if (ch == '\'')
      out += "'\\''";
    else
      out += ch;
  }
  return out + "'";
}

/// Runs viscoroll-solve with `args` (each one word), capturing stdout and stderr.
inline Run run(const std::vector<std::string>& args) {
  const fs::path dir = fs::temp_directory_path();
  const std::string stem = "viscoroll_cli_run_" + std::to_string(::getpid());
  const fs::path out = dir / (stem + ".out"), err = dir / (stem + ".err");
  std::string command = quote(solve_program().string());
  for (const auto& a : args) command.append(" ").append(quote(a));
  command.append(" >").append(quote(out.string())).append(" 2>").append(quote(err.string()));
  const int raw = std::system(command.c_str());
  Run r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
  fs::remove(out);
  fs::remove(err);
  return r;
}

/// Each line of `text` parsed as JSON, keys in their printed order (throws on a line that is not).
inline std::vector<nlohmann::ordered_json> json_lines(const std::string& text) {
  std::vector<nlohmann::ordered_json> out;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) out.push_back(nlohmann::ordered_json::parse(line));
  return out;
}

/// "%.17g": a double as text that reads back to the same double.
inline std::string exact(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

/// A change of a scene's JSON for the malformed-scene tables: the value at the JSON pointer
/// `pointer` (e.g. "/material/f") set to `value`.
inline std::function<void(nlohmann::json&)> set_at(const char* pointer, nlohmann::json value) {
  return [pointer, value](nlohmann::json& s) { s[nlohmann::json::json_pointer(pointer)] = value; };
}

/// A change of a scene's JSON: the key at the JSON pointer `pointer` removed.
inline std::function<void(nlohmann::json&)> drop_at(const char* pointer) {
  return [pointer](nlohmann::json& s) {
    const nlohmann::json::json_pointer p(pointer);
    s[p.parent_pointer()].erase(p.back());
  };
}

/// `args` refused as bad input: exit 2, nothing on stdout, `message` on stderr.
inline void check_refused(const std::vector<std::string>& args, const std::string& message) {
  const Run r = run(args);
  INFO(args.at(1) << "\n" << r.err);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::Contains(message));
}

/// The rows of a --profile-out file (tau, temperature, speed, y, f0, a, b, p_max): the header
/// checked, each row's eight fields (an empty cell: NaN).
inline std::vector<std::vector<double>> profile_rows(const fs::path& file) {
  std::istringstream in(slurp(file));
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "tau,temperature,speed,y,f0,a,b,p_max");
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ','))
      row.push_back(field.empty() ? std::nan("") : std::stod(field));
    if (line.back() == ',') row.push_back(std::nan(""));  // an empty last cell (p_max)
    REQUIRE(row.size() == 8);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace viscoroll::cli_test

/// Skips the test (with a warning) where viscoroll-solve was not built.
#define VISCOROLL_REQUIRE_SOLVE_PROGRAM()                                           \
  do {                                                                              \
    const auto program_ = viscoroll::cli_test::solve_program();                     \
    if (program_.empty() || !std::filesystem::exists(program_)) {                   \
      WARN("viscoroll-solve not built (" << program_                                \
                                         << "); build viscoroll_solve to run this " \
                                            "test");                                \
      return;                                                                       \
    }                                                                               \
  } while (false)
