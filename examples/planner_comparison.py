#!/usr/bin/env python3
"""Planners x seeds on one scenario through cosim.plan: path length and planning time, as a
figure (matplotlib, Agg: no display needed) and a table on stdout.

    PYTHONPATH=build/python python3 examples/planner_comparison.py [--quick] [--out FILE.png]
                                                                  [--scenario FILE.yaml]

The grid planners are deterministic (one point each); the sampling planners vary with the seed
(sim.seed). --quick: two planners, two seeds (for the test suite).
"""
import argparse
import statistics

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import cosim  # noqa: E402

PLANNERS = ["astar", "theta_star", "lazy_theta_star", "rrt_connect", "rrt_star",
            "informed_rrt_star"]
QUICK_PLANNERS = ["theta_star", "rrt_connect"]


def compare(scenario, planners, seeds):
    """{planner: [(seed, PlanResult), ...]}"""
    results = {}
    for planner in planners:
        results[planner] = [(seed, cosim.plan(scenario, planner=planner,
                                              overrides={"sim.seed": seed}))
                            for seed in seeds]
    return results


def plot(results, out):
    fig, (ax_len, ax_time) = plt.subplots(1, 2, figsize=(11, 4.2))
    names = list(results)
    for i, planner in enumerate(names):
        found = [p for _, p in results[planner] if p.success]
        ax_len.scatter([i] * len(found), [p.length_m for p in found], alpha=0.7)
        ax_time.scatter([i] * len(found), [p.time_ms for p in found], alpha=0.7)
    for ax, label in ((ax_len, "path length (m)"), (ax_time, "planning time (ms)")):
        ax.set_xticks(range(len(names)))
        ax.set_xticklabels(names, rotation=30, ha="right")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    ax_time.set_yscale("log")
    fig.suptitle("planners x seeds (one point per seed)")
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenario", default=cosim.DEFAULT_SCENARIO)
    parser.add_argument("--out", default="planner_comparison.png")
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--quick", action="store_true", help="2 planners x 2 seeds")
    args = parser.parse_args()
    planners = QUICK_PLANNERS if args.quick else PLANNERS
    seeds = range(1, 3 if args.quick else args.seeds + 1)

    results = compare(args.scenario, planners, seeds)
    print(f"{'planner':<20} {'found':>5} {'median length_m':>16} {'median time_ms':>15}")
    for planner, runs in results.items():
        found = [p for _, p in runs if p.success]
        length = statistics.median(p.length_m for p in found) if found else float("nan")
        time_ms = statistics.median(p.time_ms for p in found) if found else float("nan")
        print(f"{planner:<20} {len(found):>2}/{len(runs):<2} {length:>16.2f} {time_ms:>15.1f}")
    plot(results, args.out)
    print(f"figure: {args.out}")


if __name__ == "__main__":
    main()
