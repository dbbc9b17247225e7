#!/usr/bin/env bash
# README command 1: install the dependencies, build the release preset, run the main job
# (viscoroll-solve on the plane rolling case) and, when built, plane_rolling (figure data in out/).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

echo "==> [main] installing dependencies (scripts/install-deps.sh)"
bash scripts/install-deps.sh

echo "==> [main] cmake --preset release"
cmake --preset release
echo "==> [main] cmake --build --preset release"
cmake --build --preset release

solve=build/release/bin/viscoroll-solve
if [ ! -x "$solve" ]; then
  echo "ERROR: [main] $solve was not built (examples/viscoroll_solve.cpp missing?)" >&2
  exit 1
fi
args=(--method plane --mu-d 1 --nu 0.5 --f 9 --tau 0.01,0.1,1,10,100 --speed 1 --c1 1 --load 1)
echo "==> [main] $solve ${args[*]}"
"$solve" "${args[@]}"

plane=build/release/bin/plane_rolling
if [ -x "$plane" ]; then
  mkdir -p out
  echo "==> [main] $plane out/plane"
  "$plane" out/plane
  if command -v gnuplot >/dev/null 2>&1; then
    echo "==> [main] gnuplot scripts/plot_plane.gp (PNG in out/plane)"
    gnuplot -e "dir='out/plane'; outdir='out/plane'" scripts/plot_plane.gp
  fi
else
  echo "==> [main] $plane not built; skipping the figure data"
fi
echo "==> [main] done"
