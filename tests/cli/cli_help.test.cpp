// viscoroll-solve --help (-h) and --version: print to stdout and exit 0 without solving anything,
// wherever they stand among the other options; an unknown option still exits 2 with the usage.
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "cli_run.hpp"

// The file's contents live in a namespace of their own: the tests are compiled in unity batches.
namespace test_cli_help {

using namespace viscoroll::cli_test;

TEST_CASE("cli: --help and -h print the usage and exit 0", "[cli]") {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"--help"},
                                               {"-h"},
                                               {"--method", "plane", "--help"},
                                               {"--scene", "no-such-file.json", "--help"}}) {
    const Run r = run(args);
    INFO(args.front() << " ...: " << r.err);
    CHECK(r.status == 0);
    CHECK(r.out.rfind("usage: viscoroll-solve --method plane|line|bem", 0) == 0);
    CHECK(r.out.find("or: viscoroll-solve --scene FILE.json") != std::string::npos);
    CHECK(r.out.find("docs/cli.md") != std::string::npos);
    CHECK(r.err.empty());
  }
  const Run unknown = run({"--helps"});
  CHECK(unknown.status == 2);
  CHECK(unknown.out.empty());
  CHECK(unknown.err.find("unknown option '--helps'") != std::string::npos);
}

TEST_CASE("cli: --version prints the project's version and exits 0", "[cli]") {
  const Run r = run({"--version"});
  CHECK(r.status == 0);
  CHECK(r.out == std::string("viscoroll-solve ") + VISCOROLL_VERSION_STRING + "\n");
  CHECK(r.err.empty());
}

}  // namespace test_cli_help
