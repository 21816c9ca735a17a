#pragma once
// Scenario overrides from Python: a dict {"planner.name": "astar", "sim.max_time": 20,
// "vehicles[0].goal": [30, 20, 3]} becomes the "key=value" assignments of the program's --set
// (sim/scenario.h), so that a bad one is reported exactly as the program reports it.
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace cosim::python {

// None: none. A mapping: one assignment per item, its value as YAML text (a str as given, so
// YAML text passes through like --set's; bool true/false; whole numbers; other numbers with
// round-trip digits; lists, tuples and arrays [a, b]; mappings {k: v}). Also a sequence of
// "key=value" strings, as --set takes them. Throws TypeError for anything else, ValueError for a
// value that contains itself or nests deeper than 32 lists or dicts.
std::vector<std::string> overrideAssignments(const pybind11::handle& overrides);

// The bundled default scenario (what `cosim run` runs without one).
std::string defaultScenarioPath();

// A path argument (str or os.PathLike of str); TypeError naming `argument` for anything else.
std::string pathArgument(const pybind11::handle& value, const char* argument);

// The name of value's type, for TypeError messages ("int").
std::string typeName(const pybind11::handle& value);

// The scenario argument: a path (str or os.PathLike) or None for the bundled default scenario.
std::string scenarioPath(const pybind11::handle& scenario);

}  // namespace cosim::python
