"""PARI: even and odd parity checks, RST, ACT off."""

from __future__ import annotations

import pytest

from ladderworks.core.plc.functions import FunctionContext
from tests.core.functions.conftest import at


@pytest.mark.parametrize("value", range(256))
def test_even_and_odd_check_every_byte(ctx: FunctionContext, box, value: int) -> None:
    ctx.memory.write(at("X10"), value)
    ones = bin(value).count("1")
    assert box("PARI", "X10")(0, 0, 1) is (ones % 2 == 1)  # even check: odd count is an error
    assert box("PARI", "X10")(1, 0, 1) is (ones % 2 == 0)  # odd check: even count is an error


def test_error_held_until_rst(ctx: FunctionContext, box) -> None:
    pari = box("PARI", "X10")
    ctx.memory.write(at("X10"), 0b0000_0001)
    assert pari(0, 0, 1) is True
    ctx.memory.write(at("X10"), 0b0000_0011)
    assert pari(0, 0, 0) is True
    assert pari(0, 1, 0) is False
    assert pari(0, 0, 1) is False
