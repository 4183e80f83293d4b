"""What the machine itself allows a real-time PLC (issue 30): how long a process that only reads
the clock loses the processor, and how much the CPU time of the same scan varies.

1. A loop reads `time.perf_counter()` for SECONDS; every gap over 0.5 ms is time the process
   was not running (another process, or the hypervisor of a virtual machine). Printed: the
   gaps over 0.5, 2 and 4 ms, and the longest.
2. S41_F036's scan, run 1,000 times from the same state (memory and every call site's state
   put back before each), sleeping 4 ms between scans as the real-time loop does: the CPU time
   of each (`time.thread_time`), as percentiles. The same work each time: the spread is the
   machine's.

Run: python benchmarks/machine_jitter.py [SECONDS]
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))


def gaps(seconds: float) -> None:
    """Part 1: the gaps a busy loop sees."""
    found: list[float] = []
    last = time.perf_counter()
    end = last + seconds
    while last < end:
        now = time.perf_counter()
        if now - last > 0.0005:
            found.append(now - last)
        last = now
    print(f"busy loop, {seconds:.0f} s: gaps over 0.5 ms {len(found)}, over 2 ms "
          f"{sum(g > 0.002 for g in found)}, over 4 ms {sum(g > 0.004 for g in found)}, "
          f"longest {max(found, default=0) * 1e3:.1f} ms")


def same_scan(count: int = 1000) -> None:
    """Part 2: one scan's CPU time, again and again from the same state."""
    from ladderworks.core.il import parse_file
    from ladderworks.core.plc.session import PlcRun

    path = next((base / "shared" / "real-programs" / "FANUC_STUDER_S41_F036.txt"
                 for base in ROOT.parents
                 if (base / "shared" / "real-programs" / "FANUC_STUDER_S41_F036.txt").exists()),
                None)
    if path is None:
        print("S41_F036 not found in shared/real-programs: part 2 left out")
        return
    run = PlcRun()
    run.load_program(parse_file(path).program)
    run.start()
    run.run_scans(200)  # past the first scans
    engine = run.engine
    assert engine is not None
    areas = {area: bytes(data) for area, data in run.memory.areas.items()}
    state = engine.export_state()
    times = []
    for _ in range(count):
        for area, data in areas.items():
            run.memory.areas[area][:] = data
        engine.import_state(state)
        began = time.thread_time()
        engine.scan()
        times.append((time.thread_time() - began) * 1e3)
        time.sleep(0.004)
    times.sort()
    marks = ", ".join(f"{name} {times[int(len(times) * share) - 1]:.2f}"
                      for name, share in (("median", 0.5), ("90 %", 0.9), ("99 %", 0.99),
                                          ("99.9 %", 0.999), ("max", 1.0)))
    print(f"S41_F036, the same scan {count} times, CPU ms: {marks}")


if __name__ == "__main__":
    gaps(float(sys.argv[1]) if len(sys.argv) > 1 else 8.0)
    same_scan()
