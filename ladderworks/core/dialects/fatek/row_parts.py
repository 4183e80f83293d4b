"""The parts Fatek's rows are made of (`rows.py`, `rows_tables.py`): SUB numbers, operand
parameters, the forms and FO byte parameters, and a FUN box's row."""

from __future__ import annotations

from ladderworks.core.instruction_fields import Operation
from ladderworks.core.instructions import (
    FUNCTION_OPCODE,
    InstructionSpec,
    Kind,
    Param,
    ParamAccess,
    ParamKind,
)

SUB_BASE = 20_000  # a Fatek row's SUB number: 20000 + FUN n (21000.. for the others)
OTHER = 21_000
INT32_LOW, INT32_HIGH = -(2**31), 2**31 - 1


def number(name: str, low: int, high: int) -> Param:
    """A number typed on the line (a timer's number, MD)."""
    return Param(name, ParamKind.NUMBER, low, high)


def value(name: str) -> Param:
    """An operand that is a constant or a register read."""
    return Param(name, ParamKind.VALUE, INT32_LOW, INT32_HIGH, width=2)


def register(name: str, access: ParamAccess = ParamAccess.WRITE) -> Param:
    """An operand that is a register (a table's first register, a destination)."""
    return Param(name, ParamKind.ADDRESS, width=2, access=access)


def raw(name: str) -> Param:
    """A parameter kept as the engine gives it (the FO byte, the FUN number)."""
    return Param(name, ParamKind.RAW, INT32_LOW, INT32_HIGH)


MODE = number("mode", 0, 3)  # bit 0: the P (pulse) form, bit 1: the D (32-bit) form
FO = raw("fo")  # the box's output byte (FO0 bit 0 …)


def fun_row(name: str, sub: int, mnemonic: str, title: str, title_tr: str, *,
            inputs: tuple[str, ...] = ("EN",), params: tuple[Param, ...] = (),
            w1: bool = True, cnc: bool = False,
            operation: Operation = Operation.NONE) -> InstructionSpec:
    """A Fatek box's row: a FUNCTION row of the dialect with its inputs and operands."""
    return InstructionSpec(name, Kind.FUNCTION, sub, inputs=inputs, params=params, w1=w1,
                           title=title, title_tr=title_tr, opcode=FUNCTION_OPCODE,
                           mnemonic=mnemonic, cnc=cnc, source="fatek", dialect="fatek",
                           operation=operation)
