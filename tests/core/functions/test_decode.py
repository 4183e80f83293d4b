"""DEC and DECB: BCD decode by digit spec, binary decode to 8 result bits."""

from __future__ import annotations

import pytest

from ladderworks.core.plc.functions import FunctionContext
from ladderworks.core.plc.functions.decode import decode_matches
from tests.core.functions.conftest import at


@pytest.mark.parametrize(("raw", "spec", "want"), [
    (0x03, 311, True),     # M03, both digits
    (0x13, 311, False),
    (0x13, 301, True),     # low digit only: 3
    (0x23, 301, True),
    (0x24, 301, False),
    (0x35, 3010, True),    # high digit only: 3x
    (0x45, 3010, False),
    (0x3A, 3010, True),    # a bad low digit does not matter when only the high is decoded
    (0x3A, 3011, False),   # ... but it does when both are
    (0x0A, 1001, False),   # invalid BCD digit never matches
    (0x03, 300, False),    # digit spec 00 decodes nothing
])
def test_decode_spec(raw: int, spec: int, want: bool) -> None:
    assert decode_matches(raw, spec) is want


def test_dec_act_and_match(ctx: FunctionContext, box) -> None:
    dec = box("DEC", "F10", 611)
    ctx.memory.write(at("F10"), 0x06)
    assert dec(1) is True
    assert dec(0) is False  # ACT = 0 turns W1 off
    ctx.memory.write(at("F10"), 0x07)
    assert dec(1) is False


def test_decb_sets_one_bit(ctx: FunctionContext, box) -> None:
    decb = box("DECB", 2, "F10", 8, "R300")
    for code in range(0, 20):
        ctx.memory.write(at("F10"), code, 2)
        decb(1)
        want = 1 << (code - 8) if 8 <= code < 16 else 0
        assert ctx.memory.read(at("R300")) == want, code


def test_decb_four_bytes_and_act_off(ctx: FunctionContext, box) -> None:
    decb = box("DECB", 4, "D0", 100000, "R300")
    ctx.memory.write(at("D0"), 100003, 4)
    decb(1)
    assert ctx.memory.read(at("R300")) == 0b1000
    decb(0)
    assert ctx.memory.read(at("R300")) == 0  # ACT = 0 clears all 8 bits


def test_decb_one_byte_ignores_next_byte(ctx: FunctionContext, box) -> None:
    decb = box("DECB", 1, "D0", 0, "R300")
    ctx.memory.write(at("D0"), 0x0102, 2)  # low byte 2, next byte 1
    decb(1)
    assert ctx.memory.read(at("R300")) == 0b100
