"""A Fatek box's operand lines as the engine's parameters: a constant or a register, a bit."""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.fatek.branches import BranchError
from ladderworks.core.dialects.fatek.devices import (
    DeviceError,
    bit_address,
    parse_constant,
    parse_device,
    word_address,
)
from ladderworks.core.il.program import ParamValue


def operand(text: str, line: int, param: str, constant: bool, column: int = 1) -> ParamValue:
    """A box operand: a constant (where one may be) or a register's byte address."""
    value = parse_constant(text)
    if value is not None:
        if not constant:
            raise BranchError(Diagnostic("fatek-operand", {"text": text, "param": param}, line,
                                         column))
        return value
    try:
        device = parse_device(text, bit=False)
    except DeviceError:
        raise BranchError(Diagnostic("fatek-operand", {"text": text, "param": param},
                                     line, column)) from None
    return word_address(device)[0]


def bit_operand(text: str, line: int, param: str, column: int = 1) -> Address:
    """A box's bit operand (FUN 10 TOGG's D: `Y0`, `M5`): its bit address."""
    try:
        return bit_address(parse_device(text, bit=True))
    except DeviceError:
        raise BranchError(Diagnostic("fatek-bit-operand", {"text": text, "param": param},
                                     line, column)) from None
