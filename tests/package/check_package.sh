#!/usr/bin/env bash
# Checks the built quadmc Debian packages (cmake/packaging.cmake) the way a user would meet them:
# their control fields, their file lists, and the files themselves after `dpkg -x` of all three
# into one scratch root (no root rights, nothing installed on the machine). ./run.sh package
# builds the packages and runs this; CI runs ./run.sh package.
#
#   tests/package/check_package.sh DEB_FOLDER SCRATCH_FOLDER
#
# DEB_FOLDER must hold exactly quadmc_*.deb, libquadmc-dev_*.deb and python3-quadmc_*.deb.
# What it checks, each failure one line on stderr naming what was expected and what was found:
#  - of each package: Package, Version (the version CITATION.cff carries, which
#    tests/structure/release_files_test.cpp ties to project(VERSION)), Architecture (this
#    machine's); Description: a synopsis of its own and a long part that does not repeat it;
#    Depends: the package of every shared library its ELF files load (readelf's NEEDED entries,
#    owner from `dpkg -S`); files only under usr/, its license as its own Debian copyright file,
#    no test, benchmark or peer file and no GPL peer library (GSL, cubature) linked;
#  - quadmc: the command, its plot scripts and scenes, its docs, and nothing else (no header,
#    archive or CMake file); Depends on no -dev package; Recommends python3, python3-matplotlib;
#  - libquadmc-dev: every public header, every layer's static archive, quadmc::command's archives,
#    the CMake package files, and nothing else; Depends on the -dev packages whose CMake files
#    quadmcConfig.cmake find_dependency()s and on quadmc of the same version;
#  - python3-quadmc: the extension for /usr/bin/python3 and the package's Python files in
#    usr/lib/python3/dist-packages/quadmc/, and nothing else; Depends on that Python's minor
#    version (>= and <<), python3-numpy, and no -dev package;
#  - no file in two packages (dpkg refuses to install such packages together);
#  - the extracted files work from where they are: the command's --version names the package's
#    version and the extracted plot script, it runs bench/scenes/minimal.toml with plots into a
#    results folder whose meta.csv names the same version, tests/consumer builds against the
#    extracted CMake package files (find_package(quadmc) with CMAKE_PREFIX_PATH=<root>/usr), and
#    `import quadmc` from the extracted dist-packages gives the points the extracted command writes.
# The expected file lists follow the source tree: the headers of lib/include/ and
# bench/quadmc/include/, one archive per lib/src/<layer>/, the scenes of bench/scenes/, the Python
# files of bench/python/quadmc/.
#
# Not for: the install rules under any prefix (tests/cli/installed_layout_test.cpp) or the
# packages' reproducibility; it does not install the packages into the system.
set -euo pipefail
# Under pipefail a reader that stops early (grep -q, head, awk's exit) can kill the writer with
# SIGPIPE and fail the whole pipeline with 141, depending on how much the writer had buffered:
# CI once stopped here at `ldconfig -p | awk ... exit`. So every early-stopping reader below reads
# a file or a here-string, never a pipe.

if [ $# -ne 2 ]; then
  echo "usage: tests/package/check_package.sh DEB_FOLDER SCRATCH_FOLDER" >&2
  exit 2
fi
deb_folder=$(realpath "$1")
scratch=$2
source_dir=$(realpath "$(dirname "$0")/../..")

failures=0
fail() {
  echo "check_package.sh: $*" >&2
  failures=$((failures + 1))
}

packages=(quadmc libquadmc-dev python3-quadmc)
rm -rf "$scratch"
mkdir -p "$scratch"
scratch=$(realpath "$scratch")
root=$scratch/root
mkdir -p "$root"

# --- which .deb is which ----------------------------------------------------------------------
# Exactly one file per package, and no other .deb: a stray one is an install rule without a known
# COMPONENT (CPack would make it a package of its own).
declare -A deb_of=()
for pkg in "${packages[@]}"; do
  found=("$deb_folder/${pkg}_"*.deb)
  if [ ${#found[@]} -ne 1 ] || [ ! -f "${found[0]}" ]; then
    echo "check_package.sh: expected one $deb_folder/${pkg}_*.deb, found: ${found[*]}" >&2
    exit 1
  fi
  deb_of[$pkg]=${found[0]}
done
all_debs=("$deb_folder"/*.deb)
[ ${#all_debs[@]} -eq ${#packages[@]} ] ||
  fail "$deb_folder: expected only the packages ${packages[*]}, found: $(basename -a "${all_debs[@]}" | tr '\n' ' ')"

field() { dpkg-deb --field "${deb_of[$1]}" "$2"; }

expected_version=$(sed -n 's/^version:[ \t]*"\{0,1\}\([^"]*\)"\{0,1\}[ \t]*$/\1/p' \
  "$source_dir/CITATION.cff")
multiarch=$(gcc -print-multiarch)
libdir=usr/lib/$multiarch
dist_packages=usr/lib/python3/dist-packages
# The Python the module is checked with, and the one its Depends must name (its extension's ABI tag
# loads into this minor version only).
python_version=$(/usr/bin/python3 -c 'import sys; print(f"{sys.version_info[0]}.{sys.version_info[1]}")')
python_next=$(/usr/bin/python3 -c 'import sys; print(f"{sys.version_info[0]}.{sys.version_info[1] + 1}")')
ext_suffix=$(/usr/bin/python3 -c 'import sysconfig; print(sysconfig.get_config_var("EXT_SUFFIX"))')
ldconfig -p >"$scratch/ldconfig.txt"

# --- what each package must hold, and where its files may be ----------------------------------
# Expected files, one per line, per package; `allowed`: where its files may be, space-separated
# bash patterns matched with [[ == ]], where * also matches across folders.
declare -A expected_files=() allowed=()
add_expected() { expected_files[$1]+="$2"$'\n'; }

add_expected quadmc usr/bin/quadmc
for script in plot.py gallery.py render.py; do
  add_expected quadmc "usr/share/quadmc/$script"
done
for scene in "$source_dir"/bench/scenes/*.toml; do
  add_expected quadmc "usr/share/quadmc/scenes/$(basename "$scene")"
done
for doc in copyright README.md CHANGELOG.md CITATION.cff; do
  add_expected quadmc "usr/share/doc/quadmc/$doc"
done
allowed[quadmc]="usr/bin/quadmc usr/share/quadmc/* usr/share/doc/quadmc/*"

# Every public header: the library's and quadmc::command's.
while read -r header; do
  add_expected libquadmc-dev "usr/include/${header#"$source_dir"/lib/include/}"
done < <(find "$source_dir/lib/include/quadmc" -name '*.hpp' | sort)
while read -r header; do
  add_expected libquadmc-dev "usr/include/${header#"$source_dir"/bench/quadmc/include/}"
done < <(find "$source_dir/bench/quadmc/include/quadmc" -name '*.hpp' | sort)
# One static archive per layer with sources (lib/CMakeLists.txt: a layer without sources is
# header-only), and the two of quadmc::command (bench/CMakeLists.txt).
for layer_sources in "$source_dir"/lib/src/*/; do
  add_expected libquadmc-dev "$libdir/libquadmc_$(basename "$layer_sources").a"
done
for archive in command build_provenance; do
  add_expected libquadmc-dev "$libdir/libquadmc_$archive.a"
done
for cmake_file in quadmcConfig.cmake quadmcConfigVersion.cmake quadmcTargets.cmake; do
  add_expected libquadmc-dev "$libdir/cmake/quadmc/$cmake_file"
done
add_expected libquadmc-dev usr/share/doc/libquadmc-dev/copyright
allowed[libquadmc-dev]="usr/include/quadmc/* $libdir/libquadmc_*.a $libdir/cmake/quadmc/* usr/share/doc/libquadmc-dev/*"

add_expected python3-quadmc "$dist_packages/quadmc/_quadmc$ext_suffix"
for python_file in "$source_dir"/bench/python/quadmc/*.py; do
  add_expected python3-quadmc "$dist_packages/quadmc/$(basename "$python_file")"
done
# The command's plot script, which quadmc.run's write draws the SVGs with (bench/python/CMakeLists.txt).
add_expected python3-quadmc "$dist_packages/quadmc/plot.py"
add_expected python3-quadmc usr/share/doc/python3-quadmc/copyright
allowed[python3-quadmc]="$dist_packages/quadmc/* usr/share/doc/python3-quadmc/*"

# --- each package -----------------------------------------------------------------------------
declare -A synopsis_owner=()
for pkg in "${packages[@]}"; do
  deb=${deb_of[$pkg]}
  [ "$(field "$pkg" Package)" = "$pkg" ] || fail "$pkg: Package: expected $pkg, got '$(field "$pkg" Package)'"
  [ "$(field "$pkg" Version)" = "$expected_version" ] ||
    fail "$pkg: Version: expected '$expected_version' (CITATION.cff), got '$(field "$pkg" Version)'"
  [ "$(field "$pkg" Architecture)" = "$(dpkg --print-architecture)" ] ||
    fail "$pkg: Architecture: expected '$(dpkg --print-architecture)', got '$(field "$pkg" Architecture)'"

  # The Description: a synopsis line that no other of the packages has, then a long part that
  # does not repeat it, every line of it indented (deb-control(5); `dpkg-deb --field` prints the
  # long part's lines with their indent).
  description=$(field "$pkg" Description)
  synopsis=$(head -n 1 <<<"$description")
  [ -n "$synopsis" ] || fail "$pkg: Description: expected a synopsis line, got none"
  [ -z "${synopsis_owner[$synopsis]:-}" ] ||
    fail "$pkg: Description: the synopsis '$synopsis' is also ${synopsis_owner[$synopsis]}'s"
  synopsis_owner[$synopsis]=$pkg
  [ "$(sed -n 2p <<<"$description" | sed 's/^ *//')" != "$synopsis" ] ||
    fail "$pkg: Description: the long part repeats the synopsis '$synopsis'"
  [ "$(tail -n +2 <<<"$description" | grep -c .)" -ge 1 ] || fail "$pkg: Description: no long part"
  unindented=$(tail -n +2 <<<"$description" | grep -v '^ ' || true)
  [ -z "$unindented" ] || fail "$pkg: Description: long-part line not indented: $(head -n 1 <<<"$unindented")"

  # Depends, as written (one entry a line) and as package names (versions, alternatives and
  # :any stripped).
  field "$pkg" Depends | tr ',' '\n' | sed 's/^[ \t]*//; s/[ \t]*$//' | sed '/^$/d' \
    >"$scratch/$pkg.depends-entries.txt"
  tr '|' '\n' <"$scratch/$pkg.depends-entries.txt" |
    sed 's/(.*)//; s/:any//; s/^[ \t]*//; s/[ \t]*$//' | sed '/^$/d' | sort -u \
    >"$scratch/$pkg.depends.txt"

  # The file list: the tar member names without their ./, folders ending in /.
  dpkg-deb --fsys-tarfile "$deb" >"$scratch/$pkg.tar"
  tar -tf "$scratch/$pkg.tar" | sed 's|^\./||; /^$/d' >"$scratch/$pkg.contents.txt"
  grep -v '/$' "$scratch/$pkg.contents.txt" >"$scratch/$pkg.files.txt" || true
  dpkg -x "$deb" "$root"

  # Nothing outside usr/, nothing under /usr/local.
  outside=$(grep -v '^usr/' "$scratch/$pkg.contents.txt" || true)
  [ -z "$outside" ] || fail "$pkg: file list: expected only usr/, found also: $(head -n 1 <<<"$outside")"
  grep -q '^usr/local/' "$scratch/$pkg.contents.txt" &&
    fail "$pkg: file list: /usr/local in the package (prefix not /usr)"

  while read -r file; do
    [ -n "$file" ] || continue
    grep -Fqx "$file" "$scratch/$pkg.files.txt" || fail "$pkg: file list: expected /$file, not in the package"
  done <<<"${expected_files[$pkg]}"
  # read -a, not an unquoted expansion: the patterns must not be expanded against this folder.
  read -ra patterns <<<"${allowed[$pkg]}"
  while read -r file; do
    ok=""
    for pattern in "${patterns[@]}"; do
      # shellcheck disable=SC2053  # $pattern is a glob on purpose
      [[ $file == $pattern ]] && { ok=1; break; }
    done
    [ -n "$ok" ] || fail "$pkg: file list: /$file is not this package's (expected only ${allowed[$pkg]})"
  done <"$scratch/$pkg.files.txt"

  cmp -s "$root/usr/share/doc/$pkg/copyright" "$source_dir/LICENSE" ||
    fail "$pkg: /usr/share/doc/$pkg/copyright: expected the text of LICENSE"

  # The peers (GPL: GSL, cubature) stay out by name and by link; the library's own Genz-Malik
  # header rules/adaptive_cubature.hpp is no peer, so file names alone cannot say "cubature".
  grep -Eq 'quadmc_peers|/peers/|_tests|_bench' "$scratch/$pkg.contents.txt" &&
    fail "$pkg: file list: a peer, test or benchmark file is in the package: $(grep -m 1 -E 'quadmc_peers|/peers/|_tests|_bench' "$scratch/$pkg.contents.txt")"

  # Every shared library an ELF file of the package loads comes from a package it depends on.
  while read -r file; do
    [[ $(file -b "$root/$file") == ELF* ]] || continue
    readelf -d "$root/$file" | sed -n 's/.*(NEEDED).*\[\(.*\)\].*/\1/p' >"$scratch/needed.txt"
    [ -s "$scratch/needed.txt" ] || fail "$pkg: /$file: readelf found no NEEDED library"
    grep -Eq '^lib(gsl|cubature)' "$scratch/needed.txt" &&
      fail "$pkg: /$file links a GPL peer library: $(grep -m 1 -E '^lib(gsl|cubature)' "$scratch/needed.txt")"
    while read -r soname; do
      path=$(awk -v soname="$soname" '$1 == soname { print $NF; exit }' "$scratch/ldconfig.txt")
      if [ -z "$path" ]; then
        fail "$pkg: /$file needs $soname, which this machine cannot find (ldconfig -p)"
        continue
      fi
      # dpkg -S answers "package:arch: /path"; the path may be registered under /lib or /usr/lib.
      owner=$(dpkg -S "$path" 2>/dev/null || dpkg -S "$(realpath "$path")" 2>/dev/null ||
        dpkg -S "${path#/usr}" 2>/dev/null || true)
      owner=${owner%%:*}
      if [ -z "$owner" ]; then
        fail "$pkg: /$file needs $soname ($path), which no installed package owns"
      elif ! grep -Fqx "$owner" "$scratch/$pkg.depends.txt"; then
        fail "$pkg: Depends: /$file needs $soname from $owner, which Depends lacks: $(field "$pkg" Depends)"
      fi
    done <"$scratch/needed.txt"
  done <"$scratch/$pkg.files.txt"
done

# No file in two packages.
shared=$(for pkg in "${packages[@]}"; do cat "$scratch/$pkg.files.txt"; done | sort | uniq -d)
[ -z "$shared" ] || fail "file list: in two packages: $(head -n 1 <<<"$shared")"

# --- the relations between them ---------------------------------------------------------------
depends_on() { grep -Fqx "$2" "$scratch/$1.depends.txt"; }
has_depends_entry() { grep -Fqx "$2" "$scratch/$1.depends-entries.txt"; }

# The command and the module are used without the library's headers: no -dev package.
for pkg in quadmc python3-quadmc; do
  dev=$(grep -- '-dev$' "$scratch/$pkg.depends.txt" || true)
  [ -z "$dev" ] || fail "$pkg: Depends: expected no -dev package, got $(tr '\n' ' ' <<<"$dev")"
done
recommends=$(field quadmc Recommends | tr ',' '\n' | sed 's/^[ \t]*//; s/[ \t(].*//')
for recommended in python3 python3-matplotlib; do
  grep -qx "$recommended" <<<"$recommends" ||
    fail "quadmc: Recommends: expected $recommended (the plots), got '$(field quadmc Recommends)'"
done

# quadmcConfig.cmake find_dependency()s these (lib/cmake/quadmcConfig.cmake.in); the installed
# headers include theirs. quadmc::command's scripts folder, /usr/share/quadmc, is quadmc's.
for dev in libfmt-dev libboost-dev libtomlplusplus-dev librandom123-dev libquadrule-dev \
  libquantlib0-dev libfftw3-dev libcli11-dev; do
  depends_on libquadmc-dev "$dev" ||
    fail "libquadmc-dev: Depends: expected $dev (quadmcConfig.cmake needs it), got: $(field libquadmc-dev Depends)"
done
has_depends_entry libquadmc-dev "quadmc (= $expected_version)" ||
  fail "libquadmc-dev: Depends: expected 'quadmc (= $expected_version)' (quadmc::command's scripts), got: $(field libquadmc-dev Depends)"

for entry in "python3 (>= $python_version)" "python3 (<< $python_next)" python3-numpy; do
  has_depends_entry python3-quadmc "$entry" ||
    fail "python3-quadmc: Depends: expected '$entry' (the module's $ext_suffix), got: $(field python3-quadmc Depends)"
done

for program in usr/bin/quadmc usr/share/quadmc/plot.py; do
  [ -x "$root/$program" ] || fail "/$program: expected an executable file"
done

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

# The module from the extracted dist-packages, with Debian's python3 as the package's user has it
# (-s: no user site-packages). Its points are the extracted command's, bit for bit.
pythonpath=$root/$dist_packages
if (cd "$scratch" && PYTHONPATH=$pythonpath /usr/bin/python3 -s -c \
      'import quadmc; print(quadmc.points("sobol", 4, 2, seed=1))' \
      >"$scratch/python_points.txt" 2>"$scratch/python_points.err"); then
  if "$quadmc" points sobol --n 4 --s 2 --seed 1 --out "$scratch/points.csv" \
       >/dev/null 2>"$scratch/points.err"; then
    (cd "$scratch" && PYTHONPATH=$pythonpath /usr/bin/python3 -s - "$root" "$scratch/points.csv" \
       >"$scratch/python_compare.txt" 2>&1 <<'PYTHON'
import sys
import quadmc
root, csv = sys.argv[1:]
if not quadmc.__file__.startswith(root + "/"):
    sys.exit(f"imported {quadmc.__file__}, not the extracted package's")
with open(csv, encoding="utf-8") as f:
    lines = f.read().splitlines()
expected = [[float(v) for v in line.split(",")] for line in lines[1:]]
got = quadmc.points("sobol", 4, 2, seed=1).tolist()
if got != expected:
    sys.exit(f"points {got}, the command's {expected}")
PYTHON
    ) || fail "import quadmc: quadmc.points(\"sobol\", 4, 2, seed=1) is not quadmc points' CSV: $(tail -n 1 "$scratch/python_compare.txt")"
  else
    fail "quadmc points sobol --n 4 --s 2 --seed 1 failed: $(tail -n 1 "$scratch/points.err")"
  fi
else
  fail "import quadmc from $pythonpath failed: $(tail -n 1 "$scratch/python_points.err")"
fi

for pkg in "${packages[@]}"; do
  echo "package $(basename "${deb_of[$pkg]}"): $(grep -c '' "$scratch/$pkg.contents.txt") entries"
  echo "  Depends: $(field "$pkg" Depends)"
  recommends=$(field "$pkg" Recommends)
  [ -z "$recommends" ] || echo "  Recommends: $recommends"
done
if [ "$failures" -gt 0 ]; then
  echo "check_package.sh: $failures check(s) failed" >&2
  exit 1
fi
echo "check_package.sh: every check passed"
