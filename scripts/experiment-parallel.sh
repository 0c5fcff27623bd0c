#!/usr/bin/env bash
# Runs a find-ball experiment as N shards with GNU parallel -- on this
# machine, or on several hosts over ssh -- then merges the shard folders into
# one result: the same results (results.csv, tracks.csv, trial logs, figures,
# report.md) as a single `simswift experiment` run; only the wall-clock
# files (timing.md, timing.csv, trials/*.timing.*) and report.md's last
# section (wall clock) differ, as between any two runs.
#
#   scripts/experiment-parallel.sh FILE.yaml OUT [SHARDS]
#
# SHARDS defaults to the number of cores here. Environment:
#   SIMSWIFT        the simswift binary (default: build/simswift of this tree);
#                   with HOSTS it must exist at the same path on every host
#   HOSTS           GNU parallel --sshlogin list, e.g. "2/node1,2/alice@node2,:"
#                   (N/ = shards at once on that host, ":" = this machine).
#                   Default: this machine only, SHARDS at once.
#   JOBS_PER_SHARD  worker processes per shard (simswift --jobs; default 1)
# With HOSTS, FILE and OUT must be on a file system all hosts share at the same
# path (e.g. an NFS home): each shard runs in this directory (--workdir .).
# Rerun the same command after an interruption: every shard resumes where it
# stopped, then the merge runs again.
set -euo pipefail
if [ $# -lt 2 ] || [ $# -gt 3 ]; then
  sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
fi
root="$(cd "$(dirname "$0")/.." && pwd)"
file=$1
out=$2
shards=${3:-$(nproc)}
bin=${SIMSWIFT:-$root/build/simswift}
jobs=${JOBS_PER_SHARD:-1}
[[ $shards =~ ^[0-9]+$ ]] && [ "$((10#$shards))" -ge 1 ] ||
  { echo "experiment-parallel: SHARDS must be a whole number >= 1 (got '$shards')" >&2; exit 2; }
command -v parallel >/dev/null || { echo "experiment-parallel: GNU parallel is missing (scripts/install-deps.sh)" >&2; exit 1; }
[ -x "$bin" ] || { echo "experiment-parallel: no simswift binary at $bin (build it, or set SIMSWIFT)" >&2; exit 1; }
"$bin" experiment "$file" --check >/dev/null  # a bad file fails here, once, with its error
mkdir -p "$out"

opts=(--halt soon,fail=1 --line-buffer --tagstring "shard {}/$shards")
if [ -n "${HOSTS:-}" ]; then
  opts+=(--sshlogin "$HOSTS" --workdir .)
else
  opts+=(--jobs "$shards")
fi
parallel "${opts[@]}" \
  "$bin" experiment "$file" --out "$out/shard-{}" --shard "{}/$shards" --jobs "$jobs" --progress lines \
  ::: $(seq 1 "$shards")
"$bin" experiment merge "$out"/shard-* --out "$out"
