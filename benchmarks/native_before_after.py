"""Two versions of the native scan in one run: a benchmark script run alternately with each tree
on PYTHONPATH (`--before`, default the main checkout /work/main; `--after`, default this one),
`--rounds` times each, so both see the same load of the shared machine; prints every round's
figures and, per figure, the best and the median of each tree. Asserts nothing.

    python benchmarks/native_before_after.py [--rounds N] compile [PROGRAM ...]
    python benchmarks/native_before_after.py [--rounds N] scenarios [--duration S] [--programs X22]
    python benchmarks/native_before_after.py [--rounds N] scan

`compile` runs native_compile.py (one cold compile a round: CPU and wall seconds); `scenarios`
runs native_scenarios.py with the native backend (× real time by wall and by CPU time); `scan`
runs native_scan.py --native-only (µs per native scan, fast and monitored).
"""

from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
COMPILE = re.compile(r"^(\S+): \d+ steps, cold compile ([\d.]+) s CPU, ([\d.]+) s wall")
NAMED = re.compile(r"^(\S+): \d+ steps")
SPEED = re.compile(r"^  native\s+(fast|monitored)\s+([\d.]+)")
SCENARIO = re.compile(r"^(\S+)\s+native\s+(\d+) s (every scan|skipping)\s+\d+ s\s+[\d.]+ s\s+"
                      r"(\d+)x\s+[\d.]+ s\s+(\d+)x")


def figures(kind: str, output: str) -> dict[str, float]:
    """The figures of one round's output, by name."""
    found: dict[str, float] = {}
    program = ""
    for line in output.splitlines():
        if kind == "scan" and (match := NAMED.match(line)):
            program = match[1]
        if kind == "scan" and (match := SPEED.match(line)):
            found[f"{program} native {match[1]} µs"] = float(match[2])
        if kind == "compile" and (match := COMPILE.match(line)):
            found[f"{match[1]} CPU s"] = float(match[2])
            found[f"{match[1]} wall s"] = float(match[3])
        elif kind == "scenarios" and (match := SCENARIO.match(line)):
            name = f"{match[1]} inputs every {match[2]} s, {match[3]}"
            found[f"{name}: x real (wall)"] = float(match[4])
            found[f"{name}: x real (CPU)"] = float(match[5])
    return found


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", default="/work/main")
    parser.add_argument("--after", default=str(HERE.parent))
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("kind", choices=("compile", "scenarios", "scan"))
    args, rest = parser.parse_known_args()
    script = HERE / {"compile": "native_compile.py", "scenarios": "native_scenarios.py",
                     "scan": "native_scan.py"}[args.kind]
    extra = {"compile": ["--rounds", "1", *rest], "scenarios": ["--backends", "native", *rest],
             "scan": ["--native-only", *rest]}[args.kind]
    trees = {"before": args.before, "after": args.after}
    results: dict[str, dict[str, list[float]]] = {name: {} for name in trees}
    for round_ in range(args.rounds):
        for name, tree in trees.items():
            env = dict(os.environ, PYTHONPATH=tree)
            done = subprocess.run([sys.executable, str(script), *extra], env=env,
                                  capture_output=True, text=True, check=False)
            found = figures(args.kind, done.stdout)
            if not found:
                print(f"{name}: no figures\n{done.stdout}\n{done.stderr}")
                return 1
            print(f"round {round_ + 1} {name}: " +
                  ", ".join(f"{k} {v:g}" for k, v in found.items()), flush=True)
            for key, value in found.items():
                results[name].setdefault(key, []).append(value)
    print(f"\n{'figure':55} {'before best':>11} {'median':>7} {'after best':>10} {'median':>7}")
    for key in results["after"]:
        row = []
        for name in trees:
            values = results[name].get(key, [])
            lower = key.endswith((" s", " µs"))  # times: the least is best
            best = (min if lower else max)(values) if values else float("nan")
            row += [best, statistics.median(values) if values else float("nan")]
        print(f"{key:55} {row[0]:11.2f} {row[1]:7.2f} {row[2]:10.2f} {row[3]:7.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
