#!/usr/bin/env bash
# Builds the scene-parser fuzzer with clang (Debian's clang + libclang-rt-14-dev) under
# AddressSanitizer, UndefinedBehaviorSanitizer and LeakSanitizer, seeds it with the scenes in
# bench/scenes/, and runs it for SECONDS (default 60). Exit 0 = no crash, leak or sanitizer report.
#
#   tests/fuzz/run.sh [SECONDS] [BUILD_DIR]      (BUILD_DIR default build/fuzz)
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-60}"
out="${2:-build/fuzz}"
mkdir -p "$out/corpus"

CXX="${FUZZ_CXX:-clang++}"
# toml++ is compiled in header-only mode (its default), not linked as Debian's shared library:
# that way its parser is instrumented too, so the fuzzer gets coverage feedback from inside the
# TOML grammar and the sanitizers watch it. Its internal assertions are compiled out, as in
# Debian's libtomlplusplus.so that the library links: toml++ 3.3.0 asserts in parse_key() on
# input such as "[=]" although the very next branch reports that as a parse error (which is what
# the shipped library does), so leaving them on would only re-find that one false alarm.
# Line tables only: a report needs file:line, not variables, and full debug info cost a fifth of
# the build (CI's time is mostly compiling).
flags=(-std=c++20 -O1 -gline-tables-only -fno-omit-frame-pointer -fsanitize=address,undefined
       -fno-sanitize-recover=undefined -Ilib/include "-I${RANDOM123_INCLUDE:-/usr/include}"
       '-DTOML_ASSERT(expr)=static_cast<void>(0)' -DQUADMC_HAVE_LIBMVEC=1)
# The parser asks each method's descriptor to read its options (methods/), so the fuzzer links
# the library's sources below the report layer; each is compiled once into an object (instrumented
# for coverage with -fsanitize=fuzzer-no-link), and a source is recompiled only when it changed.
# The per-instruction-set kernels take their -m flag as in lib/CMakeLists.txt.
mkdir -p "$out/obj"
objects=()
for source in $(ls lib/src/{core,functions,rules,sampling,estimators,analysis,methods,scene}/*.cpp \
                  2>/dev/null); do
  object="$out/obj/$(echo "${source%.cpp}" | tr '/' '_').o"
  isa=()
  case "$source" in
    *_avx2.cpp) isa=(-mavx2) ;;
    # As lib/CMakeLists.txt compiles them: the Latin hypercube permutation, Sobol' and lattice
    # kernels need AVX-512DQ's 64-bit multiply, the Sobol' GFNI build also AVX512BW and GFNI
    # (their dispatch checks the CPU for each).
    *sampling/permutation_blocks_avx512.cpp | *sampling/sobol_blocks_avx512.cpp | \
      *sampling/rank1_lattice_blocks_avx512.cpp) isa=(-mavx512f -mavx512dq) ;;
    *sampling/sobol_blocks_avx512_gfni.cpp) isa=(-mavx512f -mavx512dq -mavx512bw -mgfni) ;;
    *_avx512.cpp) isa=(-mavx512f) ;;
  esac
  if [ ! -f "$object" ] || [ "$source" -nt "$object" ] || [ -n "$(find lib/include -newer "$object" -name '*.hpp' -print -quit)" ]; then
    "$CXX" "${flags[@]}" -fsanitize=fuzzer-no-link "${isa[@]}" -c "$source" -o "$object" &
    # Two compilations at a time: the machines this runs on have two cores.
    while [ "$(jobs -rp | wc -l)" -ge 2 ]; do wait -n; done
  fi
  objects+=("$object")
done
wait
"$CXX" "${flags[@]}" -fsanitize=fuzzer tests/fuzz/scene_parser_fuzz.cpp "${objects[@]}" \
  -lfmt -lquadrule -lQuantLib -lmvec -lpthread -o "$out/scene_parser_fuzz"

# Seed corpus: the real scenes and the inputs that once broke the parser (regressions/), copied
# fresh each run (the fuzzer adds its finds beside them).
cp bench/scenes/*.toml tests/fuzz/regressions/*.toml "$out/corpus/"

ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  "$out/scene_parser_fuzz" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -print_final_stats=1 "$out/corpus" 2>&1 | tail -n 25
# With `set -o pipefail`, a crash (non-zero exit of the fuzzer) fails this script.
echo "fuzz: scene parser ran ${seconds} s with no crash, leak or sanitizer report"
