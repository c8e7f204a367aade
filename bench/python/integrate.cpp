// quadmc.integrate (quadmc/__init__.py) over _quadmc._integrate: one method of the registry
// (methods/registry.hpp, make_method) run on one integrand at one N, `repetitions` times, each
// repetition the call a scene's cell makes (methods/method.hpp, method::run), so that the same
// method, N, seed and integrand name give the values a scene gives.
//
// The integrand is a catalogue Integrand (integrand.cpp) or any Python callable f taking an
// (m, s) float64 array of points in [0, 1]^s and returning m values. The callable is wrapped as
// an integrand of the batch contract (docs/design.md#hot-path-contract) whose evaluate takes the
// GIL and calls f once per block it is given. It asks the fixed-N kernels for blocks of up to
// 2^14 points (integrand_info::evaluation_block; at most 16 MiB of points, so 2^11 at s = 1024;
// a Monte Carlo chunk holds 12288): each call of f costs a few microseconds of Python, which on
// the kernel's own 256-point batches was a quarter of a numpy integrand's time (the README's
// Python section measures it). The kernels still generate points and sum per 256-point batch
// (core/batching.hpp), so the bits are those of any other block size. Methods that adapt
// between batches (VEGAS, Genz–Malik, the adaptive sparse grid) need a batch's values before
// they choose the next, and call f on their own batches.
//
// Threads: a callable runs on one thread (run_context::threads = 1): the GIL serialises every
// call of f anyway, so more threads would only contend for it. Results do not depend on the
// thread count (parallel_reduce folds its chunks in chunk order, core/parallel_reduce.hpp), so
// this costs no reproducibility. A catalogue integrand runs with the GIL released on `threads`
// (0 = all cores).
//
// Streams: repetition r uses stream_id({name_id(name), 0, name_id(label), N, r}) keyed by `seed`,
// the stream a scene with that seed gives the cell (integrand `name`, its instance 0, the method's
// default label, budget.N = N, repetition r: lib/src/scene/plan.cpp), drawn by the generator `rng`
// names, as a scene's top-level `rng` (run_context::rng; Philox4x32-10 by default, or ARS-4x32-7:
// docs/theory.md#counter-based-generators). The same arguments give the same bits.
//
// Errors: an exception raised by f leaves evaluate as pybind11's error_already_set, unwinds the
// kernel (parallel_reduce rethrows the lowest chunk's exception after joining), and pybind11
// restores the original Python exception with its traceback. A NaN or ±inf from f is the
// kernels' non_finite_value naming the point (check_finite_batch, functions/integrand.hpp), a
// wrong-length return an invalid_argument naming f: both ValueError (errors.cpp). A method it
// cannot run (one that runs only to a tolerance, an irradiance method) is a ValueError naming the
// method, raised before f is evaluated once.
#include "bindings.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/core/parallel_reduce.hpp"
#include "quadmc/core/rng.hpp"
#include "quadmc/functions/any_integrand.hpp"
#include "quadmc/methods/option_map.hpp"
#include "quadmc/methods/registry.hpp"

#include <pybind11/numpy.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace quadmc_python {

namespace {

using value_array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A Python callable as an integrand on [0, 1]^s. Holds f borrowed (the caller's reference keeps
// it alive for the run): no reference count changes without the GIL.
class python_integrand {
 public:
  python_integrand(PyObject* f, std::size_t s) : f_(f), info_{} {
    info_.name = "f";
    info_.formula = "a Python callable";
    info_.domain = quadmc::box::unit(s);
    constexpr std::size_t most_points = std::size_t{1} << 14;
    constexpr std::size_t most_doubles = std::size_t{1} << 21;  // 16 MiB of points
    info_.evaluation_block = std::min(most_points, most_doubles / s);
  }

  std::size_t dimension() const noexcept { return info_.dimension(); }
  const quadmc::integrand_info& info() const noexcept { return info_; }

  void evaluate(std::span<const double> x, std::span<double> y) const {
    const py::gil_scoped_acquire held;
    const std::size_t s = dimension();
    py::array_t<double> points({static_cast<py::ssize_t>(y.size()), static_cast<py::ssize_t>(s)});
    std::copy(x.begin(), x.end(), points.mutable_data());
    const value_array values(py::handle(f_)(points));  // error_already_set if f or the cast fails
    if (values.ndim() != 1 || static_cast<std::size_t>(values.shape(0)) != y.size()) {
      std::vector<py::ssize_t> extents(values.shape(), values.shape() + values.ndim());
      throw quadmc::invalid_argument(
          "f",
          fmt::format("an array of shape ({}{}) for {} points", fmt::join(extents, ", "),
                      extents.size() == 1 ? "," : "", y.size()),
          fmt::format("{} values, one per point (shape ({},))", y.size(), y.size()));
    }
    std::copy(values.data(), values.data() + y.size(), y.begin());
  }

 private:
  PyObject* f_;
  quadmc::integrand_info info_;
};

quadmc::option_table to_option_table(const py::dict& options);

// One [[method]] key as the scene gives it: a bool, a number, a string, an array of numbers, or
// a table (importance's warp = { name = "power", exponent = 2 }).
quadmc::option_value to_option_value(const std::string& key, const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (is_number(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::dict>(value)) {
    return to_option_table(py::reinterpret_borrow<py::dict>(value));
  }
  if (py::isinstance<py::sequence>(value)) {
    if (std::optional<std::vector<double>> numbers = numbers_of(value)) return *numbers;
    throw quadmc::invalid_argument(key, quoted(value), "a sequence of numbers");
  }
  throw quadmc::invalid_argument(key, quoted(value),
                                 "a bool, a number, a string, a sequence of numbers or a dict");
}

quadmc::option_table to_option_table(const py::dict& options) {
  quadmc::option_table table;
  for (const auto& [key, value] : options) {
    const std::string name = py::str(key);
    table.emplace(name, to_option_value(name, value));
  }
  return table;
}

// f as an integrand: a catalogue Integrand (s, when given, must be its dimension) or a callable
// (s required).
quadmc::any_integrand to_integrand(const py::object& f, const py::object& s) {
  if (py::isinstance<quadmc::any_integrand>(f)) {
    auto integrand = f.cast<quadmc::any_integrand>();
    if (!s.is_none() && to_count(s, "s", 1) != integrand.dimension()) {
      throw quadmc::invalid_argument(
          "s", quoted(s), fmt::format("None or {}, the dimension of f", integrand.dimension()));
    }
    return integrand;
  }
  if (!PyCallable_Check(f.ptr())) {
    throw quadmc::invalid_argument("f", quoted(f), "a quadmc.Integrand or a callable");
  }
  if (s.is_none()) {
    throw quadmc::invalid_argument("s", "None",
                                   "the dimension of the points f takes (f is a callable)");
  }
  return quadmc::any_integrand(python_integrand(f.ptr(), to_count(s, "s", 1)));
}

// The cell's size for N, or ValueError with the method's reason. Explicit sizes (a rule's
// `panels`, a file's `points`) replace budget.N in a scene, whose cells then have N = their
// evaluations (lib/src/scene/plan.cpp); here n picks one of them by that N.
quadmc::cell_size size_of(const quadmc::method& m, std::uint64_t n, std::size_t s) {
  const std::vector<quadmc::sizing> explicit_sizes = m.explicit_sizes(s);
  if (!explicit_sizes.empty()) {
    std::vector<std::uint64_t> counts;
    for (const quadmc::sizing& sized : explicit_sizes) {
      if (!sized.size) continue;
      if (sized.size->evaluations == n) return *sized.size;
      counts.push_back(sized.size->evaluations);
    }
    throw quadmc::invalid_argument("n", quadmc::quote(n),
                                   fmt::format("one of the sizes `{}` gives: [{}] evaluations",
                                               m.explicit_sizes_key(), fmt::join(counts, ", ")));
  }
  const quadmc::sizing sized = m.size_for(n, s);
  if (!sized.size) {
    throw quadmc::invalid_argument(
        "n", quadmc::quote(n),
        fmt::format("an N {} can size: {}", m.descriptor().name, sized.reason));
  }
  return *sized.size;
}

// What the method runs: its default control (the first it supports). A scene may run a method to
// a tolerance; quadmc.integrate sizes every cell from n, so a method that supports no other
// control cannot run here.
quadmc::cell_control control_of(const quadmc::method& m) {
  const quadmc::cell_control control = m.descriptor().controls.front();
  if (!m.descriptor().supports(quadmc::cell_control::fixed_size) &&
      !m.descriptor().supports(quadmc::cell_control::budget)) {
    const std::string_view name = m.descriptor().name;
    throw quadmc::invalid_argument(
        "method", name,
        fmt::format("a method that runs at a size or a budget N = n ({} runs only to a "
                    "tolerance, which quadmc.integrate does not take: run it in a scene)",
                    name));
  }
  return control;
}

// The irradiance methods (lib/src/methods/irradiance_methods.cpp) take a rendering integrand
// only, and read its light and surface from the instance's integrand_params (method_cell::params),
// not from f: an Integrand does not carry those, and a callable has none, so quadmc.integrate
// refuses them by name, whatever f is, rather than calling an irradiance integrand "not a
// rendering integrand" as the method's own incompatibility would. Asked of the method itself
// (refuses every integrand but a rendering one), so a new method of that kind is refused too.
void refuse_rendering_only(const quadmc::method& m, std::size_t s) {
  const std::string_view name = m.descriptor().name;
  const bool takes_rendering = !m.incompatibility({name, s, true});
  const bool takes_other = !m.incompatibility({name, s, false});
  if (takes_rendering && !takes_other) {
    throw quadmc::invalid_argument(
        "method", name,
        fmt::format("a method that integrates f from its values ({} estimates irradiance "
                    "from the light and surface of a scene's irradiance integrand, which "
                    "quadmc.integrate does not pass: run it in a scene, quadmc.run)",
                    name));
  }
}

struct integration {
  std::string label;
  quadmc::error_bars bars = quadmc::error_bars::own;
  std::vector<quadmc::repetition_result> repetitions;
};

// Stops between repetitions when Python has a signal to handle (Ctrl-C).
void check_signals() {
  const py::gil_scoped_acquire held;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

integration run_repetitions(const quadmc::method& m, const quadmc::any_integrand& f,
                            const quadmc::cell_size& size, quadmc::cell_control control,
                            std::uint64_t n, std::uint64_t repetitions, const std::string& name,
                            const quadmc::run_context& context) {
  integration out{std::string(m.descriptor().name) + m.label_suffix(), m.error_bars(), {}};
  quadmc::integrand_params params;
  params.dimension = f.dimension();
  const py::gil_scoped_release unlocked;
  for (std::uint64_t r = 0; r < repetitions; ++r) {
    const std::uint64_t stream =
        quadmc::stream_id({quadmc::name_id(name), 0, quadmc::name_id(out.label), n, r});
    const quadmc::method_cell cell{f, params, size, control, NAN, stream, r};
    const auto t0 = std::chrono::steady_clock::now();
    quadmc::repetition_result result = m.run(cell, context);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out.repetitions.push_back(result);
    check_signals();
  }
  return out;
}

py::dict to_dict(const integration& done, std::uint64_t n) {
  py::list values, std_errors, error_estimates, evaluations, seconds;
  for (const quadmc::repetition_result& r : done.repetitions) {
    values.append(r.value);
    std_errors.append(r.std_error);
    error_estimates.append(r.error_estimate);
    evaluations.append(r.evaluations);
    seconds.append(r.seconds);
  }
  py::dict out;
  out["method"] = done.label;
  out["n"] = n;
  out["replicates"] = done.bars == quadmc::error_bars::replicates;
  out["values"] = values;
  out["std_errors"] = std_errors;
  out["error_estimates"] = error_estimates;
  out["evaluations"] = evaluations;
  out["seconds"] = seconds;
  return out;
}

py::dict integrate(const py::object& f, const std::string& method, const py::object& n,
                   const py::object& s, const py::object& seed, const py::object& repetitions,
                   const py::object& threads, const py::object& name, const py::object& rng,
                   const py::dict& options) {
  const quadmc::any_integrand integrand = to_integrand(f, s);
  const bool callable = !py::isinstance<quadmc::any_integrand>(f);
  const auto thread_count = static_cast<unsigned>(to_count(threads, "threads", 0));
  if (callable && thread_count > 1) {
    throw quadmc::invalid_argument("threads", quoted(threads),
                                   "0 or 1 for a Python callable (the GIL serialises f)");
  }
  const std::unique_ptr<const quadmc::method> m =
      quadmc::make_method(method, to_option_table(options));
  const std::size_t dimension = integrand.dimension();
  // Every check before the first evaluation: what the method cannot run here, then f, then n.
  const quadmc::cell_control control = control_of(*m);
  // Keys of another control (a stopping rule's, which only a scene's control = "tolerance"
  // reads) would otherwise be accepted and ignored.
  if (const auto no = m->refuses(control)) {
    throw quadmc::invalid_argument(fmt::format("invalid {}: {}", no->key, no->message));
  }
  refuse_rendering_only(*m, dimension);
  const quadmc::integrand_traits traits{integrand.info().name, dimension, false};
  if (const auto why = m->incompatibility(traits)) {
    throw quadmc::invalid_argument("f", integrand.info().name, *why);
  }
  const std::uint64_t N = to_count(n, "n", 1);
  const quadmc::cell_size size = size_of(*m, N, dimension);
  std::uint64_t runs = to_count(repetitions, "repetitions", 1);
  if (m->kind() == quadmc::method_kind::deterministic) runs = 1;
  const quadmc::run_context context{to_count(seed, "seed", 0),
                                    callable ? 1U : quadmc::resolve_threads(thread_count),
                                    to_rng(rng)};
  const integration done =
      run_repetitions(*m, integrand, size, control, N, runs, py::str(name), context);
  return to_dict(done, N);
}

}  // namespace

void add_integrate(py::module_& m) {
  m.def("_integrate", &integrate, py::arg("f"), py::arg("method"), py::arg("n"), py::arg("s"),
        py::arg("seed"), py::arg("repetitions"), py::arg("threads"), py::arg("name"),
        py::arg("rng"), py::arg("options"),
        "The repetitions of quadmc.integrate as a dict of lists (quadmc/__init__.py wraps it).");
}

}  // namespace quadmc_python
