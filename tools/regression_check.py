#!/usr/bin/env python3
"""How often `simswift test --baseline` calls a regression (docs/testing.md).

For each of K seed sets, runs the file as a baseline on one seed, then (a)
the same program and (b) a weakened one on another seed against that
baseline (every set its own two seeds, so the K outcomes are independent;
with --same-seed both on the baseline's seed, as the CI templates run main
and a change: the comparison is then paired run by run),
and counts how often each is flagged: (a) is the false-alarm rate, (b) the
detection rate, with the weakened runs' smallest adjusted p-values. The weakened program is the file with every `behaviour: striker`
replaced by WEAK (default: the striker's kick power set to 0 through the
behaviour's config override).

  tools/regression_check.py --simswift build/simswift --file scenarios/tests/reference.yaml \
      --only striker_kickoff,striker_no_own_goal,two_strikers --sets 5 --out /tmp/regcheck

Prints a table and writes it to OUT/regression_check.md. A tuning harness,
never run by ctest.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys


def run(args, file, seed, out, baseline=None):
    cmd = [args.simswift, "test", file, "--seed", str(seed), "--out", out, "--jobs", str(args.jobs),
           "--progress", "none"]
    if not args.full:
        cmd.append("--short")
    if args.only:
        cmd += ["--only", args.only]
    if baseline:
        cmd += ["--baseline", baseline]
    shutil.rmtree(out, ignore_errors=True)  # never a stale summary from an earlier call
    code = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if code.returncode not in (0, 1):
        sys.exit("%s: exit code %d: %s" % (" ".join(cmd), code.returncode, code.stderr[-2000:]))
    with open(os.path.join(out, "summary.csv")) as f:
        return list(csv.DictReader(f))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--simswift", default="build/simswift")
    p.add_argument("--file", default="scenarios/tests/reference.yaml")
    p.add_argument("--only", default="")
    p.add_argument("--full", action="store_true", help="the full form (default: --short)")
    p.add_argument("--sets", type=int, default=5, help="seed sets compared with the baseline")
    p.add_argument("--base-seed", type=int, default=1000)
    p.add_argument("--same-seed", action="store_true",
                   help="run (a) and (b) on the baseline's seed (paired, as CI does) instead of another")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--weak", default="{kind: striker, skills: {kick_power: 0.0}}")
    p.add_argument("--out", default="/tmp/simswift-regression-check")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    text = open(args.file).read()
    if "behaviour: striker" not in text:
        sys.exit("no `behaviour: striker` in " + args.file + " to weaken")
    weak_file = os.path.join(args.out, "weak.yaml")
    with open(weak_file, "w") as f:
        f.write(text.replace("behaviour: striker", "behaviour: " + args.weak))
    # The copy sits in OUT: a file whose tests name scenario files by relative
    # path needs its copy beside it (the reference file's scenarios are inline).
    lines = ["| seed set | same program: tests flagged | weakened: tests flagged | weakened: smallest p (Holm) |",
             "|---:|---:|---:|---:|"]
    same_runs_flagged = weak_runs_flagged = 0
    same_tests_flagged = weak_tests_flagged = tests_compared = 0
    for k in range(1, args.sets + 1):
        seed = args.base_seed + 2 * k
        base = os.path.join(args.out, "base%d" % k)
        base_seed = seed if args.same_seed else seed - 1
        run(args, args.file, base_seed, base)
        same = run(args, args.file, seed, os.path.join(args.out, "same%d" % k), base)
        weak = run(args, weak_file, seed, os.path.join(args.out, "weak%d" % k), base)
        sf = sum(r["regressed"] == "1" for r in same)
        wf = sum(r["regressed"] == "1" for r in weak)
        if args.same_seed and any(r["pairs"] in ("", "0") for r in weak if r["p_rate"]):
            sys.exit("--same-seed: a test was not compared pair by pair")
        striker = [r for r in weak if r["p_rate_holm"]]
        ps = [float(r["p_rate_holm"]) for r in striker] + [float(r["p_time_holm"]) for r in striker if r["p_time_holm"]]
        same_runs_flagged += sf > 0
        weak_runs_flagged += wf > 0
        same_tests_flagged += sf
        weak_tests_flagged += wf
        tests_compared += len(same)
        lines.append("| %d | %d of %d | %d of %d | %s |" % (seed, sf, len(same), wf, len(weak),
                                                       "%.1e" % min(ps) if ps else "-"))
        print(lines[-1], flush=True)
    lines.append("")
    seeds = ("baseline and runs on seed %d + 2k (paired)" % args.base_seed if args.same_seed else
             "baseline seed %d + 2k - 1, runs %d + 2k" % (args.base_seed, args.base_seed))
    lines.append("Same program flagged in %d of %d seed sets (%d of %d test comparisons); weakened program "
                 "flagged in %d of %d seed sets. Seed set k: %s; file %s%s." %
                 (same_runs_flagged, args.sets, same_tests_flagged, tests_compared, weak_runs_flagged, args.sets,
                  seeds, args.file, " (--only " + args.only + ")" if args.only else ""))
    report = "\n".join(lines) + "\n"
    open(os.path.join(args.out, "regression_check.md"), "w").write(report)
    print(report)


if __name__ == "__main__":
    main()
