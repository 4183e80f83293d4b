"""A TR point as a rung's branch point: `OUT TR n`, the first branch's outputs, `LD TR n`, the
next branch's … read as one engine network with the result kept on the stack (the rows
FBS.TRPUSH / TRREAD / TRLAST: Delta's MPS / MRD / MPP), drawn as WinProladder draws it: one
rung, the branches from the point (docs/dialects.md, Fatek)."""

from __future__ import annotations

from ladderworks.core.dialects.fatek.branches import Lowered
from ladderworks.core.dialects.fatek.listing import Record
from ladderworks.core.instructions import StackOp
from ladderworks.core.ladder.reading import Undrawable, read_rung

PUSH, READ, LAST = "FBS.TRPUSH", "FBS.TRREAD", "FBS.TRLAST"
_OUTPUTS = ("OUT", "OUTS", "OUTR", "SET", "RST")


class NoBranch(Exception):
    """The network's TR points cannot be drawn as branch points: it is lowered as before."""


def _point(record: Record) -> int | None:
    """The TR point a record names (`OUT TR 0`, `LD TR0`, `AND TR0`), None for none."""
    operand = record.operand.upper()
    if operand[:2] != "TR" or not operand[2:].isdigit():
        return None
    return int(operand[2:])


def branch_points(network: list[Record]) -> dict[int, int]:
    """The TR points of a network that may be branch points, with how often each is read: set
    once by `OUT TR n`, then read only by `LD TR n` records right after an output (a coil),
    at least once; any other use (a box's input, ANDLD / ORLD, `AND TR n`) keeps the relay."""
    saved: dict[int, int] = {}
    reads: dict[int, int] = {}
    refused: set[int] = set()
    previous: Record | None = None
    for record in network:
        number = _point(record)
        if number is not None:
            if record.mnemonic == "OUT" and number not in saved and number not in reads:
                saved[number] = 1
            elif record.mnemonic == "LD" and number in saved and previous is not None \
                    and previous.mnemonic in _OUTPUTS and _point(previous) is None:
                reads[number] = reads.get(number, 0) + 1
            else:
                refused.add(number)
        previous = record
    return {n: count for n, count in reads.items() if n not in refused}


def drawn_as_branches(parts: list[Lowered]) -> bool:
    """Whether every engine network holding a branch point draws as a rung (else the network
    is lowered with its TR relays, as before)."""
    for part in parts:
        if any(ins.spec.stack is not StackOp.NONE for ins in part.instructions):
            try:
                read_rung(part.instructions)
            except Undrawable:
                return False
    return True
