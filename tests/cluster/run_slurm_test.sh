#!/usr/bin/env bash
# The cluster path on a real Slurm cluster (ctest label `cluster`): starts a
# one-node cluster of its own (munged, slurmctld, slurmd from Debian's munge
# and slurm-wlm; no systemd needed, private sockets, ports and folders), grades
# a small class with examples/slurm/submit.sh (a 4-task array, then the merge
# job), and checks that the merged report equals an unsharded run's. Stops
# the daemons it started, by their process ids, whatever happens.
#   run_slurm_test.sh RAYLAB RAYLAB_LABGEN WORKDIR
set -euo pipefail
raylab=$(realpath "$1") labgen=$(realpath "$2") work=$3
root=$(cd "$(dirname "$0")/../.." && pwd)
for tool in munged slurmctld slurmd sbatch sinfo squeue; do
  command -v "$tool" >/dev/null || { echo "cluster test: $tool is missing: run 'bash install.sh' (slurm-wlm, munge)" >&2; exit 1; }
done
[ "$(id -u)" -eq 0 ] || { echo "cluster test: needs root (slurmd runs jobs as their user)" >&2; exit 1; }
id munge >/dev/null 2>&1 || { echo "cluster test: no 'munge' user: is the munge package installed?" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work"
work=$(realpath "$work")
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

# munge: a key of our own, its socket in our folder.
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
ClusterName=raylabtest
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
[ "$up" -eq 1 ] || { echo "cluster test: the node did not come up"; tail -5 "$s/slurmctld.log" "$s/slurmd.log"; exit 1; }
echo "cluster test: a one-node Slurm cluster is up ($(sinfo -h -o '%P %D %t %c CPUs'))"

# A class of five: three solved, two untouched (stage 02 missing from one).
class=$work/class
mkdir -p "$class"
"$labgen" --solved "$class/ada" >/dev/null
cp -r "$class/ada" "$class/cy"
cp -r "$class/ada" "$class/eve"
cp -r "$root/labs" "$class/bob"
cp -r "$root/labs" "$class/dan"
rm -rf "$class/dan/02-shading"

start=$(date +%s%N)
submitted=$(bash "$root/examples/slurm/submit.sh" 4 "$class" "$work/out" 7 01,02)
echo "cluster test: $submitted"
merge_job=$(echo "$submitted" | sed -n 's/.*merge job \([0-9]*\).*/\1/p')
for _ in $(seq 600); do
  [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break
  sleep 0.5
done
[ -z "$(squeue -h -o %i)" ] || { echo "cluster test: jobs still queued after 5 minutes:"; squeue; exit 1; }
echo "cluster test: the array and the merge finished in $(( ($(date +%s%N) - start) / 1000000 )) ms"
[ -f "$work/out/report/report.html" ] || { echo "cluster test: no merged report"; cat "$work/out"/*.log; exit 1; }
for k in 0 1 2 3; do [ -f "$work/out/shard-$k/shard.json" ] || { echo "cluster test: share $k missing"; exit 1; }; done

# The same class unsharded, on this machine: the same scores.
"$raylab" grade --submissions "$class" --out "$work/whole" --seed 7 --stages 01,02 --jobs 2 >"$work/whole.log" 2>&1
if ! diff "$work/whole/summary.csv" "$work/out/report/summary.csv"; then
  echo "cluster test: the merged summary differs from the unsharded one"; exit 1
fi
echo "cluster test: passed (merged report of 4 Slurm shares = unsharded report; job $merge_job merged)"
