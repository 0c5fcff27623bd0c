"""What the get-up tuning scripts share (tune-getup-front.py, tune-getup-roll.py).

run_trial() runs one pushed-over trial of a candidate frames text (the
harness's --frames format) through the tuning harness (tools/getup_tuning.cpp,
build/tools/getup-tuning) and returns its RESULT line's words:
  RESULT <dir> trial N: UP|down up_at T attempts A best R besth H
evolve() is the (mu/mu, lambda)-ES both scripts search with, the parent
re-evaluated each generation; the best candidate so far is kept in --out.
Standard library only.
"""
import argparse
import json
import os
import random
import subprocess
import tempfile
from multiprocessing import Pool


def clamp(v, lo, hi):
    return max(lo, min(hi, v))


def parser(doc, sigma, generations, trials, test_seed, out):
    """The options both scripts take; the defaults differ per script."""
    p = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--runner", default="build/tools/getup-tuning")
    p.add_argument("--start", help="JSON written by an earlier run (its x is the start)")
    p.add_argument("--sigma", type=float, default=sigma, help="mutation step in gene units (0..1)")
    p.add_argument("--generations", type=int, default=generations)
    p.add_argument("--trials", type=int, default=trials, help="pushed-over trials per candidate")
    p.add_argument("--seed-base", type=int, default=500,
                   help="noise seed base (the test uses %d)" % test_seed)
    p.add_argument("--rng", type=int, default=1, help="seed of the search itself")
    p.add_argument("--out", default=out)
    return p


def check_runner(p, args):
    if not os.path.exists(args.runner):
        p.error("--runner %s: no such file (build the tools first)" % args.runner)


def run_trial(args, text, trial, direction, extra_args=None):
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        f.write(text)
        path = f.name
    cmd = [args.runner, "--dir", direction, "--frames", path, "--trial", str(trial), "--one", "--quiet",
           "--seed-base", str(args.seed_base)] + (extra_args or [])
    try:
        out = subprocess.run(cmd, capture_output=True, text=True).stdout
    finally:
        os.unlink(path)
    for line in out.splitlines():
        if line.startswith("RESULT"):
            return line.split()
    raise RuntimeError("no RESULT line from %s (%s)" % (args.runner, " ".join(cmd)))


def up_score(w):
    """A trial that stood on the first attempt: 3 + (13 - t) / 13, t s after the push."""
    return 3 + (13 - float(w[6])) / 13 if w[4] == "UP" else None


def evolve(args, score, mean, decode, lam, mu, lo, hi, decay, workers):
    """score(job) is the caller's top-level function of (args, x); decode(x) a --frames text."""
    rng = random.Random(args.rng)
    sigma = args.sigma
    best = (float("-inf"), None)
    with Pool(workers) as pool:
        for g in range(args.generations):
            pop = [[clamp(m + sigma * rng.gauss(0, 1), lo, hi) for m in mean] for _ in range(lam)] + [mean]
            scores = pool.map(score, [(args, x) for x in pop])
            order = sorted(range(len(pop)), key=lambda i: -scores[i])
            if scores[order[0]] > best[0]:
                best = (scores[order[0]], pop[order[0]])
                with open(args.out, "w") as f:
                    json.dump({"score": best[0], "x": best[1], "frames": decode(best[1])}, f)
            mean = [sum(pop[i][d] for i in order[:mu]) / mu for d in range(len(mean))]
            sigma *= decay
            print("generation %d: best %.3f, this generation %.3f, parent %.3f, sigma %.3f"
                  % (g, best[0], scores[order[0]], scores[-1], sigma), flush=True)
    print("best frames (%s):\n%s" % (args.out, decode(best[1])))


def start_mean(args, default):
    return json.load(open(args.start))["x"] if args.start else default
