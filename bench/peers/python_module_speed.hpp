// The Python module `quadmc` (bench/python/) timed as a Python user meets it: quadmc.points
// against scipy.stats.qmc's scrambled Sobol' points, and quadmc.integrate on an integrand written
// in numpy against the same integrand from the catalogue (C++), with the decompositions that
// explain the ratios (a fresh array's first touch; the per-batch call of a Python integrand).
//
// Use it from the peers driver (quadmc_peers.cpp). It runs bench/peers/python_module_speed.py
// once, in a /usr/bin/python3 subprocess with PYTHONPATH set to the module's folder of this
// build: one interpreter, every contender of a group in alternating rounds, the median of the
// rounds kept with their range. Not for the C++ kernels' own speed (the throughput and QMC point
// rows are), and never asserted: the README's figures are read from its rows.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace quadmc::peers {

// One contender of python_module_speed.py, as it prints it (seconds).
struct python_timing {
  std::string group;  // "points", "points_reused" or "integrand"
  std::string key;    // e.g. "quadmc_points", "integrate_numpy" (the script's docstring)
  std::size_t s = 0;
  std::uint64_t n = 0;  // points, or evaluations of the integrand
  double median = 0.0, min = 0.0, max = 0.0;
  int rounds = 0;
  double cores = 0.0;  // process CPU time / wall time over its rounds
};

struct python_module_study {
  std::string versions;  // "numpy V, scipy V", as the script reports them
  std::vector<python_timing> timings;
  std::string skipped;  // why nothing was measured (no module in this build, a failed run), or ""

  // The timing of (group, key), or nullptr.
  const python_timing* find(const std::string& group, const std::string& key) const;
};

// Runs `script` (python_module_speed.py) with `python` and PYTHONPATH = module_dir for `rounds`
// rounds with `seed`. An empty module_dir (the module is not built here), or a run that fails,
// gives an empty study whose `skipped` says why.
python_module_study measure_python_module(const std::string& python, const std::string& script,
                                          const std::string& module_dir, int rounds,
                                          std::uint64_t seed);

// The method, family and integrand columns of a contender's peers.csv row (no commas).
struct python_row_names {
  std::string method, family, integrand;
};
python_row_names names_of(const python_timing& t);

}  // namespace quadmc::peers
