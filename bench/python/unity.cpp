// The module's one translation unit: every other source of bench/python/ included once. pybind11's
// and numpy's headers are most of each file's compile, so they are parsed once; and the object
// comes from this file of the source tree in every build folder, so that ccache, which hashes the
// path of the file it compiles, hands it from one preset's build to the next (a CMake unity source
// lives in the build folder: the test, release and package presets compiled the module once each).
// bench/python/CMakeLists.txt checks at configure time that no source is left out.
#include "catalogue.cpp"
#include "discrepancy.cpp"
#include "errors.cpp"
#include "integrand.cpp"
#include "integrate.cpp"
#include "module.cpp"
#include "points.cpp"
#include "run.cpp"
