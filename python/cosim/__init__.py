"""cosim from Python: plan, fly and evaluate scenarios of the cosim co-simulator.

    import cosim
    r = cosim.run("scenario.yaml", overrides={"planner.name": "astar"})
    r.status, r.message, r.metrics, r.timeseries()
    p = cosim.plan("scenario.yaml", planner="rrt_connect")
    sim = cosim.Simulation("scenario.yaml")

See docs/python.md and help() of each function and class.
"""

try:
    import numpy  # noqa: F401  (the results are NumPy arrays)
except ImportError:
    # The extension is built against Debian's Python 3.11 (/usr/bin/python3), whose NumPy lives
    # in /usr/lib/python3/dist-packages. Another CPython 3.11 on PATH (e.g. pyenv's) has the same
    # ABI but does not look there: borrow Debian's NumPy rather than fail.
    import sys

    sys.path.append("/usr/lib/python3/dist-packages")
    import numpy  # noqa: F401

from ._cosim import (  # noqa: E402
    DEFAULT_SCENARIO,
    InputError,
    PlanResult,
    RunResult,
    Simulation,
    UnknownVehicleError,
    __version__,
    plan,
    run,
)

__all__ = [
    "DEFAULT_SCENARIO",
    "InputError",
    "PlanResult",
    "RunResult",
    "Simulation",
    "UnknownVehicleError",
    "plan",
    "run",
]
