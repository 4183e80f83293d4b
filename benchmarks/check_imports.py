"""What `ladderworks-cli check` spends importing modules: ms in fresh processes, from before
`from ladderworks.cli import main` to the end of a check of a small example (every module the
command loads, lazily or not), less the same check run again in that process (its own work).

Each figure is the median of RUNS processes, CPU time (less disturbed by other work on the
machine) and wall time; with the bytecode cached (as an installed package runs), without `site`
(-S: none of site-packages' .pth start-up imports, which load pathlib, typing, re, ... in some
environments), and with the project's modules compiled from source. Run from the repository
root.
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = ROOT / "resources" / "examples" / "all_functions.LAD"  # every functional instruction
RUNS = 9

INSIDE = """
import contextlib, io, sys, time
before = set(sys.modules)
wall, cpu = time.perf_counter(), time.process_time()
from ladderworks.cli import main
with contextlib.redirect_stdout(io.StringIO()):
    main(["check", sys.argv[1]])
first = time.perf_counter() - wall, time.process_time() - cpu
loaded = len(set(sys.modules) - before)
wall, cpu = time.perf_counter(), time.process_time()
with contextlib.redirect_stdout(io.StringIO()):
    main(["check", sys.argv[1]])
again = time.perf_counter() - wall, time.process_time() - cpu
print(f"{(first[1] - again[1]) * 1000:.2f} {(first[0] - again[0]) * 1000:.2f} {loaded}")
"""


def _runs(env: dict[str, str], options: list[str]) -> tuple[list[float], list[float], int]:
    """CPU ms, wall ms of the imports in RUNS fresh processes, and the modules loaded."""
    cpus, walls, loaded = [], [], 0
    for _ in range(RUNS + 1):  # the first run fills the bytecode cache, if there is one
        done = subprocess.run([sys.executable, *options, "-c", INSIDE, str(EXAMPLE)], cwd=ROOT,
                              env=env, capture_output=True, text=True, check=True)
        cpu, wall, count = done.stdout.split()
        cpus.append(float(cpu))
        walls.append(float(wall))
        loaded = int(count)
    return cpus[1:], walls[1:], loaded


def main() -> int:
    """Run the measurements and print one line per figure."""
    base = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    no_site = {"PYTHONPATH": str(ROOT)}
    print(f"ladderworks-cli check {EXAMPLE.name}: ms importing, median of {RUNS} processes")
    with tempfile.TemporaryDirectory() as cache:
        cases: tuple[tuple[str, dict[str, str], list[str]], ...] = (
            ("bytecode cached", {**base, "PYTHONPYCACHEPREFIX": cache}, []),
            ("bytecode cached, no site", {**base, **no_site, "PYTHONPYCACHEPREFIX": cache},
             ["-S"]),
            # the project's modules compiled at each run (a checkout without __pycache__, with
            # PYTHONDONTWRITEBYTECODE set), the standard library's read from its own cache
            ("compiled from source", {**base, "PYTHONDONTWRITEBYTECODE": "1"}, []),
        )
        for label, env, options in cases:
            cpus, walls, loaded = _runs(env, options)
            print(f"{label:26s} CPU {statistics.median(cpus):5.1f} ms  "
                  f"wall {statistics.median(walls):5.1f} ms  ({loaded} modules loaded)")
    load = os.getloadavg()
    print(f"load average: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} on {os.cpu_count()} cores")
    return 0


if __name__ == "__main__":
    sys.exit(main())
