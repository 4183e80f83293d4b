"""The machine's floor for a real-time PLC: a process that does nothing but wait for its next
scan time every period, at the priority the scan process asks for (scan_process.raise_priority)
and waiting as it does (a pipe's poll up to the due time), with no scan and no IDE. Prints how
late it woke (the worst, the 99th percentile, the wake-ups later than a period and than 2 ms)
and the CPU time the system stole from the machine meanwhile (Linux's /proc/stat "steal": a
virtual machine's processors not running). An IDE run whose overruns are no more than this
one's wake-ups later than a period is at the machine's floor. Asserts nothing.

    python benchmarks/wakeup_latency.py [SECONDS] [--period-ms 8]
"""

from __future__ import annotations

import argparse
import multiprocessing
import os
import time
from pathlib import Path

from ladderworks.core.plc import scan_process


def steal() -> int | None:
    """The CPU time stolen so far, in clock ticks (None where the system does not say)."""
    stat = Path("/proc/stat")
    if not stat.exists():
        return None
    fields = stat.read_text().split("\n", 1)[0].split()
    return int(fields[8]) if len(fields) > 8 else None


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("seconds", nargs="?", type=float, default=20.0)
    parser.add_argument("--period-ms", type=float, default=8.0)
    args = parser.parse_args()
    period = args.period_ms / 1000
    reader, _writer = multiprocessing.Pipe(duplex=False)
    got = scan_process.raise_priority()
    stolen = steal()
    late: list[float] = []
    due = time.perf_counter()
    end = due + args.seconds
    while due < end:
        due += period
        while (wait := due - time.perf_counter()) > 0:
            reader.poll(wait)
        late.append(time.perf_counter() - due)
    scan_process.normal_priority()
    stolen = None if stolen is None else (steal() or 0) - stolen
    late.sort()
    worst, p99 = late[-1] * 1000, late[int(len(late) * 0.99)] * 1000
    print(f"priority: {got}; {len(late)} wake-ups every {args.period_ms:g} ms; "
          f"late by more than a period: {sum(t > period for t in late)}, more than 2 ms: "
          f"{sum(t > 0.002 for t in late)}; worst {worst:.1f} ms, 99th percentile {p99:.2f} ms")
    if stolen is not None:
        print(f"CPU time stolen from the machine meanwhile: "
              f"{stolen / os.sysconf('SC_CLK_TCK'):.2f} s "
              "(/proc/stat steal, all processors)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
