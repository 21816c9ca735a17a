#!/usr/bin/env python3
"""Regenerates docs/benchmarks.md: the project's current figures, measured on this machine.

Every figure in that file comes from a command run here, never from a hand-written number, so
the file says when and where it was made (UTC date, commit, CPU model, cores, load average). It
runs, with the built program (build/cosim):

  - `cosim bench --section NAME` for each section in --sections (each compares two things in
    the same run, so its ratios mean something on a loaded machine too);
  - `cosim run` of some bundled scenarios (no video, no pictures): outcome, tracking and
    estimation error, planning time, speed against real time;
  - `cosim plan-bench` of our sampling planners against OMPL's on window.yaml;
  - experiments/python/bench_overhead.py (what stepping a flight from Python costs), when the
    Python module is built.

    experiments/bench/write_benchmarks_doc.py [--cosim build/cosim] [--out docs/benchmarks.md]
        [--sections a,b,...] [--runs N] [--time T] [--no-python]

The default settings take about 15-25 minutes on a 2-core machine. The file is written to a
temporary name and renamed, so an interrupted run leaves the previous one in place.
"""
import argparse
import datetime
import json
import os
import platform
import shutil
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

# Sections run by default (`cosim bench --help` lists them all). Left out: grid_astar_vs_boost
# and ant_planners, whose full workloads use MovingAI maps that are not bundled when a machine
# has them (so their figures would not come from the repository alone); team_render and
# sweep_throughput, to keep the script's run time down (name them in --sections to add them).
DEFAULT_SECTIONS = ["physics_loop", "sensing_loop", "reference_flight", "trajectory_generation",
                    "mapf_planners", "render_pipeline", "team_scale"]

# (label, scenario under experiments/scenarios, overrides): the runs whose figures the docs cite.
SCENARIO_RUNS = [
    ("default", "default.yaml", []),
    ("stacked_pair", "stacked_pair.yaml", []),
    ("stacked_pair, downwash off", "stacked_pair.yaml", ["disturbances.downwash=false"]),
    ("warehouse_robots", "warehouse_robots.yaml", []),
    ("swarm32", "swarm32.yaml", []),
]

# metrics.json keys shown per scenario run, with their column titles.
RUN_COLUMNS = [
    ("reached_goal", "goal"), ("collisions", "collisions"), ("rmse_m", "RMSE m"),
    ("max_error_m", "max error m"), ("estimation_rmse_m", "estimation RMSE m"),
    ("planning_time_ms", "planning ms"), ("sim_time_s", "simulated s"),
    ("wall_time_s", "wall s"), ("sim_speed_x", "x real time"),
]
TEAM_COLUMNS = [("min_uav_separation_m", "closest pair (ellipsoids)"),
                ("downwash_violations", "downwash violations"), ("uav_contacts", "uav contacts")]

PLAN_BENCH_PLANNERS = ("rrt_connect,ompl_rrt_connect,rrt,ompl_rrt,rrt_star,ompl_rrt_star,"
                       "informed_rrt_star,ompl_informed_rrt_star,prm,ompl_prm,theta_star")


def run(command, accept=(0,), **kwargs):
    """Runs a command, returns (stdout, seconds); another exit status than those accepted ends
    the script with the command's stderr."""
    start = time.monotonic()
    done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True, **kwargs)
    seconds = time.monotonic() - start
    if done.returncode not in accept:
        sys.exit(f"write_benchmarks_doc: {' '.join(command)} exited {done.returncode}:\n"
                 f"{done.stderr.strip()}")
    return done.stdout, seconds


def machine():
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                            capture_output=True, text=True).stdout.strip() or "unknown"
    dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=ROOT,
                           capture_output=True, text=True).stdout.strip()
    return {"cpu": model, "cores": os.cpu_count(), "system": platform.platform(),
            "commit": commit + (" with local changes" if dirty else "")}


def fmt(value):
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        return f"{value:.4g}"
    return "-" if value is None else str(value)


def bench_sections(cosim, sections):
    lines = ["## `cosim bench` sections", "",
             "Each section measures ours against a peer or the bare engine in the same run; its "
             "last line says what was compared. Verbatim output of `cosim bench --section NAME`.",
             ""]
    for name in sections:
        out, seconds = run([cosim, "bench", "--section", name])
        lines += [f"### {name}", "", f"Took {seconds:.0f} s.", "", "```", out.rstrip(), "```", ""]
    return lines


def scenario_runs(cosim, scratch):
    lines = ["## Bundled scenarios", "",
             "`cosim run experiments/scenarios/NAME.yaml --no-video --no-images` (and the "
             "overrides named); figures from its metrics.json. Outcomes and errors are "
             "deterministic (same scenario and seed, same result); times depend on the machine "
             "and its load.", ""]
    header = ["run"] + [title for _, title in RUN_COLUMNS]
    rows = []
    team_rows = []
    for label, scenario, overrides in SCENARIO_RUNS:
        out = os.path.join(scratch, label.replace(" ", "_").replace(",", ""))
        command = [cosim, "run", os.path.join("experiments", "scenarios", scenario), "--out", out,
                   "--no-video", "--no-images", "--quiet"]
        for o in overrides:
            command += ["--set", o]
        run(command, accept=(0, 1))  # 1: the run completed but failed its task; metrics say how
        with open(os.path.join(out, "metrics.json")) as f:
            metrics = json.load(f)
        name = f"`{scenario}`" + (f" `--set {' '.join(overrides)}`" if overrides else "")
        rows.append([name] + [fmt(metrics.get(key)) for key, _ in RUN_COLUMNS])
        if "min_uav_separation_m" in metrics:
            team_rows.append([name] + [fmt(metrics.get(key)) for key, _ in TEAM_COLUMNS])
    lines += table(header, rows)
    if team_rows:
        lines += ["", "Quadrotor teams (`min_uav_separation_m`: 1.0 = two separation ellipsoids "
                  "touching):", ""]
        lines += table(["run"] + [title for _, title in TEAM_COLUMNS], team_rows)
    return lines + [""]


def plan_bench(cosim, scratch, runs, seconds):
    out = os.path.join(scratch, "plan-bench")
    command = [cosim, "plan-bench", "experiments/scenarios/window.yaml", "--planners",
               PLAN_BENCH_PLANNERS, "--runs", str(runs), "--time", str(seconds), "--out", out]
    run(command)
    with open(os.path.join(out, "summary.md")) as f:
        summary = f.read().strip()
    summary = "\n".join(line.replace("# ", "### ", 1) if line.startswith("# ") else line
                        for line in summary.splitlines())
    return ["## Our planners against OMPL's: `cosim plan-bench` on `window.yaml`", "",
            f"`cosim plan-bench experiments/scenarios/window.yaml --planners {PLAN_BENCH_PLANNERS} "
            f"--runs {runs} --time {seconds}`: its summary.md.", "", summary, ""]


def python_overhead(repeat):
    package = os.path.join(ROOT, "build", "python")
    if not os.path.isdir(os.path.join(package, "cosim")):
        return ["## Stepping from Python", "", "Not measured: the Python module is not built.", ""]
    env = dict(os.environ, PYTHONPATH=package)
    python = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
    out, _ = run([python, "experiments/python/bench_overhead.py", "--repeat", str(repeat),
                  "--json"], env=env)
    data = json.loads(out)
    lines = ["## Stepping from Python", "",
             f"`experiments/python/bench_overhead.py --repeat {repeat}`: the default flight "
             "flown each way, simulated seconds per wall-clock second (median), and the ratio "
             "to `cosim.run`.", "", "```", json.dumps(data, indent=2), "```", ""]
    return lines


def table(header, rows):
    return (["| " + " | ".join(header) + " |", "|" + "---|" * len(header)] +
            ["| " + " | ".join(row) + " |" for row in rows])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cosim", default=os.path.join(ROOT, "build", "cosim"))
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "benchmarks.md"))
    parser.add_argument("--sections", default=",".join(DEFAULT_SECTIONS))
    parser.add_argument("--runs", type=int, default=5, help="plan-bench runs per planner")
    parser.add_argument("--time", type=float, default=0.5, help="plan-bench seconds per run")
    parser.add_argument("--no-python", action="store_true")
    args = parser.parse_args()
    if not os.access(args.cosim, os.X_OK):
        sys.exit(f"write_benchmarks_doc: {args.cosim}: not an executable; build cosim first")
    # SIGTERM as an exception: the running command is killed and the scratch folder removed.
    signal.signal(signal.SIGTERM,
                  lambda *_: sys.exit("write_benchmarks_doc: stopped; nothing written"))
    started = datetime.datetime.now(datetime.timezone.utc)
    load_before = os.getloadavg()
    m = machine()
    scratch = tempfile.mkdtemp(prefix="cosim-benchmarks-")
    try:
        body = scenario_runs(args.cosim, scratch)
        body += plan_bench(args.cosim, scratch, args.runs, args.time)
        if not args.no_python:
            body += python_overhead(3)
        body += bench_sections(args.cosim, [s for s in args.sections.split(",") if s])
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    minutes = (datetime.datetime.now(datetime.timezone.utc) - started).total_seconds() / 60
    load_after = os.getloadavg()
    head = ["# Benchmarks", "",
            "Generated by `experiments/bench/write_benchmarks_doc.py`; do not edit by hand, run "
            "it again. Times are wall-clock on the machine below, which may have been running "
            "other work (see the load average).", "",
            f"- date: {started.strftime('%Y-%m-%d %H:%M UTC')}, {minutes:.0f} min to generate",
            f"- machine: {m['cpu']}, {m['cores']} cores, {m['system']}",
            f"- load average (1 min) at start and end: {load_before[0]:.1f}, {load_after[0]:.1f}",
            f"- commit: {m['commit']}", ""]
    temporary = args.out + ".part"
    with open(temporary, "w") as f:
        f.write("\n".join(head + body).rstrip() + "\n")
    os.replace(temporary, args.out)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
