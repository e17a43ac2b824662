#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, to try submit.sh before a real
# cluster (and for RayLab's own test, `ctest -L cluster`):
#   examples/slurm/local_cluster.sh WORKDIR COMMAND [ARGS...]
# starts munged, slurmctld and slurmd (Debian's munge and slurm-wlm; no
# systemd needed) with their key, sockets, ports, state and logs all in
# WORKDIR (a new or empty folder), runs COMMAND with SLURM_CONF pointing at
# that cluster, waits until every job it queued has ended (at most
# LOCAL_CLUSTER_TIMEOUT seconds, default 600), stops the daemons by their
# process ids and exits with COMMAND's status (1 if jobs were still queued).
# Needs root: slurmd runs jobs as their user.
set -euo pipefail
case "${1:-}" in -h|--help) sed -n '2,12p' "$0"; exit 0 ;; esac
if [ $# -lt 2 ]; then sed -n '2,12p' "$0" >&2; exit 2; fi
case "$1" in -*) echo "local_cluster.sh: WORKDIR '$1' looks like an option" >&2; exit 2 ;; esac
for tool in munged slurmctld slurmd sbatch sinfo squeue; do
  command -v "$tool" >/dev/null || { echo "local_cluster.sh: $tool is missing: apt-get install slurm-wlm munge (bash install.sh installs them)" >&2; exit 2; }
done
[ "$(id -u)" -eq 0 ] || { echo "local_cluster.sh: needs root (slurmd runs jobs as their user)" >&2; exit 2; }
id munge >/dev/null 2>&1 || { echo "local_cluster.sh: no 'munge' user: is the munge package installed?" >&2; exit 2; }
if [ -e "$1" ] && [ -n "$(ls -A "$1" 2>/dev/null)" ]; then
  echo "local_cluster.sh: $1 is not empty (give a new folder: the cluster's state goes there)" >&2; exit 2
fi
mkdir -p "$1"
work=$(realpath "$1")
shift
chmod 755 "$work"
pids=()
stop() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
}
trap stop EXIT

# munge: a key of its own, its socket in the folder.
m=$work/munge
mkdir -p "$m"
dd if=/dev/urandom of="$m/munge.key" bs=1024 count=1 status=none
chown -R munge:munge "$m"
chmod 700 "$m"
chmod 400 "$m/munge.key"
runuser -u munge -- munged --socket="$m/munge.socket" --key-file="$m/munge.key" \
  --pid-file="$m/munged.pid" --log-file="$m/munged.log" --seed-file="$m/munged.seed" --force
pids+=("$(cat "$m/munged.pid")")

# Slurm: one node (this machine), one partition, ports off the defaults.
s=$work/slurm
mkdir -p "$s/state" "$s/spool"
host=$(hostname -s)
port=$((20000 + RANDOM % 20000))
cat > "$s/slurm.conf" <<CONF
ClusterName=raylablocal
SlurmctldHost=$host
SlurmUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$m/munge.socket
StateSaveLocation=$s/state
SlurmdSpoolDir=$s/spool
SlurmctldPidFile=$s/slurmctld.pid
SlurmdPidFile=$s/slurmd.pid
SlurmctldLogFile=$s/slurmctld.log
SlurmdLogFile=$s/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SchedulerType=sched/backfill
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$s/slurm.conf
slurmctld -f "$SLURM_CONF"
for _ in $(seq 50); do [ -s "$s/slurmctld.pid" ] && break; sleep 0.1; done
pids+=("$(cat "$s/slurmctld.pid")")
slurmd -f "$SLURM_CONF"
for _ in $(seq 50); do [ -s "$s/slurmd.pid" ] && break; sleep 0.1; done
pids+=("$(cat "$s/slurmd.pid")")
up=0
for _ in $(seq 100); do
  if sinfo -h -o %t 2>/dev/null | grep -qE '^(idle|mix|alloc)'; then up=1; break; fi
  sleep 0.1
done
[ "$up" -eq 1 ] || { echo "local_cluster.sh: the node did not come up"; tail -5 "$s/slurmctld.log" "$s/slurmd.log"; exit 1; }
echo "local_cluster.sh: a one-node Slurm cluster is up ($(sinfo -h -o '%P %D %t %c CPUs')); state in $work"

status=0
"$@" || status=$?
timeout=${LOCAL_CLUSTER_TIMEOUT:-600}
for _ in $(seq $((timeout * 2))); do
  [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break
  sleep 0.5
done
if [ -n "$(squeue -h -o %i)" ]; then
  echo "local_cluster.sh: jobs still queued after $timeout s:"; squeue; exit 1
fi
echo "local_cluster.sh: every job has ended; stopping the cluster"
exit "$status"
