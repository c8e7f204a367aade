// quadmc.run (quadmc/__init__.py) over _quadmc._run_file and _run_text: a scene parsed, planned,
// run and analysed by scene/run_scene.hpp, the pipeline of `quadmc run`, held as a SceneRun whose
// CSV texts are those of the command's results folder (report/results_csv.hpp) and whose write
// gives that folder (report/write_results.hpp, with this build's provenance in meta.csv).
//
// The GIL is released while the scene is planned and run. Ctrl-C: Python's handler only sets a
// flag while C++ runs, so the runner's progress callback (run_options::on_progress, after each
// repetition and each cell) takes the GIL, lets Python run its handlers (PyErr_CheckSignals) and
// throws the KeyboardInterrupt they raise; the runner unwinds (nothing is written before the run
// ends) and pybind11 raises it in Python.
#include "bindings.hpp"

#include "build_provenance.hpp"
#include "quadmc/report/results_csv.hpp"
#include "quadmc/report/write_results.hpp"
#include "quadmc/scene/parse.hpp"
#include "quadmc/scene/run_scene.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <utility>

namespace py = pybind11;

namespace quadmc_python {

namespace {

using results_ptr = std::shared_ptr<quadmc::scene_results>;

quadmc::run_options options_of(const py::object& threads) {
  quadmc::run_options options;
  if (!threads.is_none()) options.threads = static_cast<unsigned>(to_count(threads, "threads", 0));
  options.on_progress = [](const quadmc::run_progress&) {
    const py::gil_scoped_acquire held;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
  return options;
}

results_ptr run(quadmc::scene scene, const py::object& threads) {
  const quadmc::run_options options = options_of(threads);
  const py::gil_scoped_release unlocked;
  quadmc::plan plan = quadmc::plan_scene(std::move(scene), options);
  return std::make_shared<quadmc::scene_results>(quadmc::run_scene(std::move(plan), options));
}

results_ptr run_file(const std::string& path, const py::object& threads) {
  return run(quadmc::parse_scene_file(path), threads);
}

results_ptr run_text(const std::string& text, const std::string& file_name,
                     const py::object& threads) {
  return run(quadmc::parse_scene(text, file_name), threads);
}

std::string convergence_csv(const quadmc::scene_results& r) {
  return quadmc::convergence_csv_text(r.plan.source.name, r.tables);
}

std::string slopes_csv(const quadmc::scene_results& r) {
  return quadmc::slopes_csv_text(r.plan.source.name, r.tables);
}

// The folder `quadmc run --out folder` writes; plots only with a plot script (an empty path: none,
// whatever the scene's [output] says).
std::string write(const quadmc::scene_results& r, const std::string& folder,
                  const std::string& plot_script) {
  quadmc::results_options options;
  options.build = quadmc::bench::build_provenance();
  options.plot_script = plot_script;
  const py::gil_scoped_release unlocked;
  return quadmc::write_results(std::filesystem::path(folder), r, options);
}

}  // namespace

void add_run(py::module_& m) {
  py::class_<quadmc::scene_results, results_ptr>(m, "SceneRun",
                                                 "A scene's results in memory (quadmc.run).")
      .def_property_readonly("name",
                             [](const quadmc::scene_results& r) { return r.plan.source.name; })
      .def_property_readonly("seconds",
                             [](const quadmc::scene_results& r) { return r.run.seconds; })
      .def_property_readonly("threads",
                             [](const quadmc::scene_results& r) { return r.run.threads; })
      .def("convergence_csv", &convergence_csv, "convergence.csv's text as `quadmc run` writes it.")
      .def("slopes_csv", &slopes_csv, "slopes.csv's text as `quadmc run` writes it.")
      .def("write", &write, py::arg("folder"), py::arg("plot_script"),
           "Writes the results folder; returns 'wrote <folder>'.");
  m.def("_run_file", &run_file, py::arg("path"), py::arg("threads"));
  m.def("_run_text", &run_text, py::arg("text"), py::arg("file_name"), py::arg("threads"));
}

}  // namespace quadmc_python
