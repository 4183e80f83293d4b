"""The native scan against the Python scan, in one run: X22 and S41_F036 (shared/real-programs).

For each program: the Python variant's build time; the native backend's cold compile (IR made
in Python, then LLVM: parse, passes, code generation), a load from the in-memory cache (a
second engine of the same binary) and from the disk cache (as a new process would; the disk
cache is a fresh temporary directory for the run); µs per scan and ns per step of both
backends, fast and monitored (thread CPU time, best of ROUNDS rounds of SCANS scans from the
same state, the inputs set as a running machine might have them); a scenario-like run
(`advance` over VIRTUAL_S seconds of virtual time, inputs changing every second, scans skipped
where the state repeats, and every scan) as a factor of real time; and the instructions that
still call back into Python (by name, with their call sites). Prints figures; asserts nothing.
`--native-only`: the native scan's µs per scan alone (benchmarks/native_before_after.py).
"""

from __future__ import annotations

import collections
import os
import random
import sys
import tempfile
import time
from pathlib import Path

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import BinaryProgram, decode
from ladderworks.core.il import parse_file
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.native import jit

_ROOT = Path(__file__).resolve().parents[1]
SHARED = next((base / "shared" / "real-programs"
               for base in (_ROOT.parent, _ROOT.parent.parent, Path("/work"))
               if (base / "shared" / "real-programs").is_dir()), _ROOT / "missing")
PROGRAMS = ("FANUC_STUDER_X22_P036", "FANUC_STUDER_S41_F036")
ROUNDS = 15
SCANS = 20
VIRTUAL_S = 20


def load(name: str) -> BinaryProgram:
    result = compile_program(parse_file(SHARED / f"{name}.txt").program)
    assert result.binary is not None
    return decode(result.binary)


def inputs_of(binary: BinaryProgram) -> list[Address]:
    """The X and F bytes the program reads."""
    found = {Address(op.operand.area, op.operand.byte) for op in binary.ops
             if op.operand is not None and op.operand.area in (Area.X, Area.F)}
    return sorted(found, key=lambda a: (a.area.value, a.byte))


def drive(engine: ScanEngine, inputs: list[Address], seed: int) -> None:
    rng = random.Random(seed)
    for address in inputs:
        engine.memory.areas[address.area][address.byte] = rng.randrange(256) \
            if rng.random() < 0.3 else 0


def scan_us(engine: ScanEngine, monitored: bool) -> float:
    """Best µs per scan (thread CPU time) over ROUNDS rounds of SCANS scans."""
    engine.monitored = monitored
    engine.run_scans(5)
    best = float("inf")
    for _ in range(ROUNDS):
        started = time.thread_time_ns()
        engine.run_scans(SCANS)
        best = min(best, (time.thread_time_ns() - started) / SCANS / 1000)
    engine.monitored = False
    return best


def scenario_factor(binary: BinaryProgram, backend: str, inputs: list[Address],
                    every_scan: bool) -> float:
    """Virtual seconds per wall second over VIRTUAL_S s, inputs changing every second."""
    engine = ScanEngine(binary, backend=backend)  # built before the clock starts
    engine.every_scan = every_scan
    started = time.perf_counter()
    for second in range(VIRTUAL_S):
        drive(engine, inputs, second)
        engine.advance((second + 1) * 1000)
    return VIRTUAL_S / (time.perf_counter() - started)


def native_only(name: str) -> None:
    """The native scan's µs per scan, fast and monitored."""
    binary = load(name)
    engine = ScanEngine(binary, backend="native")
    drive(engine, inputs_of(binary), 1)
    print(f"\n{name}: {len(binary.ops)} steps")
    for mode in (False, True):
        us = scan_us(engine, mode)
        print(f"  native   {'monitored' if mode else 'fast':10} {us:9.1f} "
              f"{us * 1000 / len(binary.ops):8.2f}")


def report(name: str) -> None:
    binary = load(name)
    steps = len(binary.ops)
    inputs = inputs_of(binary)
    print(f"\n{name}: {steps} steps, {len(inputs)} input bytes")
    started = time.perf_counter()
    python = ScanEngine(binary)
    python_build = time.perf_counter() - started
    jit.clear_cache()
    started = time.perf_counter()
    native = ScanEngine(binary, backend="native")
    cold = time.perf_counter() - started
    if native.backend_reason:
        print(f"  native backend not available: {native.backend_reason}")
        return
    compiled = native._current.compiled
    started = time.perf_counter()
    again = ScanEngine(binary, backend="native")
    cached = time.perf_counter() - started
    assert again._current.from_cache
    jit.clear_cache()
    started = time.perf_counter()
    from_disk = ScanEngine(binary, backend="native")
    disk = time.perf_counter() - started
    assert from_disk._current.compiled.from_disk
    print(f"  build: python variant {python_build:.2f} s; native cold {cold:.2f} s "
          f"(IR {compiled.ir_seconds:.2f} s, LLVM {compiled.llvm_seconds:.2f} s); "
          f"from the memory cache {cached:.2f} s, from the disk cache {disk:.2f} s "
          f"(engine included)")
    for engine in (python, native):
        drive(engine, inputs, 1)
    rows = []
    for mode in (False, True):
        for engine in (python, native):
            us = scan_us(engine, mode)
            rows.append((engine.backend_used, "monitored" if mode else "fast", us))
    print(f"  {'backend':8} {'mode':10} {'µs/scan':>9} {'ns/step':>8}")
    for backend, mode, us in rows:
        print(f"  {backend:8} {mode:10} {us:9.1f} {us * 1000 / steps:8.2f}")
    fast = {b: us for b, m, us in rows if m == "fast"}
    monitored = {b: us for b, m, us in rows if m == "monitored"}
    print(f"  native speed-up: fast {fast['python'] / fast['native']:.1f}x, monitored "
          f"{monitored['python'] / monitored['native']:.1f}x; native monitored / fast "
          f"{monitored['native'] / fast['native']:.2f}")
    for every_scan in (False, True):
        label = "every scan" if every_scan else "skipping"
        factors = [scenario_factor(binary, b, inputs, every_scan) for b in ("python", "native")]
        print(f"  {VIRTUAL_S} s scenario, inputs every 1 s, {label}: python {factors[0]:.0f}x, "
              f"native {factors[1]:.0f}x real time")
    callbacks = collections.Counter(native._current.callbacks)
    print(f"  still calling back into Python: {sum(callbacks.values())} call sites: " +
          (", ".join(f"{k} {v}" for k, v in callbacks.most_common()) or "none"))


def main() -> int:
    if not SHARED.is_dir():
        print(f"shared/real-programs is missing ({SHARED})")
        return 1
    os.environ["LADDERWORKS_NATIVE_CACHE"] = tempfile.mkdtemp(prefix="native-bench-")
    names = [arg for arg in sys.argv[1:] if not arg.startswith("--")]
    for name in (names or PROGRAMS):
        if "--native-only" in sys.argv:
            native_only(name)
        else:
            report(name)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
