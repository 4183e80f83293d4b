"""Prints ms to read a generated 2,000-network Fatek listing (printed form), to save it back
unchanged, and to compile it and run 1,000 scans (no GUI)."""

from __future__ import annotations

import statistics
import time
from pathlib import Path

from ladderworks.core.compiler import compile
from ladderworks.core.dialects.fatek.reader import read
from ladderworks.core.il.printer import print_faithful
from ladderworks.core.il.textform import decode_lines
from ladderworks.core.plc.engine import ScanEngine

EXAMPLE = Path(__file__).resolve().parents[1] / "resources" / "examples" / "fatek" / "conveyor.lst"


def listing(copies: int) -> bytes:
    """The conveyor example's networks `copies` times over, steps numbered on."""
    body = EXAMPLE.read_text(encoding="utf-8").splitlines()[2:-1]  # no header, no END
    out = ["Printed Item: Mnemonic - BENCHMARK                                   Page 1", ""]
    step = 0
    for _copy in range(copies):
        for line in body:
            if line.startswith("Printed Item") or not line.strip():
                continue
            words = line.split()
            if words[0].isdigit():
                line = f"{step:6d}  " + line.split(None, 1)[1]
                step += 1
            out.append(line)
    out.append(f"{step:6d}  END")
    return ("\n".join(out) + "\n").encode()


def _best(fn, repeat: int = 5) -> tuple[float, object]:  # type: ignore[no-untyped-def]
    times = []
    result = None
    for _ in range(repeat):
        start = time.perf_counter()
        result = fn()
        times.append((time.perf_counter() - start) * 1000)
    return statistics.median(times), result


def main() -> None:
    """Run the measurements and print one line per figure."""
    data = listing(150)  # 150 copies of the 15 networks of the example: ~2,000 networks
    text, form, _problems, (lines, ends) = decode_lines(data)
    read_ms, result = _best(lambda: read(text, form, lines, ends))
    program, _diagnostics = result  # type: ignore[misc]
    save_ms, saved = _best(lambda: print_faithful(program))
    assert saved == text
    compile_ms, binary = _best(lambda: compile(program), repeat=3)
    engine = ScanEngine(binary)  # type: ignore[arg-type]
    scan_ms, _ = _best(lambda: [engine.scan() for _ in range(1000)], repeat=3)
    print(f"listing: {len(lines)} lines, {len(program.networks)} engine networks, "
          f"{program.step_count()} steps")
    print(f"read:             {read_ms:8.1f} ms  ({1000 * read_ms / len(lines):.1f} us/line)")
    print(f"save unchanged:   {save_ms:8.1f} ms")
    print(f"compile:          {compile_ms:8.1f} ms")
    print(f"1,000 scans:      {scan_ms:8.1f} ms")


if __name__ == "__main__":
    main()
