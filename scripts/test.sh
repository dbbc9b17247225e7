#!/usr/bin/env bash
# README command 2: install the dependencies, build the release preset (warnings as errors,
# header compile tests, examples, benchmarks) and run every test, [slow] ones included.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

echo "==> [test] installing dependencies (scripts/install-deps.sh)"
bash scripts/install-deps.sh

echo "==> [test] cmake --preset release"
cmake --preset release
echo "==> [test] cmake --build --preset release"
cmake --build --preset release
echo "==> [test] ctest --preset test -j2 --output-on-failure"
ctest --preset test -j2 --output-on-failure
echo "==> [test] all tests passed"
