#!/usr/bin/env bash
# One share of a class, as one task of a Slurm job array: task K of N runs
# `raylab grade --shard K/N` into $OUT/shard-K. submit.sh submits the array
# and the job that merges the shares; run by hand:
#   RAYLAB=... SUBMISSIONS=... OUT=... SEED=... [STAGES=01,02] [COURSE=course.json] sbatch --array=0-3 grade_array.sh
#SBATCH --job-name=raylab-grade
#SBATCH --cpus-per-task=2
#SBATCH --output=raylab-grade-%A_%a.log
set -euo pipefail
: "${RAYLAB:?the raylab binary (e.g. /opt/raylab/build/raylab)}"
: "${SUBMISSIONS:?the class: one folder per student}"
: "${OUT:?where the shares go (a folder every node can write)}"
k=${SLURM_ARRAY_TASK_ID:?run me as a job array: sbatch --array=0-N ...}
n=${SLURM_ARRAY_TASK_COUNT:?}
# The array's numbering may not start at 0 (--array=1-4): count from its minimum.
k=$((k - ${SLURM_ARRAY_TASK_MIN:-0}))
stages=()
[ -n "${STAGES:-}" ] && stages=(--stages "$STAGES")
# A course file's weights apply where the stages are graded.
[ -n "${COURSE:-}" ] && stages+=(--course "$COURSE")
exec "$RAYLAB" grade --submissions "$SUBMISSIONS" --out "$OUT/shard-$k" --shard "$k/$n" \
  --seed "${SEED:-0}" --jobs "${SLURM_CPUS_PER_TASK:-1}" "${stages[@]}"
