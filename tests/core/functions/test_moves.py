"""MOVB/MOVW/MOVN/MOVD (FANUC-PMC.md §6): byte counts, ACT = 0, overlap as through a buffer,
operands past the area, MOVD = MOVN 4; XMOVB with its table size at an address."""

from __future__ import annotations

import pytest

from ladderworks.core.address import Area
from ladderworks.core.plc.functions import FunctionContext
from tests.core.functions.conftest import at, run_engine
from tests.core.plc.conftest import set_bit


@pytest.mark.parametrize(("name", "count"), [("MOVB", 1), ("MOVW", 2), ("MOVD", 4)])
def test_copies_its_bytes_and_no_more(ctx: FunctionContext, box, name: str, count: int) -> None:
    move = box(name, "R0", "D10")
    ctx.memory.areas[Area.R][0:6] = bytes([1, 2, 3, 4, 5, 6])
    ctx.memory.areas[Area.D][10:16] = bytes([0xEE] * 6)
    assert move(0) is False
    assert ctx.memory.areas[Area.D][10:16] == bytes([0xEE] * 6)  # ACT = 0: nothing
    assert move(1) is False
    assert ctx.memory.areas[Area.D][10:16] == bytes([1, 2, 3, 4, 5, 6][:count]
                                                    + [0xEE] * (6 - count))


def test_movd_is_movn_4(ctx: FunctionContext, box) -> None:
    ctx.memory.areas[Area.R][0:5] = bytes([9, 8, 7, 6, 5])
    box("MOVD", "R0", "D0")(1)
    box("MOVN", 4, "R0", "D10")(1)
    assert ctx.memory.areas[Area.D][0:5] == ctx.memory.areas[Area.D][10:15] == bytes(
        [9, 8, 7, 6, 0])


@pytest.mark.parametrize(("source", "target", "expected"), [
    ("R0", "R2", [1, 2, 1, 2, 3, 4, 5, 0]),  # forward overlap: the old bytes, not a smear
    ("R2", "R0", [3, 4, 5, 0, 0, 0, 0, 0]),  # backward overlap
    ("R0", "R0", [1, 2, 3, 4, 5, 0, 0, 0]),  # onto itself
])
def test_movn_overlap_copies_as_through_a_buffer(ctx: FunctionContext, box, source: str,
                                                 target: str, expected: list[int]) -> None:
    ctx.memory.areas[Area.R][0:8] = bytes([1, 2, 3, 4, 5, 0, 0, 0])
    box("MOVN", 5, source, target)(1)
    assert list(ctx.memory.areas[Area.R][0:8]) == expected


def test_operand_past_the_area_copies_nothing(ctx: FunctionContext, box) -> None:
    size = len(ctx.memory.areas[Area.D])
    ctx.memory.areas[Area.D][size - 2:] = b"\x11\x22"
    last = f"D{size - 2}"
    box("MOVN", 4, last, "R0")(1)
    assert ctx.memory.read(at("R0"), 4) == 0
    box("MOVD", "R0", last)(1)
    assert ctx.memory.areas[Area.D][size - 2:] == b"\x11\x22"
    assert len(ctx.memory.areas[Area.D]) == size


def test_movn_count_zero_copies_nothing(ctx: FunctionContext, box) -> None:
    ctx.memory.write(at("R0"), 0x55)
    box("MOVN", 0, "R0", "R1")(1)
    assert ctx.memory.read(at("R1")) == 0


PROGRAM = """
RD R0.0
SUB 43
R10
R20
RD R0.0
SUB 44
R10
R22
RD R0.0
SUB 45
3
R10
R24
RD R0.0
MOVD R10 R28
"""


def test_engine_runs_the_fanuc_form_every_scan_with_act_1(monitored: bool) -> None:
    engine = run_engine(PROGRAM, monitored)
    engine.memory.write(at("R10"), 0x04030201, 4)
    engine.scan()
    assert engine.memory.read(at("R20"), 4) == 0  # ACT = 0
    set_bit(engine, "R0.0", 1)
    engine.scan()
    assert list(engine.memory.areas[Area.R][20:32]) == [1, 0, 1, 2, 1, 2, 3, 0, 1, 2, 3, 4]
    engine.memory.write(at("R10"), 0x0A, 1)
    engine.scan()  # level: copies again in every scan
    assert engine.memory.read(at("R20")) == 0x0A


def test_xmovb_table_size_at_an_address(ctx: FunctionContext, box) -> None:
    xmovb = box("XMOVB", 2, "R50", "D200", "R36", "R40")
    ctx.memory.write(at("D204"), 777, 2)
    ctx.memory.write(at("R40"), 2, 4)  # row 2
    ctx.memory.write(at("R50"), 2, 2)  # 2 rows: row 2 is past the table
    assert xmovb(0, 0, 1) is True
    ctx.memory.write(at("R50"), 3, 2)
    assert xmovb(0, 0, 1) is False
    assert ctx.memory.read(at("R36"), 2) == 777
    ctx.memory.write(at("R50"), -1, 2)  # a negative size has no rows
    assert xmovb(0, 0, 1) is True


def test_xmovb_constant_size_still_works(ctx: FunctionContext, box) -> None:
    xmovb = box("XMOVB", 1, 3, "D200", "R36", "R40")
    ctx.memory.write(at("D202"), 9)
    ctx.memory.write(at("R40"), 2, 4)
    assert xmovb(0, 0, 1) is False
    assert ctx.memory.read(at("R36")) == 9
