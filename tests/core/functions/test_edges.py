"""DIFU/DIFD (FANUC-PMC.md §6): one-scan pulses, edge memory 0 at power-on, shared per
(kind, number), frozen while not executed; through the engine in fast and monitored mode."""

from __future__ import annotations

from ladderworks.core.plc.functions import FunctionContext
from tests.core.functions.conftest import run_engine
from tests.core.plc.conftest import bit, set_bit

EDGES = """
RD R0.0
DIFU 1
WRT R1.0
RD R0.0
DIFD 1
WRT R1.1
"""


def trace(engine, inputs: list[int]) -> list[tuple[int, int]]:  # type: ignore[no-untyped-def]
    """(DIFU W1, DIFD W1) after a scan with each ACT value."""
    seen = []
    for act in inputs:
        set_bit(engine, "R0.0", act)
        engine.scan()
        seen.append((bit(engine, "R1.0"), bit(engine, "R1.1")))
    return seen


def test_one_scan_pulses_on_each_edge(monitored: bool) -> None:
    engine = run_engine(EDGES, monitored)
    assert trace(engine, [0, 1, 1, 1, 0, 0, 1, 0]) == [
        (0, 0), (1, 0), (0, 0), (0, 0), (0, 1), (0, 0), (1, 0), (0, 1)]


def test_memory_is_0_at_power_on_so_act_1_in_the_first_scan_pulses(monitored: bool) -> None:
    engine = run_engine(EDGES, monitored)
    assert trace(engine, [1, 1]) == [(1, 0), (0, 0)]


def test_the_same_number_shares_one_memory(monitored: bool) -> None:
    engine = run_engine("RD R0.0\nDIFU 7\nWRT R1.0\nRD R0.0\nDIFU 7\nWRT R1.1", monitored)
    set_bit(engine, "R0.0", 1)
    engine.scan()
    # the first site saw the rise and stored 1: the second finds no edge
    assert (bit(engine, "R1.0"), bit(engine, "R1.1")) == (1, 0)


def test_difu_and_difd_numbers_are_separate() -> None:
    engine = run_engine("RD R0.0\nDIFU 3\nWRT R1.0\nRD R0.1\nDIFD 3\nWRT R1.1", False)
    set_bit(engine, "R0.0", 1)
    set_bit(engine, "R0.1", 1)
    engine.scan()
    set_bit(engine, "R0.1", 0)
    engine.scan()
    assert bit(engine, "R1.1") == 1  # DIFD 3's own memory saw 1 -> 0
    assert bit(engine, "R1.0") == 0


JUMPED = """
RD R0.1
JMP 0
RD R0.0
DIFU 2
WRT R1.0
JMPE
"""


def test_not_executed_keeps_the_memory_and_the_coil(monitored: bool) -> None:
    engine = run_engine(JUMPED, monitored)
    set_bit(engine, "R0.0", 1)
    engine.scan()
    assert bit(engine, "R1.0") == 1
    set_bit(engine, "R0.1", 1)  # jump over the DIFU: frozen, its coil keeps 1
    for act in (0, 1, 0):
        set_bit(engine, "R0.0", act)
        engine.scan()
        assert bit(engine, "R1.0") == 1
    set_bit(engine, "R0.1", 0)
    engine.scan()  # ACT = 0 now; the memory still holds the 1 it had before the jump
    assert bit(engine, "R1.0") == 0
    set_bit(engine, "R0.0", 1)
    engine.scan()
    assert bit(engine, "R1.0") == 1


def test_a_rise_while_frozen_gives_its_pulse_when_executed_again() -> None:
    engine = run_engine(JUMPED, False)
    set_bit(engine, "R0.1", 1)
    set_bit(engine, "R0.0", 1)
    engine.scan()
    set_bit(engine, "R0.1", 0)
    engine.scan()
    assert bit(engine, "R1.0") == 1  # memory was 0 (never executed), ACT is 1


def test_power_on_clears_the_edge_memories(ctx: FunctionContext, box) -> None:
    difu, difd = box("DIFU", 4), box("DIFD", 4)
    assert difu(1) is True
    assert difd(1) is False
    assert ctx.edges == {("DIFU", 4): True, ("DIFD", 4): True}
    ctx.power_on()
    assert ctx.edges == {}
    assert difu(1) is True
    assert difd(0) is False  # DIFD's memory is 0 again: no fall to see


def test_call_sites_share_by_number_not_by_state(ctx: FunctionContext, box) -> None:
    first, second = box("DIFD", 9), box("DIFD", 9)
    first(1)
    assert second(0) is True  # the memory first stored is the one second reads
    assert first(0) is False
