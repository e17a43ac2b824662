#!/usr/bin/env bash
# Grades a class on a Slurm cluster in N shares and merges them:
#   examples/slurm/submit.sh N SUBMISSIONS OUT [SEED] [STAGES]
# submits an array of N tasks (grade_array.sh) and a job that runs
# `raylab grade --merge OUT/report OUT/shard-*` once all of them succeeded.
# RAYLAB (default: build/raylab of this checkout) must be reachable from the
# nodes, as must SUBMISSIONS and OUT. COURSE=course.json grades with a course
# file's weights, which the merge applies too (with its late policy, give
# SUBMITTED=times.csv). Prints the two job ids.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
case "${1:-}" in -h|--help) sed -n '2,9p' "$0"; exit 0 ;; esac
if [ $# -lt 3 ] || [ $# -gt 5 ]; then sed -n '2,9p' "$0" >&2; exit 2; fi
for arg in "$@"; do
  case "$arg" in -*) echo "submit.sh: '$arg' looks like an option; it takes none but --help (paths may not start with '-')" >&2; exit 2 ;; esac
done
n=$1 submissions=$(realpath "$2") out=$3 seed=${4:-0} stages=${5:-}
case "$n" in ''|*[!0-9]*) echo "submit.sh: N must be a whole number, not '$n'" >&2; exit 2 ;; esac
[ "$n" -ge 1 ] || { echo "submit.sh: N must be at least 1" >&2; exit 2; }
[ -d "$submissions" ] || { echo "submit.sh: $2 is not a folder" >&2; exit 2; }
raylab=$(realpath "${RAYLAB:-$here/../../build/raylab}")
command -v sbatch >/dev/null || {
  echo "submit.sh: sbatch is not installed here: run it on a Slurm cluster's login node (examples/slurm/local_cluster.sh starts a one-node cluster to try it)" >&2
  exit 2
}
# OUT is made for the jobs' logs; a refused submission takes it away again
# when this run made it (nothing is left behind for a job that never ran).
made_out=0
[ -e "$out" ] || made_out=1
mkdir -p "$out"
out=$(realpath "$out")
refused() {  # WHAT, sbatch's own message
  [ "$made_out" -eq 1 ] && rm -rf "$out"
  echo "submit.sh: sbatch refused the $1: ${2:-no reason given} (is the cluster up? sinfo tells)" >&2
  exit 1
}
err=$(mktemp)
trap 'rm -f "$err"' EXIT
# Through the environment (--export=ALL): a value in --export=NAME=VALUE
# may not hold a comma, and a stage list does.
course=${COURSE:-} submitted=${SUBMITTED:-}
[ -z "$course" ] || course=$(realpath "$course")
[ -z "$submitted" ] || submitted=$(realpath "$submitted")
array=$(RAYLAB=$raylab SUBMISSIONS=$submissions OUT=$out SEED=$seed STAGES=$stages COURSE=$course \
  sbatch --parsable --array="0-$((n - 1))" --chdir="$out" --export=ALL "$here/grade_array.sh" 2>"$err") ||
  refused "grading array" "$(tail -1 "$err")"
shards=""
for ((k = 0; k < n; ++k)); do shards+=" '$out/shard-$k'"; done
merge=$(sbatch --parsable --dependency="afterok:${array%%;*}" --job-name=raylab-merge --chdir="$out" \
  --output="$out/raylab-merge-%j.log" --wrap="'$raylab' grade --merge '$out/report'$shards${course:+ --course '$course'}${submitted:+ --submitted '$submitted'}" 2>"$err") || {
  echo "submit.sh: the grading array $array was submitted, but sbatch refused the merge job: $(tail -1 "$err"); merge by hand once it has ended: $raylab grade --merge $out/report $out/shard-*" >&2
  exit 1
}
echo "array job $array (grading, $n shares), merge job $merge (report: $out/report/report.html)"
