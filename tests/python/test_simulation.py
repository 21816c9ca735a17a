"""cosim.Simulation: the flight of cosim.run, stepped from Python, with controllers in Python."""

import os
import sys

import numpy as np
import pytest

import cosim
from conftest import DEFAULT, interrupt_after_marker, without_wall_clock

# The quaternion-to-matrix conversion of the PD example (one definition for both).
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "examples"))
from pd_controller import rotation  # noqa: E402


def hover_pd(sim, name, point, kp=6.0, kd=4.5, k_att=120.0, k_rate=22.0):
    """Holds `point`: hover thrusts plus a PD law on position, tilted into place by a PD law on
    attitude (body z along the wanted force), through the airframe's allocation matrix."""
    hover = sim.hover_thrusts(name)
    frame = sim.airframe(name)
    m, J, A_inv = frame["mass"], frame["inertia"], np.linalg.inv(frame["allocation"])

    def control(state, reference):
        R = rotation(state["quaternion"])
        force = (hover.sum() * np.array([0.0, 0.0, 1.0])
                 + m * (kp * (point - state["position"]) - kd * state["velocity"]))
        b3 = force / np.linalg.norm(force)
        b2 = np.cross(b3, [1.0, 0.0, 0.0])
        b2 /= np.linalg.norm(b2)
        Rd = np.column_stack([np.cross(b2, b3), b2, b3])
        E = Rd.T @ R - R.T @ Rd
        e_R = 0.5 * np.array([E[2, 1], E[0, 2], E[1, 0]])
        torque = J * (-k_att * e_R - k_rate * state["angular_velocity"])
        return A_inv @ np.concatenate([[force @ R[:, 2]], torque])

    return control


def test_step_advances_time_by_n_control_periods():
    with cosim.Simulation(DEFAULT) as sim:
        assert sim.vehicles == ["uav1"]
        assert sim.control_rate == 500.0  # the default scenario's sim.control_rate
        assert sim.time == 0.0 and not sim.done
        sim.step()
        assert sim.time == pytest.approx(1 / 500, abs=1e-12)
        sim.step(37)
        assert sim.time == pytest.approx(38 / 500, abs=1e-12)
        sim.step_until(0.5)
        assert sim.time == pytest.approx(0.5, abs=1e-12)
        sim.step_until(0.5031)  # the first control instant at or after t
        assert sim.time == pytest.approx(0.504, abs=1e-12)
        with pytest.raises(ValueError):
            sim.step(-1)


def test_state_is_the_true_state_and_hover_thrusts_carry_the_believed_weight():
    with cosim.Simulation(DEFAULT, overrides={"model_error.mass": 1.1}) as sim:
        s = sim.state("uav1")
        np.testing.assert_array_equal(s["position"], [2, 2, 2])  # the scenario's start
        np.testing.assert_array_equal(s["quaternion"], [1, 0, 0, 0])
        assert set(s) == {"time", "position", "velocity", "quaternion", "angular_velocity"}
        # quad_1500g believed 10 % heavier: 1.65 kg * 9.81 m/s^2 / 4 rotors.
        np.testing.assert_allclose(sim.hover_thrusts("uav1"), [1.65 * 9.81 / 4] * 4, rtol=1e-12)
        assert sim.airframe("uav1")["mass"] == pytest.approx(1.65)


def test_stepped_to_the_end_it_is_the_run_of_cosim_run():
    r = cosim.run(DEFAULT)
    with cosim.Simulation(DEFAULT) as sim:
        sim.step_until(1e9)
        assert sim.done
        assert sim.time == pytest.approx(r.metrics["sim_time_s"], abs=1e-9)
        assert without_wall_clock(sim.metrics()) == without_wall_clock(r.metrics)


def test_metrics_mid_flight_evaluate_the_flight_so_far():
    with cosim.Simulation(DEFAULT) as sim:
        sim.step_until(5.0)
        m = sim.metrics()
        assert m["end_reason"] == "running"
        assert m["message"].startswith("running")
        assert m["sim_time_s"] == pytest.approx(5.0, abs=1e-9)
        assert m["reached_goal"] is False
        assert 0 < m["rmse_m"] < 0.2
        sim.close()
        assert sim.done
        assert sim.metrics()["end_reason"] == "interrupted"
        with pytest.raises(RuntimeError):
            sim.step()
        with pytest.raises(RuntimeError):
            sim.state("uav1")


def test_a_python_pd_controller_holds_a_hover_point_within_2_cm_for_2_s():
    point = np.array([2.0, 2.0, 2.5])  # 0.5 m above the start
    # Still air (a PD law has no integral to cancel the default breeze's push, 0.14 m measured);
    # the scenario's motion-capture noise and latency stay.
    still = {"disturbances.wind": [0, 0, 0], "disturbances.gust": 0}
    with cosim.Simulation(DEFAULT, overrides=still) as sim:
        sim.set_controller("uav1", hover_pd(sim, "uav1", point))
        sim.step_until(3.0)  # climbs and settles
        errors = []
        while sim.time < 5.0 - 1e-9:
            sim.step()
            errors.append(np.linalg.norm(sim.state("uav1")["position"] - point))
        assert len(errors) == 1000  # 2 s at 500 Hz
        assert max(errors) < 0.02  # 6 mm measured
        assert not sim.done


def test_the_controller_sees_the_estimate_and_the_reference_at_the_control_rate():
    calls = []

    def spy(state, reference):
        calls.append((state, reference))
        return hover

    with cosim.Simulation(DEFAULT) as sim:
        hover = sim.hover_thrusts("uav1")
        sim.set_controller("uav1", spy)
        sim.step(5)
    assert len(calls) == 5
    state, reference = calls[-1]
    assert state["time"] == pytest.approx(4 / 500, abs=1e-12)  # called at the period's start
    # mocap: an estimate within millimetres of the start, not exactly it.
    assert np.linalg.norm(state["position"] - [2, 2, 2]) < 0.01
    assert set(reference) == {"position", "velocity", "acceleration", "yaw"}
    np.testing.assert_allclose(reference["position"], [2, 2, 2], atol=1e-3)


def test_a_wrong_controller_output_is_a_value_error_and_none_restores_the_builtin():
    with cosim.Simulation(DEFAULT) as sim:
        sim.set_controller("uav1", lambda state, reference: [1.0, 2.0, 3.0])
        with pytest.raises(ValueError, match=r"shape \(3,\).*4 rotor thrusts"):
            sim.step()
        sim.set_controller("uav1", lambda state, reference: 1 / 0)
        with pytest.raises(ZeroDivisionError):
            sim.step()
        sim.set_controller("uav1", None)
        sim.step_until(1e9)
        assert sim.metrics()["reached_goal"] is True


def test_set_controller_on_an_unknown_vehicle_raises():
    with cosim.Simulation(DEFAULT) as sim:
        with pytest.raises(cosim.UnknownVehicleError, match="no vehicle 'uav2'.*uav1"):
            sim.set_controller("uav2", lambda state, reference: [0.0] * 4)
        with pytest.raises(KeyError):
            sim.state("uav2")
        with pytest.raises(ValueError):
            sim.hover_thrusts(3)


def test_sigint_during_step_until_raises_keyboard_interrupt_within_3_s():
    # A Python controller hovering for an hour of simulated time.
    code = f"""
import cosim
sim = cosim.Simulation({DEFAULT!r}, overrides={{"sim.max_time": 3600}})
hover = sim.hover_thrusts("uav1")
sim.set_controller("uav1", lambda state, reference: hover)
print("stepping", flush=True)
sim.step_until(3600)
"""
    elapsed, stderr, _ = interrupt_after_marker(code, "stepping")
    assert elapsed < 3
    assert stderr.rstrip().endswith("KeyboardInterrupt")
