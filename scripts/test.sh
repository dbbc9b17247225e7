#!/usr/bin/env bash
# README command 2: install the dependencies, build the release preset (warnings as errors) and run
# every test, [slow] ones included. It builds the target viscoroll_check: the tests, the programs
# they run (examples), the header compile tests and the compiled library, not the benchmarks
# (`cmake --build --preset release --target viscoroll_benchmarks`; docs/building.md).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

echo "==> [test] installing dependencies (scripts/install-deps.sh)"
bash scripts/install-deps.sh

echo "==> [test] cmake --preset release"
cmake --preset release
echo "==> [test] cmake --build --preset release --target viscoroll_check"
cmake --build --preset release --target viscoroll_check
echo "==> [test] ctest --preset test -j2 --output-on-failure"
ctest --preset test -j2 --output-on-failure
echo "==> [test] all tests passed"
