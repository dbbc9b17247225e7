// The input limits (include/viscoroll/input_limits.hpp, docs/errors.md "Limits"): a file that is
// not a regular one (a FIFO, /dev/zero, a directory) is refused before it is opened, a file over
// its limit before it is read (a sparse file, or a small limit injected), a scene file that is not
// UTF-8 text by name, and too many speeds in a scene file or on the command line before any is
// parsed; each by the scene reader, the DMA reader and viscoroll-solve.
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>
#include <viscoroll/input_limits.hpp>
#include <viscoroll/material/dma_fit.hpp>

#include "cli/scene_file.hpp"
#include "cli/solve_options.hpp"
#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_input_limits {

namespace {

namespace fs = std::filesystem;
using viscoroll::cli_test::TempDir;

/// The message of read_bounded_file(path, max_bytes, "test file"), or its text after "text: ".
std::string read(const fs::path& path, std::size_t max_bytes = 64) {
  try {
    return "text: " + viscoroll::detail::read_bounded_file(
                          path, max_bytes, "test file",
                          [](const std::string& m) { throw std::invalid_argument(m); });
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

/// The message `call` throws, or "" if it does not.
template <class Call>
std::string error_of(const Call& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string paper_scene(const std::string& speeds) {
  return R"({"material": {"model": "standard_linear_solid", "mu_d": 1e6, "nu": 0.5, "f": 9, )"
         R"("tau": 0.01}, "roller": {"profile": "ellipsoid", "c1": 100, "c2": 7.98}, )"
         R"("load": 10, "speeds": [)" +
         speeds + "]}";
}

/// n speeds "0.5,0.5,...".
std::string speed_list(std::size_t n) {
  std::string out;
  for (std::size_t i = 0; i < n; ++i) out += i ? ",0.5" : "0.5";
  return out;
}

}  // namespace

TEST_CASE("input limits: special files are refused before they are opened", "[cli][limits]") {
  const TempDir dir("viscoroll_input_limits");
  const fs::path fifo = dir.path() / "fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // Opened, a FIFO without a writer would block the test here.
  CHECK(read(fifo) == "is a FIFO, not a regular file (a test file must be one)");
  CHECK(read("/dev/zero") == "is a character device, not a regular file (a test file must be one)");
  CHECK(read(dir.path()) == "is a directory, not a test file");
  CHECK(read(dir.path() / "none") == "no such file");

  CHECK_THAT(error_of([&] { (void)viscoroll::cli::read_scene_file(fifo.string()); }),
             Catch::Equals("viscoroll-solve: " + fifo.string() +
                           ": is a FIFO, not a regular file (a scene file must be one)"));
  CHECK_THAT(error_of([] { (void)viscoroll::read_dma_csv_file<double>("/dev/zero"); }),
             Catch::Equals("viscoroll: DMA CSV /dev/zero: is a character device, not a regular "
                           "file (a DMA CSV file must be one)"));
  CHECK_THAT(error_of([&] { (void)viscoroll::read_dma_csv_file<double>(fifo); }),
             Catch::Contains("is a FIFO, not a regular file"));

  // The command line: exit 2 with the message, at once (a FIFO would block it forever).
  viscoroll::cli_test::check_refused({"--scene", fifo.string()}, "is a FIFO");
  viscoroll::cli_test::check_refused({"--scene", "/dev/zero"}, "is a character device");
}

TEST_CASE("input limits: a file over its limit is refused before it is read", "[cli][limits]") {
  const TempDir dir("viscoroll_input_limits_size");
  const fs::path file = dir.path() / "file";
  std::ofstream(file) << std::string(64, 'x');
  CHECK(read(file, 64) == "text: " + std::string(64, 'x'));  // at the limit: read whole
  CHECK(read(file, 63) == "size = 64 bytes is over the limit of 63 bytes for a test file");
  CHECK(viscoroll::detail::byte_size(std::size_t(3) << 20) == "3 MiB");

  // A sparse file one byte over each real limit: nothing of it is read.
  const fs::path scene = dir.path() / "big.json";
  std::ofstream(scene).close();
  fs::resize_file(scene, viscoroll::limits::scene_file_bytes + 1);
  CHECK_THAT(error_of([&] { (void)viscoroll::cli::read_scene_file(scene.string()); }),
             Catch::Equals("viscoroll-solve: " + scene.string() +
                           ": size = 1048577 bytes is over the limit of 1 MiB for a scene file"));
  const fs::path dma = dir.path() / "big.csv";
  std::ofstream(dma).close();
  fs::resize_file(dma, viscoroll::limits::dma_file_bytes + 1);
  CHECK_THAT(error_of([&] { (void)viscoroll::read_dma_csv_file<double>(dma); }),
             Catch::Contains("size = 1048577 bytes is over the limit of 1 MiB for a DMA CSV file"));
  // A DMA file within an injected limit is read as before.
  const fs::path csv = dir.path() / "small.csv";
  std::ofstream(csv) << "frequency_hz,storage_pa,loss_pa\n1,2,3\n";
  CHECK(viscoroll::read_dma_csv_file<double>(csv, {}, 38).points.size() == 1);
  CHECK_THAT(error_of([&] { (void)viscoroll::read_dma_csv_file<double>(csv, {}, 37); }),
             Catch::Contains("size = 38 bytes is over the limit of 37 bytes"));
}

TEST_CASE("input limits: a scene file that is not UTF-8 text says so", "[cli][limits]") {
  using viscoroll::cli::scene_detail::not_utf8;
  const std::string text = paper_scene("1");
  CHECK(not_utf8(text).empty());
  CHECK(not_utf8("\xEF\xBB\xBF{\"description\": \"G\xC3\xBCmmi \xE2\x82\xAC \xF0\x9F\x98\x80\"}")
            .empty());  // a UTF-8 mark, two- three- and four-byte sequences
  CHECK(not_utf8("\xFF\xFE{\0") == "a UTF-16 byte order mark");
  CHECK(not_utf8(std::string("\xFF\xFE\0\0", 4)) == "a UTF-32 byte order mark");
  CHECK(not_utf8(std::string("{\0\"", 3)) == "a NUL byte at offset 1, as in UTF-16 text");
  CHECK(not_utf8("ab\xFC") == "byte 0xfc at offset 2");        // Latin-1
  CHECK(not_utf8("a\xC0\xAF") == "byte 0xc0 at offset 1");     // overlong
  CHECK(not_utf8("\xED\xA0\x80") == "byte 0xa0 at offset 1");  // a surrogate
  CHECK(not_utf8("a\xE2\x82") == "byte 0xe2 at offset 1");     // cut short
  CHECK_THAT(error_of([] { (void)viscoroll::cli::parse_scene("\xFF\xFE{\0", "s.json"); }),
             Catch::Equals("viscoroll-solve: s.json: scene file is not UTF-8 text (a UTF-16 byte "
                           "order mark); save it as UTF-8"));
}

TEST_CASE("input limits: too many speeds are refused before they are parsed", "[cli][limits]") {
  const std::size_t limit = viscoroll::limits::speeds;
  CHECK(viscoroll::cli::parse_scene(paper_scene(speed_list(limit)), "s.json").speeds.size() ==
        limit);
  CHECK_THAT(error_of([&] {
               (void)viscoroll::cli::parse_scene(paper_scene(speed_list(limit + 1)), "s.json");
             }),
             Catch::Equals("viscoroll-solve: s.json: speeds has 100001 values, over the limit of "
                           "100000 (docs/errors.md, \"Limits\")"));
  // The command line's --speed (too long for one argument of a real command line: 128 kB).
  const std::string list = speed_list(limit + 1);
  const std::vector<std::string_view> args = {"--method", "plane", "--mu-d",  "1", "--nu", "0.5",
                                              "--f",      "9",     "--tau",   "1", "--c1", "1",
                                              "--load",   "1",     "--speed", list};
  CHECK_THAT(error_of([&] { (void)viscoroll::cli::parse_solve_options(args); }),
             Catch::Equals("viscoroll-solve: --speed has 100001 values, over the limit of 100000 "
                           "(docs/errors.md, \"Limits\")"));
  const std::string within = speed_list(limit);
  std::vector<std::string_view> ok = args;
  ok.back() = within;
  CHECK(viscoroll::cli::parse_solve_options(ok).speeds.size() == limit);
}

}  // namespace test_input_limits
