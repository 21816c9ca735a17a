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



def build_info():
    """Which build of cosim this session loaded: a dict of "version", "package" (the folder of
    this package), "extension" (the compiled module's file) and "checkout" (the source folder it
    was built from, whose scenarios and models it reads). Two checkouts on one machine can both
    make `import cosim` work; this says which one did."""
    import os

    from . import _cosim

    checkout = os.path.dirname(os.path.dirname(os.path.dirname(DEFAULT_SCENARIO)))
    return {
        "version": __version__,
        "package": os.path.dirname(os.path.abspath(__file__)),
        "extension": os.path.abspath(_cosim.__file__),
        "checkout": checkout,
    }


__all__ = [
    "build_info",
    "DEFAULT_SCENARIO",
    "InputError",
    "PlanResult",
    "RunResult",
    "Simulation",
    "UnknownVehicleError",
    "plan",
    "run",
]
