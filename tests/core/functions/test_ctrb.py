"""CTRB (FANUC-PMC.md §6): CTR with the preset in the program, the value at C5000 + 2(n-1);
counts on ACT's rising edge, CN0, UPDOWN, RST, wrap; fast and monitored mode."""

from __future__ import annotations

from ladderworks.core.address import Address, Area
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.functions import FunctionContext
from ladderworks.core.plc.functions.counters import ctrb_value_address
from tests.core.functions.conftest import fanuc_memory, run_engine
from tests.core.plc.conftest import bit, set_bit

# CN0 = R0.0, UPDOWN = R0.1, RST = R0.2, ACT = R0.3; W1 -> R1.0
PROGRAM = """
RD R0.0
RD.STK R0.1
RD.STK R0.2
RD.STK R0.3
CTRB 2 3
WRT R1.0
"""


def counter(monitored: bool, *, cn0: int = 0, down: int = 0) -> ScanEngine:
    engine = run_engine(PROGRAM, monitored, "fanuc", fanuc_memory())
    set_bit(engine, "R0.0", cn0)
    set_bit(engine, "R0.1", down)
    return engine


def value(engine: ScanEngine) -> int:
    return engine.memory.read(ctrb_value_address(2), 2)


def pulses(engine: ScanEngine, times: int) -> list[tuple[int, int]]:
    """ACT on for a scan, off for a scan: (value, W1) after each count."""
    seen = []
    for _ in range(times):
        set_bit(engine, "R0.3", 1)
        engine.scan()
        seen.append((value(engine), bit(engine, "R1.0")))
        set_bit(engine, "R0.3", 0)
        engine.scan()
    return seen


def test_value_address() -> None:
    assert ctrb_value_address(1) == Address(Area.C, 5000)
    assert ctrb_value_address(100) == Address(Area.C, 5198)


def test_counts_up_to_the_preset_then_wraps(monitored: bool) -> None:
    engine = counter(monitored)
    assert pulses(engine, 5) == [(1, 0), (2, 0), (3, 1), (0, 0), (1, 0)]


def test_counts_only_on_rising_edges(monitored: bool) -> None:
    engine = counter(monitored)
    set_bit(engine, "R0.3", 1)
    engine.run_scans(4)
    assert value(engine) == 1


def test_cn0_1_counts_from_1(monitored: bool) -> None:
    engine = counter(monitored, cn0=1)
    assert pulses(engine, 4) == [(1, 0), (2, 0), (3, 1), (1, 0)]  # wraps to 1, not 0


def test_down_counts_to_the_minimum_then_wraps_to_the_preset(monitored: bool) -> None:
    engine = counter(monitored, down=1)
    engine.memory.write(ctrb_value_address(2), 3, 2)
    assert pulses(engine, 4) == [(2, 0), (1, 0), (0, 1), (3, 0)]


def test_rst_gives_w1_0_and_the_start_value(monitored: bool) -> None:
    engine = counter(monitored)
    pulses(engine, 3)
    assert bit(engine, "R1.0") == 1
    set_bit(engine, "R0.2", 1)
    set_bit(engine, "R0.3", 1)
    engine.scan()
    assert (value(engine), bit(engine, "R1.0")) == (0, 0)
    set_bit(engine, "R0.1", 1)  # down: the start is the preset
    engine.scan()
    assert value(engine) == 3


def test_ctr_and_ctrb_of_the_same_number_are_separate(monitored: bool) -> None:
    engine = run_engine(PROGRAM + "RD R0.0\nRD.STK R0.1\nRD.STK R0.2\nRD.STK R0.3\nCTR 2\n"
                        "WRT R1.1", monitored, "fanuc", fanuc_memory())
    engine.memory.write(Address(Area.C, 4), 10, 2)  # CTR 2's preset
    pulses(engine, 2)
    assert value(engine) == 2
    assert engine.memory.read(Address(Area.C, 6), 2) == 2  # CTR 2's own value


def test_the_30i_c_area_holds_the_values_at_c5000(ctx: FunctionContext, box) -> None:
    ctrb = box("CTRB", 1, 2)
    assert len(ctx.memory.areas[Area.C]) >= 5200  # the 30i map: C0..C399 and C5000..C5199
    values = []
    for _ in range(3):
        ctrb(0, 0, 0, 1)
        ctrb(0, 0, 0, 0)
        values.append(ctx.memory.read(Address(Area.C, 5000), 2))
    assert values == [1, 2, 0]  # CN0 = 0: the ring goes back to 0 after the preset
