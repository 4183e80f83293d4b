"""Fatek programs on the native scan against the Python scan: the real WinProladder project
(shared/real-programs/fatek/VERTINO_SKO-Program.pdw) and the examples (resources/examples/
fatek): the call sites that still call back into Python, and µs per scan of both backends,
fast (thread CPU time, best of ROUNDS rounds of SCANS scans, every scan run, the X inputs
changing each scan). Prints figures; asserts nothing.

    python benchmarks/native_fatek.py
"""

from __future__ import annotations

import random
import time
from pathlib import Path

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import decode
from ladderworks.core.il import parse_file
from ladderworks.core.plc.engine import ScanEngine

_ROOT = Path(__file__).resolve().parents[1]
SHARED = next((base / "shared" / "real-programs"
               for base in (_ROOT.parent, _ROOT.parent.parent, Path("/work"))
               if (base / "shared" / "real-programs").is_dir()), _ROOT / "missing")
ROUNDS = 15
SCANS = 200


def _per_scan(engine: ScanEngine, inputs: list[bytes]) -> float:
    """µs per scan: the best of ROUNDS rounds of SCANS scans."""
    best = float("inf")
    x = engine.memory.areas[Area.X]
    for _ in range(ROUNDS):
        start = time.thread_time_ns()
        for k in range(SCANS):
            x[0:4] = inputs[k]
            engine.scan()
        best = min(best, (time.thread_time_ns() - start) / SCANS / 1000)
    return best


def main() -> int:
    paths = [SHARED / "fatek" / "VERTINO_SKO-Program.pdw",
             *sorted((_ROOT / "resources" / "examples" / "fatek").glob("*.lst"))]
    draw = random.Random(1)
    inputs = [bytes(draw.randrange(256) for _ in range(4)) for _ in range(SCANS)]
    for path in paths:
        if not path.exists():
            continue
        compiled = compile_program(parse_file(path).program)
        if compiled.binary is None:
            continue
        binary = decode(compiled.binary)
        python = ScanEngine(binary)
        native = ScanEngine(binary, backend="native")
        python.every_scan = native.every_scan = True
        callbacks = getattr(native._current, "callbacks", [])
        print(f"{path.name}: {len(binary.ops)} ops, native: {native.backend_used}, "
              f"{len(callbacks)} call sites call back {sorted(set(callbacks))}; µs per scan: "
              f"Python {_per_scan(python, inputs):.1f}, native {_per_scan(native, inputs):.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
