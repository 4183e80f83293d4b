"""What drawing programs as ladder costs: layout (program → grid) and decoding (grid →
program) of a generated 4000-network PMC program and of a Delta program of edge/comparison
contacts and MPS branches. Prints the best of a few runs in ms; run from the repository root."""

from __future__ import annotations

import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from benchmarks.large_program import large_program_text  # noqa: E402
from ladderworks.core.il import Program, parse  # noqa: E402
from ladderworks.core.il.reading import parse_bytes  # noqa: E402
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder  # noqa: E402

RUNS = 3
DELTA_RUNG = ("LD X0\nMPS\nAND= D0 K5\nOUT Y0\nMRD\nANDP X1\nOUT Y1\nMPP\nLD< C1 C2\nOR> D1 K9\n"
              "ANB\nOUT Y2\n")


def _times(program: Program) -> tuple[float, float]:
    layout = decode = float("inf")
    for _ in range(RUNS):
        start = time.perf_counter()
        doc = program_to_ladder(program)
        layout = min(layout, time.perf_counter() - start)
        for net in doc.networks:
            net.source = None  # decode the drawing itself
        start = time.perf_counter()
        ladder_to_program(doc)
        decode = min(decode, time.perf_counter() - start)
    return layout * 1000, decode * 1000


def main() -> None:
    """Print the figures."""
    pmc = parse(large_program_text(4000)).program
    print("PMC, 4000 networks: layout {:.0f} ms, decode {:.0f} ms".format(*_times(pmc)))
    delta = parse_bytes((DELTA_RUNG * 1000 + "END\n").encode(), "delta").program
    print("Delta, 1000 rungs with MPS branches and edge/comparison contacts: "
          "layout {:.0f} ms, decode {:.0f} ms".format(*_times(delta)))


if __name__ == "__main__":
    main()
