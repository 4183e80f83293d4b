"""The engine logs every change of the A area with its scan's time: no alarm pulse is missed."""

from __future__ import annotations

from tests.core.plc.conftest import engine_for, set_bit

PULSE = "RD X1.0\nAND.NOT R1.0\nWRT A0.3\nRD X1.0\nWRT R1.0"  # A0.3 on for exactly one scan


def test_a_one_scan_alarm_pulse_is_logged_at_its_scan_time() -> None:
    engine = engine_for(PULSE)
    engine.run_scans(10)  # 0 .. 72 ms
    assert engine.take_alarm_changes() == []
    set_bit(engine, "X1.0", 1)
    engine.run_scans(5)  # the pulse is the scan at 80 ms; A0.3 is 0 again from 88 ms
    changes = engine.take_alarm_changes()
    assert [(now, data[0]) for now, data in changes] == [(80, 0b1000), (88, 0)]
    assert engine.take_alarm_changes() == []  # taken once
    assert engine.active_alarms() == []  # a view that only looked now would have missed it
