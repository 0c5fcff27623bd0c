"""The library's cost per tick on one scenario (default scenarios/walk_one.yaml,
20 s): step() from C++ (build/bench/bench_api), step() from Python, and
`simswift run --inline` (the same programs on the same thread), in turn,
ROUNDS times; prints medians and min..max and appends them to
build/bench-results.txt.

    PYTHONPATH=build/python python3 bench/bench_api.py [--rounds 3] [--seconds 20]
"""
import argparse
import pathlib
import re
import statistics
import subprocess
import time

import simswift

ROOT = pathlib.Path(__file__).resolve().parents[1]


def python_step(scenario, seconds):
    sim = simswift.Simulation(str(scenario))
    sim.step()  # builds the world: not timed
    n = round(seconds / 0.01)
    t0 = time.perf_counter()
    for _ in range(n):
        sim.step()
    return 1e6 * (time.perf_counter() - t0) / n


def cpp_step(build, scenario, seconds):
    out = subprocess.run([str(build / "bench" / "bench_api"), str(scenario), str(seconds)],
                         capture_output=True, text=True, check=True).stdout
    return float(re.search(r"api\.cpp\.step_us_per_tick\s+([\d.]+)", out).group(1))


def cli_run(build, scenario, seconds):
    out = subprocess.run([str(build / "simswift"), "run", str(scenario), "--duration", str(seconds), "--inline"],
                         capture_output=True, text=True, check=True).stdout
    wall = float(re.search(r"wall ([\d.]+) s", out).group(1))
    return 1e6 * wall / round(seconds / 0.01)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--seconds", type=float, default=20.0)
    ap.add_argument("--scenario", default=str(ROOT / "scenarios" / "walk_one.yaml"))
    ap.add_argument("--build", default=str(ROOT / "build"))
    args = ap.parse_args()
    build = pathlib.Path(args.build)
    figures = {"cli": [], "cpp": [], "python": []}
    for _ in range(args.rounds):
        figures["cli"].append(cli_run(build, args.scenario, args.seconds))
        figures["cpp"].append(cpp_step(build, args.scenario, args.seconds))
        figures["python"].append(python_step(args.scenario, args.seconds))
    med = {k: statistics.median(v) for k, v in figures.items()}
    lines = []
    for k in ("cli", "cpp", "python"):
        lines.append(f"api.{k}.us_per_tick {med[k]:.1f} us (min {min(figures[k]):.1f}, max {max(figures[k]):.1f}, "
                     f"{args.rounds} rounds)")
    lines.append(f"api.python_over_cpp {100 * (med['python'] / med['cpp'] - 1):.1f} %")
    lines.append(f"api.cpp_over_cli {100 * (med['cpp'] / med['cli'] - 1):.1f} %")
    for l in lines:
        print(l)
    with open(build / "bench-results.txt", "a") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
