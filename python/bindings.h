#pragma once
// The parts of the Python module `cosim._cosim`, one per bound concept; module.cpp calls each.
#include <pybind11/pybind11.h>

namespace cosim::python {

void bindInputError(pybind11::module_& m);  // cosim.InputError
void bindRun(pybind11::module_& m);         // cosim.run, cosim.RunResult
void bindPlan(pybind11::module_& m);        // cosim.plan, cosim.PlanResult
void bindSimulation(pybind11::module_& m);  // cosim.Simulation

}  // namespace cosim::python
