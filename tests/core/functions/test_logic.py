"""Byte-wise LOGAND (`AND`), LOGOR (`OR`), EOR and NOT (FANUC-PMC.md §6): formats 1/2/4 with a
constant, 1001/1002/1004 with an address, constant range and wrap, ACT = 0, R9000 untouched."""

from __future__ import annotations

import operator

import pytest

from ladderworks.core.address import Area
from ladderworks.core.plc.functions import FunctionContext
from tests.core.functions.conftest import at, run_engine
from tests.core.plc.conftest import set_bit

OPS = {"LOGAND": operator.and_, "LOGOR": operator.or_, "EOR": operator.xor}
INPUT = 0x8421_F00F


@pytest.mark.parametrize("name", OPS)
@pytest.mark.parametrize("width", [1, 2, 4])
def test_constant_operand(ctx: FunctionContext, box, name: str, width: int) -> None:
    mask = (1 << 8 * width) - 1
    ctx.memory.write(at("R0"), INPUT, 4)
    ctx.memory.write(at("R10"), 0xDDDD_DDDD, 4)
    box(name, width, "R0", 0x5AA5_3C3C & mask, "R10")(1)
    expected = OPS[name](INPUT & mask, 0x5AA5_3C3C & mask)
    assert ctx.memory.read(at("R10"), width) == expected
    assert ctx.memory.read(at("R10").offset(width), 4 - width) == 0xDDDD_DDDD >> 8 * width


@pytest.mark.parametrize("name", OPS)
@pytest.mark.parametrize("width", [1, 2, 4])
def test_address_operand(ctx: FunctionContext, box, name: str, width: int) -> None:
    ctx.memory.write(at("R0"), INPUT, 4)
    ctx.memory.write(at("D0"), 0x0FF0_1234, 4)
    box(name, 1000 + width, "R0", "D0", "R10")(1)
    mask = (1 << 8 * width) - 1
    assert ctx.memory.read(at("R10"), 4) == OPS[name](INPUT, 0x0FF0_1234) & mask


@pytest.mark.parametrize(("width", "constant", "bits"), [
    (2, 65295, 0xFF0F),  # the X22 mask: unsigned up to 2^16 - 1
    (2, -241, 0xFF0F),  # the same bits written signed
    (1, -128, 0x80),
    (1, 255, 0xFF),
    (4, -1, 0xFFFF_FFFF),
    (4, 2**32 - 1, 0xFFFF_FFFF),
    (2, 0x1_0001, 0x0001),  # beyond the width: wrapped (check reports it)
])
def test_constants_wrap_to_the_width(ctx: FunctionContext, box, width: int, constant: int,
                                     bits: int) -> None:
    ctx.memory.write(at("R0"), 0xFFFF_FFFF, 4)
    box("LOGAND", width, "R0", constant, "R10")(1)
    assert ctx.memory.read(at("R10"), width) == bits


@pytest.mark.parametrize("width", [1, 2, 4])
def test_not_inverts_every_bit(ctx: FunctionContext, box, width: int) -> None:
    ctx.memory.write(at("R0"), 0x1234_5678, 4)
    box("NOT", width, "R0", "R10")(1)
    assert ctx.memory.read(at("R10"), 4) == ~0x1234_5678 & ((1 << 8 * width) - 1)


def test_output_may_be_the_input(ctx: FunctionContext, box) -> None:
    ctx.memory.write(at("R5"), 0b1010_0000)
    box("NOT", 1, "R5", "R5")(1)
    assert ctx.memory.read(at("R5")) == 0b0101_1111
    box("EOR", 1001, "R5", "R5", "R5")(1)
    assert ctx.memory.read(at("R5")) == 0


@pytest.mark.parametrize(("name", "params"), [
    ("LOGAND", (2, "R0", 0, "R10")), ("LOGOR", (1002, "R0", "R2", "R10")),
    ("EOR", (4, "R0", -1, "R10")), ("NOT", (2, "R0", "R10")),
])
def test_act_0_writes_nothing_and_r9000_is_untouched(ctx: FunctionContext, box, name: str,
                                                     params: tuple) -> None:
    ctx.memory.write(at("R0"), 0xFFFF, 2)
    ctx.memory.write(at("R10"), 0x1234, 2)
    ctx.set_result_register(0x21, 1)
    call = box(name, *params)
    assert call(0) is False
    assert ctx.memory.read(at("R10"), 2) == 0x1234
    assert call(1) is False  # no W1
    assert ctx.memory.read(at("R10"), 2) != 0x1234
    assert ctx.memory.read(at("R9000")) == 0x21


@pytest.mark.parametrize(("name", "params"), [
    ("LOGAND", (3, "R0", 0, "R10")), ("LOGOR", (1003, "R0", "R2", "R10")),
    ("NOT", (1001, "R0", "R10")), ("NOT", (8, "R0", "R10")),
])
def test_other_formats_do_nothing(ctx: FunctionContext, box, name: str, params: tuple) -> None:
    ctx.memory.write(at("R10"), 0x77, 1)
    box(name, *params)(1)
    assert ctx.memory.read(at("R10")) == 0x77


def test_operands_past_the_area_do_nothing(ctx: FunctionContext, box) -> None:
    size = len(ctx.memory.areas[Area.R])
    box("LOGOR", 4, f"R{size - 2}", 0xFF, "R10")(1)
    box("LOGOR", 1004, "R0", f"R{size - 1}", "R10")(1)
    box("NOT", 2, "R0", f"R{size - 1}")(1)
    assert ctx.memory.read(at("R10"), 4) == 0
    assert len(ctx.memory.areas[Area.R]) == size


PROGRAM = """
RD R0.0
SUB 60
2
R20
65295
R30
RD R0.0
LOGOR 1001 R20 R22 R32
RD R0.0
SUB 59
1001
R20
R22
R33
RD R0.0
SUB 62
1
R20
R34
"""


def test_engine_runs_both_forms(monitored: bool) -> None:
    engine = run_engine(PROGRAM, monitored)
    engine.memory.write(at("R20"), 0xA5F0, 2)
    engine.memory.write(at("R22"), 0x0F, 1)
    engine.scan()
    assert engine.memory.read(at("R30"), 5) == 0
    set_bit(engine, "R0.0", 1)
    engine.scan()
    assert engine.memory.read(at("R30"), 2) == 0xA500
    assert engine.memory.read(at("R32")) == 0xFF
    assert engine.memory.read(at("R33")) == 0xFF
    assert engine.memory.read(at("R34")) == 0x0F
