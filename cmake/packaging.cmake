# The Debian package of quadmc: `cpack -G DEB` in a build folder (./run.sh package uses the
# `package` preset, prefix /usr, and checks the result with tests/package/check_package.sh).
#
# One package, quadmc_<version>_<arch>.deb, holding everything `cmake --install` installs: the
# `quadmc` command with its plot script and scenes (share/quadmc/), the library's static archives,
# headers and CMake package files (find_package(quadmc)), and the license, changelog and citation
# (share/doc/quadmc/). The GPL peers (bench/peers: GSL, cubature) are never installed, so the
# package is MIT throughout.
#
# Dependencies, as Debian package names:
#  - Depends, the command's shared libraries (libc6, libstdc++6, libgcc-s1, libfmt9, …), found by
#    dpkg-shlibdeps from the binary when it and `file` are installed (dpkg-dev, file), else the
#    Debian 12 list below;
#  - Depends, what the installed CMake package files find_dependency(): the -dev packages of fmt,
#    Boost, toml++ and Random123 (the library's headers include theirs) and CLI11 (quadmc::command
#    links it);
#  - Recommends, python3 and python3-matplotlib: only the plots need them (a run with plots on and
#    no matplotlib is refused in one line before it computes anything; CSV and Markdown need
#    neither).
include_guard(GLOBAL)

set(CPACK_PACKAGE_NAME quadmc)
set(CPACK_PACKAGE_VENDOR "the quadmc authors")
set(CPACK_PACKAGE_CONTACT
    "quadmc maintainers <maintainers@users.noreply.h-seed-f5053aa5.example>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "convergence of quadrature rules against Monte Carlo (command and C++20 library)")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_GENERATOR DEB)
# Release binaries are stripped, as Debian policy asks (static archives are left as they are).
set(CPACK_STRIP_FILES ON)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # quadmc_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# The Description's long part. CPack puts CPACK_PACKAGE_DESCRIPTION_SUMMARY before it as the
# synopsis line and indents it as deb-control(5) asks (an empty line becomes " ."), so it is
# written here unindented and without the synopsis.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "quadmc measures how fast numerical integrators converge and what each digit
costs: deterministic quadrature (midpoint, trapezoid, Simpson, Gauss-Legendre,
Romberg, tensor products in s dimensions) against Monte Carlo (plain,
importance, stratified, Latin hypercube) on test functions with exact
integrals, fitting error-vs-N slopes with confidence intervals beside theory.

This package holds the quadmc command (scene files in, CSV, Markdown and SVG
results out), its scenes, and the C++20 library with its headers and CMake
package files (find_package(quadmc)).")

find_program(QUADMC_DPKG_SHLIBDEPS dpkg-shlibdeps)
find_program(QUADMC_FILE_COMMAND file)
if(QUADMC_DPKG_SHLIBDEPS AND QUADMC_FILE_COMMAND)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
  set(quadmc_runtime_depends "")
else()
  message(STATUS "dpkg-shlibdeps or file not found (packages dpkg-dev, file): the Debian "
                 "package declares the Debian 12 runtime libraries by name instead")
  set(quadmc_runtime_depends "libc6, libstdc++6, libgcc-s1, libfmt9, libtomlplusplus3, ")
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "${quadmc_runtime_depends}libfmt-dev, libboost-dev (>= 1.74), libtomlplusplus-dev, librandom123-dev, libquadrule-dev, libquantlib0-dev, libcli11-dev")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3, python3-matplotlib")

include(CPack)
