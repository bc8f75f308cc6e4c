#!/usr/bin/env bash
# Installs the Debian packages cablefilm needs that are not installed yet (Debian 12).
# With --tests also what the tests need: a headless browser and Python's WebSocket client, and
# clang with its sanitizer and libFuzzer runtimes (the sanitizer build and the scene fuzzer).
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libtomlplusplus-dev libcli11-dev libgtest-dev libbenchmark-dev
  libosmesa6-dev libpng-dev libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
  libfreetype-dev libfontconfig-dev fonts-dejavu-core
  libcivetweb-dev libjpeg62-turbo-dev nlohmann-json3-dev libnetcdf-dev
  libfftw3-dev                             # a recorded sea's and the tensions' spectra
  pybind11-dev python3-dev python3-numpy   # the Python module (src/python) and its arrays
)
if [ "${1:-}" = "--tests" ]; then
  packages+=(python3 chromium chromium-driver python3-selenium python3-websocket
             clang libclang-rt-14-dev llvm)
  packages+=(python3-distributed)   # examples/dask_sweep.py, tested on a local Dask cluster
  packages+=(python3-xarray python3-netcdf4)  # results.nc opened in xarray (netcdf_xarray_test)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all packages present"
  exit 0
fi
echo "setup: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
