"""The CNC-side instructions without a CNC (FANUC-PMC.md §6 "CNC stub"): AXCTL, WINDR, WINDW,
EXIN, DISPB, and impl_for's stub for a `SUB n` the table does not know (W1 = ACT)."""

from __future__ import annotations

import pytest

from ladderworks.core import instructions as it
from ladderworks.core.address import Area
from ladderworks.core.plc.functions import REGISTRY, FunctionContext, impl_for
from tests.core.functions.conftest import at, run_engine
from tests.core.plc.conftest import bit, set_bit


def test_axctl_w1_is_act_and_not_rst(ctx: FunctionContext, box) -> None:
    axctl = box("AXCTL", 1, "R6076")
    ctx.memory.write(at("R6076"), 0x0102030405060708, 8)
    assert [axctl(rst, act) for rst, act in [(0, 0), (0, 1), (1, 1), (1, 0)]] == [
        False, True, False, False]
    assert ctx.memory.read(at("R6076"), 8) == 0x0102030405060708  # the block is not touched


@pytest.mark.parametrize("name", ["WINDR", "WINDW"])
def test_window_writes_completion_code_0_only(ctx: FunctionContext, box, name: str) -> None:
    window = box(name, "D100")
    block = bytes(range(17, 17 + 14))
    ctx.memory.areas[Area.D][100:114] = block
    assert window(0) is False
    assert ctx.memory.areas[Area.D][100:114] == block  # ACT = 0: nothing
    assert window(1) is True
    assert ctx.memory.areas[Area.D][100:114] == block[:2] + b"\0\0" + block[4:]


def test_window_block_at_the_end_of_the_area_grows_nothing(ctx: FunctionContext, box) -> None:
    size = len(ctx.memory.areas[Area.R])
    assert box("WINDR", f"R{size - 3}")(1) is True
    assert len(ctx.memory.areas[Area.R]) == size


def test_exin_w1_is_act(ctx: FunctionContext, box) -> None:
    exin = box("EXIN", "R5472")
    ctx.memory.write(at("R5472"), 0xDEADBEEF, 4)
    assert (exin(0), exin(1)) == (False, True)
    assert ctx.memory.read(at("R5472"), 4) == 0xDEADBEEF


def test_dispb_has_no_w1_and_writes_nothing(ctx: FunctionContext, box) -> None:
    before = ctx.memory.snapshot()
    assert box("DISPB", 2)(1) is False
    assert ctx.memory.snapshot() == before


def test_unknown_sub_w1_is_act_and_nothing_else(ctx: FunctionContext) -> None:
    spec = it.unknown_sub(300, 2)
    impl = impl_for(spec)
    assert impl is not REGISTRY.get(spec.name)
    before = ctx.memory.snapshot()
    params = (5, at("R3"))
    assert impl(ctx, {}, (True,), params) is True
    assert impl(ctx, {}, (False,), params) is False
    assert ctx.memory.snapshot() == before


def test_impl_for_known_rows() -> None:
    for spec in it.FUNCTIONS:
        if spec.flow is it.Flow.NONE:
            assert impl_for(spec) is REGISTRY[spec.name]
    with pytest.raises(KeyError):
        impl_for(it.BY_NAME["CALL"])


PROGRAM = """
RD R0.1
RD.STK R0.0
AXCTL 1 R6076
WRT R1.0
RD R0.0
WINDR R10
WRT R1.1
RD R0.0
SUB 52
R30
WRT R1.2
RD R0.0
EXIN R50
WRT R1.3
RD R0.0
DISPB 2
"""


def test_engine_stubs_complete_in_the_scan_that_asks(monitored: bool) -> None:
    engine = run_engine(PROGRAM, monitored)
    engine.memory.write(at("R12"), 0xFFFF, 2)
    engine.memory.write(at("R32"), 0xFFFF, 2)
    engine.scan()
    assert [bit(engine, f"R1.{k}") for k in range(4)] == [0, 0, 0, 0]
    set_bit(engine, "R0.0", 1)
    engine.scan()
    assert [bit(engine, f"R1.{k}") for k in range(4)] == [1, 1, 1, 1]
    assert engine.memory.read(at("R12"), 2) == engine.memory.read(at("R32"), 2) == 0
    set_bit(engine, "R0.1", 1)  # AXCTL RST
    engine.scan()
    assert [bit(engine, f"R1.{k}") for k in range(4)] == [0, 1, 1, 1]
