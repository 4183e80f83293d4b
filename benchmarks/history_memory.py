"""Time-travel history on the real X22 program: bytes kept per second of run, scan cost.

Runs X22 monitored on the virtual clock with inputs changing every 100 ms, first without a
history, then with one (core/plc/history.py), and prints the history's size per second of
run, how many seconds fit in 200 MB, and the scan time with and without it. Prints figures;
asserts nothing.
"""

from __future__ import annotations

import random
import sys
import time
from pathlib import Path

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.il import parse_file
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.history import DEFAULT_BUDGET, ScanHistory

_ROOT = Path(__file__).resolve().parents[1]
X22 = next((base / "shared" / "real-programs" / "FANUC_STUDER_X22_P036.txt"
            for base in (_ROOT.parent, _ROOT.parent.parent)
            if (base / "shared" / "real-programs").is_dir()), _ROOT / "missing")
SECONDS = 10


def run(engine: ScanEngine, scans: int, seed: int) -> float:
    """Run `scans` scans changing a few X bytes every 100 ms; the seconds taken."""
    rng = random.Random(seed)
    began = time.perf_counter()
    for scan in range(scans):
        if scan % 12 == 0:
            for _ in range(3):
                engine.memory.areas[Area.X][rng.randrange(16)] = rng.randrange(256)
        engine.scan()
    return time.perf_counter() - began


def measured(history: ScanHistory) -> int:
    """The history's bytes counted object by object (sys.getsizeof), to check its estimate."""
    total = 0
    for segment in history.segments:
        total += sys.getsizeof(segment) + sys.getsizeof(segment.areas)
        total += sum(sys.getsizeof(data) for data in segment.areas.values())
        for items in (segment.scans, segment.times, segment.deltas):
            total += sys.getsizeof(items) + sum(sys.getsizeof(item) for item in items)
        for delta in segment.deltas:
            total += sum(sys.getsizeof(change) + sys.getsizeof(change[2]) for change in delta)
    return total


def main() -> int:
    """Print the figures."""
    if not X22.exists():
        print(f"{X22} is missing")
        return 1
    compiled = compile_program(parse_file(X22).program)
    assert compiled.binary is not None
    scans = SECONDS * 1000 // 8
    plain = ScanEngine(compiled.binary)
    plain.monitored = True
    kept = ScanEngine(compiled.binary)
    kept.monitored = True
    kept.history = ScanHistory()
    without = with_history = 0.0
    chunk = 125  # interleaved (the machine is shared): 1 s of each in turn
    for part in range(scans // chunk):
        without += run(plain, chunk, part)
        with_history += run(kept, chunk, part)
    per_second = kept.history.size / SECONDS
    print(f"X22 ({len(kept.program.ops)} ops), {SECONDS} s monitored at 8 ms: history "
          f"{kept.history.size / 1e6:.1f} MB = {per_second / 1e6:.2f} MB per second of run; "
          f"{DEFAULT_BUDGET / 1024 / 1024:.0f} MB hold {DEFAULT_BUDGET / per_second:.0f} s")
    print(f"counted object by object: {measured(kept.history) / 1e6:.1f} MB "
          f"(the budget's estimate: {kept.history.size / 1e6:.1f} MB)")
    print(f"scan: {without / scans * 1e3:.2f} ms monitored, {with_history / scans * 1e3:.2f} ms "
          f"monitored + history ({(with_history / without - 1) * 100:+.0f}%)")
    frame_began = time.perf_counter()
    last = kept.history.last_scan or 0
    kept.history.frame(last - 100)
    print(f"rebuilding one past scan: {(time.perf_counter() - frame_began) * 1e3:.1f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
