"""Sweeps one behaviour parameter of the 2017 ball search (the entropy rate of
its distribution) over a few values, runs a small find-ball experiment per
value and prints a find-rate table.

    PYTHONPATH=build/python python3 python/examples/sweep.py [--jobs 2]
"""
import argparse
import pathlib
import tempfile

import simswift

ROOT = pathlib.Path(__file__).resolve().parents[2]

EXPERIMENT = """name: sweep_{tag}
base_dir: {root}
seed: 2017
time_limit: 60
trials_per_position: 2
start: {{penalised: 1.0}}
found: {{distance: 0.300, sees: true, seen_frames: 5}}
vision: {{ball: {{max_distance_mm: 2500}}}}
balls:
  - {{position: 1, x: 2.25, y: 0.0}}
  - {{position: 3, x: 4.0, y: 2.5}}
setups:
  - name: "2017"
    behaviour: findball2017
    config: {{distribution: {{entropy_rate: {value}}}}}
    robots:
      - {{team: 19, player: 2, x: -3.25, y: 3.0, theta: -1.5708}}
      - {{team: 19, player: 3, x: -2.0, y: -3.0, theta: 1.5708}}
      - {{team: 19, player: 4, x: -1.75, y: 3.0, theta: -1.5708}}
"""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--jobs", type=int, default=0)
    ap.add_argument("--values", default="0.005,0.02,0.08")
    args = ap.parse_args()
    print("| entropy_rate | found | mean find time (s) |")
    print("|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for value in args.values.split(","):
            tag = value.replace(".", "p")
            f = pathlib.Path(tmp) / f"sweep_{tag}.yaml"
            f.write_text(EXPERIMENT.format(tag=tag, root=ROOT, value=value))
            rows = simswift.run_experiment(str(f), jobs=args.jobs, out=str(pathlib.Path(tmp) / tag))
            times = [float(r["seconds"]) for r in rows if r["found"] == "1"]
            mean = f"{sum(times) / len(times):.1f}" if times else "-"
            print(f"| {value} | {len(times)}/{len(rows)} | {mean} |")


if __name__ == "__main__":
    main()
