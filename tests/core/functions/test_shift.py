"""SFT: one shift per rising edge of ACT, both directions, CONT, W1 = bit out, RST."""

from __future__ import annotations

from ladderworks.core.plc.functions import FunctionContext
from ladderworks.core.plc.functions.shift import shift_word
from tests.core.functions.conftest import at


def test_shift_word() -> None:
    assert shift_word(0b0100, right=False, keep=False) == (0b1000, False)
    assert shift_word(0b0100, right=True, keep=False) == (0b0010, False)
    assert shift_word(0b0100, right=False, keep=True) == (0b1100, False)
    assert shift_word(0b0100, right=True, keep=True) == (0b0110, False)
    assert shift_word(0x8000, right=False, keep=False) == (0, True)
    assert shift_word(0x0001, right=True, keep=False) == (0, True)


def test_one_shift_per_rising_edge(ctx: FunctionContext, box) -> None:
    sft = box("SFT", "R100")
    ctx.memory.write(at("R100"), 1, 2)
    for _ in range(5):
        sft(0, 0, 0, 1)  # ACT held: one shift only
    assert ctx.memory.read(at("R100"), 2) == 0b10
    sft(0, 0, 0, 0)
    sft(0, 0, 0, 1)
    assert ctx.memory.read(at("R100"), 2) == 0b100


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
    sft(0, 1, 0, 1)  # ACT still 1: no new edge
    assert ctx.memory.read(at("R100"), 2) == 0x8001
