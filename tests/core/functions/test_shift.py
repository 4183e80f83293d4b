"""SFT: one shift in every scan with ACT = 1 (issue #17), both directions, CONT, W1 = bit out,
RST; in fast and monitored mode through the engine too."""

from __future__ import annotations

import pytest

from ladderworks.core.plc.functions import FunctionContext
from ladderworks.core.plc.functions.shift import shift_word
from tests.core.functions.conftest import at
from tests.core.plc.conftest import bit, engine_for, set_bit


def test_shift_word() -> None:
    assert shift_word(0b0100, right=False, keep=False) == (0b1000, False)
    assert shift_word(0b0100, right=True, keep=False) == (0b0010, False)
    assert shift_word(0b0100, right=False, keep=True) == (0b1100, False)
    assert shift_word(0b0100, right=True, keep=True) == (0b0110, False)
    assert shift_word(0x8000, right=False, keep=False) == (0, True)
    assert shift_word(0x0001, right=True, keep=False) == (0, True)


def test_shifts_every_scan_while_act_is_1(ctx: FunctionContext, box) -> None:
    sft = box("SFT", "R100")
    ctx.memory.write(at("R100"), 1, 2)
    for _ in range(5):
        sft(0, 0, 0, 1)  # ACT held: a shift in each scan
    assert ctx.memory.read(at("R100"), 2) == 0b100000
    sft(0, 0, 0, 0)  # ACT = 0: no shift
    assert ctx.memory.read(at("R100"), 2) == 0b100000
    sft(0, 0, 0, 1)
    assert ctx.memory.read(at("R100"), 2) == 0b1000000


def test_walks_sixteen_bits_and_w1_is_the_bit_out(ctx: FunctionContext, box) -> None:
    sft = box("SFT", "R100")
    ctx.memory.write(at("R100"), 1, 2)
    outs = []
    for _ in range(16):
        outs.append(sft(0, 0, 0, 1))
        sft(0, 0, 0, 0)
    assert outs == [False] * 15 + [True]
    assert ctx.memory.read(at("R100"), 2) == 0
    assert sft(0, 0, 0, 0) is True  # W1 held between shifts
    assert sft(0, 0, 1, 0) is False  # RST: W1 = 0
    assert sft(0, 0, 0, 0) is False


def test_right_shift_crosses_the_byte(ctx: FunctionContext, box) -> None:
    sft = box("SFT", "R100")
    ctx.memory.write(at("R100"), 0x0100, 2)
    sft(1, 0, 0, 1)
    assert ctx.memory.read(at("R100")) == 0x80
    assert ctx.memory.read(at("R101")) == 0


def test_rst_does_not_shift_or_clear_data(ctx: FunctionContext, box) -> None:
    sft = box("SFT", "R100")
    ctx.memory.write(at("R100"), 0x8001, 2)
    assert sft(0, 1, 1, 1) is False
    assert ctx.memory.read(at("R100"), 2) == 0x8001
    assert sft(0, 1, 0, 1) is True  # RST back to 0, ACT 1: shifts (CONT keeps the 1s)
    assert ctx.memory.read(at("R100"), 2) == 0x8003


SFT_PROGRAM = """
RD R0.0
RD.STK R0.1
RD.STK R0.2
RD.STK R0.3
SFT R100
WRT R1.0
"""


@pytest.mark.parametrize("monitored", [False, True])
def test_engine_shifts_each_scan_and_a_one_scan_act_shifts_once(monitored: bool) -> None:
    engine = engine_for(SFT_PROGRAM)
    engine.monitored = monitored
    engine.memory.write(at("R100"), 1, 2)
    set_bit(engine, "R0.3", 1)
    engine.run_scans(3)
    assert engine.memory.read(at("R100"), 2) == 0b1000
    set_bit(engine, "R0.3", 0)  # the seed's way to shift only one: ACT = 1, then at once 0
    engine.run_scans(2)
    set_bit(engine, "R0.3", 1)
    engine.scan()
    set_bit(engine, "R0.3", 0)
    engine.run_scans(2)
    assert engine.memory.read(at("R100"), 2) == 0b10000
    engine.memory.write(at("R100"), 0x4000, 2)
    set_bit(engine, "R0.3", 1)
    engine.run_scans(2)  # bit 14 -> 15 -> out
    assert (engine.memory.read(at("R100"), 2), bit(engine, "R1.0")) == (0, 1)
