// quadmc.integrands(), quadmc.methods(), quadmc.point_sets(): the library's tables as `quadmc
// list` prints them (bench/quadmc/catalogue_listing.cpp), as lists of dicts in listing order,
// so that a script finds a family's keys or a method's options without parsing text. Read from
// the same tables, so a family, method or set added to the library appears here by itself.
#include "bindings.hpp"

#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/functions/catalogue.hpp"
#include "quadmc/methods/registry.hpp"

#include <pybind11/stl.h>

#include <span>
#include <string>
#include <string_view>

namespace py = pybind11;

namespace quadmc_python {

namespace {

py::list strings(std::span<const std::string_view> values) {
  py::list out;
  for (const std::string_view v : values) out.append(py::str(v.data(), v.size()));
  return out;
}

py::str text(std::string_view value) {
  return {value.data(), value.size()};
}

py::list integrands() {
  py::list out;
  for (const quadmc::catalogue_entry& e : quadmc::integrand_catalogue()) {
    py::dict d;
    d["name"] = text(e.name);
    d["description"] = text(e.description);
    d["smoothness"] = text(e.smoothness);
    d["vector_keys"] = strings(e.vector_keys);
    d["scalar_keys"] = strings(e.scalar_keys);
    py::dict string_keys;
    for (const quadmc::string_key& k : e.string_keys) string_keys[text(k.key)] = strings(k.choices);
    d["string_keys"] = string_keys;
    d["parameters"] = text(e.parameters);
    d["dimension"] = e.fixed_dimension == 0 ? py::object(py::none()) : py::int_(e.fixed_dimension);
    out.append(d);
  }
  return out;
}

py::list methods() {
  py::list out;
  for (const quadmc::method_descriptor* m : quadmc::method_registry()) {
    py::dict d;
    d["name"] = text(m->name);
    d["description"] = text(m->description);
    d["kind"] = m->kind == quadmc::method_kind::deterministic ? "deterministic" : "randomized";
    py::list controls;
    for (const quadmc::cell_control c : m->controls) controls.append(text(quadmc::to_string(c)));
    d["controls"] = controls;
    py::dict options;
    for (const quadmc::option_doc& o : m->options) options[text(o.key)] = text(o.meaning);
    d["options"] = options;
    out.append(d);
  }
  return out;
}

py::list point_sets() {
  py::list out;
  for (const quadmc::point_set_entry& p : quadmc::point_set_catalogue()) {
    py::dict d;
    d["name"] = text(p.name);
    d["description"] = text(p.description);
    py::list randomizations;
    for (const quadmc::randomization r : p.randomizations) {
      randomizations.append(text(quadmc::to_string(r)));
    }
    d["randomizations"] = randomizations;
    // key → its choices (the default first; ints for an integer key such as interlacing), or
    // None for a flag (True or False). Only the choices quadmc.points takes: the lattice's
    // weighted periodizations (c0 … c3sin) weight the points and have none to give
    // (docs/theory.md#lattice-periodizations).
    py::dict options;
    for (const quadmc::point_set_option& o : p.options) {
      if (o.integer) {
        py::list values;
        for (const std::string_view c : o.choices)
          values.append(py::int_(std::stoll(std::string(c))));
        options[text(o.key)] = values;
        continue;
      }
      options[text(o.key)] =
          o.is_flag() ? py::object(py::none()) : py::object(strings(o.point_choices()));
    }
    d["options"] = options;
    d["max_dimension"] = p.max_dimension == 0 ? py::object(py::none()) : py::int_(p.max_dimension);
    out.append(d);
  }
  return out;
}

}  // namespace

void add_catalogue(py::module_& m) {
  m.def(
      "integrands", &integrands,
      "The integrand families as `quadmc list` prints them: dicts of name, description "
      "(formula and domain), smoothness, vector_keys, scalar_keys, string_keys ({key: its "
      "choices}), parameters (what each key means) and dimension (the only s it takes, or None).");
  m.def("methods", &methods,
        "The methods as `quadmc list` prints them: dicts of name, description, kind "
        "('deterministic' or 'randomized'), controls (the first is the default) and options "
        "({key: meaning}).");
  m.def("point_sets", &point_sets,
        "The point sets of quadmc.points: dicts of name, description, randomizations (the "
        "default first), options ({key: choices, the default first, or None for a flag}) and "
        "max_dimension (None: any s).");
}

}  // namespace quadmc_python
