"""Prints the ms to read the real WinProladder project (../shared/real-programs/fatek/*.pdw):
its records and mask (read_pdw: the decoded listing), and the whole open (parse_file: the
listing through the Fatek reader, the comments as symbols); and the ms for every cut of it.
Run from the repository root: python3 benchmarks/pdw_read.py"""

from __future__ import annotations

import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from real_files import median_ms, real_folder  # noqa: E402

from ladderworks.core.dialects.fatek.pdw_file import read_pdw  # noqa: E402
from ladderworks.core.il.reading import parse_file  # noqa: E402


def main() -> int:
    """One line per project: size, steps, read_pdw ms, parse_file ms, every cut ms."""
    folder = real_folder()
    if folder is None:
        print("no ../shared/real-programs beside the repository", file=sys.stderr)
        return 1
    for path in sorted((folder / "fatek").glob("*.pdw")):
        data = path.read_bytes()
        result = read_pdw(data)
        steps = sum(len(steps) for _unit, steps in result.units)
        decode = median_ms(lambda data=data: read_pdw(data), 20)
        whole = median_ms(lambda path=path: parse_file(path), 20)
        start = time.perf_counter()
        for length in range(len(data)):
            read_pdw(data[:length])
        cuts = (time.perf_counter() - start) * 1000
        print(f"{path.name}: {len(data)} bytes, {steps} steps; read_pdw {decode:.2f} ms, "
              f"parse_file {whole:.2f} ms; all {len(data)} cuts {cuts:.0f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
