#!/bin/bash
# Submits a cosim sweep to Slurm: an array of TASKS shards, then a merge job that starts when the
# whole array has ended (afterany: a failed shard still gets its finished jobs merged).
#   experiments/slurm/submit_sweep.sh SWEEP.yaml OUT_DIR TASKS [COSIM_BINARY] [-- extra sbatch args]
# Prints "array=<job id> merge=<job id>". OUT_DIR must be on a file system every node sees.
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 SWEEP.yaml OUT_DIR TASKS [COSIM_BINARY] [-- sbatch args]" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
sweep=$(realpath "$1"); out=$(realpath -m "$2"); tasks=$3; shift 3
cosim=${1:-$(command -v cosim || echo "$here/../../build/cosim")}
[ $# -gt 0 ] && shift
[ "${1:-}" = "--" ] && shift
cosim=$(realpath "$cosim")
[ -x "$cosim" ] || { echo "$0: no cosim binary at $cosim" >&2; exit 2; }
[[ "$tasks" =~ ^[1-9][0-9]*$ ]] || { echo "$0: TASKS must be a positive number" >&2; exit 2; }
mkdir -p "$out"
export COSIM="$cosim" SWEEP="$sweep" OUT="$out"
array=$(sbatch --parsable --export=ALL --array=1-"$tasks" --output="$out/slurm-%A_%a.out" "$@" \
  "$here/sweep_array.sbatch")
array=${array%%;*}
merge=$(sbatch --parsable --export=ALL --dependency=afterany:"$array" --output="$out/slurm-merge-%j.out" "$@" \
  "$here/sweep_merge.sbatch")
echo "array=$array merge=${merge%%;*}"
