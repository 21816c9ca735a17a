"""Shared set-up of the Python API tests (run by CTest as python_api, see tests/CMakeLists.txt).

COSIM_BINARY names the built `cosim` program: tests compare the module with it on the same input.
"""
import csv
import os
import subprocess
import sys

import pytest

import cosim


@pytest.fixture(scope="session")
def cosim_binary():
    path = os.environ.get("COSIM_BINARY")
    assert path and os.path.exists(path), "COSIM_BINARY must name the built cosim program"
    return path


def run_python(code, timeout=120, **kwargs):
    """Runs `code` in a fresh interpreter (this one) with this PYTHONPATH; returns the process."""
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=timeout, env=dict(os.environ), **kwargs)


def read_csv_rows(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


DEFAULT = cosim.DEFAULT_SCENARIO

# Wall-clock figures: the only metrics that differ between two runs of the same scenario.
WALL_CLOCK = {"wall_time_s", "sim_speed_x", "planning_time_ms"}


def without_wall_clock(metrics):
    m = {k: v for k, v in metrics.items() if k not in WALL_CLOCK}
    m["trajectory_counters"] = {k: v for k, v in m["trajectory_counters"].items()
                                if k != "time_ms"}
    return m
