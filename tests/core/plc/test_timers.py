"""Timers TMR, TMRB and TMRC on the virtual clock (SEMANTICS.md)."""

from __future__ import annotations

from ladderworks.core.plc.functions.timers import (
    effective_preset,
    read_timer_preset,
    timer_preset_address,
    timer_tick,
    write_timer_preset,
)
from tests.core.plc.conftest import at, bit, engine_for


def first_on(engine, coil: str, limit: int = 400) -> int | None:  # type: ignore[no-untyped-def]
    """ms after now at which `coil` first reads 1 (scanning), or None."""
    start = engine.now_ms
    for _ in range(limit):
        now = engine.now_ms
        engine.scan()
        if bit(engine, coil):
            return now - start
    return None


def test_timer_table_layout_is_four_bytes_of_ms_per_timer() -> None:
    assert timer_preset_address(1) == at("T0")
    assert timer_preset_address(2) == at("T4")
    assert timer_preset_address(100) == at("T396")
    engine = engine_for("RD R0.0\nTMR 2\nWRT R0.1")
    write_timer_preset(engine.memory, 2, 70_000)
    assert engine.memory.read(at("T4"), 4) == 70_000
    assert read_timer_preset(engine.memory, 2) == 70_000


def test_ticks_and_rounding() -> None:
    assert [timer_tick(n) for n in (1, 8, 9, 100)] == [48, 48, 8, 8]
    assert effective_preset(100, 48) == 96
    assert effective_preset(47, 48) == 0
    assert effective_preset(100, 8) == 96
    assert effective_preset(104, 8) == 104


def test_tmr_resets_when_act_drops_before_the_preset() -> None:
    engine = engine_for("RD R0.0\nTMR 9\nWRT R0.1")
    write_timer_preset(engine.memory, 9, 80)
    engine.memory.set_bit(at("R0.0"), 1)
    engine.step(72)  # scans at 0..64: 64 ms elapsed, not yet
    assert bit(engine, "R0.1") == 0
    engine.memory.set_bit(at("R0.0"), 0)
    engine.scan()
    assert bit(engine, "R0.1") == 0
    engine.memory.set_bit(at("R0.0"), 1)
    assert first_on(engine, "R0.1") == 80  # the full preset again, from the new start


def test_tmr_output_drops_at_once_when_act_drops() -> None:
    engine = engine_for("RD R0.0\nTMR 9\nWRT R0.1")
    write_timer_preset(engine.memory, 9, 16)
    engine.memory.set_bit(at("R0.0"), 1)
    engine.step(40)
    assert bit(engine, "R0.1") == 1
    engine.memory.set_bit(at("R0.0"), 0)
    engine.scan()
    assert bit(engine, "R0.1") == 0


def test_tmr_reads_a_changed_preset_while_running() -> None:
    engine = engine_for("RD R0.0\nTMR 10\nWRT R0.1")
    write_timer_preset(engine.memory, 10, 1000)
    engine.memory.set_bit(at("R0.0"), 1)
    engine.step(200)
    assert bit(engine, "R0.1") == 0
    write_timer_preset(engine.memory, 10, 160)
    engine.scan()
    assert bit(engine, "R0.1") == 1


def test_tmr_with_preset_zero_is_on_in_the_first_scan() -> None:
    engine = engine_for("RD R0.0\nTMR 5\nWRT R0.1")
    engine.memory.set_bit(at("R0.0"), 1)
    engine.scan()
    assert bit(engine, "R0.1") == 1


def test_tmrb_uses_its_fixed_preset_rounded_to_8_ms() -> None:
    engine = engine_for("RD R0.0\nTMRB 1 30\nWRT R0.1")
    engine.memory.set_bit(at("R0.0"), 1)
    assert first_on(engine, "R0.1") == 24


def test_tmrb_is_independent_of_the_timer_table() -> None:
    engine = engine_for("RD R0.0\nTMRB 1 1000\nWRT R0.1")
    write_timer_preset(engine.memory, 1, 8)
    engine.memory.set_bit(at("R0.0"), 1)
    assert first_on(engine, "R0.1") == 1000


def test_tmrc_accuracy_1_ms_counts_its_register() -> None:
    engine = engine_for("RD R0.0\nTMRC 0 D10 D20\nWRT R0.1")
    engine.memory.write(at("D10"), 20, 2)
    engine.memory.set_bit(at("R0.0"), 1)
    engine.step(16)  # scans at 0 and 8
    assert engine.memory.read(at("D20"), 4) == 8
    assert bit(engine, "R0.1") == 0
    assert first_on(engine, "R0.1") == 8  # reached at 24 ms (the first scan at >= 20)
    assert engine.memory.read(at("D20"), 4) == 20  # held at the preset
    engine.memory.set_bit(at("R0.0"), 0)
    engine.scan()
    assert engine.memory.read(at("D20"), 4) == 0
    assert bit(engine, "R0.1") == 0


def test_tmrc_accuracy_8_ms_counts_in_8_ms_units() -> None:
    engine = engine_for("RD R0.0\nTMRC 1 D10 D20\nWRT R0.1")
    engine.memory.write(at("D10"), 5, 2)  # 5 x 8 ms
    engine.memory.set_bit(at("R0.0"), 1)
    assert first_on(engine, "R0.1") == 40
    assert engine.memory.read(at("D20"), 4) == 5


def test_two_timers_run_independently() -> None:
    engine = engine_for("RD R0.0\nTMR 9\nWRT R0.1\nRD R0.2\nTMR 10\nWRT R0.3")
    write_timer_preset(engine.memory, 9, 40)
    write_timer_preset(engine.memory, 10, 40)
    engine.memory.set_bit(at("R0.0"), 1)
    engine.step(24)
    engine.memory.set_bit(at("R0.2"), 1)
    engine.step(24)
    assert (bit(engine, "R0.1"), bit(engine, "R0.3")) == (1, 0)
    engine.step(24)
    assert (bit(engine, "R0.1"), bit(engine, "R0.3")) == (1, 1)
