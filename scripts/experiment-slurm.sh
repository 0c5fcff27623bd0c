#!/usr/bin/env bash
# Submits a find-ball experiment to Slurm: a job array of N shards, each
# `simswift experiment FILE --shard K/N`, and a merge job that runs once every
# shard has ended (afterany) and says which trials are missing if one failed
# or was cancelled. Results in OUT (shards in OUT/shard-K, logs OUT/slurm-*.log).
#
#   scripts/experiment-slurm.sh FILE.yaml OUT [SHARDS] [sbatch options...]
#
# SHARDS (a whole number, 1-10000; default 10) comes before any sbatch option.
# Environment:
#   SIMSWIFT    the simswift binary (default: build/simswift of this tree; must
#               be reachable at that path on the compute nodes, as must FILE and OUT)
#   CPUS        cores per shard (sbatch --cpus-per-task; simswift --jobs; default 2);
#               refused if no node of the partition has that many (sinfo)
#   DRY_RUN=1   print the sbatch commands; submit and create nothing
# A failed or cancelled shard: resubmit the same command. Finished trials are
# kept, every shard resumes where it stopped, and a merge of OUT still queued
# from an earlier submission is cancelled (one merge per OUT).
set -euo pipefail
usage() { sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//' >&2; }
fail() { echo "experiment-slurm: $*" >&2; exit 2; }
if [ $# -lt 2 ]; then
  usage
  exit 2
fi
root="$(cd "$(dirname "$0")/.." && pwd)"
[ -f "$1" ] || fail "no experiment file $1"
file=$(realpath "$1")
out=$(realpath -m "$2")
shards=10
if [ $# -ge 3 ]; then
  case $3 in
    -*) fail "SHARDS is missing before the sbatch options ($3): give it as the third argument, e.g. 10" ;;
  esac
  shards=$3
fi
[[ $shards =~ ^[0-9]+$ ]] && [ "$((10#$shards))" -ge 1 ] && [ "$((10#$shards))" -le 10000 ] ||
  fail "SHARDS must be a whole number from 1 to 10000 (got '$shards')"
shards=$((10#$shards))
shift $(( $# >= 3 ? 3 : 2 ))
bin=${SIMSWIFT:-$root/build/simswift}
cpus=${CPUS:-2}
[[ $cpus =~ ^[0-9]+$ ]] && [ "$((10#$cpus))" -ge 1 ] || fail "CPUS must be a whole number >= 1 (got '$cpus')"
cpus=$((10#$cpus))
[ -x "$bin" ] || { echo "experiment-slurm: no simswift binary at $bin (build it, or set SIMSWIFT)" >&2; exit 1; }
bin=$(realpath "$bin")  # the jobs run it from wherever Slurm starts them
"$bin" experiment "$file" --check >/dev/null  # refuse a bad file before queueing anything

# The partition the jobs go to: the last --partition/-p among the sbatch
# options, else $SBATCH_PARTITION, else the cluster's default.
partition=${SBATCH_PARTITION:-}
prev=
for a in "$@"; do
  case $prev in -p|--partition) partition=$a ;; esac
  case $a in --partition=*) partition=${a#--partition=} ;; -p?*) partition=${a#-p} ;; esac
  prev=$a
done
# Most CPUs of one node in that partition (-N: a line per node; "%c" may
# read "4+" on mixed nodes; the default partition is marked "*").
if command -v sinfo >/dev/null && nodes=$(sinfo -h -N ${partition:+-p "$partition"} -o '%P %c' 2>&1); then
  node_cpus=$(printf '%s\n' "$nodes" | awk -v p="$partition" '
    (p != "" || $1 ~ /\*$/) {gsub(/\+/, "", $2); if ($2 + 0 > m) m = $2 + 0} END {if (m) print m}')
  [ -n "$node_cpus" ] || fail "sinfo lists no nodes in partition ${partition:-(the default)}"
  [ "$cpus" -le "$node_cpus" ] ||
    fail "CPUS=$cpus, but the nodes of partition ${partition:-(the default)} have at most $node_cpus CPUs (the shards would pend forever)"
elif [ "${DRY_RUN:-0}" = 1 ]; then
  echo "experiment-slurm: no Slurm reachable here (sinfo): CPUS not checked" >&2
else
  echo "experiment-slurm: sinfo failed or is missing: is this a Slurm login node? ${nodes:-}" >&2
  exit 1
fi

q() { printf '%q' "$1"; }
# \$SLURM_ARRAY_TASK_ID is expanded on the node, in the job's shell.
shard_cmd="$(q "$bin") experiment $(q "$file") --shard \$SLURM_ARRAY_TASK_ID/$shards --out $(q "$out")/shard-\$SLURM_ARRAY_TASK_ID --jobs $cpus --progress lines"
merge_cmd="$(q "$bin") experiment merge $(q "$out")/shard-* --out $(q "$out")"
# The job comment names OUT, so a later submission finds this one's jobs.
array=(sbatch --parsable --job-name=simswift-exp --comment="simswift:$out" --array="1-$shards"
       --cpus-per-task="$cpus" --output="$out/slurm-%A_%a.log" "$@" --wrap "$shard_cmd")
merge=(sbatch --parsable --dependency="afterany:JOBID" --job-name=simswift-merge --comment="simswift:$out"
       --output="$out/slurm-merge-%j.log" "$@" --wrap "$merge_cmd")
if [ "${DRY_RUN:-0}" = 1 ]; then
  printf '%q ' "${array[@]}"; echo
  printf '%q ' "${merge[@]}"; echo
  exit 0
fi

# Jobs of an earlier submission for the same OUT (`squeue --me`: this user's).
# Shards still queued or running would write the same shard folders: refuse.
# A merge still waiting would merge too early or never: cancel it.
listing=$(squeue -h --me -o '%i|%j|%T|%k') || { echo "experiment-slurm: squeue failed (above): is slurmctld reachable?" >&2; exit 1; }
mine=$(printf '%s\n' "$listing" | awk -F'|' -v c="simswift:$out" '$4 == c')
running=$(printf '%s\n' "$mine" | awk -F'|' '$2 == "simswift-exp" {split($1, id, "_"); print id[1]}' | sort -u | tr '\n' ' ')
[ -z "${running// /}" ] ||
  fail "shards of an earlier submission for $out are still queued or running (job ${running% }): wait for them or scancel them, then submit again"
stale=$(printf '%s\n' "$mine" | awk -F'|' '$2 == "simswift-merge" {print $1}' | tr '\n' ' ')
if [ -n "${stale// /}" ]; then
  # shellcheck disable=SC2086
  scancel $stale
  echo "cancelled the merge job(s) ${stale% } of an earlier submission for $out"
fi

mkdir -p "$out"
jobid=$("${array[@]}")
jobid=${jobid%%;*}
merge[2]="--dependency=afterany:$jobid"
mergeid=$("${merge[@]}")
mergeid=${mergeid%%;*}
cat <<EOF
submitted shards as job array $jobid (1-$shards) and the merge as job $mergeid; results in $out
  shard logs:  $out/slurm-${jobid}_K.log (K = 1..$shards)
  merge log:   $out/slurm-merge-$mergeid.log (it says which trials are missing if a shard failed)
  watch:       squeue -j $jobid,$mergeid;  after the end: sacct -j $jobid,$mergeid
  a shard failed or was cancelled: run this command again
EOF
