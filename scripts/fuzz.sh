#!/usr/bin/env bash
# Builds the libFuzzer target over viscoroll-solve's option parser and scene-file reader with clang
# (AddressSanitizer and UndefinedBehaviorSanitizer) and runs it for $1 seconds (default 30) from the
# seed corpus (tests/fuzz/corpus: option lists, and scene files, whose first byte is '{').
# nlohmann-json (nlohmann-json3-dev) is found in /usr/include.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
seconds=${1:-30}
mkdir -p build/fuzz/corpus
cp -n tests/fuzz/corpus/* build/fuzz/corpus/ 2>/dev/null || true
echo "==> [fuzz] clang++ -fsanitize=fuzzer,address,undefined tests/fuzz/fuzz_cli_parser.cpp"
clang++ -std=c++20 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -I include -I examples -I /usr/include/eigen3 -I /usr/include tests/fuzz/fuzz_cli_parser.cpp -o build/fuzz/fuzz_cli_parser
echo "==> [fuzz] running for ${seconds} s"
build/fuzz/fuzz_cli_parser -max_total_time="$seconds" -max_len=4096 -timeout=5 build/fuzz/corpus
echo "==> [fuzz] no findings"
