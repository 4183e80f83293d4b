"""S7 Real/LReal ADD/SUB/MUL/DIV and CONVERT from LReal on the native scan against the Python
scan: a program of such boxes (each under an input bit, operands in %MD, results to their own
places), its call sites that call back into Python and µs per scan of both backends (thread
CPU time, best of ROUNDS rounds of SCANS scans, every scan run, inputs and operands changing
each scan). Run it on an older checkout (PYTHONPATH) for the figures before. Prints; asserts
nothing.

    python benchmarks/s7_real_native.py
"""

from __future__ import annotations

import random
import struct
import time

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler.binary import BinaryProgram, Op, SourcePosition
from ladderworks.core.plc import typed
from ladderworks.core.plc.engine import ScanEngine

ROUNDS = 10
SCANS = 200
_HERE = SourcePosition(0, 0, 1, 1)


def program() -> BinaryProgram:
    """Each of ADD … DIV on Real and on LReal five times, CONVERT LReal → Real/DInt/Int five
    times each; operands D0-D31, results from D100."""
    ops: list[Op] = []
    boxes = [(name, (int(vtype), Address(Area.D, 8 * (n % 4)), Address(Area.D, 16 + 8 * (n % 2))))
             for name in ("S7.ADD", "S7.SUB", "S7.MUL", "S7.DIV")
             for vtype in (typed.ValueType.REAL, typed.ValueType.LREAL) for n in range(5)]
    boxes += [("S7.CONVERT", (int(typed.ValueType.LREAL), int(target),
                              Address(Area.D, 8 * (n % 4))))
              for target in (typed.ValueType.REAL, typed.ValueType.DINT, typed.ValueType.INT)
              for n in range(5)]
    for k, (name, params) in enumerate(boxes):
        ops.append(Op("RD", Address(Area.X, k % 4, k % 8), (), _HERE))
        ops.append(Op(name, None, (*params, Address(Area.D, 100 + 8 * k)), _HERE))
        ops.append(Op("WRT", Address(Area.R, 100 + k // 8, k % 8), (), _HERE))
    return BinaryProgram(tuple(ops), dialect="s7")


def _per_scan(engine: ScanEngine, data: list[bytes]) -> float:
    best = float("inf")
    for _ in range(ROUNDS):
        start = time.thread_time_ns()
        for k in range(SCANS):
            engine.memory.areas[Area.X][0:4] = data[k][:4]
            engine.memory.areas[Area.D][0:32] = data[k][4:]
            engine.scan()
        best = min(best, (time.thread_time_ns() - start) / SCANS / 1000)
    return best


def main() -> int:
    draw = random.Random(1)
    data = [bytes(draw.randrange(256) for _ in range(4)) +
            b"".join(struct.pack(">d", draw.uniform(-1e6, 1e6)) for _ in range(2)) +
            b"".join(struct.pack(">ff", draw.uniform(-1e3, 1e3), draw.uniform(-1e3, 1e3))
                     for _ in range(2)) for _ in range(SCANS)]
    binary = program()
    python = ScanEngine(binary)
    native = ScanEngine(binary, backend="native")
    python.every_scan = native.every_scan = True
    callbacks = getattr(native._current, "callbacks", [])
    print(f"{len(binary.ops) // 3} boxes, native: {native.backend_used}, {len(callbacks)} call "
          f"sites call back {sorted(set(callbacks))}; µs per scan: "
          f"Python {_per_scan(python, data):.1f}, native {_per_scan(native, data):.1f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
