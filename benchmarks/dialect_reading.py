"""What recognising and reading dialects costs: the content sniffing that every File › Open and
CLI read now does (on the real FANUC programs and a Delta example), a Delta program read, and
its scans (the seeds' flip/flop, fast and monitored). Prints ms; run from the repository root."""

from __future__ import annotations

import statistics
import time
from pathlib import Path

from ladderworks.core.compiler import compile
from ladderworks.core.il import parser
from ladderworks.core.il.reading import choose, parse_bytes
from ladderworks.core.plc.engine import ScanEngine

ROOT = Path(__file__).resolve().parent.parent
REAL = ROOT.parent.parent / "shared" / "real-programs"
DELTA = ROOT / "resources" / "examples" / "delta" / "motor_flip_flop.txt"
RUNS = 7


def _ms(work, runs: int = RUNS) -> float:
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return statistics.median(times) * 1000


def main() -> None:
    files = sorted(REAL.glob("FANUC_STUDER_*.txt")) if REAL.is_dir() else []
    for path in files:
        data = path.read_bytes()
        sniff = _ms(lambda data=data: choose(data))
        whole = _ms(lambda data=data: parser.parse_bytes(data), 3)
        print(f"{path.name}: sniff {sniff:.2f} ms, PMC parse {whole:.0f} ms "
              f"({sniff / whole * 100:.2f} % added by the dispatch)")
    data = DELTA.read_bytes()
    print(f"{DELTA.name}: sniff {_ms(lambda: choose(data)):.3f} ms, "
          f"read {_ms(lambda: parse_bytes(data)):.3f} ms")
    big = b"".join(data.split(b"END")[0] for _ in range(500)) + b"END\n"
    lines = big.count(b"\n")
    print(f"{lines} lines of Delta (the example 500 times): "
          f"read {_ms(lambda: parse_bytes(big), 3):.0f} ms")
    binary = compile(parse_bytes(data).program)
    scans = 20_000
    for monitored in (False, True):
        engine = ScanEngine(binary, monitored=monitored)
        spent = _ms(lambda engine=engine: engine.run_scans(scans), 3)
        mode = "monitored" if monitored else "fast"
        print(f"{DELTA.name} {mode}: {spent / scans * 1000:.1f} µs a scan")


if __name__ == "__main__":
    main()
