"""Timers against FANUC-PMC.md: TMRBF (off-delay), TMR in a FANUC program (2-byte ticks at
T[2(n-1)], precision codes at T9000+2(n-1)), TMRC's FANUC accuracy codes, and timers that
count only the scans that execute them (frozen when skipped, once per scan)."""

from __future__ import annotations

import pytest

from ladderworks.core.address import Address, Area
from ladderworks.core.plc.functions import FunctionContext
from ladderworks.core.plc.functions.timers import (
    fanuc_preset_ms,
    timer_precision_address,
    timer_preset_address,
)
from ladderworks.core.plc.memory import Memory
from tests.core.functions.conftest import at, fanuc_memory, run_engine
from tests.core.plc.conftest import bit, set_bit

TMRBF = "RD R0.0\nTMRBF 3 40\nWRT R1.0"


def w1_trace(engine, acts: list[int]) -> list[int]:  # type: ignore[no-untyped-def]
    """W1 (R1.0) after one scan (8 ms) with each ACT (R0.0) value."""
    seen = []
    for act in acts:
        set_bit(engine, "R0.0", act)
        engine.scan()
        seen.append(bit(engine, "R1.0"))
    return seen


def test_tmrbf_holds_w1_for_the_preset_after_act_drops(monitored: bool) -> None:
    engine = run_engine(TMRBF, monitored)
    # scans 8 ms apart; the drop is at t = 0 of timing: 0, 8, 16, 24, 32 ms < 40, then 40
    assert w1_trace(engine, [1, 1, 0, 0, 0, 0, 0, 0, 0]) == [1, 1, 1, 1, 1, 1, 1, 0, 0]


def test_tmrbf_is_0_at_power_on(monitored: bool) -> None:
    engine = run_engine(TMRBF, monitored)
    assert w1_trace(engine, [0, 0, 1, 0]) == [0, 0, 1, 1]


def test_tmrbf_act_back_to_1_while_timing_clears_the_timer(monitored: bool) -> None:
    engine = run_engine(TMRBF, monitored)
    assert w1_trace(engine, [1, 0, 0, 0, 1]) == [1, 1, 1, 1, 1]  # 16 ms used of 40
    # the next drop times the full 40 ms again
    assert w1_trace(engine, [0, 0, 0, 0, 0, 0]) == [1, 1, 1, 1, 1, 0]


def test_tmrbf_preset_0_follows_act_and_presets_round_down_to_8_ms(monitored: bool) -> None:
    engine = run_engine("RD R0.0\nTMRBF 1 0\nWRT R1.0\nRD R0.0\nTMRBF 2 23\nWRT R1.1",
                        monitored)
    assert w1_trace(engine, [1, 0, 1, 0]) == [1, 0, 1, 0]
    set_bit(engine, "R0.0", 1)
    engine.scan()
    set_bit(engine, "R0.0", 0)
    seen = []
    for _ in range(4):
        engine.scan()
        seen.append(bit(engine, "R1.1"))
    assert seen == [1, 1, 0, 0]  # 23 ms acts as 16 ms (24 ms would give 1, 1, 1, 0)


def test_fanuc_tmr_layout() -> None:
    assert timer_preset_address(1, "fanuc") == at("T0")
    assert timer_preset_address(10, "fanuc") == at("T18")
    assert timer_preset_address(10) == at("T36")  # seed: 4 bytes a timer
    assert timer_precision_address(1) == Address(Area.T, 9000)
    assert timer_precision_address(19) == Address(Area.T, 9036)


@pytest.mark.parametrize(("number", "code", "ticks", "ms"), [
    (1, 0, 10, 480),  # X22: NUMEB 2 10 T0 before TMR 1 -> 10 x 48 ms
    (8, 0, 3, 144),
    (9, 0, 10, 80),
    (250, 0, 1, 8),
    (10, 1, 1250, 1250),
    (10, 2, 7, 70),
    (10, 3, 7, 700),
    (19, 4, 10, 10_000),  # X22: WRT T9036.2 (code 4, 1 s) before TMR 19
    (20, 5, 2, 120_000),
    (10, 9, 5, 40),  # an unknown code counts as 0 (default tick)
    (10, 0, 40_000, 32767 * 8),  # at most 32767 ticks
])
def test_fanuc_preset_in_ticks_of_the_precision(number: int, code: int, ticks: int,
                                                 ms: int) -> None:
    memory = fanuc_memory()
    memory.write(timer_preset_address(number, "fanuc"), ticks, 2)
    memory.write(timer_precision_address(number), code, 1)
    assert fanuc_preset_ms(memory, number) == ms


def test_fanuc_precision_past_a_small_t_area_is_the_default() -> None:
    memory = Memory()
    memory.write(timer_preset_address(9, "fanuc"), 5, 2)
    assert fanuc_preset_ms(memory, 9) == 40


def first_on(engine, limit: int) -> int | None:  # type: ignore[no-untyped-def]
    """ms after the first scan at which R1.0 reads 1, or None."""
    start = engine.now_ms
    for _ in range(limit):
        now = engine.now_ms
        engine.scan()
        if bit(engine, "R1.0"):
            return now - start
    return None


def test_engine_fanuc_tmr_preset_10_with_code_4_is_10_s(monitored: bool) -> None:
    engine = run_engine("RD R0.0\nTMR 19\nWRT R1.0", monitored, "fanuc", fanuc_memory())
    engine.memory.write(at("T36"), 10, 2)
    engine.memory.set_bit(Address(Area.T, 9036, 2), 1)  # WRT T9036.2 in X22
    set_bit(engine, "R0.0", 1)
    assert first_on(engine, 1300) == 10_000


def test_engine_fanuc_tmr_default_ticks(monitored: bool) -> None:
    engine = run_engine("RD R0.0\nTMR 1\nWRT R1.0\nRD R0.0\nTMR 9\nWRT R1.1", monitored,
                        "fanuc", fanuc_memory())
    engine.memory.write(at("T0"), 2, 2)  # TMR 1: 2 x 48 ms
    engine.memory.write(at("T16"), 2, 2)  # TMR 9: 2 x 8 ms
    set_bit(engine, "R0.0", 1)
    engine.run_scans(3)  # 0, 8, 16 ms
    assert (bit(engine, "R1.0"), bit(engine, "R1.1")) == (0, 1)
    assert first_on(engine, 20) == 72  # at 96 ms


def test_seed_program_reads_4_bytes_of_ms_at_the_same_number(monitored: bool) -> None:
    engine = run_engine("RD R0.0\nTMR 9\nWRT R1.0", monitored, "seed", fanuc_memory())
    engine.memory.write(at("T32"), 24, 4)
    engine.memory.write(Address(Area.T, 9016), 4, 1)  # a precision code means nothing in seed
    set_bit(engine, "R0.0", 1)
    assert first_on(engine, 10) == 24


@pytest.mark.parametrize(("dialect", "accuracy", "unit"), [
    ("seed", 0, 1), ("seed", 1, 8), ("seed", 7, 1),
    ("fanuc", 0, 8), ("fanuc", 1, 48), ("fanuc", 2, 1000), ("fanuc", 3, 10_000),
    ("fanuc", 4, 60_000), ("fanuc", 5, 1), ("fanuc", 6, 10), ("fanuc", 7, 100),
    ("fanuc", 9, 8),
])
def test_tmrc_accuracy_codes(ctx: FunctionContext, box, dialect: str, accuracy: int,
                             unit: int) -> None:
    ctx.dialect = dialect
    ctx.scan_ms = 8
    tmrc = box("TMRC", accuracy, "D10", "D20")
    ctx.memory.write(at("D10"), 3, 2)
    ticks = 0
    while not tmrc(1):
        ctx.now_ms += 8
        ticks += 1
    assert ctx.memory.read(at("D20"), 4) == 3
    assert ticks * 8 == -(-3 * unit // 8) * 8  # the first scan at or after 3 units


@pytest.mark.parametrize(("dialect", "ms"), [("seed", 16), ("fanuc", 96)])
def test_engine_tmrc_code_1_is_8_ms_in_seed_and_48_ms_in_fanuc(monitored: bool, dialect: str,
                                                             ms: int) -> None:
    engine = run_engine("RD R0.0\nTMRC 1 D10 D20\nWRT R1.0", monitored, dialect)
    engine.memory.write(at("D10"), 2, 2)
    set_bit(engine, "R0.0", 1)
    assert first_on(engine, 20) == ms


def test_fanuc_tmrc_480_minutes(ctx: FunctionContext, box) -> None:
    ctx.dialect, ctx.scan_ms = "fanuc", 60_000  # one-minute scans keep the test short
    tmrc = box("TMRC", 4, "R7943", "R7945")  # X22: the DCS MCC-test timer, 480 min
    ctx.memory.write(at("R7943"), 480, 2)
    seen = []
    for minute in range(481):
        ctx.now_ms = minute * 60_000
        seen.append(tmrc(1))
    assert seen == [False] * 480 + [True]
    assert ctx.memory.read(at("R7945"), 4) == 480


JUMPED_TIMER = """
RD R0.1
JMP 0
RD R0.0
TMRB 1 80
WRT R1.0
JMPE
"""


def test_a_skipped_timer_is_frozen(monitored: bool) -> None:
    engine = run_engine(JUMPED_TIMER, monitored)
    set_bit(engine, "R0.0", 1)
    engine.run_scans(5)  # 0 .. 32 ms
    set_bit(engine, "R0.1", 1)
    set_bit(engine, "R0.0", 0)  # ACT = 0 while skipped resets nothing
    engine.run_scans(50)
    assert bit(engine, "R1.0") == 0
    set_bit(engine, "R0.1", 0)
    set_bit(engine, "R0.0", 1)
    assert w1_trace(engine, [1] * 7) == [0, 0, 0, 0, 0, 1, 1]  # 40, 48 … 80 ms


def test_two_executions_in_one_scan_count_the_scan_once(ctx: FunctionContext, box) -> None:
    tmrb = box("TMRB", 1, 16)
    ctx.scan_ms = 8
    for now in (0, 8, 16):
        ctx.now_ms = now
        results = [tmrb(1), tmrb(1)]  # as a subprogram called twice in a scan
    assert results == [True, True]
    assert tmrb.state["elapsed"] == 16


def test_a_timer_skipped_for_scans_adds_one_scan_when_run_again(ctx: FunctionContext,
                                                                 box) -> None:
    tmrb = box("TMRB", 1, 24)
    ctx.scan_ms = 8
    assert tmrb(1) is False  # starts at 0
    ctx.now_ms = 800  # 99 scans later: not executed in between
    assert tmrb(1) is False
    assert tmrb.state["elapsed"] == 8
