#!/bin/bash
# Stops exactly the daemons single_node_setup.sh started (by PID, from $PIDS_FILE), and removes
# the stale PID files that would otherwise break a later `apt-get purge slurmctld`.
PIDS_FILE=${PIDS_FILE:-/tmp/cosim-slurm-pids.env}
[ -f "$PIDS_FILE" ] || exit 0
. "$PIDS_FILE"
for pid in ${SLURMD_PID:-} ${SLURMCTLD_PID:-}; do kill "$pid" 2>/dev/null || true; done
for _ in $(seq 1 50); do
  alive=0
  for pid in ${SLURMD_PID:-} ${SLURMCTLD_PID:-}; do
    # A zombie still answers kill -0; /proc/PID/stat's state field tells them apart.
    [ -r /proc/$pid/stat ] && [ "$(awk '{print $3}' /proc/$pid/stat)" != Z ] && alive=1
  done
  [ $alive = 0 ] && break
  sleep 0.2
done
[ -n "${MUNGED_PID:-}" ] && kill "$MUNGED_PID" 2>/dev/null
[ -n "${SLURMCTLD_PID:-}" ] && rm -f /run/slurmctld.pid
[ -n "${SLURMD_PID:-}" ] && rm -f /run/slurmd.pid
rm -f "$PIDS_FILE"
exit 0
