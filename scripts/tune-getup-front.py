#!/usr/bin/env python3
"""Search for the front get-up's keyframes in simswift (issue 10).

How the front get-up in agent/motion/Generators.cpp (getupFrontFrames) was
retuned for the faithful motors (torque falling linearly with speed, gear
efficiency 0.8): an evolution strategy over the symmetric keyframes after the
arms have gone overhead, starting from the previous sequence. Each candidate
is written as a GETUP_FRAMES file and run through the tuning harness
(tests/runner/motion_getup_tuning_test.cpp, DISABLED_Trace) on several
pushed-over trials; a trial scores

  3 + (13 - t) / 13      if the robot stands on the first attempt, t s after the push
  best                   otherwise: torso height - 0.2 |AngleY| - 0.2 |AngleX|
                         (m, rad), the best value held for 0.5 s

and a candidate scores the mean over its trials. Tune on other noise seeds
(--seed-base, default 500) than the test's (100), then check with the test.

  python3 scripts/tune-getup-front.py --generations 40 --out front.json

Standard library only; --workers processes (default 1: the machine is shared).
"""
import argparse
import json
import os
import random
import subprocess
import tempfile
from multiprocessing import Pool

# Symmetric frame columns (GETUP_FRAMES format) and their ranges (rad):
# sp sr ey er hyp hr hp kn ap ar.
RANGES = [(-2.08, 2.08), (-0.31, 1.32), (-2.08, 2.08), (-1.54, -0.04), (-1.14, 0.74),
          (-0.37, 0.79), (-1.53, 0.48), (-0.09, 2.11), (-1.18, 0.92), (-0.39, 0.76)]
DUR = (0.2, 1.6)
# Fixed opening: arms out sideways along the ground, then turned overhead.
OPENING = "0.3 1.2 1.3 0 -0.05 0 0 0 0 0 0\n0.3 -1.357 1.3 0 -0.05 0 0 0 0 0 0\n"
# The previous sequence's tuned frames (duration + 10 columns), the start.
START = [
    [0.33, -1.357, 0.19, 0.0, -0.657, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [0.504, 0.181, 0.19, 0.0, -0.115, -0.487, 0.26, -1.53, 2.11, -0.53, 0.0],
    [0.6, 0.574, 0.19, 0.0, -0.531, -1.015, 0.6, -1.498, 1.428, -0.443, 0.0],
    [0.828, 0.805, 0.15, -1.2, -0.4, -0.321, 0.332, -1.184, 1.917, -0.68, 0.0],
]
START_TAIL = [1.307, 0.8]  # crouch, stand durations


def clamp(v, lo, hi):
    return max(lo, min(hi, v))


def norm(v, lo, hi):
    return (v - lo) / (hi - lo)


def start_genes(frames):
    x = []
    for f in frames:
        x.append(norm(f[0], *DUR))
        x += [norm(v, *r) for v, r in zip(f[1:], RANGES)]
    x += [norm(d, *DUR) for d in START_TAIL]
    return x


def decode(x, nframes):
    lines = [OPENING.rstrip("\n")]
    w = 1 + len(RANGES)
    for f in range(nframes):
        g = x[f * w:(f + 1) * w]
        dur = DUR[0] + (DUR[1] - DUR[0]) * clamp(g[0], 0, 1)
        vals = [lo + (hi - lo) * clamp(v, 0, 1) for v, (lo, hi) in zip(g[1:], RANGES)]
        lines.append("%.3f " % dur + " ".join("%.3f" % v for v in vals))
    tail = x[nframes * w:]
    lines.append("crouch %.3f" % (DUR[0] + (DUR[1] - DUR[0]) * clamp(tail[0], 0, 1)))
    lines.append("stand %.3f" % (DUR[0] + (DUR[1] - DUR[0]) * clamp(tail[1], 0, 1)))
    return "\n".join(lines) + "\n"


def trial_score(args, text, trial):
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        f.write(text)
        path = f.name
    env = dict(os.environ, GETUP_DIR="front", GETUP_FRAMES=path, GETUP_SEED=str(trial), GETUP_ONE="1",
               GETUP_QUIET="1", GETUP_SEED_BASE=str(args.seed_base))
    out = subprocess.run([args.runner, "--gtest_filter=*DISABLED_Trace", "--gtest_also_run_disabled_tests"],
                         env=env, capture_output=True, text=True).stdout
    os.unlink(path)
    for line in out.splitlines():
        if line.startswith("RESULT"):  # RESULT front trial N: UP|down up_at T attempts A best R besth H
            w = line.split()
            if w[4] == "UP":
                return 3 + (13 - float(w[6])) / 13
            return float(w[w.index("best") + 1])
    raise RuntimeError("no RESULT line from %s (is it built with the tuning test?)" % args.runner)


def score(job):
    args, x, nframes = job
    text = decode(x, nframes)
    results = [trial_score(args, text, t) for t in range(args.trials)]
    return sum(results) / len(results)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--runner", default="build/tests/test_runner")
    p.add_argument("--start", help="JSON written by an earlier run (its x is the start)")
    p.add_argument("--sigma", type=float, default=0.1, help="mutation step in gene units (0..1)")
    p.add_argument("--generations", type=int, default=40)
    p.add_argument("--trials", type=int, default=3, help="pushed-over trials per candidate")
    p.add_argument("--seed-base", type=int, default=500, help="noise seed base (the test uses 100)")
    p.add_argument("--rng", type=int, default=1, help="seed of the search itself")
    p.add_argument("--workers", type=int, default=1)
    p.add_argument("--out", default="getup-front-best.json")
    args = p.parse_args()
    if not os.path.exists(args.runner):
        p.error("--runner %s: no such file (build the tests first)" % args.runner)

    nframes = len(START)
    rng = random.Random(args.rng)
    mean = json.load(open(args.start))["x"] if args.start else start_genes(START)
    sigma, lam, mu = args.sigma, 12, 3  # (mu/mu, lambda)-ES with the parent re-evaluated
    best = (float("-inf"), None)
    with Pool(args.workers) as pool:
        for g in range(args.generations):
            pop = [[clamp(m + sigma * rng.gauss(0, 1), -0.05, 1.05) for m in mean] for _ in range(lam)] + [mean]
            scores = pool.map(score, [(args, x, nframes) for x in pop])
            order = sorted(range(len(pop)), key=lambda i: -scores[i])
            if scores[order[0]] > best[0]:
                best = (scores[order[0]], pop[order[0]])
                with open(args.out, "w") as f:
                    json.dump({"score": best[0], "x": best[1], "frames": decode(best[1], nframes)}, f)
            mean = [sum(pop[i][d] for i in order[:mu]) / mu for d in range(len(mean))]
            sigma *= 0.98
            print("generation %d: best %.3f, this generation %.3f, parent %.3f, sigma %.3f"
                  % (g, best[0], scores[order[0]], scores[-1], sigma), flush=True)
    print("best frames (%s):\n%s" % (args.out, decode(best[1], nframes)))


if __name__ == "__main__":
    main()
