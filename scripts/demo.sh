#!/usr/bin/env bash
# Installs what is missing, builds, and renders the default scene (case P63) into
# output/polachek1963/: equilibrium.csv, timeseries.csv, film.mp4, max_tension.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
./build/cablefilm run scenes/polachek1963.toml "$@"
