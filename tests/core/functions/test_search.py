"""DSCH and DSCHB: first match, not found, table bounds, RST, ACT off."""

from __future__ import annotations

from ladderworks.core.plc.functions import FunctionContext
from tests.core.functions.conftest import at


def _fill_bcd(ctx: FunctionContext, head: str, values: list[int], width: int) -> None:
    for row, value in enumerate(values):
        ctx.memory.write_bcd(at(head).offset(row * width), value, width)


def test_dsch_finds_first_match(ctx: FunctionContext, box) -> None:
    _fill_bcd(ctx, "D100", [12, 34, 56, 34], 2)
    dsch = box("DSCH", 4, "D100", "R10", "R12")
    ctx.memory.write_bcd(at("R10"), 34, 2)
    assert dsch(1, 0, 1) is False
    assert ctx.memory.read_bcd(at("R12"), 2) == 1
    ctx.memory.write_bcd(at("R10"), 56, 2)
    assert dsch(1, 0, 1) is False
    assert ctx.memory.read_bcd(at("R12"), 2) == 2


def test_dsch_not_found_latches(ctx: FunctionContext, box) -> None:
    _fill_bcd(ctx, "D100", [12, 34, 56, 78], 1)
    dsch = box("DSCH", 3, "D100", "R10", "R12")  # 78 is past the 3 entries
    ctx.memory.write_bcd(at("R12"), 9, 1)
    ctx.memory.write_bcd(at("R10"), 78, 1)
    assert dsch(0, 0, 1) is True
    assert ctx.memory.read_bcd(at("R12"), 1) == 9  # result kept
    assert dsch(0, 0, 0) is True
    assert dsch(0, 1, 0) is False
    ctx.memory.write(at("R10"), 0xAB)  # invalid BCD search data
    assert dsch(0, 0, 1) is True


def test_dsch_table_past_area_end(ctx: FunctionContext, box) -> None:
    ctx.memory.write_bcd(at("D9998"), 77, 2)
    ctx.memory.write_bcd(at("R10"), 77, 2)
    dsch = box("DSCH", 50, "D9990", "R10", "R12")
    assert dsch(1, 0, 1) is False
    assert ctx.memory.read_bcd(at("R12"), 2) == 4
    ctx.memory.write_bcd(at("R10"), 1, 2)
    assert dsch(1, 0, 1) is True


def test_dschb_size_from_memory(ctx: FunctionContext, box) -> None:
    for row, value in enumerate([-5, 100000, 7, 100000]):
        ctx.memory.write(at("D0").offset(4 * row), value, 4)
    ctx.memory.write(at("R0"), 4, 4)
    ctx.memory.write(at("R4"), 100000, 4)
    dschb = box("DSCHB", 4, "R0", "D0", "R4", "R8")
    assert dschb(0, 1) is False
    assert ctx.memory.read(at("R8"), 4) == 1
    ctx.memory.write(at("R4"), -5, 4)
    assert dschb(0, 1) is False
    assert ctx.memory.read(at("R8"), 4) == 0
    ctx.memory.write(at("R0"), 0, 4)  # empty table
    assert dschb(0, 1) is True
    ctx.memory.write(at("R0"), -3, 4)
    assert dschb(0, 1) is True
    assert dschb(1, 1) is False
