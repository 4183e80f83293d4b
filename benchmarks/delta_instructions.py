"""What Delta's added instructions cost a scan: a program of the 32-bit, block, float, module,
step-ladder and loop instructions, and the shared real machine program (its WPLSoft separators
made spaces here), fast and monitored, and how many scans the skipping engine skips in 60 s of a
quiet machine. Prints µs a scan; run from the repository root."""

from __future__ import annotations

import statistics
import time
from pathlib import Path

from ladderworks.core.compiler import compile
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine

ROOT = Path(__file__).resolve().parent.parent
MACHINE = next((base / "shared" / "real-programs" / "delta" /
                "METALURGICA_c91257f_proejto_clp.csv" for base in ROOT.parents
                if (base / "shared" / "real-programs").is_dir()), Path("missing"))
MIXED = """LD M1002
SET S0
STL S0
OUT Y0
LD X0
SET S20
STL S20
TMR T0 K5
LD T0
SET S0
RET
LD M1000
DADD D0 K1 D0
DMUL D0 K3 D4
FLT D10 D20
DEDIV D20 K7 D22
INT D22 D24
ZRST M100 M131
FMOV K5 D100 K16
SFTL X1 M200 K16 K1
FROM K0 K12 D30 K4
FOR K4
LD M1000
INC D40
NEXT
DLD> D0 K100000
OUT Y1
END
"""


def _spaced(raw: bytes) -> bytes:
    lines = []
    for line in raw.decode("latin-1").splitlines():
        fields = [field for field in line.replace(";", ",").split(",") if field]
        lines.append(" ".join(fields[1:] if fields and fields[0].isdigit() else fields))
    return ("\n".join(lines) + "\n").encode()


def _per_scan(engine: ScanEngine, scans: int) -> float:
    times = []
    for _ in range(3):
        start = time.perf_counter()
        engine.run_scans(scans)
        times.append(time.perf_counter() - start)
    return statistics.median(times) / scans * 1e6


def main() -> None:
    programs = {"mixed new instructions": MIXED.encode()}
    if MACHINE.is_file():
        programs[MACHINE.name] = _spaced(MACHINE.read_bytes())
    for name, data in programs.items():
        binary = compile(parse_bytes(data, "delta").program)
        for monitored in (False, True):
            engine = ScanEngine(binary, monitored=monitored)
            mode = "monitored" if monitored else "fast"
            print(f"{name} {mode}: {_per_scan(engine, 5000):.1f} µs a scan")
        engine = ScanEngine(binary)
        ran = engine.advance(60_000)
        print(f"{name}: 60 s of a quiet machine: {engine.skipped} of {engine.scan_count} scans "
              f"skipped ({ran} returned by advance)")


if __name__ == "__main__":
    main()
