#!/usr/bin/env bash
# The two commands of the README, and the install step they share.
#
#   ./run.sh bench   install what is missing, build (Release), run the default scene → results/
#                    (extra arguments go to `quadmc run`, e.g. --out DIR, --threads T)
#   ./run.sh test    install what is missing, build, run every test with CTest
#   ./run.sh fuzz [SECONDS]   fuzz the scene parser (libFuzzer + ASan/UBSan), default 60 s
#   ./run.sh deps    only install what is missing (idempotent: does nothing when all is present)
#
# Every dependency is a Debian 12 package; nothing is downloaded from anywhere else.
set -euo pipefail
cd "$(dirname "$0")"

# What the library and its tests need.
LIB_PACKAGES=(build-essential cmake ninja-build pkg-config
              libgtest-dev libgmock-dev       # GoogleTest
              libbenchmark-dev                # Google Benchmark
              libboost-dev                    # Boost.Math (header-only, part of libboost1.74-dev)
              libfmt-dev                      # fmt
              libcli11-dev                    # CLI11 (command-line flags)
              libtomlplusplus-dev             # toml++ (scene files)
              librandom123-dev)               # Random123 (Philox counter-based RNG)
# What only the benchmark command needs: plots (Debian's python3, not a pyenv one) and the
# peers measured beside quadmc in bench/peers/ (GSL, cubature).
BENCH_PACKAGES=(python3 python3-matplotlib libgsl-dev libcubature-dev)
# The scene-parser fuzzer: libFuzzer and the sanitizer runtimes come with Debian's clang.
FUZZ_PACKAGES=(clang libclang-rt-14-dev)

install_missing() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "run.sh: installing ${missing[*]}" >&2
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

case "${1:-}" in
  deps)
    install_missing "${LIB_PACKAGES[@]}" "${BENCH_PACKAGES[@]}" "${FUZZ_PACKAGES[@]}"
    ;;
  fuzz)
    install_missing "${LIB_PACKAGES[@]}" "${FUZZ_PACKAGES[@]}"
    tests/fuzz/run.sh "${2:-60}" build/fuzz
    ;;
  bench)
    install_missing "${LIB_PACKAGES[@]}" "${BENCH_PACKAGES[@]}"
    cmake --preset release >/dev/null
    cmake --build --preset release
    shift
    ./build/release/bench/quadmc run bench/scenes/default.toml "$@"
    ;;
  test)
    install_missing "${LIB_PACKAGES[@]}"
    cmake --preset test >/dev/null
    cmake --build --preset test
    ctest --preset test
    ;;
  *)
    echo "usage: ./run.sh bench | test | fuzz [SECONDS] | deps" >&2
    exit 2
    ;;
esac
