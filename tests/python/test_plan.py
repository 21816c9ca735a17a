"""cosim.plan: the first vehicle's path, as `cosim plan` finds it."""
import json
import subprocess

import numpy as np
import pytest

import cosim
from conftest import DEFAULT


def test_plan_path_is_an_n_by_3_array_whose_segments_sum_to_length_m():
    p = cosim.plan(DEFAULT, planner="rrt_connect")
    assert p.success
    assert p.planner == "rrt_connect"
    assert p.path.ndim == 2 and p.path.shape[1] == 3 and p.path.shape[0] >= 2
    segments = np.linalg.norm(np.diff(p.path, axis=0), axis=1).sum()
    assert p.length_m == pytest.approx(segments, rel=1e-12)
    np.testing.assert_allclose(p.path[0], [2, 2, 2])  # the default scenario's start ...
    np.testing.assert_allclose(p.path[-1], [36, 26, 3])  # ... and goal
    assert p.time_ms > 0


def test_plan_equals_the_programs_plan_json(cosim_binary, tmp_path):
    p = cosim.plan(DEFAULT, planner="theta_star")
    r = subprocess.run([cosim_binary, "plan", DEFAULT, "--planner", "theta_star", "--out",
                        str(tmp_path)], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    with open(tmp_path / "plan.json") as f:
        plan_json = json.load(f)
    assert p.length_m == pytest.approx(plan_json["length_m"], rel=1e-9)
    assert p.status == plan_json["status"] == "exact_solution"
    assert p.counters == plan_json["counters"]
    assert p.params == plan_json["params"]
    assert len(p.path) == plan_json["waypoints"]
    np.testing.assert_allclose(p.path, np.loadtxt(tmp_path / "path.csv", delimiter=",",
                                                  skiprows=1), rtol=1e-8)


def test_overrides_take_python_values_as_yaml():
    goal = np.array([30.0, 20.0, 3.5])
    p = cosim.plan(DEFAULT, overrides={"vehicles[0].goal": goal, "planner.resolution": 0.25,
                                       "planner.corner_cutting": False})
    assert p.success
    np.testing.assert_allclose(p.path[-1], goal)
    assert p.params["resolution"] == "0.25"
    assert p.params["corner_cutting"] == "false"
    # The --set form works as well.
    q = cosim.plan(DEFAULT, overrides=["vehicles[0].goal=[30, 20, 3.5]"])
    np.testing.assert_allclose(q.path[-1], goal)


def test_overrides_of_another_type_are_a_type_error():
    with pytest.raises(TypeError):
        cosim.plan(DEFAULT, overrides="planner.name=astar")
    with pytest.raises(TypeError):
        cosim.plan(DEFAULT, overrides={"sim.max_time": object()})
