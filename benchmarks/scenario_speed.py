"""Scenario speed: real programs on the virtual clock, every scan and skipped scans side by side.

For X22 and S41_F036 (shared/real-programs), builds a scenario that changes two machine inputs
the program reads (a bit toggled and a byte written) every second, and one that does so every
5 s, for MINUTES minutes (default 10; `--minutes 0.5` for a short run), then checks one of
them at the end. Each runs from a cold start the way `ladderworks-cli test` does, once with
every scan run (`--every-scan`) and once skipping the scans of a repeating state (the
default); the two must end with the same memory. Prints virtual time / CPU time of this
process (the speed-up over real time on one core; the shared machine's wall time is printed
beside it) of both. Prints figures; asserts nothing.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import BinaryProgram, decode
from ladderworks.core.il import parse_file
from ladderworks.core.plc.parameters import PmcParameters
from ladderworks.core.plc.scenario import ScenarioResult, parse_scenario, run_scenario
from ladderworks.core.plc.session import PlcRun

_ROOT = Path(__file__).resolve().parents[1]
REAL = next((base / "shared" / "real-programs" for base in (_ROOT.parent, _ROOT.parent.parent)
             if (base / "shared" / "real-programs").is_dir()), _ROOT / "missing")
PROGRAMS = ("FANUC_STUDER_X22_P036", "FANUC_STUDER_S41_F036")


def inputs_of(binary: BinaryProgram) -> tuple[Address, Address]:
    """Two X bytes the program reads: a bit of the first is toggled, the second written."""
    read = sorted({op.operand.byte for op in binary.ops
                   if op.operand is not None and op.operand.area is Area.X
                   and op.spec.is_contact})
    first, second = [*read, 0, 1][:2]
    bit = next(op.operand.bit for op in binary.ops if op.operand is not None
               and op.operand.area is Area.X and op.operand.byte == first
               and op.operand.bit is not None) if read else 0
    return Address(Area.X, first, bit), Address(Area.X, second)


def scenario_text(bit: Address, byte: Address, minutes: float, every_ms: int) -> str:
    """SET lines every `every_ms` for `minutes`, then an EXPECT of the toggled bit."""
    lines = ["PMC SIGNAL DATA", f"REMARK,{minutes} minutes, inputs every {every_ms} ms"]
    count = max(1, int(minutes * 60_000 // every_ms))
    for step in range(count):
        lines.append(f"SET,{0 if step == 0 else every_ms},{bit},{step % 2},,"
                     f"{byte},{step * 37 % 256},BYTE")
    lines.append(f"EXPECT,{every_ms},{bit},{(count - 1) % 2}")
    return "\n".join(lines) + "\n"


def run(binary: bytes, program: object, text: str, every_scan: bool
        ) -> tuple[ScenarioResult, PlcRun, float]:
    """Play the scenario from a cold start; the result, the PLC and the CPU seconds."""
    plc = PlcRun(every_scan=every_scan)
    plc.set_parameters(PmcParameters())
    assert plc.load(binary, program) == []  # type: ignore[arg-type]
    scenario = parse_scenario(text, "speed")
    assert scenario.ok, scenario.error_texts()
    began = time.process_time()
    result = run_scenario(plc, scenario)
    return result, plc, time.process_time() - began


def main() -> int:
    """Print the every-scan and skipping speed-ups of each program and input rate."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=10.0)
    args = parser.parse_args()
    if not REAL.is_dir():
        print(f"{REAL} is missing")
        return 1
    for name in PROGRAMS:
        parsed = parse_file(REAL / f"{name}.txt")
        compiled = compile_program(parsed.program)
        if compiled.binary is None:
            print(f"{name}: does not compile")
            continue
        bit, byte = inputs_of(decode(compiled.binary))
        for every_ms in (1000, 5000):
            text = scenario_text(bit, byte, args.minutes, every_ms)
            figures = []
            memories = []
            for every_scan in (True, False):
                result, plc, cpu = run(compiled.binary, parsed.program, text, every_scan)
                virtual = result.virtual_ms / 1000
                figures.append((virtual / cpu if cpu else 0.0,
                                virtual / result.seconds if result.seconds else 0.0, result))
                memories.append(plc.memory.snapshot())
                skipped = plc.engine.skipped if plc.engine is not None else 0
                scans = plc.engine.scan_count if plc.engine is not None else 0
            (full, full_wall, full_result), (fast, fast_wall, fast_result) = figures
            same = "same memory" if memories[0] == memories[1] else "MEMORY DIFFERS"
            agree = "same checks" if fast_result.passed == full_result.passed else "CHECKS DIFFER"
            print(f"{name}, {args.minutes:g} min, inputs ({bit}, {byte}) every {every_ms} ms:\n"
                  f"  every scan  {full:7.1f}x real time on one core (CPU; wall {full_wall:.1f}x)\n"
                  f"  skipping    {fast:7.1f}x real time on one core (CPU; wall {fast_wall:.1f}x)"
                  f"  {fast / full if full else 0:.2f}x the every-scan speed, {skipped} of {scans}"
                  f" scans skipped; {same}, {agree}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
