#!/usr/bin/env bash
# Submits a find-ball experiment to Slurm: a job array of N shards, each
# `simswift experiment FILE --shard K/N`, and a merge job that runs once every
# shard has succeeded (afterok). Results in OUT (shards in OUT/shard-K).
#
#   scripts/experiment-slurm.sh FILE.yaml OUT [SHARDS] [sbatch options...]
#
# SHARDS defaults to 10. Environment:
#   SIMSWIFT    the simswift binary (default: build/simswift of this tree; must
#               be reachable at that path on the compute nodes, as must FILE and OUT)
#   CPUS        cores per shard (sbatch --cpus-per-task; simswift --jobs; default 2)
#   DRY_RUN=1   print the sbatch commands instead of submitting
# A failed or cancelled shard: resubmit the same command; finished trials are
# kept and every shard resumes where it stopped.
set -euo pipefail
if [ $# -lt 2 ]; then
  sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
fi
root="$(cd "$(dirname "$0")/.." && pwd)"
file=$(realpath "$1")
out=$(realpath -m "$2")
shards=${3:-10}
shift $(( $# >= 3 ? 3 : 2 ))
bin=${SIMSWIFT:-$root/build/simswift}
cpus=${CPUS:-2}
"$bin" experiment "$file" --check >/dev/null  # refuse a bad file before queueing anything
mkdir -p "$out"

q() { printf '%q' "$1"; }
# \$SLURM_ARRAY_TASK_ID is expanded on the node, in the job's shell.
shard_cmd="$(q "$bin") experiment $(q "$file") --shard \$SLURM_ARRAY_TASK_ID/$shards --out $(q "$out")/shard-\$SLURM_ARRAY_TASK_ID --jobs $cpus --progress lines"
merge_cmd="$(q "$bin") experiment merge $(q "$out")/shard-* --out $(q "$out")"
array=(sbatch --parsable --job-name=simswift-exp --array="1-$shards" --cpus-per-task="$cpus"
       --output="$out/slurm-%A_%a.log" "$@" --wrap "$shard_cmd")
if [ "${DRY_RUN:-0}" = 1 ]; then
  printf '%q ' "${array[@]}"; echo
  printf '%q ' sbatch --dependency=afterok:JOBID --job-name=simswift-merge --output="$out/slurm-merge-%j.log" "$@" --wrap "$merge_cmd"; echo
  exit 0
fi
jobid=$("${array[@]}")
jobid=${jobid%%;*}
merge=$(sbatch --parsable --dependency="afterok:$jobid" --job-name=simswift-merge \
               --output="$out/slurm-merge-%j.log" "$@" --wrap "$merge_cmd")
echo "submitted shards as job array $jobid (1-$shards) and the merge as job ${merge%%;*}; results in $out"
