#!/usr/bin/env bash
# clang-tidy (.clang-tidy: bugprone-*, performance-*) over the project's translation units,
# using the compile database of the debug preset (configured here if needed).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

if [ ! -f build/debug/compile_commands.json ]; then
  echo "==> [tidy] cmake --preset debug"
  cmake --preset debug
fi
run_clang_tidy=${RUN_CLANG_TIDY:-run-clang-tidy-14}
echo "==> [tidy] $run_clang_tidy -p build/debug"
"$run_clang_tidy" -quiet -p build/debug "$PWD/(tests|examples|benchmarks|build/debug/header_checks)/.*\\.cpp$"
