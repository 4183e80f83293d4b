"""RNGB/RNGW/RNGD (FANUC-PMC.md §6, SUB 218/219/220): limits in either order, signed data,
constants, ACT = 0 -> W1 = 0, R9000 untouched; fast and monitored mode."""

from __future__ import annotations

import pytest

from ladderworks.core.address import Area
from ladderworks.core.plc.functions import FunctionContext
from tests.core.functions.conftest import at, run_engine
from tests.core.plc.conftest import bit, set_bit


@pytest.mark.parametrize(("name", "width"), [("RNGB", 1), ("RNGW", 2), ("RNGD", 4)])
@pytest.mark.parametrize(("low", "high"), [(-5, 70), (70, -5)])
def test_limits_in_either_order(ctx: FunctionContext, box, name: str, width: int, low: int,
                                high: int) -> None:
    rng = box(name, "R0", "R4", "R8")
    ctx.memory.write(at("R0"), low, width)
    ctx.memory.write(at("R4"), high, width)
    for data, inside in [(-6, False), (-5, True), (0, True), (70, True), (71, False)]:
        ctx.memory.write(at("R8"), data, width)
        assert rng(1) is inside, data


@pytest.mark.parametrize(("name", "width", "low", "high"), [
    ("RNGB", 1, -128, 127), ("RNGW", 2, -32768, 32767), ("RNGD", 4, -2**31, 2**31 - 1)])
def test_data_is_signed(ctx: FunctionContext, box, name: str, width: int, low: int,
                        high: int) -> None:
    rng = box(name, "R0", "R4", "R8")
    ctx.memory.write(at("R0"), -1, width)
    ctx.memory.write(at("R4"), 1, width)
    ctx.memory.write(at("R8"), high, width)
    assert rng(1) is False  # all ones read unsigned would lie between 1 and 2^(8w) - 1
    ctx.memory.write(at("R8"), -1, width)
    assert rng(1) is True
    ctx.memory.write(at("R0"), low, width)
    ctx.memory.write(at("R4"), high, width)
    ctx.memory.write(at("R8"), low, width)
    assert rng(1) is True


def test_constants_in_any_operand(ctx: FunctionContext, box) -> None:
    ctx.memory.write(at("R8"), 80, 2)
    assert box("RNGW", 99, 70, "R8")(1) is True
    assert box("RNGW", 70, 79, "R8")(1) is False
    assert box("RNGW", 70, 99, 85)(1) is True
    assert box("RNGW", 65535, 1, 0)(1) is True  # 65535 in 2 bytes is -1


def test_act_0_gives_0_and_r9000_is_untouched(ctx: FunctionContext, box) -> None:
    ctx.set_result_register(0x23, 1)
    rng = box("RNGW", 0, 10, 5)
    assert rng(0) is False
    assert rng(1) is True
    assert ctx.memory.read(at("R9000")) == 0x23


def test_operand_past_the_area_gives_0(ctx: FunctionContext, box) -> None:
    size = len(ctx.memory.areas[Area.R])
    assert box("RNGD", -10, 10, f"R{size - 2}")(1) is False


PROGRAM = """
RD R0.0
SUB 219
R6056
R6058
R14
WRT R6256.6
RD R0.0
SUB 220
R100
R96
R104
WRT R6256.7
RD R0.0
RNGB -1 1 R108
WRT R6257.0
"""


def test_engine_fanuc_form(monitored: bool) -> None:
    engine = run_engine(PROGRAM, monitored)
    engine.memory.write(at("R6056"), 70, 2)  # X22 13922: NUMEB 2 70 R6056, NUMEB 2 99 R6058
    engine.memory.write(at("R6058"), 99, 2)
    engine.memory.write(at("R14"), 99, 2)
    engine.memory.write(at("R96"), -100_000, 4)
    engine.memory.write(at("R100"), 100_000, 4)
    engine.memory.write(at("R104"), -99_999, 4)
    engine.memory.write(at("R108"), 0xFF)
    engine.scan()
    assert [bit(engine, b) for b in ("R6256.6", "R6256.7", "R6257.0")] == [0, 0, 0]
    set_bit(engine, "R0.0", 1)
    engine.scan()
    assert [bit(engine, b) for b in ("R6256.6", "R6256.7", "R6257.0")] == [1, 1, 1]
    engine.memory.write(at("R14"), 100, 2)
    engine.scan()
    assert bit(engine, "R6256.6") == 0
