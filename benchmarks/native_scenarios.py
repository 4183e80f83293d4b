"""Scenario runs of the real programs on both scan backends: speed-up over real time.

X22 and S41_F036 (shared/real-programs beside the repository) run `--duration` seconds of
virtual time (default 600: the 10-minute scenario of issue 40) at the 8 ms period, as a
scenario test does: a cold start, the machine's inputs set, then `advance` from one input
change to the next. The inputs change every 1 s and every 5 s (each change toggles `--bits`
input bits the program reads, chosen at random with a fixed seed, so both backends see the
same run); every scan, and with the scans of a repeating state skipped. For each run: the
speed-up over real time by wall time and by the process's CPU time (the machine is shared),
the scans run and skipped. The Python runs may be given a shorter `--python-duration` (a rate
does not need the whole 10 minutes; the Python scan needs about as long as real time).
Prints figures; asserts nothing.

    python benchmarks/native_scenarios.py [--duration S] [--python-duration S]
        [--programs X22,S41] [--backends python,native]
"""

from __future__ import annotations

import argparse
import os
import random
import tempfile
import time
from pathlib import Path

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import BinaryProgram, decode
from ladderworks.core.il import parse_file
from ladderworks.core.plc.engine import ScanEngine

_ROOT = Path(__file__).resolve().parents[1]
SHARED = next((base / "shared" / "real-programs"
               for base in (_ROOT.parent, _ROOT.parent.parent, Path("/work"))
               if (base / "shared" / "real-programs").is_dir()), _ROOT / "missing")
PROGRAMS = {"X22": "FANUC_STUDER_X22_P036", "S41": "FANUC_STUDER_S41_F036"}
INTERVALS_S = (1, 5)


def load(name: str) -> BinaryProgram:
    result = compile_program(parse_file(SHARED / f"{name}.txt").program)
    assert result.binary is not None
    return decode(result.binary)


def input_bits(binary: BinaryProgram) -> list[Address]:
    """The X and F bits the program reads."""
    found = {op.operand for op in binary.ops if op.operand is not None
             and op.operand.area in (Area.X, Area.F) and op.operand.bit is not None}
    return sorted(found, key=lambda a: (a.area.value, a.byte, a.bit or 0))


def run(binary: BinaryProgram, backend: str, bits: list[Address], duration_s: int,
        interval_s: int, every_scan: bool, toggled: int) -> tuple[float, float, int, int, str]:
    """(wall s, CPU s, scans run, scans skipped, backend used) of one scenario run."""
    engine = ScanEngine(binary, backend=backend)  # compiled before the clock starts
    engine.every_scan = every_scan
    rng = random.Random(40)
    areas = engine.memory.areas
    for address in bits:  # the machine as it stands: about a third of the inputs on
        if rng.random() < 0.3:
            areas[address.area][address.byte] |= 1 << (address.bit or 0)
    wall, cpu = time.perf_counter(), time.process_time()
    now = 0
    while now < duration_s * 1000:
        for address in rng.sample(bits, min(toggled, len(bits))):
            areas[address.area][address.byte] ^= 1 << (address.bit or 0)
        now += interval_s * 1000
        engine.advance(now)
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    return wall, cpu, engine.scan_count - engine.skipped, engine.skipped, engine.backend_used


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=int, default=600, help="virtual seconds (600)")
    parser.add_argument("--python-duration", type=int, default=None,
                        help="virtual seconds of the Python runs (default: --duration)")
    parser.add_argument("--programs", default="X22,S41")
    parser.add_argument("--backends", default="python,native")
    parser.add_argument("--bits", type=int, default=4, help="input bits toggled per change")
    args = parser.parse_args()
    if not SHARED.is_dir():
        print(f"shared/real-programs is missing ({SHARED})")
        return 1
    os.environ.setdefault("LADDERWORKS_NATIVE_CACHE", tempfile.mkdtemp(prefix="native-bench-"))
    print(f"{'program':7} {'backend':8} {'inputs':>7} {'mode':10} {'virtual':>8} {'wall':>8} "
          f"{'x real':>7} {'CPU':>8} {'x (CPU)':>8} {'run':>7} {'skipped':>7}")
    for short in args.programs.split(","):
        binary = load(PROGRAMS[short])
        bits = input_bits(binary)
        for backend in args.backends.split(","):
            duration = args.python_duration if backend == "python" and \
                args.python_duration else args.duration
            # the compile (cached) and the clocks the program reads (found once per program
            # by the skipper, 0.1-0.4 s, kept: skipping.clocks_read) are not timed
            ScanEngine(binary, backend=backend).advance(8)
            for interval in INTERVALS_S:
                for every_scan in (True, False):
                    wall, cpu, ran, skipped, used = run(binary, backend, bits, duration,
                                                        interval, every_scan, args.bits)
                    mode = "every scan" if every_scan else "skipping"
                    print(f"{short:7} {used:8} {interval:>5} s {mode:10} {duration:>6} s "
                          f"{wall:>6.1f} s {duration / wall:>6.0f}x {cpu:>6.1f} s "
                          f"{duration / cpu:>7.0f}x {ran:>7} {skipped:>7}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
