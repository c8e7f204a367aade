#!/usr/bin/env bash
# Builds the scene-parser fuzzer (tests/fuzz/CMakeLists.txt: libFuzzer with ASan, UBSan and LSan,
# clang) in the sanitize preset's tree, seeds it with the scenes in bench/scenes/ and the inputs
# that once broke the parser, and runs it for SECONDS (default 60). Exit 0 = no crash, leak or
# sanitizer report.
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

ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  build/sanitize/tests/fuzz/quadmc_scene_parser_fuzz -max_total_time="$seconds" -timeout=10 \
  -rss_limit_mb=2048 -print_final_stats=1 "$corpus" 2>&1 | tail -n 25
# With `set -o pipefail`, a crash (non-zero exit of the fuzzer) fails this script.
echo "fuzz: scene parser ran ${seconds} s with no crash, leak or sanitizer report"
