// viscoroll-solve's other outputs: --csv writes a CSV whose rows are the JSON lines' numbers and
// booleans; --format table prints a header and one row per speed; --plot writes sweep.csv and,
// with gnuplot on PATH, sweep.png.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_outputs {

namespace {

using namespace viscoroll::cli_test;

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, separator)) out.push_back(cell);
  if (!line.empty() && line.back() == separator) out.emplace_back();
  return out;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

/// The CSV `text` matches the JSON lines `json`: the header is their number and boolean fields
/// in order, and each cell is the field's value (empty for null).
void check_csv_matches(const std::string& text, const std::vector<nlohmann::ordered_json>& json) {
  const auto rows = lines_of(text);
  REQUIRE(rows.size() == json.size() + 1);
  const auto header = split(rows[0], ',');
  std::vector<std::string> expected;
  for (const auto& [key, value] : json[0].items())
    if (value.is_number() || value.is_boolean() || value.is_null()) expected.push_back(key);
  CHECK(header == expected);
  for (std::size_t k = 0; k < json.size(); ++k) {
    const auto cells = split(rows[k + 1], ',');
    REQUIRE(cells.size() == header.size());
    for (std::size_t c = 0; c < header.size(); ++c) {
      const auto& value = json[k][header[c]];
      INFO("row " << k << ", " << header[c] << " = " << cells[c]);
      if (value.is_null())
        CHECK(cells[c].empty());
      else if (value.is_boolean())
        CHECK(cells[c] == (value.get<bool>() ? "true" : "false"));
      else
        CHECK(std::strtod(cells[c].c_str(), nullptr) == value.get<double>());
    }
  }
}

}  // namespace

TEST_CASE("cli: --csv writes the sweep as CSV matching the JSON lines", "[cli][scene]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_csv");
  for (const char* scene : {"rubber_roller.json", "polyamide_cylinder.json"}) {
    const std::string csv = (dir.path() / "sweep.csv").string();
    const Run r = run({"--scene", (scenes_dir() / scene).string(), "--csv", csv});
    INFO(scene << "\nstdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.status == 0);
    const auto json = json_lines(r.out);
    REQUIRE(!json.empty());
    check_csv_matches(slurp(csv), json);
  }
  const Run bad = run({"--scene", (scenes_dir() / "paper.json").string(), "--csv",
                       (dir.path() / "no" / "such" / "dir.csv").string()});
  CHECK(bad.status == 2);
  CHECK(bad.out.empty());
  CHECK(bad.err.find("--csv") != std::string::npos);
}

TEST_CASE("cli: --format table prints a header and a row per speed", "[cli][scene]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  struct Case {
    std::string scene, method, header;
  };
  const std::vector<Case> cases = {
      {"rubber_roller.json", "line", "tau speed Vtau/a_lt a0 b0 l d chi F_N P_W converged"},
      {"rubber_ball.json", "bem", "tau speed Vtau/a_lt a0 b0 l d chi F_N P_W converged"},
      {"polyamide_cylinder.json", "plane", "tau speed Vtau/a_lt a0 b0 chi F_N/m P_W/m converged"},
  };
  for (const auto& c : cases) {
    const Run json = run({"--scene", (scenes_dir() / c.scene).string(), "--method", c.method});
    const Run table = run(
        {"--scene", (scenes_dir() / c.scene).string(), "--method", c.method, "--format", "table"});
    INFO(c.scene << "\n" << table.out << "\nstderr: " << table.err);
    CHECK(table.status == 0);
    const auto values = json_lines(json.out);
    const auto rows = lines_of(table.out);
    REQUIRE(rows.size() == values.size() + 1);
    std::istringstream words(rows[0]);
    std::string word, header;
    while (words >> word) {
      if (!header.empty()) header += ' ';
      header += word;
    }
    CHECK(header == c.header);
    const auto columns = split(c.header, ' ');
    for (std::size_t k = 0; k < values.size(); ++k) {
      std::istringstream cells(rows[k + 1]);
      std::vector<std::string> row;
      while (cells >> word) row.push_back(word);
      REQUIRE(row.size() == columns.size());
      CHECK(std::strtod(row[1].c_str(), nullptr) == Approx(values[k]["speed"].get<double>()));
      if (values[k]["converged"].get<bool>())
        CHECK(std::strtod(row[3].c_str(), nullptr) ==
              Approx(values[k]["a0"].get<double>()).epsilon(1e-6));
      else
        CHECK(row[3] == "-");
      const bool minimum = values[k].contains("root") && !values[k]["root"].get<bool>();
      CHECK(row.back() == (!values[k]["converged"].get<bool>() ? "no" : minimum ? "min" : "yes"));
    }
  }
}

TEST_CASE("cli: --plot writes sweep.csv and, with gnuplot, sweep.png", "[cli][scene]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  const TempDir dir("viscoroll_cli_plot");
  const fs::path out = dir.path() / "plot";
  const Run r =
      run({"--scene", (scenes_dir() / "rubber_ball.json").string(), "--plot", out.string()});
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find("--plot needs gnuplot on PATH") != std::string::npos);
    return;
  }
  CHECK(r.status == 0);
  check_csv_matches(slurp(out / "sweep.csv"), json_lines(r.out));
  CHECK(fs::exists(out / "sweep.png"));
  CHECK(fs::file_size(out / "sweep.png") > 1000);
}

TEST_CASE("cli: the line method's slow-regime options are passed and validated", "[cli][line]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // The slow-regime scene (V tau ~ 0.01 a0): the least-squares fit over twice the points
  // in the mapped variable (docs/line-solver.md, "Oversampling") converges and satisfies the load.
  const std::vector<std::string> scene = {"--method", "line",
                                          "--mu-d",   "0.8039135086325981",
                                          "--nu",     "0.30003219277831694",
                                          "--f",      "2.785164659360882",
                                          "--speed",  "0.23336242599102316",
                                          "--c1",     "20.762562182128647",
                                          "--load",   "23.306722647201934",
                                          "--c2",     "0.681408522179955",
                                          "--tau",    "0.004466981994343957",
                                          "--grid",   "6"};
  std::vector<std::string> args = scene;
  for (const char* extra : {"--oversampling", "2", "--basis", "mapped", "--max-iterations", "1000"})
    args.push_back(extra);
  const Run r = run(args);
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.status == 0);
  const auto lines = json_lines(r.out);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0]["converged"] == true);
  CHECK(lines[0]["l"].get<double>() > 0);
  // The options differ from the defaults' result (a different discretisation).
  const auto plain = json_lines(run(scene).out);
  REQUIRE(plain.size() == 1);
  CHECK(plain[0]["l"].get<double>() != lines[0]["l"].get<double>());
  // Out of range or unknown: exit 2 naming the option; other methods do not take them.
  struct Bad {
    std::vector<std::string> extra;
    std::string message;
  };
  for (const Bad& b :
       std::vector<Bad>{{{"--oversampling", "9"}, "--oversampling"},
                        {{"--basis", "chebyshev"}, "--basis"},
                        {{"--max-iterations", "0"}, "--max-iterations"},
                        {{"--quadrature-tolerance", "1e-3"}, "--quadrature-tolerance"},
                        {{"--quadrature-tolerance", "-1"}, "--quadrature-tolerance"}}) {
    std::vector<std::string> bad = scene;
    bad.insert(bad.end(), b.extra.begin(), b.extra.end());
    const Run e = run(bad);
    INFO(b.message << ": " << e.err);
    CHECK(e.status == 2);
    CHECK(e.out.empty());
    CHECK(e.err.find(b.message) != std::string::npos);
  }
  const Run plane = run({"--method", "plane", "--mu-d", "1", "--nu", "0.5", "--f", "9", "--tau",
                         "1", "--speed", "1", "--c1", "1", "--load", "1", "--oversampling", "2"});
  CHECK(plane.status == 2);
  CHECK(plane.err.find("--oversampling") != std::string::npos);
}

TEST_CASE("cli: the line method's quadrature tolerance", "[cli][line]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // Integrals to 1e-8 instead of rounding: the same contact to the bound of docs/performance.md
  // ("The fast setting": 1e-12 on the paper's scene; 1e-10 allows a hundredfold), a different
  // computation (the digits are not all equal).
  const std::vector<std::string> scene = {
      "--method", "line",  "--mu-d", "1", "--nu", "0.5",    "--f",    "9", "--tau",  "1",
      "--speed",  "0.3,3", "--c1",   "1", "--c2", "0.0798", "--load", "1", "--grid", "4"};
  std::vector<std::string> args = scene;
  for (const char* extra : {"--quadrature-tolerance", "1e-8"}) args.push_back(extra);
  const auto exact = json_lines(run(scene).out);
  const auto loose = json_lines(run(args).out);
  REQUIRE(exact.size() == 2);
  REQUIRE(loose.size() == 2);
  bool differs = false;
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK(loose[i]["converged"] == true);
    for (const char* key : {"a0", "b0", "l", "d", "chi"}) {
      const double x = loose[i][key].get<double>(), y = exact[i][key].get<double>();
      CAPTURE(i, key, x, y);
      CHECK(std::abs(x - y) <= 1e-10 * std::abs(y));
      differs = differs || x != y;
    }
  }
  CHECK(differs);
}

TEST_CASE("cli: a result that did not converge shows no numbers in the table and the CSV",
          "[cli]") {
  VISCOROLL_REQUIRE_SOLVE_PROGRAM();
  // The paper's scene by the line method with one iteration allowed: not converged (exit 1).
  const TempDir dir("viscoroll_cli_not_converged");
  const std::string csv = (dir.path() / "sweep.csv").string();
  const std::vector<std::string> scene = {
      "--scene", (scenes_dir() / "paper.json").string(), "--speed", "0.5", "--max-iterations", "1"};
  auto args = scene;
  args.insert(args.end(), {"--format", "table", "--csv", csv});
  const Run table = run(args);
  const Run json = run(scene);
  INFO(table.out << "\nstderr: " << table.err);
  CHECK(table.status == 1);
  const auto values = json_lines(json.out);
  REQUIRE(values.size() == 1);
  REQUIRE(!values[0]["converged"].get<bool>());
  CHECK(values[0]["a0"].is_number());  // JSON keeps its fields, with the reason
  CHECK(!values[0]["reason"].get<std::string>().empty());
  CHECK(values[0]["code"] == "iteration_limit");
  // The table row: tau, speed, Vtau/a_lt, then a0 b0 l d chi F_N P_W as "-", then "no".
  const auto rows = lines_of(table.out);
  REQUIRE(rows.size() == 2);
  std::istringstream cells(rows[1]);
  std::vector<std::string> row;
  for (std::string word; cells >> word;) row.push_back(word);
  REQUIRE(row.size() == 11);
  for (std::size_t k = 3; k < 10; ++k) CHECK(row[k] == "-");
  CHECK(row[10] == "no");
  // The CSV row: empty solution cells, the speed and the diagnostics kept.
  std::istringstream file(slurp(csv));
  std::string header, line;
  std::getline(file, header);
  std::getline(file, line);
  const auto keys = split(header, ',');
  const auto fields = split(line, ',');
  REQUIRE(keys.size() == fields.size());
  for (std::size_t k = 0; k < keys.size(); ++k) {
    INFO(keys[k] << " = '" << fields[k] << "'");
    if (keys[k] == "a0" || keys[k] == "b0" || keys[k] == "l" || keys[k] == "d" ||
        keys[k] == "chi" || keys[k] == "rolling_resistance" || keys[k] == "power_loss" ||
        keys[k] == "energy_per_revolution" || keys[k] == "pmax")
      CHECK(fields[k].empty());
    if (keys[k] == "speed" || keys[k] == "iterations" || keys[k] == "a_long_term")
      CHECK(!fields[k].empty());
    if (keys[k] == "converged") CHECK(fields[k] == "false");
  }
}

}  // namespace test_cli_outputs
