// cosim.Simulation: a scenario's flight stepped from Python, one control period at a time, with
// any quadrotor's controller replaceable by a Python function (python/python_controller.h).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <map>
#include <memory>
#include <stdexcept>

#include "python/bindings.h"
#include "python/interrupt_guard.h"
#include "python/overrides.h"
#include "python/python_controller.h"
#include "python/python_values.h"
#include "python/stepped_simulation.h"
#include "python/unknown_vehicle_error.h"

namespace py = pybind11;

namespace cosim::python {

namespace {

class Simulation {
 public:
  Simulation(const py::object& scenario, const py::object& overrides) {
    const std::string path = scenarioPath(scenario);
    const std::vector<std::string> sets = overrideAssignments(overrides);
    InterruptGuard guard;
    std::exception_ptr failure;
    {
      py::gil_scoped_release release;
      try {
        sim_ = std::make_unique<SteppedSimulation>(path, sets);
      } catch (...) {
        failure = std::current_exception();
      }
    }
    guard.finish();  // Ctrl-C while planning: KeyboardInterrupt, not the planner's "no path"
    if (failure) std::rethrow_exception(failure);
  }

  py::list vehicles() const { return py::cast(sim_->vehicleNames()); }
  double time() const { return sim_->time(); }
  double controlRate() const { return sim_->controlRate(); }
  bool done() const { return sim_->done(); }

  py::dict state(const py::object& vehicle) const {
    const TrueVehicleState s = sim_->trueState(index(vehicle));
    py::dict d;
    d["time"] = sim_->time();
    d["position"] = vectorArray(Eigen::VectorXd(s.position));
    d["velocity"] = vectorArray(Eigen::VectorXd(s.velocity));
    d["quaternion"] = vectorArray(Eigen::VectorXd(s.quaternion));
    d["angular_velocity"] = vectorArray(Eigen::VectorXd(s.angular_velocity));
    return d;
  }

  py::array_t<double> hoverThrusts(const py::object& vehicle) const {
    const QuadrotorParams& a = sim_->believedAirframe(index(vehicle));
    return vectorArray(std::vector<double>(4, a.mass * a.gravity / 4.0));
  }

  py::dict airframe(const py::object& vehicle) const {
    const QuadrotorParams& a = sim_->believedAirframe(index(vehicle));
    std::vector<Eigen::Vector3d> rotors;
    for (const auto& xy : a.rotor_xy) rotors.emplace_back(xy.x(), xy.y(), a.rotor_z);
    Eigen::Matrix4d allocation;  // control/mixer.h: [f, tau]^T = A u
    for (int i = 0; i < 4; ++i)
      allocation.col(i) << 1.0, a.rotor_xy[i].y(), -a.rotor_xy[i].x(),
          a.spin[i] * a.torque_per_thrust;
    py::dict d;
    d["mass"] = a.mass;
    d["gravity"] = a.gravity;
    d["inertia"] = vectorArray(Eigen::VectorXd(a.inertia));
    d["rotor_positions"] = pointsArray(rotors);
    d["spin"] = vectorArray(std::vector<double>(a.spin.begin(), a.spin.end()));
    d["torque_per_thrust"] = a.torque_per_thrust;
    d["min_thrust"] = a.min_thrust;
    d["max_thrust"] = a.max_thrust;
    py::array_t<double> matrix({4, 4});
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) matrix.mutable_at(r, c) = allocation(r, c);
    d["allocation"] = matrix;
    return d;
  }

  void setController(const py::object& vehicle, const py::object& fn) {
    const std::size_t v = index(vehicle);
    std::unique_ptr<PythonController> controller;  // none: the built-in one
    if (!fn.is_none()) {
      if (!PyCallable_Check(fn.ptr()))
        throw py::type_error("set_controller: fn must be callable as fn(state, reference)");
      controller = std::make_unique<PythonController>(
          py::reinterpret_borrow<py::function>(fn), [this] { return sim_->time(); },
          sim_->believedAirframe(v), sim_->vehicleNames()[v]);
    }
    // Inside a controller callback the running controller must outlive its call, and the
    // period under way keeps the controllers it began with: the swap waits for its end.
    if (stepping_)
      pending_[v] = std::move(controller);
    else
      install(v, std::move(controller));
  }

  void step(long n) {
    notStepping("step()");
    notClosed();
    if (n < 0) throw py::value_error("step(n): n must be >= 0 control periods");
    for (long i = 0; i < n && !sim_->done(); ++i) stepOnce();
  }

  void stepUntil(double t) {
    notStepping("step_until()");
    notClosed();
    // Whole control periods: the first control instant at or after t (within rounding).
    while (!sim_->done() && sim_->time() < t - 1e-9) stepOnce();
  }

  py::object metrics() const { return jsonValue(sim_->metricsJson().json()); }
  void close() {
    notStepping("close()");  // the loop under way would run on freed data
    sim_->close();
  }

  // Python's cyclic garbage collector: a controller function that refers to its own Simulation
  // forms a cycle only the collector can break (custom_type_setup in bindSimulation).
  int traverse(visitproc visit, void* arg) const {
    for (const auto& [v, controller] : python_controllers_) Py_VISIT(controller->function().ptr());
    for (const auto& [v, controller] : pending_)
      if (controller) Py_VISIT(controller->function().ptr());
    return 0;
  }
  void clear() {
    pending_.clear();
    for (const auto& [v, controller] : python_controllers_) sim_->setController(v, nullptr);
    // Moved out first: dropping a function may run Python code that comes back here.
    auto dropped = std::move(python_controllers_);
    python_controllers_.clear();
  }

 private:
  std::size_t index(const py::object& vehicle) const {
    return vehicleIndex(vehicle, sim_->vehicleNames());
  }

  void notStepping(const char* call) const {
    if (stepping_)
      throw std::runtime_error(std::string(call) +
                               " inside a controller callback: the simulation is in the middle "
                               "of a control period; call it after step() returns");
  }

  void install(std::size_t v, std::unique_ptr<PythonController> controller) {
    sim_->setController(v, controller.get());
    if (controller)
      python_controllers_[v] = std::move(controller);
    else
      python_controllers_.erase(v);
  }

  void installPending() {
    auto pending = std::move(pending_);
    pending_.clear();
    for (auto& [v, controller] : pending) install(v, std::move(controller));
  }

  void notClosed() const {
    if (sim_->closed()) throw std::logic_error("the simulation is closed");
  }

  // One control period; Ctrl-C and a Python controller's exception surface after it.
  void stepOnce() {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    installPending();
    {
      stepping_ = true;
      struct Done {
        bool& flag;
        ~Done() { flag = false; }
      } done{stepping_};
      sim_->stepControl();
    }
    std::exception_ptr error;
    for (auto& [v, controller] : python_controllers_)
      if (std::exception_ptr e = controller->takeError(); e && !error) error = e;
    installPending();  // set_controller inside a callback: from the next period
    if (error) std::rethrow_exception(error);
  }

  std::unique_ptr<SteppedSimulation> sim_;
  std::map<std::size_t, std::unique_ptr<PythonController>> python_controllers_;
  // set_controller calls made inside a callback, installed once the period ends (nullptr: the
  // built-in controller back).
  std::map<std::size_t, std::unique_ptr<PythonController>> pending_;
  bool stepping_ = false;  // a control period is under way (its callbacks are running)
};

// The collector's hooks for Simulation (pybind11's custom_type_setup). An instance whose
// __init__ failed holds no Simulation: nothing to visit.
Simulation* simulationOf(PyObject* self) {
  auto* inst = reinterpret_cast<py::detail::instance*>(self);
  const py::detail::value_and_holder vh = inst->get_value_and_holder();
  return vh.holder_constructed() ? vh.holder<std::unique_ptr<Simulation>>().get() : nullptr;
}

void enableGarbageCollection(PyHeapTypeObject* heap_type) {
  PyTypeObject* type = &heap_type->ht_type;
  type->tp_flags |= Py_TPFLAGS_HAVE_GC;
  // Untracked before the C++ object goes: its destructor drops Python functions, which may run
  // the collector, which must not traverse a half-destroyed Simulation.
  type->tp_dealloc = [](PyObject* self) {
    PyObject_GC_UnTrack(self);
    py::detail::pybind11_object_dealloc(self);
  };
  type->tp_traverse = [](PyObject* self, visitproc visit, void* arg) {
#if PY_VERSION_HEX >= 0x03090000
    Py_VISIT(Py_TYPE(self));  // a heap type's instances own a reference to it
#endif
    const Simulation* sim = simulationOf(self);
    return sim ? sim->traverse(visit, arg) : 0;
  };
  type->tp_clear = [](PyObject* self) {
    if (Simulation* sim = simulationOf(self)) sim->clear();
    return 0;
  };
}

}  // namespace

void bindSimulation(py::module_& m) {
  py::class_<Simulation>(m, "Simulation", py::custom_type_setup(enableGarbageCollection),
                         R"(A scenario's flight, stepped from Python.

Simulation(scenario=None, overrides=None) plans and prepares the flight as cosim.run does (the
same planner, trajectory, controller, sensors and disturbances) and stops before the first
control step, the vehicles hovering at their starts. Then step(n) or step_until(t) fly it, one
control period (1 / control_rate s) at a time; set_controller puts a Python function in place of
a quadrotor's controller; metrics() evaluates what was flown as metrics.json would.
Quadrotor scenarios only (ground robots: cosim.run). Raises cosim.InputError for bad input,
RuntimeError if planning found no path, KeyboardInterrupt on Ctrl-C while planning.
Usable as a context manager (close() at the end).)")
      .def(py::init<const py::object&, const py::object&>(), py::arg("scenario") = py::none(),
           py::arg("overrides") = py::none())
      .def_property_readonly("vehicles", &Simulation::vehicles, "the vehicles' names, in order")
      .def_property_readonly("time", &Simulation::time, "simulated time, s")
      .def_property_readonly("control_rate", &Simulation::controlRate,
                             "control steps per simulated second, Hz (sim.control_rate, rounded "
                             "to whole physics steps)")
      .def_property_readonly("done", &Simulation::done,
                             "the run has ended: every vehicle reached its goal and held it, "
                             "sim.max_time, a fault (diverged, unstable, saturated), or close()")
      .def("state", &Simulation::state, py::arg("name"),
           "The vehicle's true state (MuJoCo's, not the estimate): dict of time (s), position "
           "(m, world), velocity (m/s, world), quaternion (w, x, y, z; body to world), "
           "angular_velocity (rad/s, body frame).")
      .def("hover_thrusts", &Simulation::hoverThrusts, py::arg("name"),
           "Each rotor's thrust in hover, shape (4,), N: m g / 4, the weight shared by four "
           "rotors (the hover condition sum f_i = m g; Mahony, Kumar and Corke 2012, IEEE RAM "
           "19(3)), with m and g of the airframe the flight software believes (model_error).")
      .def("airframe", &Simulation::airframe, py::arg("name"),
           "The airframe the flight software believes: mass (kg), gravity (m/s^2), inertia "
           "(principal, kg m^2), rotor_positions ((4, 3), body frame, m), spin (each rotor's "
           "reaction-torque sign), torque_per_thrust (m), min_thrust and max_thrust (N per "
           "rotor), allocation (4x4 A with [f, tau_x, tau_y, tau_z] = A @ thrusts).")
      .def("set_controller", &Simulation::setController, py::arg("name"), py::arg("fn"),
           R"(Fly vehicle `name` under fn(state, reference) from the next control step.

fn is called once per control period (control_rate times a simulated second) with
state: what the controller sees (the estimate under the scenario's sensors), a dict as
state() returns; reference: dict of position, velocity, acceleration (world frame) and yaw (rad)
from the vehicle's reference trajectory. It returns the 4 rotor thrusts in N (a sequence or an
array of shape (4,), in the order of airframe()'s rotors), clamped to [min_thrust, max_thrust].
A wrong shape raises ValueError from step(); so does any exception fn raises (that control
period keeps the previous command). fn=None puts the built-in controller back. Called inside a
controller callback, the change takes effect from the next control period.
Raises cosim.UnknownVehicleError (a KeyError and a ValueError) for an unknown name.)")
      .def("step", &Simulation::step, py::arg("n") = 1,
           "Advance n control periods (n / control_rate simulated seconds), or until the run "
           "ends (then it does nothing). Ctrl-C raises KeyboardInterrupt after the current "
           "period; RuntimeError after close() and inside a controller callback.")
      .def("step_until", &Simulation::stepUntil, py::arg("t"),
           "Advance whole control periods until time >= t (s), or until the run ends. Ctrl-C "
           "raises KeyboardInterrupt after the current period; RuntimeError after close() and "
           "inside a controller callback.")
      .def("metrics", &Simulation::metrics,
           "dict: what metrics.json would hold for what was flown so far (the pipeline's own "
           "evaluation). While the run goes on, end_reason is 'running'.")
      .def("close", &Simulation::close,
           "End the run and free MuJoCo's data (metrics() still answers). Idempotent. "
           "RuntimeError inside a controller callback (the period under way needs the data).")
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [](Simulation& s, const py::args&) { s.close(); });
}

}  // namespace cosim::python
