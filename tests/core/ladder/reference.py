"""A tiny reference stack machine for the basic instructions (RD … OR.STK, WRT, SET, RST)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from ladderworks.core.address import Address
from ladderworks.core.il.program import Instruction


@dataclass
class Run:
    """What one pass over the instructions did."""

    writes: list[tuple[Address, bool]] = field(default_factory=list)
    calls: list[tuple[str, list[bool]]] = field(default_factory=list)  # function, stack bottom→ST0


def run(instructions: list[Instruction], value: Callable[[Address], bool]) -> Run:
    """Execute RD/AND/OR(.NOT)(.STK)/AND.STK/OR.STK/WRT(.NOT)/SET/RST; a function records its
    inputs (the whole stack) and leaves W1 = 0 in ST0. SET/RST write only when ST0 = 1."""
    out = Run()
    stack: list[bool] = []
    for ins in instructions:
        name = ins.name
        if ins.is_function or ins.spec.kind.value == "end":
            out.calls.append((name, list(stack)))
            stack = [False]
            continue
        if name in ("AND.STK", "OR.STK"):
            b = stack.pop()
            a = stack.pop()
            stack.append(a and b if name == "AND.STK" else a or b)
            continue
        if name.startswith("WRT"):
            out.writes.append((ins.operand, stack[-1] != name.endswith(".NOT")))
            continue
        if name in ("SET", "RST"):
            if stack[-1]:
                out.writes.append((ins.operand, name == "SET"))
            continue
        assert ins.operand is not None
        bit = value(ins.operand) != (".NOT" in name)
        if name in ("RD", "RD.NOT"):
            stack = [bit]
        elif name.endswith(".STK"):
            stack.append(bit)
        elif name.startswith("AND"):
            stack[-1] = stack[-1] and bit
        else:
            stack[-1] = stack[-1] or bit
    return out
