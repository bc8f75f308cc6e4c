#!/usr/bin/env bash
# Fuzzes the scene loader, `check` and the first outputs of a run (tests/fuzz/scene_fuzzer.cpp)
# with libFuzzer under AddressSanitizer + UndefinedBehaviorSanitizer, for SECONDS (default 600).
# Its inputs are mutated as scenes (tests/fuzz/scene_mutator.cpp: one change to a value or a
# key), not as bytes; it prints at exit how many passed the TOML parser and reached a run.
#   bash scripts/fuzz.sh [SECONDS] [BUILD_DIR]      # BUILD_DIR: default build-clang
# Needs a build configured as scripts/test.sh does (clang, CABLEFILM_SANITIZE, CABLEFILM_FUZZ).
# Starts from tests/fuzz/corpus, tests/fuzz/regressions and the shipped scenes (read only); new inputs go to
# BUILD_DIR/fuzz/corpus. An input that fails (crash-*, leak-*, timeout-*, oom-*) is kept in
# BUILD_DIR/fuzz/ and the script fails: fix it, then add it to tests/fuzz/regressions/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-600}"
build="${2:-build-clang}"
fuzzer="$build/scene_fuzzer"
if [ ! -x "$fuzzer" ]; then
  echo "fuzz: $fuzzer not built (scripts/test.sh builds it)" >&2
  exit 2
fi
work="$build/fuzz"
mkdir -p "$work/corpus"
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
# -timeout: an input still running after 10 s is a hang (each takes well under a second: the
# fuzzer stops its runs after 0.3 s, through the program's own cancel flag).
"$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
  -dict=tests/fuzz/scene.dict -print_final_stats=1 -artifact_prefix="$work/" \
  "$work/corpus" tests/fuzz/corpus tests/fuzz/regressions scenes
