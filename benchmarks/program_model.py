"""Prints ns to make, read, compare and hash the program model's objects (the parser makes one
Instruction per line and one Network per rung). Best of several timeit repeats, since the
machine may be shared. Run from the repository root: python3 benchmarks/program_model.py"""

from __future__ import annotations

import sys
import timeit
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from ladderworks.core.address import parse_address  # noqa: E402
from ladderworks.core.il.program import Instruction, Network, new_instruction  # noqa: E402

NUMBER = 200_000
REPEAT = 7
X = parse_address("X0.0")
FIRST = new_instruction("RD", X, (), "c", ("l",), 3, 1)
SECOND = new_instruction("RD", X, (), "c", ("l",), 4, 2)  # equal: only the position differs
CASES = (
    ("new_instruction(7 fields)", lambda: new_instruction("RD", X, (), "", (), 3, 1)),
    ("Instruction(name, operand)", lambda: Instruction("RD", X)),
    ("Instruction(..., comment=, line=, column=)",
     lambda: Instruction("RD", X, comment="", line=3, column=1)),
    ("Network(comments=, label=)", lambda: Network(comments=[], label="")),
    ("Network()", Network),
    ("instruction.name", lambda: FIRST.name),
    ("instruction == other", lambda: FIRST == SECOND),
    ("hash(instruction)", lambda: hash(FIRST)),
)


def main() -> int:
    """One line per operation: ns per call, the empty lambda's own cost taken off."""
    empty = min(timeit.repeat(lambda: None, number=NUMBER, repeat=REPEAT)) / NUMBER
    for title, call in CASES:
        best = min(timeit.repeat(call, number=NUMBER, repeat=REPEAT)) / NUMBER
        print(f"{title:44s} {(best - empty) * 1e9:7.0f} ns")
    return 0


if __name__ == "__main__":
    sys.exit(main())
