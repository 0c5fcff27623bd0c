#!/usr/bin/env bash
# scripts/experiment-slurm.sh against a real Slurm (Debian's slurmctld,
# slurmd, slurm-client and munge; scripts/install-deps.sh installs them).
#
#   tests/slurm/test_slurm.sh args    SIMSWIFT SOURCE_DIR   # argument checks, no cluster, anyone
#   tests/slurm/test_slurm.sh cluster SIMSWIFT SOURCE_DIR   # as root: a one-node cluster
#
# cluster: starts munged, slurmctld and slurmd directly (no systemd) from a
# generated slurm.conf in a temporary folder, with their own ports and
# munge socket, so a cluster the machine may already run is not touched.
# Then a tiny experiment (3 trials, 3 shards):
#   1. submitted held; shard 2 cancelled; a resubmit is refused while shards 1
#      and 3 are still queued;
#   2. shards 1 and 3 run; the merge (afterany) then runs and reports the
#      missing trials (exit 1) instead of waiting forever;
#   3. a held submission whose shards are all cancelled leaves its merge
#      queued; the next submission cancels that stale merge and its shards
#      finish the experiment (shards 1 and 3 resume as done);
#   4. the merged results.csv is byte-identical to a single run's;
#   5. CPUS above the node's CPUs is refused (sinfo).
# Exits 77 (ctest SKIP_RETURN_CODE) when not root or a package is missing.
# Every wait has a deadline, and the whole test gives up after 110 s; the
# daemons are stopped by pid on any exit.
set -euo pipefail
mode=${1:?mode: args or cluster}
bin=$(realpath "${2:?the simswift binary}")
src=$(realpath "${3:?the source folder}")
script=$src/scripts/experiment-slurm.sh
T=$(mktemp -d /tmp/simswift-slurm-test.XXXXXX)
pids=()
ok=0
cluster_up=0
watchdog=
cleanup() {
  local p
  [ -z "$watchdog" ] || kill "$watchdog" 2>/dev/null || true
  # Jobs of this test's cluster first (their steps outlive slurmd), then the daemons.
  [ "$cluster_up" = 1 ] && timeout 5 scancel --me 2>/dev/null && sleep 1 || true
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$p" 2>/dev/null || true
  done
  if [ "$ok" != 1 ] && [ "$mode" = cluster ]; then
    for f in "$T"/slurmctld.log "$T"/slurmd.log; do
      [ -f "$f" ] && { echo "---- last lines of $f"; tail -n 15 "$f"; }
    done
    for f in "$T"/out/slurm-*.log; do
      [ -f "$f" ] && { echo "---- $f"; tail -n 5 "$f"; }
    done
  fi
  rm -rf "$T"
}
trap cleanup EXIT
trap 'echo "test_slurm: interrupted" >&2; exit 1' INT TERM
# The whole test's deadline (ctest's TIMEOUT is 120 s).
# Short sleeps, so the watchdog leaves nothing behind for long once killed.
( end=$((SECONDS + 110)); while [ "$SECONDS" -lt "$end" ]; do sleep 1; done
  echo "test_slurm: over 110 s: giving up" >&2
  # The daemons first (the script may be inside a command that waits on them).
  [ -f "$T/daemons" ] && kill $(cat "$T/daemons") 2>/dev/null
  kill -TERM $$ 2>/dev/null ) &
watchdog=$!
disown "$watchdog"

die() { echo "test_slurm: FAIL: $*" >&2; exit 1; }
skip() { echo "test_slurm: SKIPPED: $*"; exit 77; }
# expect CODE PATTERN COMMAND...: the command exits CODE and its stderr+stdout matches PATTERN.
expect() {
  local code=$1 pattern=$2 got=0
  shift 2
  "$@" >"$T/expect.out" 2>&1 || got=$?
  [ "$got" = "$code" ] || die "$* exited $got, expected $code: $(cat "$T/expect.out")"
  grep -q -- "$pattern" "$T/expect.out" || die "$* did not say '$pattern': $(cat "$T/expect.out")"
}

# A tiny experiment: one robot, three balls near it, one trial each, 8 s.
cat >"$T/tiny.yaml" <<'EOF'
name: slurm_tiny
seed: 7
time_limit: 8
trials_per_position: 1
start: {penalised: 0.5}
found: {distance: 0.300, sees: true, seen_frames: 5}
balls:
  - {position: 1, x: -2.5, y: 0.0}
  - {position: 2, x: -2.0, y: 0.6}
  - {position: 3, x: -3.5, y: -0.5}
setups:
  - name: "2017"
    behaviour: findball2017
    robots:
      - {team: 19, player: 2, x: -3.0, y: 0.0, theta: 0.0}
EOF

if [ "$mode" = args ]; then
  # Checks that need no cluster (DRY_RUN skips the sinfo check when sinfo is absent).
  export SIMSWIFT=$bin
  expect 2 "SHARDS must be a whole number" "$script" "$T/tiny.yaml" "$T/o" 0
  expect 2 "SHARDS must be a whole number" "$script" "$T/tiny.yaml" "$T/o" abc
  expect 2 "SHARDS is missing before the sbatch options" "$script" "$T/tiny.yaml" "$T/o" --partition=short
  expect 2 "CPUS must be a whole number" env CPUS=x "$script" "$T/tiny.yaml" "$T/o" 3
  expect 1 "no simswift binary at $T/nothing" env SIMSWIFT="$T/nothing" "$script" "$T/tiny.yaml" "$T/o" 3
  expect 2 "Usage\|scripts/experiment-slurm.sh FILE.yaml OUT" "$script"
  "$script" >"$T/usage.txt" 2>&1 || true
  ! grep -q "set -euo\|^usage()" "$T/usage.txt" || die "the usage text prints code: $(cat "$T/usage.txt")"
  if [ -x "$bin" ]; then
    # With or without a cluster here (no cluster: CPUS is not checked, and it says so).
    DRY_RUN=1 "$script" "$T/tiny.yaml" "$T/dry" 3 >"$T/dry.txt" 2>&1 || die "DRY_RUN failed: $(cat "$T/dry.txt")"
    [ ! -e "$T/dry" ] || die "DRY_RUN=1 created $T/dry"
    grep -q -- "--array=1-3" "$T/dry.txt" || die "DRY_RUN did not print the array: $(cat "$T/dry.txt")"
  fi
  "$src/scripts/experiment-parallel.sh" >"$T/usage.txt" 2>&1 || true
  ! grep -q "set -euo" "$T/usage.txt" || die "the parallel script's usage text prints code"
  ok=1
  echo "test_slurm: args ok"
  exit 0
fi

[ "$mode" = cluster ] || die "mode must be args or cluster"
[ "$(id -u)" = 0 ] || skip "needs root (it starts munged, slurmctld and slurmd); CI runs it as root"
for c in munged mungekey slurmctld slurmd sbatch squeue scancel scontrol sinfo; do
  command -v "$c" >/dev/null || skip "$c is missing (scripts/install-deps.sh installs slurmctld slurmd slurm-client munge)"
done

# ---- munge: own key, socket and pid file.
mungekey -c -k "$T/munge.key" -b 1024 >/dev/null
chmod 400 "$T/munge.key"
munged -F --force --key-file="$T/munge.key" --socket="$T/munge.socket" --pid-file="$T/munged.pid" \
  --seed-file="$T/munge.seed" --log-file="$T/munged.log" >"$T/munged.out" 2>&1 &
pids+=($!)
echo $! >>"$T/daemons"
for _ in $(seq 100); do [ -S "$T/munge.socket" ] && break; sleep 0.1; done
[ -S "$T/munge.socket" ] || die "munged did not start: $(cat "$T/munged.out" "$T/munged.log" 2>/dev/null)"

# ---- slurm.conf: this node, its real CPUs (slurmd -C), ports of our own.
node_line=$(slurmd -C | head -n 1)
node=$(printf '%s\n' "$node_line" | sed 's/^NodeName=\([^ ]*\).*/\1/')
cpus=$(printf '%s\n' "$node_line" | sed 's/.* CPUs=\([0-9]*\).*/\1/')
# Two ports of our own, below the kernel's ephemeral range (its first port,
# 32768 by default): one inside it can be held by any outgoing connection
# of the tests running beside this one (slurmctld then fails with "Address
# already in use", seen once), and one a listener already has is skipped.
ephemeral=$(cut -f1 /proc/sys/net/ipv4/ip_local_port_range 2>/dev/null || echo 32768)
[ "$ephemeral" -gt 21000 ] 2>/dev/null || ephemeral=32768
listening=$(ss -Htln 2>/dev/null | awk '{n = split($4, a, ":"); print a[n]}' || true)
port=$((20000 + $$ % (ephemeral - 20002)))
while grep -qx -e "$port" -e "$((port + 1))" <<<"$listening"; do
  port=$((20000 + (port - 20000 + 2) % (ephemeral - 20002)))
done
mkdir -p "$T/state" "$T/spool"
cat >"$T/slurm.conf" <<EOF
ClusterName=simswift-test
SlurmctldHost=$node(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$T/munge.socket
StateSaveLocation=$T/state
SlurmdSpoolDir=$T/spool
SlurmctldPidFile=$T/slurmctld.pid
SlurmdPidFile=$T/slurmd.pid
SlurmctldLogFile=$T/slurmctld.log
SlurmdLogFile=$T/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
SlurmdTimeout=30
$node_line NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=simswift Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
sed -i 's/ UpTime=[^ ]*//' "$T/slurm.conf"
export SLURM_CONF=$T/slurm.conf
unset SBATCH_PARTITION SLURM_JOB_ID || true
slurmctld -D -c -f "$SLURM_CONF" >"$T/slurmctld.out" 2>&1 &
pids+=($!)
echo $! >>"$T/daemons"
slurmd -D -f "$SLURM_CONF" -N "$node" >"$T/slurmd.out" 2>&1 &
pids+=($!)
echo $! >>"$T/daemons"
state=
for _ in $(seq 150); do
  state=$(timeout 5 sinfo -h -N -o '%T' 2>/dev/null | head -n 1 || true)
  [ "$state" = idle ] && break
  sleep 0.2
done
[ "$state" = idle ] || die "the node did not come up (state '$state'): $(cat "$T/slurmctld.out" "$T/slurmd.out")"
cluster_up=1
echo "test_slurm: one-node cluster up ($node, $cpus CPUs, ports $port-$((port + 1)))"

# Waits until no job named $1 is queued or running (deadline $2 s).
wait_gone() {
  local name=$1 limit=$2 t=0
  while [ -n "$(timeout 5 squeue -h -n "$name" -o '%i' 2>/dev/null || echo busy)" ]; do
    [ "$t" -lt $((limit * 5)) ] || die "jobs '$name' still queued after $limit s: $(squeue 2>&1)"
    sleep 0.2
    t=$((t + 1))
  done
}
submit() { # submit OUT [sbatch options]: prints the script's output; JOB and MERGE set from it
  local out=$1
  shift
  SIMSWIFT=$bin CPUS=1 timeout 30 "$script" "$T/tiny.yaml" "$out" 3 "$@" >"$T/submit.out" 2>&1 ||
    die "submit failed: $(cat "$T/submit.out")"
  JOB=$(sed -n 's/^submitted shards as job array \([0-9]*\) .*/\1/p' "$T/submit.out")
  MERGE=$(sed -n 's/.* the merge as job \([0-9]*\);.*/\1/p' "$T/submit.out")
  [ -n "$JOB" ] && [ -n "$MERGE" ] || die "no job ids in: $(cat "$T/submit.out")"
}

# The single run to compare with, while the cluster is idle.
timeout 40 "$bin" experiment "$T/tiny.yaml" --out "$T/single" --jobs 2 --progress none >"$T/single.out" 2>&1 ||
  die "the single run failed: $(cat "$T/single.out")"

# 5 (first: it queues nothing). CPUS above the node's.
expect 2 "at most $cpus CPUs" env SIMSWIFT="$bin" CPUS=$((cpus + 1)) "$script" "$T/tiny.yaml" "$T/out" 3
DRY_RUN=1 SIMSWIFT=$bin "$script" "$T/tiny.yaml" "$T/dry" 3 >/dev/null
[ ! -e "$T/dry" ] || die "DRY_RUN=1 created $T/dry"

# 1. Held; cancel shard 2; a resubmit is refused while shards 1 and 3 wait.
submit "$T/out" --hold
grep -q "merge log:   $T/out/slurm-merge-$MERGE.log" "$T/submit.out" || die "no merge log named: $(cat "$T/submit.out")"
timeout 10 scancel "${JOB}_2"
expect 2 "still queued or running (job $JOB)" env SIMSWIFT="$bin" CPUS=1 "$script" "$T/tiny.yaml" "$T/out" 3

# 2. Shards 1 and 3 run; the merge runs after them and reports what is missing.
timeout 10 scontrol release "$JOB"
wait_gone simswift-exp 60
timeout 10 scontrol release "$MERGE"
wait_gone simswift-merge 30
grep -q "trials are missing" "$T/out/slurm-merge-$MERGE.log" ||
  die "the merge did not report the missing shard: $(cat "$T/out/slurm-merge-$MERGE.log")"
[ ! -e "$T/out/results.csv" ] || die "a merge with a trial missing wrote results.csv"

# 3. A stale merge: held shards all cancelled, their merge still queued.
submit "$T/out" --hold
stale=$MERGE
timeout 10 scancel "$JOB"
wait_gone simswift-exp 20
[ -n "$(squeue -h -j "$stale" -o '%i' 2>/dev/null)" ] || die "the held merge $stale is not queued"
submit "$T/out"
grep -q "cancelled the merge job(s) $stale" "$T/submit.out" || die "the stale merge was not cancelled: $(cat "$T/submit.out")"
wait_gone simswift-exp 60
wait_gone simswift-merge 30
grep -q "merged .* 3 trials" "$T/out/slurm-merge-$MERGE.log" || die "the merge failed: $(cat "$T/out/slurm-merge-$MERGE.log")"

# 4. The same results as one run.
cmp "$T/single/results.csv" "$T/out/results.csv" || die "results.csv differs from the single run's"
ok=1
echo "test_slurm: ok: a cancelled shard, a refused resubmit, a merge reporting the missing trials, a stale merge cancelled; results.csv identical to a single run ($(wc -l <"$T/out/results.csv") lines)"
