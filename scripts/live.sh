#!/usr/bin/env bash
# Installs what is missing, builds, and serves the live view of the default scene (case P63):
# it prints "live view at http://127.0.0.1:8080/"; open that in a browser. Ctrl-C stops it.
# Options go to `cablefilm live` (e.g. --port 0 --size 1920x1080 --speed 2).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
exec ./build/cablefilm live scenes/polachek1963.toml "$@"
