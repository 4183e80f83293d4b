"""Prints ms of the compiler's checks alone (`check(program)`) on each real FANUC program
(../shared/real-programs), parsed once: the first run in this process and the median of warm
runs, wall and CPU. Run from the repository root:
python3 benchmarks/checks_real.py
"""

from __future__ import annotations

import os
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from real_files import NAMES, real_folder  # noqa: E402

from ladderworks.core.compiler import check  # noqa: E402
from ladderworks.core.il import parse_file  # noqa: E402

RUNS = 21


def _timed(fn: Callable[[], object]) -> tuple[float, float]:
    """(wall ms, CPU ms) of one call of `fn`."""
    wall, cpu = time.perf_counter(), time.process_time()
    fn()
    return (time.perf_counter() - wall) * 1000, (time.process_time() - cpu) * 1000


def main() -> int:
    """One line per program: instructions, diagnostics, first run, median warm run."""
    folder = real_folder()
    if folder is None:
        print("no ../shared/real-programs beside the repository", file=sys.stderr)
        return 1
    for name in NAMES:
        program = parse_file(folder / f"{name}.txt").program
        steps = sum(len(network.instructions) for network in program.networks)
        first_wall, first_cpu = _timed(lambda p=program: check(p))
        runs = [_timed(lambda p=program: check(p)) for _ in range(RUNS)]
        print(f"{name:24s} {steps:6d} steps  {len(check(program)):5d} diagnostics  "
              f"first {first_wall:6.1f} ms (CPU {first_cpu:6.1f})  "
              f"warm median {statistics.median(w for w, _ in runs):6.1f} ms "
              f"(CPU {statistics.median(c for _, c in runs):6.1f})")
    load = os.getloadavg()
    print(f"load average: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} on {os.cpu_count()} cores")
    return 0


if __name__ == "__main__":
    sys.exit(main())
