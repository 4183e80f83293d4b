"""MOVE, MOVOR, XMOV, XMOVB: masks, OR, indexed read/write, table bounds, RST, ACT off."""

from __future__ import annotations

from ladderworks.core.plc.functions import FunctionContext
from tests.core.functions.conftest import at


def test_move_masks_the_byte(ctx: FunctionContext, box) -> None:
    move = box("MOVE", 0b1111, 0b0000, "X35", "R20")
    ctx.memory.write(at("X35"), 0xA7)
    ctx.memory.write(at("R20"), 0x0F)
    move(0)
    assert ctx.memory.read(at("R20")) == 0x0F  # ACT = 0: nothing
    move(1)
    assert ctx.memory.read(at("R20")) == 0xA0  # whole byte written: in AND 1111 0000


def test_move_low_mask(ctx: FunctionContext, box) -> None:
    move = box("MOVE", 0b0000, 0b0101, "X35", "R20")
    ctx.memory.write(at("X35"), 0xFF)
    move(1)
    assert ctx.memory.read(at("R20")) == 0x05


def test_movor(ctx: FunctionContext, box) -> None:
    movor = box("MOVOR", "R0", "R1", "R2")
    ctx.memory.write(at("R0"), 0b1100_0000)
    ctx.memory.write(at("R1"), 0b0000_0011)
    movor(0)
    assert ctx.memory.read(at("R2")) == 0
    movor(1)
    assert ctx.memory.read(at("R2")) == 0b1100_0011


def test_xmov_read_and_write(ctx: FunctionContext, box) -> None:
    xmov = box("XMOV", 5, "D100", "R10", "R12")
    for row in range(5):
        ctx.memory.write_bcd(at("D100").offset(2 * row), 1000 + row, 2)
    ctx.memory.write_bcd(at("R12"), 3, 2)
    assert xmov(1, 0, 0, 1) is False  # read
    assert ctx.memory.read_bcd(at("R10"), 2) == 1003
    ctx.memory.write_bcd(at("R10"), 4321, 2)
    ctx.memory.write_bcd(at("R12"), 4, 2)
    assert xmov(1, 1, 0, 1) is False  # write
    assert ctx.memory.read_bcd(at("D108"), 2) == 4321


def test_xmov_bounds_latch_and_reset(ctx: FunctionContext, box) -> None:
    xmov = box("XMOV", 5, "D100", "R10", "R12")
    ctx.memory.write_bcd(at("R12"), 5, 2)
    assert xmov(1, 1, 0, 1) is True
    assert ctx.memory.read(at("D110"), 2) == 0  # nothing written past the table
    assert xmov(1, 1, 0, 0) is True
    assert xmov(1, 1, 1, 0) is False
    ctx.memory.write(at("R12"), 0xAA, 2)  # invalid BCD index
    assert xmov(1, 0, 0, 1) is True


def test_xmov_one_byte_entries(ctx: FunctionContext, box) -> None:
    xmov = box("XMOV", 3, "D0", "R10", "R12")
    ctx.memory.write(at("D2"), 0x42)
    ctx.memory.write_bcd(at("R12"), 2, 1)
    assert xmov(0, 0, 0, 1) is False
    assert ctx.memory.read(at("R10")) == 0x42


def test_xmovb_binary_index_and_area_end(ctx: FunctionContext, box) -> None:
    xmovb = box("XMOVB", 4, 10, "D9980", "R10", "R20")
    ctx.memory.write(at("R10"), -7, 4)
    ctx.memory.write(at("R20"), 2, 4)
    assert xmovb(1, 0, 1) is False
    assert ctx.memory.read(at("D9988"), 4, signed=True) == -7
    ctx.memory.write(at("R20"), 5, 4)  # D9980 + 20 is past D9999
    assert xmovb(1, 0, 1) is True
    ctx.memory.write(at("R20"), -1, 4)
    assert xmovb(0, 0, 1) is True
    assert len(ctx.memory.areas[at("D0").area]) == 10000
