"""cosim.run: the same run as `cosim run`, its metrics and log in memory."""
import json
import os
import subprocess

import numpy as np
import pytest

import cosim
from conftest import DEFAULT, read_csv_rows, without_wall_clock

OVERRIDES = {"sim.max_time": 60}  # the default flight lands at 30.2 s


@pytest.fixture(scope="module")
def python_run():
    return cosim.run(DEFAULT, overrides=OVERRIDES)


@pytest.fixture(scope="module")
def cli_run(cosim_binary, tmp_path_factory):
    out = tmp_path_factory.mktemp("cli_run")
    p = subprocess.run([cosim_binary, "run", DEFAULT, "--set", "sim.max_time=60", "--no-video",
                        "--no-images", "--quiet", "--out", str(out)],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    with open(out / "metrics.json") as f:
        return out, json.load(f)


def test_run_of_the_default_scenario_reaches_the_goal(python_run):
    assert python_run.status == 0
    assert python_run.message == ""
    assert python_run.metrics["reached_goal"] is True
    assert python_run.metrics["collisions"] == 0
    assert python_run.out is None


def test_metrics_have_the_keys_and_values_of_the_programs_metrics_json(python_run, cli_run):
    _, cli_metrics = cli_run
    assert list(python_run.metrics) == list(cli_metrics)
    assert list(python_run.metrics["vehicles"][0]) == list(cli_metrics["vehicles"][0])
    # Deterministic: everything but the wall clock is the same number.
    assert without_wall_clock(python_run.metrics) == without_wall_clock(cli_metrics)


def test_timeseries_has_the_columns_and_rows_of_timeseries_csv(python_run, cli_run):
    out, _ = cli_run
    header, rows = read_csv_rows(out / "timeseries.csv")
    table = python_run.timeseries()
    assert list(table) == header
    assert len(table["x"]) == len(rows)
    assert all(len(column) == len(rows) for column in table.values())
    for name in ("t", "x", "ref_z", "qw", "cmd3", "w0"):
        column = header.index(name)
        np.testing.assert_allclose(table[name], [float(r[column]) for r in rows], rtol=1e-8,
                                   atol=1e-12)
    assert set(table["vehicle"]) == {"uav1"}
    # One vehicle: by name or index, the same rows.
    np.testing.assert_array_equal(python_run.timeseries("uav1")["x"], table["x"])
    np.testing.assert_array_equal(python_run.timeseries(0)["x"], table["x"])
    with pytest.raises(ValueError, match="no vehicle 'uav9'.*uav1"):
        python_run.timeseries("uav9")


def test_run_without_out_writes_nothing(tmp_path):
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        r = cosim.run(DEFAULT, overrides={"planner.name": "astar", "sim.max_time": 60})
    finally:
        os.chdir(cwd)
    assert r.status == 0
    assert r.metrics["planner"] == "astar"
    assert list(tmp_path.iterdir()) == []


def test_run_with_out_writes_the_programs_files_and_video_only_when_asked(tmp_path):
    r = cosim.run(DEFAULT, overrides=OVERRIDES, out=tmp_path / "run")
    assert r.out == str(tmp_path / "run")
    names = {p.name for p in (tmp_path / "run").iterdir()}
    assert {"metrics.json", "timeseries.csv", "path.csv", "final.png"} <= names
    assert "video.mp4" not in names
    with open(tmp_path / "run" / "metrics.json") as f:
        assert without_wall_clock(json.load(f)) == without_wall_clock(r.metrics)


def test_a_failed_task_is_status_1_with_the_programs_message():
    # 10 s are not enough for the 30 s flight.
    r = cosim.run(DEFAULT, overrides={"sim.max_time": 10})
    assert r.status == 1
    assert r.message == "goal not reached within sim.max_time"
    assert r.metrics["reached_goal"] is False
    assert r.timeseries()["t"][-1] == pytest.approx(10.0, abs=0.01)


def test_run_with_out_and_video_renders_video_mp4(tmp_path):
    # A small time-lapse: the flight's 30 s in 3 s of 160x120 video.
    r = cosim.run(DEFAULT, overrides={"render.width": 160, "render.height": 120,
                                      "render.speed": 10}, out=tmp_path, video=True)
    assert r.status == 0
    assert (tmp_path / "video.mp4").stat().st_size > 1000
    assert (tmp_path / "metrics.json").exists()
