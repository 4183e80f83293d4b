"""The code generator's values: a stack level's Python expression, and an open JMP or COM range."""

from __future__ import annotations

from dataclasses import dataclass

from ladderworks.core.address import Address


@dataclass(slots=True)
class Range:
    """An open JMP or COM range: its id (JMP) or gate variable (COM), and the coils left
    (None: up to the end instruction, JMPE or COME)."""

    ident: int
    left: int | None
    gates_boxes: bool = False  # COM only: its gate also turns the boxes' inputs off (Delta MC)


def count_in_innermost(ranges: list[Range]) -> Range | None:
    """Count one coil in the innermost of `ranges`; the range it ended, if any.

    A coil counts only for the innermost open range (JMP and COM alike): a counted range
    nested inside another counts its own coils, and the outer one goes on counting after it.
    """
    if not ranges or ranges[-1].left is None:
        return None
    ranges[-1].left -= 1
    if ranges[-1].left > 0:
        return None
    return ranges.pop()


def counted(coils: object) -> int | None:
    """A range's coil count from the instruction's parameter: None for 0 (up to the end)."""
    return coils if isinstance(coils, int) and coils > 0 else None


class Value:
    """The Python expression for one stack level, and how it was built."""

    __slots__ = ("expr", "nesting", "terms", "top")

    def __init__(self, expr: str, top: str = "", nesting: int = 0, terms: int = 1) -> None:
        self.expr = expr
        self.top = top  # top-level operator: "", "&" or "|"
        self.nesting = nesting
        self.terms = terms


def bit_expr(address: Address, inverted: bool) -> str:
    assert address.bit is not None
    byte = f"{address.area.value}[{address.byte}]"
    if inverted:
        byte = "~" + byte
    if address.bit:
        return f"({byte} >> {address.bit} & 1)"
    return f"({byte} & 1)"
