"""The seed manual's programs behave as written."""

from __future__ import annotations

import pytest

from ladderworks.core.plc.functions.timers import write_timer_preset
from tests.core.plc.conftest import at, bit, engine_for, engine_for_example, set_bit

# Switch position p = X2.1 * 1 + X2.3 * 2 + X2.5 * 4 -> spindle override in %.
OVERRIDES = [10, 20, 40, 60, 80, 100, 125, 150]


@pytest.mark.parametrize("position", range(8))
def test_spindle_override_gives_the_manuals_percentages(position: int) -> None:
    engine = engine_for_example("spindle_override.LAD")
    set_bit(engine, "X2.1", position & 1)
    set_bit(engine, "X2.3", position >> 1 & 1)
    set_bit(engine, "X2.5", position >> 2 & 1)
    engine.scan()
    assert engine.memory.read(at("G30")) == OVERRIDES[position]
    assert engine.memory.read(at("R102")) == 1 << position


def test_spindle_override_follows_the_switch_every_scan() -> None:
    engine = engine_for_example("spindle_override.LAD")
    seen = []
    for position in [7, 0, 5, 2]:
        set_bit(engine, "X2.1", position & 1)
        set_bit(engine, "X2.3", position >> 1 & 1)
        set_bit(engine, "X2.5", position >> 2 & 1)
        engine.scan()
        seen.append(engine.memory.read(at("G30")))
    assert seen == [150, 10, 100, 40]


def test_or_triple_latch_holds_and_releases() -> None:
    # Y0.0 = NOT F1.4 OR (Y0.0 AND NOT Y0.1 AND NOT Y0.2)
    engine = engine_for_example("or_triple.LAD")
    set_bit(engine, "F1.4", 1)
    engine.run_scans(3)
    assert bit(engine, "Y0.0") == 0
    set_bit(engine, "F1.4", 0)  # spindle enable drops: the stop relay pulls in
    engine.scan()
    assert bit(engine, "Y0.0") == 1
    set_bit(engine, "F1.4", 1)  # ... and holds itself
    engine.run_scans(5)
    assert bit(engine, "Y0.0") == 1
    engine.memory.set_bit(at("Y0.1"), 1)  # a breaking contact releases it
    engine.scan()
    assert bit(engine, "Y0.0") == 0
    engine.memory.set_bit(at("Y0.1"), 0)
    engine.scan()
    assert bit(engine, "Y0.0") == 0


def test_or_triple_and_latch_holds_while_enabled_and_releases_on_m04() -> None:
    # Y0.1 = (F7.0 AND R3.3 OR Y0.1 AND F1.4) AND NOT R3.4
    engine = engine_for_example("or_triple_and.LAD")
    set_bit(engine, "F1.4", 1)
    engine.memory.set_bit(at("R3.3"), 1)
    engine.scan()
    assert bit(engine, "Y0.1") == 0  # no M strobe yet
    set_bit(engine, "F7.0", 1)
    engine.scan()
    assert bit(engine, "Y0.1") == 1
    set_bit(engine, "F7.0", 0)
    engine.memory.set_bit(at("R3.3"), 0)
    engine.run_scans(4)
    assert bit(engine, "Y0.1") == 1  # held through Y0.1 AND F1.4
    engine.memory.set_bit(at("R3.4"), 1)  # M04 releases it
    engine.scan()
    assert bit(engine, "Y0.1") == 0
    engine.memory.set_bit(at("R3.4"), 0)
    engine.scan()
    assert bit(engine, "Y0.1") == 0


def test_or_triple_and_latch_releases_when_enable_drops() -> None:
    engine = engine_for_example("or_triple_and.LAD")
    set_bit(engine, "F1.4", 1)
    set_bit(engine, "F7.0", 1)
    engine.memory.set_bit(at("R3.3"), 1)
    engine.scan()
    set_bit(engine, "F7.0", 0)
    engine.scan()
    assert bit(engine, "Y0.1") == 1
    set_bit(engine, "F1.4", 0)
    engine.scan()
    assert bit(engine, "Y0.1") == 0


def test_or_double_latch_holds_and_releases() -> None:
    # R1.4 = NOT F9.4 AND R1.0 OR R1.4 AND NOT R1.6
    engine = engine_for_example("or_double.LAD")
    set_bit(engine, "F9.4", 1)
    engine.memory.set_bit(at("R1.0"), 1)
    engine.scan()
    assert bit(engine, "R1.4") == 0
    set_bit(engine, "F9.4", 0)  # M30 decode signal goes off
    engine.scan()
    assert bit(engine, "R1.4") == 1
    engine.memory.set_bit(at("R1.0"), 0)
    engine.run_scans(3)
    assert bit(engine, "R1.4") == 1
    engine.memory.set_bit(at("R1.6"), 1)
    engine.scan()
    assert bit(engine, "R1.4") == 0


def test_or_single_stop_signal_is_inverted() -> None:
    engine = engine_for_example("or_single.LAD")
    engine.scan()
    assert bit(engine, "G8.5") == 1  # nothing asks for a stop: *SP stays 1
    set_bit(engine, "F9.6", 1)  # M01 with optional stop and the M strobe
    set_bit(engine, "F2.5", 1)
    set_bit(engine, "F7.0", 1)
    engine.scan()
    assert bit(engine, "G8.5") == 0
    set_bit(engine, "F9.6", 0)
    engine.memory.set_bit(at("R11.1"), 1)  # the stop button
    engine.scan()
    assert bit(engine, "G8.5") == 0


def test_rising_edge_in_the_right_order_lasts_exactly_one_scan() -> None:
    engine = engine_for_example("rising_edge_pulse.LAD")
    pulses = []
    for press in [0, 0, 1, 1, 1, 1, 0, 0, 1, 1]:
        set_bit(engine, "X17.0", press)
        engine.scan()
        pulses.append(bit(engine, "R11.0"))
    assert pulses == [0, 0, 1, 0, 0, 0, 0, 0, 1, 0]


def test_rising_edge_as_printed_in_the_seed_never_pulses() -> None:
    # The seed writes R10.0 before reading it, so in one top-to-bottom scan the pulse network
    # always sees R10.0 = X17.0: the engine shows exactly that.
    engine = engine_for_example("rising_edge.LAD")
    pulses = []
    for press in [0, 1, 1, 0, 1]:
        set_bit(engine, "X17.0", press)
        engine.scan()
        pulses.append(bit(engine, "R11.0"))
    assert pulses == [0, 0, 0, 0, 0]


def test_alarm_bit_follows_the_axis_moving_signal() -> None:
    engine = engine_for_example("alarm.LAD")
    set_bit(engine, "F102.0", 1)
    engine.scan()
    assert engine.active_alarms() == [0]
    set_bit(engine, "F102.0", 0)
    engine.scan()
    assert engine.active_alarms() == []


def test_mcode_decoder_sets_one_relay_per_code() -> None:
    engine = engine_for_example("mcode_decoder.LAD")
    relays = {3: "R3.3", 4: "R3.4", 5: "R3.5", 6: "R3.6", 8: "R4.0", 9: "R4.1", 19: "R5.3",
              20: "R5.4", 32: "R7.0"}
    for code, relay in relays.items():
        engine.memory.write(at("F10"), code)
        engine.scan()
        on = [name for name in relays.values() if bit(engine, name)]
        assert on == [relay]


@pytest.mark.parametrize(("preset", "switch_ms"), [(100, 96), (96, 96), (47, 0), (500, 480)])
def test_timer_relay_switches_after_the_preset_rounded_to_48_ms(preset: int,
                                                                switch_ms: int) -> None:
    engine = engine_for_example("timer_relay.LAD")
    write_timer_preset(engine.memory, 1, preset)
    engine.run_scans(2)
    engine.memory.set_bit(at("R1.4"), 1)
    start = engine.now_ms
    while engine.now_ms - start < switch_ms:
        engine.scan()
        assert bit(engine, "R1.7") == 0, engine.now_ms - start
    engine.scan()  # the scan at start + switch_ms
    assert bit(engine, "R1.7") == 1
    engine.memory.set_bit(at("R1.4"), 0)
    engine.scan()
    assert bit(engine, "R1.7") == 0


@pytest.mark.parametrize(("timer", "preset", "switch_ms"),
                         [(9, 100, 96), (9, 104, 104), (100, 13, 8), (8, 100, 96)])
def test_timer_rounds_to_8_ms_from_timer_9(timer: int, preset: int, switch_ms: int) -> None:
    engine = engine_for(f"RD R1.4\nTMR {timer}\nWRT R1.7")
    write_timer_preset(engine.memory, timer, preset)
    engine.memory.set_bit(at("R1.4"), 1)
    start = engine.now_ms
    on_at = None
    for _ in range(100):
        now = engine.now_ms
        engine.scan()
        if bit(engine, "R1.7") and on_at is None:
            on_at = now - start
    assert on_at == switch_ms
