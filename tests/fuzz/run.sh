#!/usr/bin/env bash
# Builds the scene-parser fuzzer (tests/fuzz/CMakeLists.txt: libFuzzer with ASan, UBSan and LSan,
# clang) in the sanitize preset's tree, seeds it with the scenes in bench/scenes/ and the inputs
# that once broke the parser, and runs it for SECONDS (default 60) on every core, so two cores fuzz
# twice as many inputs in the same wall time. Exit 0 = no crash, leak or sanitizer report.
#
#   tests/fuzz/run.sh [SECONDS] [CORPUS_DIR]      (CORPUS_DIR default build/fuzz/corpus)
#
# After `./run.sh sanitize` the library is already built there, so this compiles only the scene
# layer and the fuzz target; alone, it builds the layers it links first.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-60}"
corpus="${2:-build/fuzz/corpus}"

cmake --preset sanitize >/dev/null
cmake --build --preset sanitize --target quadmc_scene_parser_fuzz

# Seed corpus: copied fresh each run (the fuzzer adds its finds beside them).
mkdir -p "$corpus"
cp bench/scenes/*.toml tests/fuzz/regressions/*.toml "$corpus/"

# One fuzzer per core (libFuzzer's -jobs/-workers): independent processes on the one corpus
# folder, each reloading what the others add to it. (Fork mode, -fork, restarts its workers every
# few seconds and ran half as many inputs per second here.) Each writes its log to fuzz-<job>.log
# in the current folder and a crashing input beside it, so they run in a folder of their own;
# the run fails when any of them does.
cores=$(nproc)
corpus=$(realpath "$corpus")
logs=$(realpath -m "$corpus/../logs")
rm -rf "$logs"
mkdir -p "$logs"
fuzzer=$(realpath build/sanitize/tests/fuzz/quadmc_scene_parser_fuzz)
status=0
(cd "$logs" &&
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  "$fuzzer" -jobs="$cores" -workers="$cores" -max_total_time="$seconds" -timeout=10 \
  -rss_limit_mb=2048 -print_final_stats=1 "$corpus" >/dev/null 2>&1) || status=$?
for log in "$logs"/fuzz-*.log; do
  echo "--- $log"
  tail -n 12 "$log"
done
if [ "$status" -ne 0 ]; then
  echo "fuzz: a fuzzer failed (exit $status): its log above, the input in $logs" >&2
  exit "$status"
fi
echo "fuzz: scene parser ran ${seconds} s on ${cores} cores with no crash, leak or sanitizer report"
