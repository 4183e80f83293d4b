"""Prints ms of the first `parse_file` of the 37,883-step FANUC_STUDER_S41_F036 in a fresh
process (imports done first, not counted), wall and CPU, median of fresh processes: what
`ladderworks-cli check` and File › Open pay (parse_real.py times later parses in one process,
which its caches help). Run from the repository root: python3 benchmarks/parse_cold.py [N]
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from real_files import real_file  # noqa: E402

NAME = "FANUC_STUDER_S41_F036"

# one fresh process: import the parser, then time one parse (wall and CPU, in ms)
_CHILD = """
import sys, time
from ladderworks.core.il.parser import parse_file
wall, cpu = time.perf_counter(), time.process_time()
parse_file(sys.argv[1])
print(1000 * (time.perf_counter() - wall), 1000 * (time.process_time() - cpu))
"""


def main() -> int:
    """Median wall and CPU ms of the first parse in N fresh processes (default 9)."""
    path = real_file(NAME)
    if path is None:
        print("no ../shared/real-programs beside the repository", file=sys.stderr)
        return 1
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 9
    walls: list[float] = []
    cpus: list[float] = []
    for _ in range(runs):
        out = subprocess.run([sys.executable, "-c", _CHILD, str(path)], cwd=ROOT, check=True,
                             capture_output=True, text=True).stdout.split()
        walls.append(float(out[0]))
        cpus.append(float(out[1]))
    print(f"{NAME}: first parse in a fresh process {statistics.median(walls):6.1f} ms wall, "
          f"{statistics.median(cpus):6.1f} ms CPU (median of {runs}; min wall "
          f"{min(walls):.1f} ms)")
    print(f"load average: {' '.join(f'{x:.2f}' for x in os.getloadavg())} on "
          f"{os.cpu_count()} cores")
    return 0


if __name__ == "__main__":
    sys.exit(main())
