"""Ring counters CTR and CTRC (SEMANTICS.md): edges, up/down, CN0, reset, wrap."""

from __future__ import annotations

from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.functions.counters import (
    counter_preset_address,
    counter_value_address,
    write_counter_preset,
)
from tests.core.plc.conftest import at, bit, engine_for

# Inputs: CN0 = R0.0, UPDOWN = R0.1, RST = R0.2, ACT = R0.3; W1 -> R1.0.
CTR = """
RD R0.0
RD.STK R0.1
RD.STK R0.2
RD.STK R0.3
CTR 3
WRT R1.0
"""
CTRC = """
RD R0.0
RD.STK R0.1
RD.STK R0.2
RD.STK R0.3
CTRC D0 D4
WRT R1.0
"""


def counter(preset: int, *, cn0: int = 0, down: int = 0) -> ScanEngine:
    engine = engine_for(CTR)
    write_counter_preset(engine.memory, 3, preset)
    engine.memory.set_bit(at("R0.0"), cn0)
    engine.memory.set_bit(at("R0.1"), down)
    return engine


def value(engine: ScanEngine) -> int:
    return engine.memory.read(counter_value_address(3), 2)


def pulse(engine: ScanEngine, times: int = 1) -> list[tuple[int, int]]:
    """ACT on for a scan and off for a scan, `times` times: (value, W1) after each count."""
    seen = []
    for _ in range(times):
        engine.memory.set_bit(at("R0.3"), 1)
        engine.scan()
        seen.append((value(engine), bit(engine, "R1.0")))
        engine.memory.set_bit(at("R0.3"), 0)
        engine.scan()
    return seen


def test_counter_area_layout() -> None:
    assert counter_preset_address(1) == at("C0")
    assert counter_value_address(1) == at("C2")
    assert counter_preset_address(20) == at("C76")
    assert counter_value_address(20) == at("C78")


def test_up_counter_counts_on_rising_edges_only() -> None:
    engine = counter(5)
    engine.memory.set_bit(at("R0.3"), 1)
    engine.run_scans(10)  # ACT held on: one count
    assert value(engine) == 1
    engine.memory.set_bit(at("R0.3"), 0)
    engine.run_scans(3)
    assert value(engine) == 1


def test_up_counter_from_0_reaches_preset_then_wraps_to_0() -> None:
    engine = counter(3)
    assert pulse(engine, 5) == [(1, 0), (2, 0), (3, 1), (0, 0), (1, 0)]


def test_up_counter_w1_stays_on_at_the_preset_between_counts() -> None:
    engine = counter(2)
    pulse(engine, 2)
    engine.run_scans(5)
    assert bit(engine, "R1.0") == 1


def test_up_counter_with_cn0_counts_from_1() -> None:
    engine = counter(3, cn0=1)
    assert pulse(engine, 4) == [(1, 0), (2, 0), (3, 1), (1, 0)]


def test_down_counter_counts_from_preset_to_0_then_wraps() -> None:
    engine = counter(3, down=1)
    engine.memory.set_bit(at("R0.2"), 1)  # reset: value to the preset
    engine.scan()
    assert value(engine) == 3
    engine.memory.set_bit(at("R0.2"), 0)
    assert pulse(engine, 5) == [(2, 0), (1, 0), (0, 1), (3, 0), (2, 0)]


def test_down_counter_with_cn0_stops_at_1_then_wraps() -> None:
    engine = counter(3, cn0=1, down=1)
    engine.memory.set_bit(at("R0.2"), 1)
    engine.scan()
    engine.memory.set_bit(at("R0.2"), 0)
    assert pulse(engine, 4) == [(2, 0), (1, 1), (3, 0), (2, 0)]


def test_reset_clears_w1_and_blocks_counting() -> None:
    engine = counter(2)
    pulse(engine, 2)
    assert bit(engine, "R1.0") == 1
    engine.memory.set_bit(at("R0.2"), 1)
    pulse(engine, 3)  # counts are ignored while RST = 1
    assert (value(engine), bit(engine, "R1.0")) == (0, 0)
    engine.memory.set_bit(at("R0.2"), 0)
    assert pulse(engine, 1) == [(1, 0)]


def test_reset_with_cn0_goes_to_1() -> None:
    engine = counter(4, cn0=1)
    pulse(engine, 3)
    engine.memory.set_bit(at("R0.2"), 1)
    engine.scan()
    assert value(engine) == 1


def test_act_held_through_reset_does_not_count_when_reset_drops() -> None:
    engine = counter(5)
    engine.memory.set_bit(at("R0.2"), 1)
    engine.memory.set_bit(at("R0.3"), 1)
    engine.scan()
    engine.memory.set_bit(at("R0.2"), 0)
    engine.run_scans(3)  # ACT has stayed 1: no new rising edge
    assert value(engine) == 0


def test_counter_preset_changed_below_the_value_wraps_on_the_next_count() -> None:
    engine = counter(10)
    pulse(engine, 6)
    write_counter_preset(engine.memory, 3, 4)
    engine.scan()
    assert bit(engine, "R1.0") == 1
    assert pulse(engine, 1) == [(0, 0)]


def test_ctrc_counts_with_preset_and_register_at_addresses() -> None:
    engine = engine_for(CTRC)
    engine.memory.write(at("D0"), 2, 2)
    engine.memory.write(at("D6"), 0xBEEF, 2)  # the register's last two bytes are left alone
    seen = []
    for _ in range(4):
        engine.memory.set_bit(at("R0.3"), 1)
        engine.scan()
        seen.append((engine.memory.read(at("D4"), 2), bit(engine, "R1.0")))
        engine.memory.set_bit(at("R0.3"), 0)
        engine.scan()
    assert seen == [(1, 0), (2, 1), (0, 0), (1, 0)]
    assert engine.memory.read(at("D6"), 2) == 0xBEEF


def test_ctrc_down_and_reset() -> None:
    engine = engine_for(CTRC)
    engine.memory.write(at("D0"), 3, 2)
    engine.memory.set_bit(at("R0.1"), 1)
    engine.memory.set_bit(at("R0.2"), 1)
    engine.scan()
    assert engine.memory.read(at("D4"), 2) == 3
    engine.memory.set_bit(at("R0.2"), 0)
    for _ in range(3):
        engine.memory.set_bit(at("R0.3"), 1)
        engine.scan()
        engine.memory.set_bit(at("R0.3"), 0)
        engine.scan()
    assert (engine.memory.read(at("D4"), 2), bit(engine, "R1.0")) == (0, 1)


def test_ctrc_preset_is_limited_to_32767() -> None:
    engine = engine_for(CTRC)
    engine.memory.write(at("D0"), 40000, 2)
    engine.memory.write(at("D4"), 32767, 2)
    engine.scan()
    assert bit(engine, "R1.0") == 1
