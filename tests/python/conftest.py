"""Shared set-up of the Python API tests (run by CTest as python_api, see tests/CMakeLists.txt).

COSIM_BINARY names the built `cosim` program: tests compare the module with it on the same input.
"""
import csv
import os
import signal
import subprocess
import time
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


def interrupt_after_marker(code, marker, wait=1.0):
    """Starts `code` in a fresh interpreter, waits for it to print `marker` (a line), lets it work
    `wait` s more, sends SIGINT and waits up to 3 s for it to end. Returns (seconds from SIGINT to
    the end, stderr, exit status)."""
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, env=dict(os.environ))
    assert p.stdout.readline() == marker + "\n"
    time.sleep(wait)
    assert p.poll() is None, "the call should still be running"
    sent = time.monotonic()
    p.send_signal(signal.SIGINT)
    try:
        _, stderr = p.communicate(timeout=3)
    finally:
        p.kill()
    return time.monotonic() - sent, stderr, p.returncode


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
