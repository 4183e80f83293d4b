"""Prints ms to parse a generated SimaticML export (the compare example's networks 300 times,
about 5 MB) safely, to read it into the S7 graph, and to open it as a program (lowering
included); and ms to refuse a 100 MB file by its size. No GUI."""

from __future__ import annotations

import tempfile
import time
from pathlib import Path

from ladderworks.core.dialects.s7 import xml_open
from ladderworks.core.dialects.s7.xml_reader import read_document
from ladderworks.core.dialects.s7.xml_safe import parse
from ladderworks.core.dialects.s7.xml_writer import write_block
from ladderworks.core.il.reading import parse_bytes

EXAMPLE = Path(__file__).resolve().parents[1] / "resources" / "examples" / "s7-xml" / "compare"


def export(copies: int) -> bytes:
    """The compare example's block with its networks repeated `copies` times."""
    block = read_document((EXAMPLE / "Main.xml").read_bytes()).blocks[0]
    block.networks = block.networks * copies
    return write_block(block, 5).encode()


def _best(fn, repeat: int = 3) -> float:  # type: ignore[no-untyped-def]
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append((time.perf_counter() - start) * 1000)
    return min(times)


def main() -> None:
    """Print the figures."""
    data = export(300)
    print(f"export: {len(data) / 1e6:.1f} MB, {300 * 6} networks")
    print(f"safe parse (expat, no DTD): {_best(lambda: parse(data)):.0f} ms")
    print(f"read into the graph: {_best(lambda: read_document(data)):.0f} ms")
    print(f"open as a program (lowering too): {_best(lambda: parse_bytes(data, 's7')):.0f} ms")
    with tempfile.TemporaryDirectory() as folder:
        big = Path(folder) / "Main.xml"
        with open(big, "wb") as file:
            file.write(data[:4000])
            file.truncate(100 * 1024 * 1024)
        print(f"refuse a 100 MB file: {_best(lambda: xml_open.open_path(big, None)):.2f} ms")


if __name__ == "__main__":
    main()
