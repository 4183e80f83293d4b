"""COMP, COIN (BCD) and COMPB (binary, R9000 flags): constants, addresses, invalid BCD, ACT."""

from __future__ import annotations

import pytest

from ladderworks.core.plc.functions import FunctionContext
from tests.core.functions.conftest import at


@pytest.mark.parametrize(("value", "data", "le", "eq"), [
    (5, 7, True, False), (7, 7, True, True), (8, 7, False, False), (0, 0, True, True),
])
def test_comp_and_coin_constant(ctx: FunctionContext, box, value: int, data: int, le: bool,
                                eq: bool) -> None:
    ctx.memory.write_bcd(at("R10"), data, 1)
    assert box("COMP", 0, value, "R10")(0, 1) is le
    assert box("COIN", 0, value, "R10")(0, 1) is eq


def test_four_digits_from_addresses(ctx: FunctionContext, box) -> None:
    ctx.memory.write_bcd(at("R10"), 1234, 2)
    ctx.memory.write_bcd(at("R12"), 1233, 2)
    assert box("COMP", 1, "R10", "R12")(1, 1) is False
    assert box("COMP", 1, "R12", "R10")(1, 1) is True
    assert box("COIN", 1, "R12", "R12")(1, 1) is True
    # with BYT = 0 only the low byte counts: 34 vs 33
    assert box("COMP", 1, "R12", "R10")(0, 1) is True
    assert box("COIN", 1, "R10", "R12")(0, 1) is False


def test_act_off_and_invalid_data_give_zero(ctx: FunctionContext, box) -> None:
    ctx.memory.write_bcd(at("R10"), 7, 1)
    assert box("COIN", 0, 7, "R10")(0, 0) is False
    assert box("COMP", 0, 7, "R10")(0, 0) is False
    ctx.memory.write(at("R10"), 0xF7)
    assert box("COMP", 0, 1, "R10")(0, 1) is False
    assert box("COIN", 0, 0x7, "R10")(0, 1) is False
    ctx.memory.write_bcd(at("R10"), 99, 1)
    assert box("COMP", 0, 100, "R10")(0, 1) is False  # 3 digits are not a 2-digit input
    assert box("COMP", 0, -1, "R10")(0, 1) is False  # BCD has no sign


@pytest.mark.parametrize(("width", "value", "data", "flags"), [
    (1, -1, 1, 0b10), (1, 1, -1, 0b00), (2, 300, 300, 0b01), (4, -70000, -69999, 0b10),
    (4, 2**31 - 1, -(2**31), 0b00),
])
def test_compb_flags(ctx: FunctionContext, box, width: int, value: int, data: int,
                     flags: int) -> None:
    ctx.memory.write(at("D0"), value, width)
    ctx.memory.write(at("D4"), data, width)
    ctx.memory.write(at("R9000"), 0xFF)
    assert box("COMPB", 1000 + width, "D0", "D4")(1) is False
    assert ctx.memory.read(at("R9000")) == flags
    ctx.memory.write(at("R9000"), 0xFF)
    box("COMPB", width, value, "D4")(1)  # the same with a constant input
    assert ctx.memory.read(at("R9000")) == flags


def test_compb_act_off_leaves_r9000(ctx: FunctionContext, box) -> None:
    ctx.memory.write(at("R9000"), 0x55)
    box("COMPB", 2, 1, "D4")(0)
    assert ctx.memory.read(at("R9000")) == 0x55
