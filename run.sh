#!/usr/bin/env bash
# The two commands of the README, the CI stages, and the install step they share.
#
#   ./run.sh bench      install what is missing, build the command (Release), run the default scene → results/
#                       (extra arguments go to `quadmc run`, e.g. --out DIR, --threads T)
#   ./run.sh test       install what is missing, build, run every test with CTest
#   ./run.sh benchmarks install what is missing, build the Google Benchmark binaries and bench/peers
#                       (Release, beside README command 1's command) → build/release/bench/
#   ./run.sh sanitize   the same tests (the command's end-to-end runs included) under ASan + UBSan
#   ./run.sh format     check that every C++ file is clang-format clean
#   ./run.sh fuzz [SECONDS]   fuzz the scene parser (libFuzzer + ASan/UBSan), default 60 s on each core
#   ./run.sh consumer   install the package into a prefix and build two outside find_package users
#                       (tests/consumer/, bench/examples/own_integrand/)
#   ./run.sh package    build the Debian packages (cpack -G DEB) → build/package/deb/: quadmc_*.deb,
#                       libquadmc-dev_*.deb, python3-quadmc_*.deb, and check them extracted into a
#                       scratch root (tests/package/check_package.sh)
#   ./run.sh deps       only install what is missing (idempotent: does nothing when all is present)
#   ./run.sh packages [COMMAND]   print every package of every install list (or COMMAND's), one per
#                       line (.ci/run uses it)
#
# Each command installs exactly the packages of its own list, so a machine that happens to have a
# package already cannot hide a missing install step: .ci/run removes them all first (CI=true)
# and reinstalls them through these commands. Every dependency is a Debian 12 package; nothing is
# downloaded from anywhere else.
set -euo pipefail
cd "$(dirname "$0")"

# The tools of every build: ccache keeps compiled objects under ~/.cache/ccache, so that the
# presets that compile the library alike (release, package) and repeated builds reuse them
# (CMakeLists.txt, QUADMC_CCACHE).
BUILD_PACKAGES=(build-essential cmake ninja-build pkg-config ccache)
# What the library and the quadmc command need to build, without the test and timing frameworks.
LIBRARY_PACKAGES=(libboost-dev                # Boost.Math (header-only, part of libboost1.74-dev)
                  libfmt-dev                  # fmt
                  libcli11-dev                # CLI11 (command-line flags)
                  libtomlplusplus-dev         # toml++ (scene files)
                  librandom123-dev            # Random123 (Philox counter-based RNG)
                  libquadrule-dev             # quadrule (Gauss–Patterson tables of the sparse grids)
                  libquantlib0-dev            # QuantLib: the lattice generating vectors
                  libfftw3-dev)               # FFTW: the power spectrum of render error images
# ... and with them: every preset but `package` configures the tests and the timing binaries.
LIB_PACKAGES=("${BUILD_PACKAGES[@]}" "${LIBRARY_PACKAGES[@]}"
              libgtest-dev libgmock-dev       # GoogleTest
              libbenchmark-dev)               # Google Benchmark
# Plots: Debian's python3 with matplotlib (not a pyenv one). The tests need it too: the
# end-to-end tests run `quadmc run` with plots on, which runs bench/plot.py.
PLOT_PACKAGES=(python3 python3-matplotlib)
# The peers beside quadmc in bench/peers/: GSL and cubature (GPL) for the peers benchmark and the
# quadmc_with_peers command that runs scenes naming peer_* methods (bench/scenes/time_to_error.toml),
# and python3-scipy for scipy.stats.qmc's Sobol' and Halton points (bench/peers/scipy_qmc.py).
PEER_PACKAGES=(libgsl-dev libcubature-dev python3-scipy)
# Open MPI: `mpirun -np K quadmc run SCENE.toml` (bench/quadmc/mpi_run.hpp). The command is
# built with MPI where CMake finds it (QUADMC_MPI=AUTO), and tests/mpi/ runs mpirun on loopback.
MPI_PACKAGES=(libopenmpi-dev openmpi-bin)
# The Python module `import quadmc` (bench/python/): Python's C headers (python3-dev; Debian's
# pybind11-dev does not depend on them), numpy and pybind11. The test and package presets require
# them (QUADMC_PYTHON=ON); the release preset builds the module only where they happen to be
# installed (AUTO), so README command 1 needs none of them.
PYTHON_MODULE_PACKAGES=(python3-dev python3-numpy pybind11-dev)
# What the tests need: the library, the plots of the end-to-end runs, the peers, whose adapter
# tests (tests/peers/) build only where they are installed (ctest passes without them too), Open
# MPI for the mpirun tests (tests/mpi/, likewise built only with it), and the Python module with
# pytest for its suite (tests/python/).
TEST_PACKAGES=("${LIB_PACKAGES[@]}" "${PLOT_PACKAGES[@]}" "${PEER_PACKAGES[@]}" "${MPI_PACKAGES[@]}"
               "${PYTHON_MODULE_PACKAGES[@]}" python3-pytest)
# What only the benchmark command adds: the peers measured beside quadmc in bench/peers, and
# Open MPI for the command's mpirun use.
BENCH_PACKAGES=("${LIB_PACKAGES[@]}" "${PLOT_PACKAGES[@]}" "${PEER_PACKAGES[@]}"
                "${MPI_PACKAGES[@]}")
# The sanitizer build: the tests' packages, compiled by clang (its ASan and UBSan runtimes come
# with libclang-rt-14-dev). clang, not GCC: at -O1 with both sanitizers it compiles this code base
# in about a third of GCC's time, and compiling is most of CI's 90 minutes (README, Tests and CI).
SANITIZE_PACKAGES=("${TEST_PACKAGES[@]}" clang libclang-rt-14-dev)
# The scene-parser fuzzer: libFuzzer and the sanitizer runtimes come with Debian's clang. It is
# built in the sanitize preset's tree and links its library (tests/fuzz/CMakeLists.txt), so it
# configures that preset: the library's packages, GoogleTest and CLI11 included, and the Python
# module's, which the preset builds (QUADMC_PYTHON=ON).
FUZZ_PACKAGES=("${LIB_PACKAGES[@]}" "${PYTHON_MODULE_PACKAGES[@]}" clang libclang-rt-14-dev)
FORMAT_PACKAGES=(clang-format)
# The outside projects built against what the test preset installs: the library's packages, Open
# MPI (the installed quadmc::command links it where the test build found it, and quadmcConfig.cmake
# then finds it again), and python3 for the check of bench/examples/own_integrand's results.
CONSUMER_PACKAGES=("${LIB_PACKAGES[@]}" "${MPI_PACKAGES[@]}" python3)
# The Debian packages: the library, the command and the Python module (no tests, no benchmarks),
# CPack's DEB generator with dpkg-shlibdeps (dpkg-dev) and `file` to declare the shared libraries
# they need, and the plots, since the check runs the extracted command with plots on (and imports
# the extracted module with Debian's python3 and numpy).
PACKAGE_PACKAGES=("${BUILD_PACKAGES[@]}" "${LIBRARY_PACKAGES[@]}" "${PYTHON_MODULE_PACKAGES[@]}"
                  dpkg-dev file "${PLOT_PACKAGES[@]}")

install_missing() {
  local missing=()
  for p in "$@"; do
    # No `| grep -q`: with pipefail, grep leaving early can SIGPIPE the writer (exit 141).
    [ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)" = "install ok installed" ] ||
      missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "run.sh: installing ${missing[*]}" >&2
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# The install list of each command: what it installs, and what `./run.sh packages COMMAND`
# prints, from this one table.
packages_of() {
  case "$1" in
    bench | benchmarks) printf '%s\n' "${BENCH_PACKAGES[@]}" ;;
    test) printf '%s\n' "${TEST_PACKAGES[@]}" ;;
    sanitize) printf '%s\n' "${SANITIZE_PACKAGES[@]}" ;;
    fuzz) printf '%s\n' "${FUZZ_PACKAGES[@]}" ;;
    format) printf '%s\n' "${FORMAT_PACKAGES[@]}" ;;
    consumer) printf '%s\n' "${CONSUMER_PACKAGES[@]}" ;;
    package) printf '%s\n' "${PACKAGE_PACKAGES[@]}" ;;
    *) echo "run.sh packages: unknown command '$1'; expected bench, benchmarks, test, sanitize, fuzz, format, consumer or package" >&2
       exit 2 ;;
  esac
}

# Installs the list of command $1 (package names hold no spaces: one word each).
install_for() {
  local list
  list=$(packages_of "$1")
  # shellcheck disable=SC2086
  install_missing $list
}

case "${1:-}" in
  deps)
    install_missing "${BENCH_PACKAGES[@]}" "${FUZZ_PACKAGES[@]}" "${FORMAT_PACKAGES[@]}" \
      "${PACKAGE_PACKAGES[@]}"
    ;;
  packages)
    # With a command: that command's own list, the one it installs (tests/package/
    # check_install_lists.py checks it against what the command's CMake configuration finds).
    if [ -z "${2:-}" ]; then
      printf '%s\n' "${BENCH_PACKAGES[@]}" "${SANITIZE_PACKAGES[@]}" "${FUZZ_PACKAGES[@]}" \
        "${FORMAT_PACKAGES[@]}" "${PACKAGE_PACKAGES[@]}" | sort -u
    else
      packages_of "$2"
    fi
    ;;
  bench)
    install_for bench
    cmake --preset release >/dev/null
    # Only what the scene runs: the command. The Google Benchmark binaries and bench/peers are
    # `./run.sh benchmarks` (README, Benchmarks).
    cmake --build --preset release --target quadmc_cli
    shift
    ./build/release/bench/quadmc run bench/scenes/default.toml "$@"
    ;;
  benchmarks)
    install_for benchmarks
    cmake --preset release >/dev/null
    cmake --build --preset release
    ;;
  test)
    install_for test
    cmake --preset test >/dev/null
    cmake --build --preset test
    # One test process per core: the suites share nothing but the machine (each end-to-end run
    # works in a scratch folder of its own).
    ctest --preset test -j "$(nproc)"
    ;;
  sanitize)
    install_for sanitize
    cmake --preset sanitize >/dev/null
    cmake --build --preset sanitize
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
      ctest --preset sanitize -j "$(nproc)"
    ;;
  format)
    install_for format
    find lib bench tests \( -name '*.hpp' -o -name '*.cpp' \) -print0 |
      xargs -0 clang-format --dry-run --Werror
    ;;
  fuzz)
    install_for fuzz
    tests/fuzz/run.sh "${2:-60}" build/fuzz/corpus
    ;;
  consumer)
    # Installs what the test preset built (run `./run.sh test` first).
    install_for consumer
    rm -rf build/install build/consumer
    cmake --install build/test --prefix build/install >/dev/null
    cmake -S tests/consumer -B build/consumer -G Ninja -DCMAKE_PREFIX_PATH="$PWD/build/install" \
      >/dev/null
    cmake --build build/consumer
    ./build/consumer/consumer
    # The outside command of bench/examples/own_integrand/ (README "Your own points, rules and
    # integrands"): built on quadmc::command, its scene run from its own folder, and its numbers
    # checked against values derived independently (tests/consumer/check_own_integrand.py).
    rm -rf build/own_integrand
    cmake -S bench/examples/own_integrand -B build/own_integrand -G Ninja \
      -DCMAKE_PREFIX_PATH="$PWD/build/install" >/dev/null
    cmake --build build/own_integrand
    (root=$PWD && cd bench/examples/own_integrand &&
       "$root/build/own_integrand/mybench" run my.toml --out "$root/build/own_integrand/results")
    /usr/bin/python3 tests/consumer/check_own_integrand.py build/own_integrand/results
    ;;
  package)
    install_for package
    cmake --preset package >/dev/null
    cmake --build --preset package
    rm -rf build/package/deb
    # One .deb per install COMPONENT (cmake/packaging.cmake); the check finds each by its name
    # and fails on a missing or a stray one.
    cpack -G DEB --config build/package/CPackConfig.cmake -B build/package/deb >/dev/null
    tests/package/check_package.sh build/package/deb build/package-check
    ;;
  *)
    echo "usage: ./run.sh bench | test | benchmarks | sanitize | format | fuzz [SECONDS] | consumer | package | deps | packages" >&2
    exit 2
    ;;
esac
