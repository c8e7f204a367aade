#!/usr/bin/env bash
# Checks a built quadmc Debian package (cmake/packaging.cmake) the way a user would meet it:
# its control fields, its file list, and the files themselves after `dpkg -x` into a scratch root
# (no root rights, nothing installed on the machine). ./run.sh package builds the package and
# runs this; CI runs ./run.sh package.
#
#   tests/package/check_package.sh PACKAGE.deb SCRATCH_FOLDER
#
# What it checks, each failure one line on stderr naming what was expected and what was found:
#  - Package, Version and Architecture: quadmc, the version CITATION.cff carries (which
#    tests/structure/release_files_test.cpp ties to project(VERSION)), this machine's architecture;
#    Description: a synopsis and a long part that does not repeat it;
#  - Depends: the package of every shared library the command loads (readelf's NEEDED entries,
#    owner from `dpkg -S`), and the -dev packages whose CMake files quadmcConfig.cmake
#    find_dependency()s; Recommends: python3-matplotlib, which only the plots need;
#  - the file list: everything under usr/, the command, its plot script and scenes, the headers,
#    every layer's static archive, the CMake package files, the license as Debian's copyright
#    file; no test, benchmark or peer binary (the GSL/cubature peers would bring the GPL in);
#  - the extracted files work from where they are: the command's --version names the package's
#    version and the extracted plot script, it runs bench/scenes/minimal.toml with plots into a
#    results folder whose meta.csv names the same version, and tests/consumer builds against the
#    extracted CMake package files (find_package(quadmc) with CMAKE_PREFIX_PATH=<root>/usr).
#
# Not for: the install rules under any prefix (tests/cli/installed_layout_test.cpp) or the
# package's reproducibility; it does not install the package into the system.
set -euo pipefail
# Under pipefail a reader that stops early (grep -q, head, awk's exit) can kill the writer with
# SIGPIPE and fail the whole pipeline with 141, depending on how much the writer had buffered:
# CI once stopped here at `ldconfig -p | awk ... exit`. So every early-stopping reader below reads
# a file or a here-string, never a pipe.

if [ $# -ne 2 ]; then
  echo "usage: tests/package/check_package.sh PACKAGE.deb SCRATCH_FOLDER" >&2
  exit 2
fi
deb=$(realpath "$1")
scratch=$2
source_dir=$(realpath "$(dirname "$0")/../..")

failures=0
fail() {
  echo "check_package.sh: $*" >&2
  failures=$((failures + 1))
}

[ -f "$deb" ] || { echo "check_package.sh: no package file $deb" >&2; exit 1; }
rm -rf "$scratch"
mkdir -p "$scratch"
scratch=$(realpath "$scratch")
root=$scratch/root

field() { dpkg-deb --field "$deb" "$1"; }

# --- control fields ---------------------------------------------------------------------------
expected_version=$(sed -n 's/^version:[ \t]*"\{0,1\}\([^"]*\)"\{0,1\}[ \t]*$/\1/p' \
  "$source_dir/CITATION.cff")
[ "$(field Package)" = quadmc ] || fail "Package: expected quadmc, got '$(field Package)'"
[ "$(field Version)" = "$expected_version" ] ||
  fail "Version: expected '$expected_version' (CITATION.cff), got '$(field Version)'"
[ "$(field Architecture)" = "$(dpkg --print-architecture)" ] ||
  fail "Architecture: expected '$(dpkg --print-architecture)', got '$(field Architecture)'"

# The Description: a synopsis line, then a long part that does not repeat it, every line of it
# indented (deb-control(5); `dpkg-deb --field` prints the long part's lines with their indent).
description=$(field Description)
synopsis=$(head -n 1 <<<"$description")
[ -n "$synopsis" ] || fail "Description: expected a synopsis line, got none"
[ "$(sed -n 2p <<<"$description" | sed 's/^ *//')" != "$synopsis" ] ||
  fail "Description: the long part repeats the synopsis '$synopsis'"
[ "$(tail -n +2 <<<"$description" | grep -c .)" -ge 1 ] || fail "Description: no long part"
unindented=$(tail -n +2 <<<"$description" | grep -v '^ ' || true)
[ -z "$unindented" ] || fail "Description: long-part line not indented: $(head -n 1 <<<"$unindented")"

# Depends as a list of package names (versions and alternatives stripped).
depends=$(field Depends | tr ',|' '\n' | sed 's/(.*)//; s/:any//; s/^[ \t]*//; s/[ \t]*$//' |
  sed '/^$/d' | sort -u)
depends_on() { grep -Fqx "$1" <<<"$depends"; }

# --- the files --------------------------------------------------------------------------------
dpkg-deb --contents "$deb" >"$scratch/contents.txt"
dpkg -x "$deb" "$root"
multiarch=$(gcc -print-multiarch)
libdir=usr/lib/$multiarch

# Every shared library the command needs at run time comes from a package it depends on.
readelf -d "$root/usr/bin/quadmc" | sed -n 's/.*(NEEDED).*\[\(.*\)\].*/\1/p' >"$scratch/needed.txt"
[ -s "$scratch/needed.txt" ] || fail "usr/bin/quadmc: readelf found no NEEDED library"
ldconfig -p >"$scratch/ldconfig.txt"
while read -r soname; do
  path=$(awk -v soname="$soname" '$1 == soname { print $NF; exit }' "$scratch/ldconfig.txt")
  if [ -z "$path" ]; then
    fail "usr/bin/quadmc needs $soname, which this machine cannot find (ldconfig -p)"
    continue
  fi
  # dpkg -S answers "package:arch: /path"; the path may be registered under /lib or /usr/lib.
  owner=$(dpkg -S "$path" 2>/dev/null || dpkg -S "$(realpath "$path")" 2>/dev/null ||
    dpkg -S "${path#/usr}" 2>/dev/null || true)
  owner=${owner%%:*}
  if [ -z "$owner" ]; then
    fail "usr/bin/quadmc needs $soname ($path), which no installed package owns"
  elif ! depends_on "$owner"; then
    fail "Depends: usr/bin/quadmc needs $soname from $owner, which Depends lacks: $(field Depends)"
  fi
done <"$scratch/needed.txt"

# quadmcConfig.cmake find_dependency()s these (lib/cmake/quadmcConfig.cmake.in); the installed
# headers include theirs.
for dev in libfmt-dev libboost-dev libtomlplusplus-dev librandom123-dev libquadrule-dev \
  libquantlib0-dev libcli11-dev; do
  depends_on "$dev" || fail "Depends: expected $dev (quadmcConfig.cmake needs it), got: $(field Depends)"
done
recommends=$(field Recommends | tr ',' '\n' | sed 's/^[ \t]*//; s/[ \t(].*//')
for recommended in python3 python3-matplotlib; do
  grep -qx "$recommended" <<<"$recommends" ||
    fail "Recommends: expected $recommended (the plots), got '$(field Recommends)'"
done

# The files a user of the command and of the library needs, where Debian puts them.
expected_files=(
  usr/bin/quadmc
  usr/share/quadmc/plot.py
  usr/share/quadmc/gallery.py
  usr/share/quadmc/render.py
  usr/share/quadmc/scenes/render.toml
  usr/share/quadmc/scenes/default.toml
  usr/share/quadmc/scenes/minimal.toml
  usr/share/doc/quadmc/copyright
  usr/share/doc/quadmc/README.md
  usr/share/doc/quadmc/CHANGELOG.md
  usr/share/doc/quadmc/CITATION.cff
  usr/include/quadmc/methods/registry.hpp
  usr/include/quadmc/command.hpp
  "$libdir/libquadmc_command.a"
  "$libdir/libquadmc_build_provenance.a"
  usr/include/quadmc/report/provenance.hpp
  "$libdir/cmake/quadmc/quadmcConfig.cmake"
  "$libdir/cmake/quadmc/quadmcConfigVersion.cmake"
  "$libdir/cmake/quadmc/quadmcTargets.cmake"
)
# One static archive per layer with sources (lib/CMakeLists.txt: a layer without sources is
# header-only).
for layer_sources in "$source_dir"/lib/src/*/; do
  expected_files+=("$libdir/libquadmc_$(basename "$layer_sources").a")
done
# Every public header.
while read -r header; do
  expected_files+=("usr/include/${header#"$source_dir"/lib/include/}")
done < <(find "$source_dir/lib/include/quadmc" -name '*.hpp')
for file in "${expected_files[@]}"; do
  [ -f "$root/$file" ] || fail "file list: expected /$file, not in the package"
done
for program in usr/bin/quadmc usr/share/quadmc/plot.py; do
  [ -x "$root/$program" ] || fail "/$program: expected an executable file"
done
cmp -s "$root/usr/share/doc/quadmc/copyright" "$source_dir/LICENSE" ||
  fail "/usr/share/doc/quadmc/copyright: expected the text of LICENSE"

# Nothing outside usr/, nothing the package must not carry.
outside=$(find "$root" -mindepth 1 -maxdepth 1 ! -name usr -printf '%f\n')
[ -z "$outside" ] || fail "file list: expected only usr/, found also: $outside"
[ ! -e "$root/usr/local" ] || fail "file list: /usr/local in the package (prefix not /usr)"
unexpected=$(cd "$root" && find usr/bin -type f ! -name quadmc)
[ -z "$unexpected" ] || fail "file list: expected only usr/bin/quadmc, found also: $unexpected"
# The peers (GPL: GSL, cubature) stay out by name and by link; the library's own Genz-Malik
# header rules/adaptive_cubature.hpp is no peer, so file names alone cannot say "cubature".
grep -Eq 'quadmc_peers|/peers/|_tests|_bench' "$scratch/contents.txt" &&
  fail "file list: a peer, test or benchmark file is in the package: $(grep -m 1 -E 'quadmc_peers|/peers/|_tests|_bench' "$scratch/contents.txt")"
grep -Eq '^lib(gsl|cubature)' "$scratch/needed.txt" &&
  fail "usr/bin/quadmc links a GPL peer library: $(grep -m 1 -E '^lib(gsl|cubature)' "$scratch/needed.txt")"

# --- the extracted files at work --------------------------------------------------------------
quadmc=$root/usr/bin/quadmc
if "$quadmc" --version >"$scratch/version.txt" 2>"$scratch/version.err"; then
  [ "$(head -n 1 "$scratch/version.txt")" = "quadmc $expected_version" ] ||
    fail "quadmc --version: expected first line 'quadmc $expected_version', got '$(head -n 1 "$scratch/version.txt")'"
  grep -qx "plot script: $root/usr/share/quadmc/plot.py" "$scratch/version.txt" ||
    fail "quadmc --version: expected 'plot script: $root/usr/share/quadmc/plot.py', got '$(grep '^plot script' "$scratch/version.txt")'"
else
  fail "quadmc --version failed: $(cat "$scratch/version.err")"
fi

if (cd "$scratch" && "$quadmc" run "$root/usr/share/quadmc/scenes/minimal.toml" --out minimal \
      >"$scratch/run.txt" 2>"$scratch/run.err"); then
  for file in README.md convergence.csv slopes.csv meta.csv error_genz_gaussian_s3.svg \
              work_precision_genz_gaussian_s3.svg; do
    [ -f "$scratch/minimal/$file" ] || fail "quadmc run minimal.toml: expected $file in its results folder"
  done
  meta_version=$(sed -n '2s/,.*//p' "$scratch/minimal/meta.csv" 2>/dev/null || true)
  [ "$meta_version" = "$expected_version" ] ||
    fail "minimal/meta.csv: expected quadmc_version '$expected_version', got '$meta_version'"
else
  fail "quadmc run $root/usr/share/quadmc/scenes/minimal.toml failed: $(tail -n 1 "$scratch/run.err")"
fi

# The library through its CMake package files only, relocated under the scratch root.
if cmake -S "$source_dir/tests/consumer" -B "$scratch/consumer" -G Ninja \
     -DCMAKE_PREFIX_PATH="$root/usr" -DCMAKE_FIND_PACKAGE_PREFER_CONFIG=ON \
     >"$scratch/consumer.log" 2>&1 &&
   cmake --build "$scratch/consumer" >>"$scratch/consumer.log" 2>&1; then
  grep -Fqx "quadmc_DIR:PATH=$root/$libdir/cmake/quadmc" "$scratch/consumer/CMakeCache.txt" ||
    fail "tests/consumer: find_package(quadmc) did not use the extracted package: $(grep quadmc_DIR "$scratch/consumer/CMakeCache.txt")"
  "$scratch/consumer/consumer" >>"$scratch/consumer.log" 2>&1 ||
    fail "tests/consumer built against the package gave a wrong answer (see $scratch/consumer.log)"
else
  fail "tests/consumer does not build against the extracted package: $(grep -m 1 -i error "$scratch/consumer.log")"
fi

echo "package $(basename "$deb"): $(grep -c '' "$scratch/contents.txt") entries"
echo "Depends: $(field Depends)"
echo "Recommends: $(field Recommends)"
if [ "$failures" -gt 0 ]; then
  echo "check_package.sh: $failures check(s) failed" >&2
  exit 1
fi
echo "check_package.sh: every check passed"
