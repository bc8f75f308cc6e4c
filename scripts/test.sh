#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test: the optimised build (GCC), then the
# sanitizer build (clang: AddressSanitizer + UndefinedBehaviorSanitizer with float-cast-overflow)
# with the scene fuzzer, run for a bounded time (FUZZ_SECONDS, default 90).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --tests
jobs="$(nproc)"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"
ctest --test-dir build -j"$jobs" --output-on-failure
# Mesa's software rasteriser keeps some allocations for the process lifetime: not our leaks.
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cmake -S . -B build-clang -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++ -DCABLEFILM_SANITIZE=ON -DCABLEFILM_FUZZ=ON
cmake --build build-clang -j"$jobs"
# Every test again under the sanitizers, but those tests/not_sanitized.txt lists with why: each
# checks behaviour the optimised build has just checked, its code run sanitized by another test.
skipped="$(sed -e 's/#.*//' -e 's/[[:space:]]//g' -e '/^$/d' tests/not_sanitized.txt | paste -sd'|')"
ctest --test-dir build-clang -j"$jobs" --output-on-failure -E "^(${skipped//./\\.})\$"
bash scripts/fuzz.sh "${FUZZ_SECONDS:-90}" build-clang
