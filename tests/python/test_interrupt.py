"""Ctrl-C stops a long call promptly with KeyboardInterrupt, and the module works on after it."""
import os
import subprocess
import sys

import pytest

from conftest import DEFAULT, interrupt_after_marker

# RRT* improves its path until its time limit: a plan that would take a minute.
LONG_PLAN = (f"cosim.plan({DEFAULT!r}, planner='rrt_star', "
             "overrides={'planner.time_limit': 60})")


@pytest.mark.parametrize("call", [
    LONG_PLAN,
    # Simulation plans in its constructor, as cosim.run does.
    f"cosim.Simulation({DEFAULT!r}, overrides={{'planner.name': 'rrt_star', "
    "'planner.time_limit': 60})",
])
def test_sigint_during_a_long_plan_raises_keyboard_interrupt_within_3_s(call):
    elapsed, stderr, status = interrupt_after_marker(
        f"import cosim; print('planning', flush=True); {call}", "planning")
    assert elapsed < 3
    assert "Traceback" in stderr and stderr.rstrip().endswith("KeyboardInterrupt")
    assert status != 0


def test_after_an_interrupt_the_next_call_runs_normally():
    code = f"""
import os, signal, threading, cosim
threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT)).start()
try:
    {LONG_PLAN}
    print('not interrupted')
except KeyboardInterrupt:
    print('interrupted')
p = cosim.plan({DEFAULT!r}, planner='theta_star')
print('then', p.success, round(p.length_m, 3))
"""
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=30,
                       env=dict(os.environ))
    assert p.returncode == 0, p.stderr
    # 43.389 m: the default scenario's Theta* path (metrics.json's planned_length_m), from the
    # exact start to the exact goal without a step to either's cell centre.
    assert p.stdout.splitlines() == ["interrupted", "then True 43.389"]


def test_sigint_during_a_run_raises_keyboard_interrupt_and_leaves_no_metrics(tmp_path):
    # A slow flight: 0.1 ms physics steps, rendering a video afterwards.
    code = (f"import cosim; print('running', flush=True); cosim.run({DEFAULT!r}, "
            f"overrides={{'sim.timestep': 0.0001}}, out={str(tmp_path)!r}, video=True)")
    elapsed, stderr, _ = interrupt_after_marker(code, "running")
    assert elapsed < 3
    assert stderr.rstrip().endswith("KeyboardInterrupt")
    assert not (tmp_path / "metrics.json").exists()
