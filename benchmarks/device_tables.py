"""What a Delta/Fatek program's device tables cost: collecting the devices a big program uses
(once a load) and reading each table's rows from a memory image (each snapshot the table on
top takes), and the scan cost of Fatek timers (they read their value from memory). Prints ms
and µs; run from the repository root."""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from pathlib import Path

from ladderworks.core import dialects
from ladderworks.core.compiler import compile
from ladderworks.core.dialects.device_tables import (
    Table,
    program_devices,
    read_rows,
    table_places,
    table_rows,
)
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine

ROOT = Path(__file__).resolve().parent.parent
RUNS = 7
SCANS = 2000


def _ms(work: Callable[[], object], runs: int = RUNS) -> float:
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return statistics.median(times) * 1000


def _delta_program() -> str:
    """Every timer and counter, and 2000 D registers."""
    lines = []
    lines += [f"LD X0\nTMR T{n} K{n + 1}" for n in range(256)]
    lines += [f"LD X1\nCNT C{n} K{n + 1}" for n in range(200)]
    lines += [f"LD X1\nDCNT C{n} K{n}" for n in range(200, 256)]
    lines += [f"LD M1000\nMOV K{n} D{n}" for n in range(2000)]
    return "\n".join(lines) + "\nEND\n"


def main() -> None:
    text = _delta_program()
    plc = ScanEngine(compile(parse_bytes(text.encode(), "delta").program), period_ms=10)
    plc.scan()
    delta = dialects.get("delta")
    assert delta is not None
    tables = delta.device_tables()
    assert tables is not None
    ops = plc.program.ops
    print(f"Delta, {len(ops)} ops (T0-T255, C0-C255, D0-D1999): devices used "
          f"{_ms(lambda: program_devices(tables, delta.devices, ops)):.1f} ms")
    used = program_devices(tables, delta.devices, ops)
    areas = plc.memory.areas
    for table in Table:
        count = len(table_rows(table, tables, delta.devices, used, set(), areas))
        whole = _ms(lambda table=table: table_rows(table, tables, delta.devices, used, set(),
                                                   areas))
        places = table_places(table, tables, delta.devices, used, set())
        read = _ms(lambda places=places: read_rows(places, tables, delta.devices, areas))
        print(f"  {table.value}: {count} rows: found and read {whole:.2f} ms, read from the "
              f"places found (each snapshot) {read:.2f} ms")
    fatek = parse_bytes((ROOT / "resources" / "examples" / "fatek" / "conveyor.lst").read_bytes())
    timers = "\n".join(f"ORG X0\nTMR T{n} {n + 1}" for n in range(256)) + "\nEND\n"
    for name, program in (("conveyor.lst", fatek.program),
                          ("256 Fatek timers", parse_bytes(timers.encode(), "fatek").program)):
        engine = ScanEngine(compile(program), period_ms=10)
        engine.memory.set_bit(dialects.parse_target("X0", "fatek")[0], 1)
        spent = _ms(lambda engine=engine: engine.run_scans(SCANS), 3)
        print(f"{name}: {spent / SCANS * 1000:.1f} µs a scan (X0 on)")


if __name__ == "__main__":
    main()
