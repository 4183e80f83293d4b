"""Prints ms to parse, print and lay out as ladder a generated 2,000-network program (no GUI)."""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from large_program import large_program_text

from ladderworks.core.il import parse, print_program
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder


def _best(fn, repeat: int = 5) -> tuple[float, object]:
    times = []
    result = None
    for _ in range(repeat):
        start = time.perf_counter()
        result = fn()
        times.append((time.perf_counter() - start) * 1000)
    return statistics.median(times), result


def main() -> None:
    """Run the measurements and print one line per figure."""
    text = large_program_text(2000)
    lines = text.count("\n")
    parse_ms, result = _best(lambda: parse(text))
    program = result.program  # type: ignore[union-attr]
    print_ms, _ = _best(lambda: print_program(program))
    layout_ms, doc = _best(lambda: program_to_ladder(program))
    decode_ms, _ = _best(lambda: ladder_to_program(doc))
    print(f"program: 2000 networks, {lines} lines, {program.step_count()} steps")
    print(f"parse:            {parse_ms:8.1f} ms  ({1000 * parse_ms / lines:.1f} us/line)")
    print(f"print:            {print_ms:8.1f} ms")
    print(f"program -> grid:  {layout_ms:8.1f} ms")
    print(f"grid -> program:  {decode_ms:8.1f} ms")


if __name__ == "__main__":
    main()
