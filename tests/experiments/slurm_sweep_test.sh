#!/bin/bash
# A cosim sweep on a real single-node Slurm: starts munge + slurmctld + slurmd on localhost
# (experiments/slurm/single_node_setup.sh; installs slurm-wlm and munge if missing), submits a
# 4-job sweep as a 2-task job array plus the merge job (experiments/slurm/submit_sweep.sh), and
# checks the merged results.csv: 4 rows, ids 0-3 in order, all ok, and each shard ran 2 jobs.
# Stops its daemons on every exit (trap). Exit 77 (CTest SKIP) with a message when Slurm cannot
# be set up here (not root, no package, daemons that will not start, a Slurm already running).
# Usage: slurm_sweep_test.sh COSIM_BINARY SOURCE_DIR
set -uo pipefail
cosim=$1; src=$2
skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*"; for f in "$work"/out/slurm-*.out; do [ -f "$f" ] && { echo "--- $f"; cat "$f"; }; done; exit 1; }

[ "$(id -u)" = 0 ] || skip "needs root to install and start munge and Slurm"
work=$(mktemp -d /tmp/cosim-slurm-test.XXXXXX)
export PIDS_FILE="$work/pids.env"
cleanup() { "$src/experiments/slurm/single_node_teardown.sh"; rm -rf "$work"; }
trap cleanup EXIT

if ! "$src/experiments/slurm/single_node_setup.sh" > "$work/setup.log" 2>&1; then
  cat "$work/setup.log"
  skip "single-node Slurm could not be started here (see above)"
fi

cat > "$work/sweep.yaml" <<'SWEEP'
generators: [{type: city, density: 0.5, size: [16, 16, 5], seed: 1}]
vary:
  planner.name: [astar, theta_star]
  sim.seed: [1, 2]
set: {sim.max_time: 30}
limits: {job_timeout_s: 60}
SWEEP
ids=$("$src/experiments/slurm/submit_sweep.sh" "$work/sweep.yaml" "$work/out" 2 "$cosim") || fail "sbatch failed"
echo "submitted: $ids"
merge=${ids##*merge=}
# Poll (sbatch --wait backs off to ~10 s): done when the merge job has left the queue.
end=$(( $(date +%s) + 100 ))
while squeue -h -j "$merge" 2>/dev/null | grep -q .; do
  [ "$(date +%s)" -ge "$end" ] && fail "the sweep did not finish within 100 s"
  sleep 0.3
done

csv="$work/out/results.csv"
[ -f "$csv" ] || fail "no merged results.csv"
cat "$csv" | cut -c1-100
[ "$(wc -l < "$csv")" = 5 ] || fail "expected a header and 4 rows"
[ "$(tail -n +2 "$csv" | cut -d, -f1 | tr '\n' ' ')" = "0 1 2 3 " ] || fail "job ids not 0-3 in order"
[ "$(tail -n +2 "$csv" | cut -d, -f5 | sort -u)" = ok ] || fail "not every job ok"
for task in 1 2; do
  grep -q "shard $task/2\]: 2 jobs, 0 already finished, 2 to run" "$work"/out/slurm-*_"$task".out \
    || fail "array task $task did not run its 2-job shard"
done
echo "PASS: 2 array tasks ran 2 jobs each; merged results.csv has the 4 jobs"
