#!/usr/bin/env python3
"""What stepping a flight from Python costs: simulated seconds per wall-clock second of the
bundled default scenario's flight (30.2 s simulated, 500 Hz control, 1 kHz physics), flown

  run            by cosim.run (the pipeline's own loop; its metrics' sim_speed_x),
  step_until     by cosim.Simulation.step_until (the same loop, stepped from the binding),
  python_loop    by `while not sim.done: sim.step()` (one Python call per control period),
  python_pd      under a controller written in Python (examples/pd_controller.py), 500 Hz,
  python_hover   under the cheapest Python controller (returns the hover thrusts), first 10 s,

each the median of --repeat flights, and the ratio of each to `run`. Planning is not timed.

    PYTHONPATH=build/python python3 experiments/python/bench_overhead.py [--repeat N] [--json]
"""
import argparse
import json
import os
import statistics
import sys
import time

import cosim

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "examples"))
from pd_controller import PDController  # noqa: E402


def speed_of_run(scenario):
    m = cosim.run(scenario).metrics
    return m["sim_speed_x"]


def speed_of_simulation(scenario, until=float("inf"), controller=None, per_step=False):
    with cosim.Simulation(scenario) as sim:
        if controller is not None:
            sim.set_controller(sim.vehicles[0], controller(sim))
        start_time = sim.time
        start = time.perf_counter()
        if per_step:
            while not sim.done:
                sim.step()
        else:
            sim.step_until(until)
        wall = time.perf_counter() - start
        return (sim.time - start_time) / wall


def hover(sim):
    thrusts = sim.hover_thrusts(sim.vehicles[0])
    return lambda state, reference: thrusts


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario", default=cosim.DEFAULT_SCENARIO)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    s = args.scenario
    cases = {
        "run": lambda: speed_of_run(s),
        "step_until": lambda: speed_of_simulation(s),
        "python_loop": lambda: speed_of_simulation(s, per_step=True),
        "python_pd": lambda: speed_of_simulation(
            s, controller=lambda sim: PDController(sim.airframe(sim.vehicles[0]))),
        "python_hover": lambda: speed_of_simulation(s, until=10.0, controller=hover),
    }
    speeds = {name: statistics.median(case() for _ in range(args.repeat))
              for name, case in cases.items()}
    figures = {}
    for name, x in speeds.items():
        figures[f"{name}_sim_speed_x"] = round(x, 2)
        figures[f"{name}_ratio_to_run"] = round(x / speeds["run"], 3)
    if args.json:
        print(json.dumps(figures, indent=2))
        return
    print(f"{'flown by':<14} {'sim s / wall s':>15} {'ratio to run':>13}")
    for name, x in speeds.items():
        print(f"{name:<14} {x:>15.1f} {x / speeds['run']:>13.3f}")


if __name__ == "__main__":
    main()
