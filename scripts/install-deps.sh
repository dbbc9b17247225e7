#!/usr/bin/env bash
# Install viscoroll's build and test dependencies from Debian packages (Debian 12).
# Idempotent: does nothing when every package is already installed.
set -euo pipefail

packages=(
  g++ cmake ninja-build        # toolchain (cmake >= 3.25 for CMakePresets.json v6)
  libeigen3-dev libboost-dev   # the library's dependencies
  nlohmann-json3-dev           # viscoroll-solve's scene files (the command-line tool only)
  catch2 libbenchmark-dev      # tests, benchmarks
  gnuplot-nox                  # figures
  doxygen                      # the API reference (the docs target, docs/reference.md)
  libfftw3-dev                 # optional FFT back end
  clang libclang-rt-14-dev     # libFuzzer target (scripts/fuzz.sh)
  pybind11-dev python3-dev python3-numpy   # the Python module (python/, docs/python.md)
  python3-pytest python3-matplotlib        # its tests and examples
  python3-venv python3-wheel               # pip install . into a venv (docs/python.md)
  python3-scipy                            # benchmarks/layer_fft_peer.py, the layers' peer
  python3-xarray python3-netcdf4 python3-tqdm   # vr.study: labelled arrays, netCDF, progress
  python3-dask python3-distributed              # vr.study on a Dask cluster (docs/python.md)
)

missing=()
for pkg in "${packages[@]}"; do
  if ! dpkg -s "$pkg" 2>/dev/null | grep -q '^Status: install ok installed'; then
    missing+=("$pkg")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "==> install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo=(sudo)
  else
    echo "install-deps: missing packages (${missing[*]}) and not root, no sudo" >&2
    exit 1
  fi
fi

export DEBIAN_FRONTEND=noninteractive
echo "==> install-deps: apt-get update"
"${sudo[@]}" apt-get update
echo "==> install-deps: apt-get install ${missing[*]}"
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}" </dev/null
