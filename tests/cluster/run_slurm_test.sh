#!/usr/bin/env bash
# The cluster path on a real Slurm cluster (ctest label `cluster`): a one-node
# cluster of its own (examples/slurm/local_cluster.sh: munged, slurmctld,
# slurmd from Debian's munge and slurm-wlm; no systemd, private sockets,
# ports and folders, stopped by process id whatever happens) grades a small
# class with examples/slurm/submit.sh (a 4-task array, then the merge job),
# and the merged report must equal an unsharded run's.
#   run_slurm_test.sh RAYLAB RAYLAB_LABGEN WORKDIR
set -euo pipefail
raylab=$(realpath "$1") labgen=$(realpath "$2") work=$3
root=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work"
mkdir -p "$work"
work=$(realpath "$work")

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
RAYLAB=$raylab LOCAL_CLUSTER_TIMEOUT=300 bash "$root/examples/slurm/local_cluster.sh" "$work/cluster" \
  bash "$root/examples/slurm/submit.sh" 4 "$class" "$work/out" 7 01,02 | tee "$work/cluster.log"
echo "cluster test: the array and the merge finished in $(( ($(date +%s%N) - start) / 1000000 )) ms, the cluster's start and stop included"
grep -q "merge job" "$work/cluster.log" || { echo "cluster test: submit.sh did not submit"; exit 1; }
[ -f "$work/out/report/report.html" ] || { echo "cluster test: no merged report"; cat "$work/out"/*.log; exit 1; }
for k in 0 1 2 3; do [ -f "$work/out/shard-$k/shard.json" ] || { echo "cluster test: share $k missing"; exit 1; }; done

# The same class unsharded, on this machine: the same scores.
"$raylab" grade --submissions "$class" --out "$work/whole" --seed 7 --stages 01,02 --jobs 2 >"$work/whole.log" 2>&1
if ! diff "$work/whole/summary.csv" "$work/out/report/summary.csv"; then
  echo "cluster test: the merged summary differs from the unsharded one"; exit 1
fi
echo "cluster test: passed (merged report of 4 Slurm shares = unsharded report)"
