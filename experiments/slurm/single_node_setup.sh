#!/bin/bash
# A single-node Slurm (slurmctld + slurmd on localhost, munge auth) on Debian 12 without systemd,
# for CI and for trying the sweep scripts on one machine. Run as root. Installs slurm-wlm and munge
# if they are missing. Writes the daemons' PIDs to $PIDS_FILE (default /tmp/cosim-slurm-pids.env)
# for single_node_teardown.sh, which stops exactly those. The recipe follows Slurm's own
# single-node setup (slurm.conf with one node and one partition).
# Exit 0 when the node is idle; non-zero with a message otherwise.
set -euo pipefail
PIDS_FILE=${PIDS_FILE:-/tmp/cosim-slurm-pids.env}

# Wait until "$@" succeeds, polling every 0.2 s, for at most $TMO seconds.
wait_for() { local end=$(( $(date +%s) + TMO )); until "$@" >/dev/null 2>&1; do
  [ "$(date +%s)" -ge "$end" ] && { echo "single_node_setup: timeout waiting for: $*" >&2; return 1; }
  sleep 0.2; done; }

if [ "$(id -u)" != 0 ]; then echo "single_node_setup: must run as root" >&2; exit 1; fi
if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null || ! command -v sbatch >/dev/null \
   || ! command -v munged >/dev/null; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends slurmctld slurmd slurm-client munge >/dev/null
fi
# Live daemons only: killed ones linger as zombies until init reaps them (seen on this kind of
# machine).
running() { for pid in $(pgrep -x "$1"); do
  [ "$(awk '{print $3}' "/proc/$pid/stat" 2>/dev/null)" = Z ] || return 0; done; return 1; }
if running slurmctld || running slurmd; then
  echo "single_node_setup: a slurmctld or slurmd is already running; not starting another" >&2
  exit 1
fi

: > "$PIDS_FILE"
# munge: the key comes from the package's postinst; the socket folder lives on tmpfs.
[ -s /etc/munge/munge.key ] || mungekey --create --keyfile=/etc/munge/munge.key
chown munge:munge /etc/munge/munge.key; chmod 0400 /etc/munge/munge.key
install -d -o munge -g munge -m 0755 /run/munge
if ! (munge -n | unmunge) >/dev/null 2>&1; then
  runuser -u munge -- /usr/sbin/munged        # as root it refuses: "Logfile is insecure"
  TMO=10 wait_for sh -c 'munge -n | unmunge'
  echo "MUNGED_PID=$(cat /run/munge/munged.pid)" >> "$PIDS_FILE"
fi

CPUS=$(nproc)
MEM=$(( $(free -m | awk '/^Mem:/{print $2}') * 9 / 10 ))   # must not exceed what slurmd detects
mkdir -p /etc/slurm
[ -f /etc/slurm/slurm.conf ] && [ ! -f /etc/slurm/slurm.conf.before-cosim ] && \
  cp /etc/slurm/slurm.conf /etc/slurm/slurm.conf.before-cosim
cat > /etc/slurm/slurm.conf <<CONF
ClusterName=ci
SlurmctldHost=localhost(127.0.0.1)
AuthType=auth/munge
CryptoType=crypto/munge
SlurmUser=slurm
SlurmdUser=root
SlurmctldPort=6817
SlurmdPort=6818
SlurmctldPidFile=/run/slurmctld.pid
SlurmdPidFile=/run/slurmd.pid
StateSaveLocation=/var/spool/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
MpiDefault=none
SwitchType=switch/none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
ReturnToService=2
MailProg=/bin/true
NodeName=localhost NodeAddr=127.0.0.1 CPUs=${CPUS} RealMemory=${MEM} State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
install -d -o slurm -g slurm -m 0755 /var/spool/slurmctld /var/log/slurm
install -d -o root -g root -m 0755 /var/spool/slurmd
rm -rf /var/spool/slurmctld/*                 # no jobs carried over from an earlier start
# In the foreground (-D), in the background of this script: $! is the daemon's PID (a daemonizing
# start returns before its PID file exists).
slurmctld -D > /var/log/slurm/slurmctld.stdout 2>&1 &
echo "SLURMCTLD_PID=$!" >> "$PIDS_FILE"
slurmd -D > /var/log/slurm/slurmd.stdout 2>&1 &
echo "SLURMD_PID=$!" >> "$PIDS_FILE"
TMO=30 wait_for sh -c '[ "$(sinfo -h -o %T)" = idle ]'
echo "single_node_setup: node idle ($(tr '\n' ' ' < "$PIDS_FILE"))"
