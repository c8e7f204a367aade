# The Debian packages of quadmc: `cpack -G DEB` in a build folder (./run.sh package uses the
# `package` preset, prefix /usr, and checks the result with tests/package/check_package.sh).
#
# Three packages, split as Debian splits a library with a program (one per install COMPONENT,
# CPACK_DEB_COMPONENT_INSTALL), each <package>_<version>_<arch>.deb:
#  - quadmc (COMPONENT command): the `quadmc` command, its plot scripts and scenes
#    (share/quadmc/), and the license, README, changelog and citation (share/doc/quadmc/). It
#    depends only on the shared libraries the command loads, so a user of the command installs no
#    -dev package;
#  - libquadmc-dev (COMPONENT dev): the library's headers, static archives (quadmc::command's
#    among them) and CMake package files (find_package(quadmc));
#  - python3-quadmc (COMPONENT python): the module `import quadmc` in Debian's
#    /usr/lib/python3/dist-packages/, when the build has it (QUADMC_WITH_PYTHON).
# The GPL peers (bench/peers: GSL, cubature) are never installed, so every package is MIT.
#
# Dependencies, as Debian package names:
#  - quadmc: Depends, the command's shared libraries (libc6, libstdc++6, libgcc-s1, libfmt9, …),
#    found by dpkg-shlibdeps from the binary when it and `file` are installed (dpkg-dev, file),
#    else the Debian 12 list below; Recommends, python3 and python3-matplotlib: only the plots
#    need them (a run with plots on and no matplotlib is refused in one line before it computes
#    anything; CSV and Markdown need neither);
#  - libquadmc-dev: Depends, what the installed CMake package files find_dependency() (the -dev
#    packages of fmt, Boost, toml++, Random123, quadrule, QuantLib and FFTW, whose headers or libraries
#    the library's use, and CLI11, which quadmc::command links), and quadmc of the same version:
#    quadmc::command compiles the path /usr/share/quadmc (QUADMC_COMMAND_SCRIPTS,
#    bench/CMakeLists.txt) into the commands built on it, and the quadmc package ships that folder;
#  - python3-quadmc: Depends, the Python the extension was built for (its ABI tag, e.g.
#    cpython-311, loads into that minor version only), numpy (the module returns arrays), and the
#    extension's shared libraries (dpkg-shlibdeps, as for the command).
include_guard(GLOBAL)

set(CPACK_PACKAGE_NAME quadmc)
set(CPACK_PACKAGE_VENDOR "the quadmc authors")
set(CPACK_PACKAGE_CONTACT
    "quadmc maintainers <maintainers@users.noreply.h-seed-f5053aa5.example>")
# No CPACK_PACKAGE_DESCRIPTION_SUMMARY: CPack would put that one synopsis before every package's
# description, and each of the three needs its own (the first line of its description below).
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_GENERATOR DEB)
# Release binaries are stripped, as Debian policy asks (static archives are left as they are).
set(CPACK_STRIP_FILES ON)

# One .deb per install COMPONENT, named by CPACK_DEBIAN_<COMPONENT>_PACKAGE_NAME.
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL command dev)
if(QUADMC_WITH_PYTHON)
  list(APPEND CPACK_COMPONENTS_ALL python)
endif()
set(CPACK_DEBIAN_COMMAND_PACKAGE_NAME quadmc)
set(CPACK_DEBIAN_DEV_PACKAGE_NAME libquadmc-dev)
set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-quadmc)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # <package>_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# Debian's archive sections of each kind of package.
set(CPACK_DEBIAN_COMMAND_PACKAGE_SECTION science)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)

# The Descriptions: the synopsis line, then the long part. CPack indents the long part as
# deb-control(5) asks (an empty line becomes " ."), so it is written here unindented.
set(quadmc_description_common
    "quadmc measures how fast numerical integrators converge and what each digit
costs: deterministic quadrature (midpoint, trapezoid, Simpson, Gauss-Legendre,
Romberg, tensor products in s dimensions) against Monte Carlo (plain,
importance, stratified, Latin hypercube) on test functions with exact
integrals, fitting error-vs-N slopes with confidence intervals beside theory.")
set(CPACK_DEBIAN_COMMAND_DESCRIPTION
    "convergence of quadrature rules against Monte Carlo (command)
${quadmc_description_common}

This package holds the quadmc command (scene files in, CSV, Markdown and SVG
results out), its plot scripts and its scenes.")
set(CPACK_DEBIAN_DEV_DESCRIPTION
    "convergence of quadrature rules against Monte Carlo (C++20 library)
${quadmc_description_common}

This package holds the C++20 library: its headers, static libraries and CMake
package files (find_package(quadmc)), and quadmc::command, the command as a
library for building a command with one's own integrands and methods.")
set(CPACK_DEBIAN_PYTHON_DESCRIPTION
    "convergence of quadrature rules against Monte Carlo (Python 3 module)
${quadmc_description_common}

This package holds the Python 3 module quadmc: the point sets, discrepancies,
integrands and method listings of the library as numpy arrays.")

# dpkg-shlibdeps runs on each package's ELF files (the command, the extension); the archives of
# libquadmc-dev have none.
find_program(QUADMC_DPKG_SHLIBDEPS dpkg-shlibdeps)
find_program(QUADMC_FILE_COMMAND file)
if(QUADMC_DPKG_SHLIBDEPS AND QUADMC_FILE_COMMAND)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
  set(quadmc_runtime_depends "")
else()
  message(STATUS "dpkg-shlibdeps or file not found (packages dpkg-dev, file): the Debian "
                 "packages declare the Debian 12 runtime libraries by name instead")
  set(quadmc_runtime_depends "libc6, libstdc++6, libgcc-s1, libfmt9, libtomlplusplus3, libquadrule1, libquantlib0v5, libfftw3-double3")
endif()
# No CPACK_DEBIAN_PACKAGE_DEPENDS: a component without its own Depends would inherit it.
set(CPACK_DEBIAN_COMMAND_PACKAGE_DEPENDS "${quadmc_runtime_depends}")
set(CPACK_DEBIAN_COMMAND_PACKAGE_RECOMMENDS "python3, python3-matplotlib")
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS
    "quadmc (= ${PROJECT_VERSION}), libfmt-dev, libboost-dev (>= 1.74), libtomlplusplus-dev, librandom123-dev, libquadrule-dev, libquantlib0-dev, libfftw3-dev, libcli11-dev")
if(QUADMC_WITH_PYTHON)
  math(EXPR quadmc_python_next_minor "${Python3_VERSION_MINOR} + 1")
  set(quadmc_python_depends
      "python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}), python3 (<< ${Python3_VERSION_MAJOR}.${quadmc_python_next_minor}), python3-numpy")
  if(quadmc_runtime_depends)
    string(APPEND quadmc_python_depends ", ${quadmc_runtime_depends}")
  endif()
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "${quadmc_python_depends}")
endif()

include(CPack)
