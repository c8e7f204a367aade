// The extension `_quadmc` behind `import quadmc` (bindings.hpp): one line per concept's file.
#include "bindings.hpp"

PYBIND11_MODULE(_quadmc, m) {
  m.doc() = "quadmc's point sets, discrepancies, integrands and methods over numpy arrays";
  quadmc_python::add_errors(m);
  quadmc_python::add_points(m);
  quadmc_python::add_discrepancy(m);
  quadmc_python::add_catalogue(m);
  quadmc_python::add_integrand(m);
  quadmc_python::add_integrate(m);
  quadmc_python::add_run(m);
}
