#include "python/overrides.h"

#include <cmath>
#include <vector>

#include "core/json_writer.h"

namespace py = pybind11;

namespace cosim::python {

namespace {

bool isInstance(const py::handle& value, const char* module, const char* type) {
  return py::isinstance(value, py::module_::import(module).attr(type));
}

// The lists and mappings being written, outermost first: a value that contains itself (l = [];
// l.append(l)) would recurse without end, and a deep nesting would exhaust the C++ stack.
struct Enclosing {
  const std::string& key;
  std::vector<PyObject*> open;
};

// Deeper than any scenario value (a list of waypoints is 2 levels, a vehicle's mapping 3).
constexpr std::size_t kMaxNesting = 32;

std::string yamlText(const py::handle& value, bool nested, Enclosing& enclosing);

// A list's or mapping's text: `write` adds its items, inside `enclosing`.
template <typename Write>
std::string containerText(const py::handle& value, Enclosing& enclosing, Write write) {
  for (const PyObject* outer : enclosing.open)
    if (outer == value.ptr())
      throw py::value_error("override '" + enclosing.key +
                            "': the value contains itself (a list or dict that refers to itself "
                            "has no YAML text)");
  if (enclosing.open.size() >= kMaxNesting)
    throw py::value_error("override '" + enclosing.key + "': the value nests lists or dicts " +
                          "deeper than " + std::to_string(kMaxNesting) + " levels");
  enclosing.open.push_back(value.ptr());
  std::string text = write();
  enclosing.open.pop_back();
  return text;
}

// `value` as YAML flow text; `nested`: inside a list or mapping, where a string must be quoted
// (JSON's double-quoted strings are YAML's too).
std::string yamlText(const py::handle& value, bool nested, Enclosing& enclosing) {
  if (value.is_none()) return "null";
  if (py::isinstance<py::str>(value)) {
    const std::string text = value.cast<std::string>();
    return nested ? JsonObject::quote(text) : text;
  }
  // numpy's scalars and 0-d arrays answer .item() with the Python number they hold.
  if (py::hasattr(value, "dtype") && py::hasattr(value, "item") &&
      py::len(value.attr("shape")) == 0)
    return yamlText(value.attr("item")(), nested, enclosing);
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (isInstance(value, "numbers", "Integral"))
    return py::str(py::int_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
  if (isInstance(value, "numbers", "Real")) {
    const double x = value.cast<double>();
    if (std::isnan(x)) return ".nan";
    if (std::isinf(x)) return x > 0 ? ".inf" : "-.inf";
    return py::repr(py::float_(x)).cast<std::string>();  // the shortest text that round-trips
  }
  if (py::hasattr(value, "tolist"))
    return yamlText(value.attr("tolist")(), nested, enclosing);  // arrays
  if (isInstance(value, "collections.abc", "Mapping"))
    return containerText(value, enclosing, [&] {
      std::string text = "{";
      for (const auto& item : py::reinterpret_borrow<py::object>(value).attr("items")()) {
        const py::tuple kv = py::reinterpret_borrow<py::tuple>(item);
        text += (text.size() > 1 ? ", " : "") + yamlText(py::str(kv[0]), true, enclosing) + ": " +
                yamlText(kv[1], true, enclosing);
      }
      return text + "}";
    });
  if (isInstance(value, "collections.abc", "Sequence"))
    return containerText(value, enclosing, [&] {
      std::string text = "[";
      for (const auto& item : value)
        text += (text.size() > 1 ? ", " : "") + yamlText(item, true, enclosing);
      return text + "]";
    });
  throw py::type_error("cannot write an override value of type " +
                       py::str(py::type::of(value).attr("__name__")).cast<std::string>() +
                       " as YAML (use numbers, bools, strings, lists or dicts)");
}

}  // namespace

std::string defaultScenarioPath() {
  return std::string(COSIM_SCENARIOS_DIR) + "/default.yaml";
}

std::vector<std::string> overrideAssignments(const py::handle& overrides) {
  std::vector<std::string> assignments;
  if (overrides.is_none()) return assignments;
  if (isInstance(overrides, "collections.abc", "Mapping")) {
    for (const auto& item : py::reinterpret_borrow<py::object>(overrides).attr("items")()) {
      const py::tuple kv = py::reinterpret_borrow<py::tuple>(item);
      if (!py::isinstance<py::str>(kv[0]))
        throw py::type_error("override keys are scenario keys as strings, e.g. 'planner.name'");
      const std::string key = kv[0].cast<std::string>();
      Enclosing enclosing{key, {}};
      assignments.push_back(key + "=" + yamlText(kv[1], false, enclosing));
    }
    return assignments;
  }
  if (!py::isinstance<py::str>(overrides) && isInstance(overrides, "collections.abc", "Sequence")) {
    for (const auto& item : overrides) {
      if (!py::isinstance<py::str>(item))
        throw py::type_error("overrides as a list are 'key=value' strings, as --set takes them");
      assignments.push_back(item.cast<std::string>());
    }
    return assignments;
  }
  throw py::type_error(
      "overrides: a dict of scenario keys to values, e.g. {'planner.name': 'astar'}, or None");
}

std::string pathArgument(const py::handle& value, const char* argument) {
  const py::module_ os = py::module_::import("os");
  if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value) ||
      py::isinstance(value, os.attr("PathLike")))
    // os.fsdecode: bytes as the file system encodes names, os.PathLike through __fspath__.
    return os.attr("fsdecode")(value).cast<std::string>();
  throw py::type_error(std::string(argument) + ": a path (str or os.PathLike) is needed, not " +
                       typeName(value));
}

std::string scenarioPath(const py::handle& scenario) {
  if (scenario.is_none()) return defaultScenarioPath();
  return pathArgument(scenario, "scenario");
}

std::string typeName(const py::handle& value) {
  return py::str(py::type::of(value).attr("__name__")).cast<std::string>();
}

}  // namespace cosim::python
