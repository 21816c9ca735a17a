"""The module misused as an attacker would: calls back into a Simulation from its own controller,
values that refer to themselves, reference cycles, arguments of the wrong type. Each is a clear
Python exception (or works), never a crash, a nested flight or a leak."""

import gc
import weakref

import pytest

import cosim
from conftest import DEFAULT


def hover(sim):
    thrusts = sim.hover_thrusts("uav1")
    return lambda state, reference: thrusts


def test_close_inside_a_callback_is_a_runtime_error_and_the_flight_goes_on():
    with cosim.Simulation(DEFAULT) as sim:
        base = hover(sim)

        def closing(state, reference):
            sim.close()
            return base(state, reference)

        sim.set_controller("uav1", closing)
        with pytest.raises(RuntimeError, match=r"close\(\) inside a controller callback"):
            sim.step()
        sim.set_controller("uav1", None)
        sim.step(3)  # the data is still there: no use of freed memory
        assert sim.time == pytest.approx(4 / sim.control_rate)


def test_step_inside_a_callback_is_a_runtime_error_not_a_nested_flight():
    with cosim.Simulation(DEFAULT) as sim:
        base = hover(sim)
        times = []

        def stepping(state, reference):
            times.append(sim.time)
            sim.step()
            return base(state, reference)

        sim.set_controller("uav1", stepping)
        with pytest.raises(RuntimeError, match=r"step\(\) inside a controller callback"):
            sim.step()
        assert times == [0.0]  # one call: no nested control period ran
        assert sim.time == pytest.approx(1 / sim.control_rate)


def test_a_controller_replaced_inside_its_own_callback_runs_to_its_end_and_the_new_one_follows():
    with cosim.Simulation(DEFAULT) as sim:
        base = hover(sim)
        calls = []

        def second(state, reference):
            calls.append(("second", state["time"]))
            return base(state, reference)

        def first(state, reference):
            calls.append(("first", state["time"]))
            sim.set_controller("uav1", second)  # drops `first` while it runs
            del state  # touches the frame after the swap
            return base(None, reference)

        sim.set_controller("uav1", first)
        sim.step(3)
        period = 1 / sim.control_rate
        assert [c[0] for c in calls] == ["first", "second", "second"]
        assert calls[1][1] == pytest.approx(period)  # from the next period on

        def removing(state, reference):
            calls.append(("removing", state["time"]))
            sim.set_controller("uav1", None)
            return base(state, reference)

        sim.set_controller("uav1", removing)
        sim.step(3)
        assert [c[0] for c in calls[3:]] == ["removing"]  # the built-in one flies after it


def test_a_self_referencing_override_value_is_a_value_error():
    loop = []
    loop.append(loop)
    with pytest.raises(ValueError, match="vehicles\\[0\\].goal.*contains itself"):
        cosim.plan(DEFAULT, overrides={"vehicles[0].goal": loop})
    mapping = {}
    mapping["a"] = [mapping]
    with pytest.raises(ValueError, match="contains itself"):
        cosim.Simulation(DEFAULT, overrides={"sim": mapping})
    deep = 0.0
    for _ in range(10000):
        deep = [deep]
    with pytest.raises(ValueError, match="deeper than 32"):
        cosim.plan(DEFAULT, overrides={"vehicles[0].goal": deep})
    # The same list twice side by side is no cycle.
    goal = [30.0, 20.0, 3.0]
    assert cosim.plan(DEFAULT, overrides={"vehicles[0].goal": goal,
                                          "vehicles[0].start": [goal[0] - 28, 2, 2]}).success


def resident_bytes():
    """This process's resident memory after glibc returned what it could to the system."""
    import ctypes
    import os
    ctypes.CDLL("libc.so.6").malloc_trim(0)
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def test_a_simulation_whose_controller_refers_to_it_is_collected():
    def cycle(close):
        sim = cosim.Simulation(DEFAULT)
        thrusts = sim.hover_thrusts("uav1")
        sim.set_controller("uav1", lambda state, reference: sim.hover_thrusts("uav1") + 0 * thrusts)
        sim.step(2)
        if close:
            sim.close()
        return weakref.ref(sim)

    refs = [cycle(i % 2 == 0) for i in range(4)]
    gc.collect()
    assert all(r() is None for r in refs)
    # Steady state: once the heap holds what one Simulation needs, more of them freed in turn
    # reuse it. A Simulation of the default scenario holds about 6 MB: eight never freed would
    # add about 48 MB.
    before = resident_bytes()
    for _ in range(8):
        cycle(False)
        gc.collect()
    assert resident_bytes() - before < 16e6


def test_arguments_of_the_wrong_type_are_type_errors_naming_the_argument():
    with pytest.raises(TypeError, match="planner: a planner name"):
        cosim.plan(None, planner=123)
    with pytest.raises(TypeError, match="scenario: a path"):
        cosim.plan(123)
    with pytest.raises(TypeError, match="scenario: a path"):
        cosim.Simulation(3.5)
    with pytest.raises(TypeError, match="out: a path"):
        cosim.run(DEFAULT, out=7)
    with pytest.raises(TypeError, match="name: a vehicle name"):
        with cosim.Simulation(DEFAULT) as sim:
            sim.state(1.5)
    with pytest.raises(TypeError):
        cosim.run(DEFAULT, video="yes")
