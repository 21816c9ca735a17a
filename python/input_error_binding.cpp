// cosim.InputError: the library's InputError (core/input_error.h) as a Python exception, a
// ValueError. str(e) is the line `cosim` prints on stderr for the same bad input
// ("cosim: FILE: PLACE: PROBLEM", cli/main.cpp), so scripts and the program report alike; the
// parts are its attributes file, place and problem.
#include <pybind11/pybind11.h>

#include "core/input_error.h"
#include "python/bindings.h"

namespace py = pybind11;

namespace cosim::python {

void bindInputError(py::module_& m) {
  // Created with the C API: pybind11's register_exception cannot attach attributes.
  static PyObject* type = PyErr_NewExceptionWithDoc(
      "cosim.InputError",
      "Bad input (a scenario file, an override, an argument). str(e) is the one-line message "
      "the cosim program prints on stderr for it; e.file, e.place and e.problem are its parts.",
      PyExc_ValueError, nullptr);
  if (type == nullptr) throw py::error_already_set();
  m.attr("InputError") = py::handle(type);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::object error = py::handle(type)(std::string("cosim: ") + e.what());
      error.attr("file") = e.file();
      error.attr("place") = e.place();
      error.attr("problem") = e.problem();
      PyErr_SetObject(type, error.ptr());
    }
  });
}

}  // namespace cosim::python
