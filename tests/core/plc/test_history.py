"""Time travel: every scan's memory and power flow kept as changes, within a memory budget."""

from __future__ import annotations

from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.history import ScanHistory
from tests.core.plc.conftest import at, bit, engine_for, set_bit

LATCH = """
RD X2.1
OR Y0.0
AND.NOT X2.2
WRT Y0.0
RD R9091.5
WRT R10.0
"""


def recorded(keyframe_every: int = 4) -> tuple[ScanEngine, ScanHistory]:
    engine = engine_for(LATCH)
    engine.monitored = True
    engine.history = ScanHistory(keyframe_every=keyframe_every)
    return engine, engine.history


def test_every_scan_can_be_rebuilt_with_its_power_flow() -> None:
    engine, history = recorded()
    truth = []
    for scan in range(30):
        set_bit(engine, "X2.1", scan == 5)
        set_bit(engine, "X2.2", scan == 20)
        engine.scan()
        truth.append((engine.memory.snapshot(), bytes(engine.power_flow)))
    assert (history.first_scan, history.last_scan, len(history)) == (0, 29, 30)
    for scan, (areas, flow) in enumerate(truth):
        frame = history.frame(scan)
        assert frame is not None
        assert (frame.scan, frame.time_ms) == (scan, scan * 8)
        assert frame.areas == areas and frame.power_flow == flow, scan
    assert history.scan_at(45) == 5 and history.scan_at(-3) == 0


def test_why_finds_the_scan_and_the_contacts() -> None:
    engine, history = recorded()
    for scan in range(30):
        set_bit(engine, "X2.1", scan == 5)
        set_bit(engine, "X2.2", scan == 20)
        engine.scan()
    assert bit(engine, "Y0.0") == 0
    changes = history.bit_changes(at("Y0.0"))
    assert [(s, v) for s, _t, v in changes] == [(5, 1), (20, 0)]
    why = history.why(engine, at("Y0.0"), 25)
    assert why is not None and (why.scan, why.time_ms, why.value) == (20, 160, 0)
    ops = engine.program.ops
    assert [str(ops[i].operand) for i in why.writers] == ["Y0.0"]
    assert [ops[i].name for i in why.contacts] == ["AND.NOT"]  # X2.2 turned it off
    first = history.why(engine, at("Y0.0"), 10)
    assert first is not None and first.scan == 5
    assert [str(ops[i].operand) for i in first.contacts] == ["X2.1"]
    assert history.why(engine, at("Y0.0"), 4) is None


def test_the_budget_drops_the_oldest_segments() -> None:
    engine, history = recorded(keyframe_every=16)
    engine.history = ScanHistory(budget_bytes=300_000, keyframe_every=16)
    history = engine.history
    for _ in range(400):
        engine.scan()
    assert history.size <= 300_000
    assert history.first_scan is not None and history.first_scan > 0
    assert history.last_scan == 399
    assert history.frame(0) is None and history.frame(399) is not None


def test_off_by_default() -> None:
    assert engine_for(LATCH).history is None
