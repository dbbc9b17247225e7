#!/usr/bin/env bash
# README command 1, the main job: install the dependencies, build only what it runs (the
# command-line tool viscoroll-solve and the example panek_kalker), solve the paper's scene made
# dimensional (examples/scenes/paper.json) with the line method over speed and print a table,
# then write the data and PNGs of the paper's Figs. 3-6 to out/panek_kalker/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
start=$SECONDS

echo "==> [main] installing dependencies (scripts/install-deps.sh)"
bash scripts/install-deps.sh

echo "==> [main] cmake --preset release"
cmake --preset release >/dev/null
echo "==> [main] cmake --build --preset release --target viscoroll_solve panek_kalker"
cmake --build --preset release --target viscoroll_solve panek_kalker

solve=build/release/bin/viscoroll-solve
scene=examples/scenes/paper.json
mkdir -p out/paper
echo "==> [main] $solve --scene $scene --method line --format table --csv out/paper/sweep.csv" \
     "(after $((SECONDS - start)) s)"
"$solve" --scene "$scene" --method line --format table --csv out/paper/sweep.csv

echo "==> [main] build/release/bin/panek_kalker out/panek_kalker (the figures' 61 speeds)"
build/release/bin/panek_kalker out/panek_kalker
if command -v gnuplot >/dev/null 2>&1; then
  echo "==> [main] gnuplot scripts/plot_panek_kalker.gp (PNG in out/panek_kalker)"
  gnuplot -e "dir='out/panek_kalker'; outdir='out/panek_kalker'" scripts/plot_panek_kalker.gp
fi
echo "==> [main] done in $((SECONDS - start)) s"
