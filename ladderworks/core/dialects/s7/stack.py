"""A network's power as stack code: the expressions of power and the pins' wiring.

`emit_expr` writes an expression as the engine's stack instructions (RD, AND, OR, RD.STK,
AND.STK, OR.STK, one-input boxes, S7.NOT); `PinGraph` indexes a network's wires by pin.
"""

from __future__ import annotations

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects.s7.graph import End, Operand, Part, S7Network
from ladderworks.core.il.program import Instruction

ALWAYS_OFF = Address(Area.R, 9091, 0)  # the engine's always-0 and always-1 relays
ALWAYS_ON = Address(Area.R, 9091, 1)

# an expression of power: ("on",) | ("bit", Address, negated) | ("and", a, b) | ("or", [..])
# | ("box", name, params, a) a one-input pure box | ("not", a)
Expr = tuple


def emit_expr(expr: Expr, push: bool, code: list[Instruction], line: int) -> None:
    """Code leaving `expr` on the stack: as a new value (RD) or pushed on the one before."""
    kind = expr[0]
    if kind == "on":
        code.append(Instruction("RD.STK" if push else "RD", ALWAYS_ON, line=line))
    elif kind == "bit":
        name = ("RD.NOT" if expr[2] else "RD") + (".STK" if push else "")
        code.append(Instruction(name, expr[1], line=line))
    elif kind == "and" and expr[1][0] == "on":
        emit_expr(expr[2], push, code, line)
    elif kind == "and":
        left, right = expr[1], expr[2]
        emit_expr(left, push, code, line)
        if right[0] == "bit":
            code.append(Instruction("AND.NOT" if right[2] else "AND", right[1], line=line))
        elif right[0] != "on":
            emit_expr(right, True, code, line)
            code.append(Instruction("AND.STK", line=line))
    elif kind == "or":
        terms = expr[1]
        emit_expr(terms[0], push, code, line)
        for term in terms[1:]:
            if term[0] == "bit":
                code.append(Instruction("OR.NOT" if term[2] else "OR", term[1], line=line))
            else:
                emit_expr(term, True, code, line)
                code.append(Instruction("OR.STK", line=line))
    elif kind == "box":
        emit_expr(expr[3], push, code, line)
        code.append(Instruction(expr[1], None, expr[2], line=line))
    elif kind == "not":
        emit_expr(expr[1], push, code, line)
        code.append(Instruction("S7.NOT", line=line))


class PinGraph:
    """A network's wires by pin: where power comes from, which operand a pin reads/writes."""

    def __init__(self, network: S7Network) -> None:
        self.network = network
        self.index = 0
        self.parts: dict[str, Part] = {p.uid: p for p in network.parts}
        self.power_in: dict[tuple[str, str], list[End]] = {}
        self.operand_in: dict[tuple[str, str], Operand] = {}
        self.operand_out: dict[tuple[str, str], list[Operand]] = {}
        self.extra_out: dict[tuple[str, str], Expr] = {}
        self.readers: dict[str, int] = {}
        self.missing = [end.part for wire in network.wires for end in (wire.source, *wire.targets)
                        if end.part and end.part not in self.parts]
        for wire in network.wires:
            source = wire.source
            for target in wire.targets:
                if source.operand is not None and target.part:
                    self.operand_in[(target.part, target.pin.lower())] = source.operand
                elif target.operand is not None and source.part:
                    self.operand_out.setdefault((source.part, source.pin.lower()), []).append(
                        target.operand)
                elif target.part:
                    end = End(source.powerrail, source.part, source.pin.lower())
                    self.power_in.setdefault((target.part, target.pin.lower()), []).append(end)
                    if source.part:
                        self.readers[source.part] = self.readers.get(source.part, 0) + 1

    def used(self, uid: str) -> bool:
        """True when other parts take power from this part."""
        return self.readers.get(uid, 0) > 0

    def order(self, loop: object) -> list[Part]:
        """The parts, each after every part it takes power from; a loop raises `loop(uid)`."""
        done: list[Part] = []
        state: dict[str, int] = {}

        def visit(uid: str) -> None:
            mark = state.get(uid, 0)
            if mark == 2:
                return
            if mark == 1:
                raise loop(uid)  # type: ignore[operator]
            state[uid] = 1
            for (target, _pin), ends in self.power_in.items():
                if target == uid:
                    for end in ends:
                        if end.part in self.parts:
                            visit(end.part)
            state[uid] = 2
            done.append(self.parts[uid])

        for part in self.network.parts:
            visit(part.uid)
        return done
