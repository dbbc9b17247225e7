#!/usr/bin/env bash
# Regenerates the error-against-run-time report of docs/performance.md: builds the report
# program benchmarks/error_vs_time.cpp with the release preset, runs it on the paper's scene
# (V tau/a0 = 0.1, 1, 10; line solver terms 2 ... 32, BEM N = 4 ... 64, one core) and plots
# docs/figures/error_vs_time.png from docs/figures/error_vs_time.csv (summary in
# docs/figures/error_vs_time.txt). Takes 2-4 minutes. Extra arguments go to the program, e.g.
#   scripts/error_vs_time.sh --speeds 1 --terms 2,4,8 --grids 4,8,16    (a quick look)
# Run it on a quiet machine: the plotted seconds are wall-clock times.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

out=docs/figures
echo "==> [error_vs_time] cmake --preset release"
cmake --preset release >/dev/null
echo "==> [error_vs_time] cmake --build build/release -t error_vs_time"
cmake --build build/release -t error_vs_time

start=$(date +%s)
echo "==> [error_vs_time] build/release/bin/error_vs_time $out --check-cold 12 $*"
status=0
# One thread (the solvers are single-threaded; this pins any library threading too).
OMP_NUM_THREADS=1 build/release/bin/error_vs_time "$out" --check-cold 12 "$@" || status=$?
echo "==> [error_vs_time] report took $(($(date +%s) - start)) s (exit status $status)"

if command -v gnuplot >/dev/null 2>&1; then
  echo "==> [error_vs_time] gnuplot scripts/plot_error_vs_time.gp -> $out/error_vs_time.png"
  # The speeds in the CSV (column 2), in order, for the rows of panels.
  speeds=$(awk -F, 'NR > 1 && !seen[$2]++ { printf "%s%s", sep, $2; sep = " " }' "$out/error_vs_time.csv")
  gnuplot -e "dir='$out'; outdir='$out'; speeds='$speeds'" scripts/plot_error_vs_time.gp
else
  echo "WARNING: [error_vs_time] gnuplot not found; $out/error_vs_time.png not regenerated" >&2
fi
# Status 1: a BEM solve did not converge (the line solver's non-converged points are expected
# and marked in the CSV and the plot; see docs/performance.md).
exit "$status"
