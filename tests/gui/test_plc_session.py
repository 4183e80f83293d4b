"""PlcSession on the virtual clock and on its real-time thread: signals, forcing, tables."""

from __future__ import annotations

import pytest
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.compiler import compile
from ladderworks.core.il import parse
from ladderworks.gui.plc_session import PlcSession, PlcSnapshot, PlcStatus
from ladderworks.paths import EXAMPLES
from tests.gui.plc_docks_help import override_code


def a(text: str):
    """An address from text."""
    return parse_address(text)


def program_binary(name: str) -> bytes:
    """The compiled binary of an example program."""
    result = parse((EXAMPLES / name).read_text(encoding="utf-8"))
    return compile(result.program)


@pytest.fixture
def session(qtbot: QtBot) -> PlcSession:
    """A session on the virtual clock with the spindle-override program loaded."""
    s = PlcSession(realtime=False)
    assert s.load(program_binary("spindle_override.LAD")) == []
    return s


def set_switch(session: PlcSession, position: int) -> None:
    """Turn the rotary switch: X2.1, X2.3, X2.5 carry the position's three bits."""
    for bit, address in enumerate(("X2.1", "X2.3", "X2.5")):
        session.set_bit(a(address), position >> bit & 1)


def test_load_refuses_bad_bytes_as_data(qtbot: QtBot) -> None:
    s = PlcSession(realtime=False)
    problems = s.load(b"not a program")
    assert problems and problems[0].code == "bad-binary"
    assert s.run.engine is None and not s.start()


def test_virtual_scans_publish_status_and_snapshot(qtbot: QtBot, session: PlcSession) -> None:
    statuses: list[PlcStatus] = []
    snaps: list[PlcSnapshot] = []
    session.status_changed.connect(statuses.append)
    session.snapshot_ready.connect(snaps.append)
    with qtbot.waitSignal(session.running_changed) as blocker:
        assert session.start()
    assert blocker.args == [True]
    assert session.step(80) == 10
    assert statuses[-1].running and statuses[-1].scan_count == 10
    assert statuses[-1].now_ms == 80 and statuses[-1].max_ms >= statuses[-1].min_ms > 0
    assert snaps[-1].scan_count == 10


@pytest.mark.parametrize("position", range(8))
def test_switch_position_gives_r102_and_g30(session: PlcSession, position: int) -> None:
    session.start()
    set_switch(session, position)
    session.run_scans(1)
    snap = session.run.snapshot()
    assert snap.read(a("R102")) == 1 << position
    assert snap.read(a("G30")) == override_code(position)


def test_stop_stops_the_scans_and_clears_outputs(session: PlcSession) -> None:
    session.start()
    session.write(a("Y0"), 0)
    session.run_scans(3)
    session.write(a("Y0"), 0xFF)  # as if the program had set outputs
    session.stop()
    assert not session.run.running
    assert session.run.read(a("Y0")) == 0  # the safe state
    assert session.step(100) == 0
    assert session.run.status().scan_count == 3


def test_force_and_disable_change_the_result(qtbot: QtBot, session: PlcSession) -> None:
    session.start()
    set_switch(session, 0)
    session.run_scans(1)
    assert session.run.bit(a("R102.0")) == 1
    with qtbot.waitSignal(session.forces_changed) as blocker:
        session.force(a("X2.1"), 1)  # the switch says position 1 whatever the wire says
    assert [str(e) for e in blocker.args[0]] == ["force X2.1 = 1"]
    session.run_scans(1)
    assert session.run.bit(a("R102.0")) == 0 and session.run.bit(a("R102.1")) == 1
    session.release(a("X2.1"))
    session.run_scans(1)
    assert session.run.bit(a("R102.0")) == 1
    index = session.disable((0, 0))  # RD.NOT X2.1 of network 0: an open contact
    session.run_scans(1)
    assert session.run.bit(a("R102.0")) == 0
    assert [e.op for e in session.run.forces()] == [index]
    session.enable(index)
    session.run_scans(1)
    assert session.run.bit(a("R102.0")) == 1 and session.run.forces() == []


def test_monitoring_records_power_flow(session: PlcSession) -> None:
    session.run.monitor(True)
    session.start()
    set_switch(session, 0)
    session.run_scans(1)
    snap = session.run.snapshot()
    assert snap.monitored and len(snap.power_flow) == len(session.run.binary.ops)
    assert snap.power_flow[3] == 1  # WRT R102.0 got ST0 = 1
    session.run.monitor(False)
    assert not session.run.engine.monitored


def test_trace_samples_inside_the_scan(session: PlcSession) -> None:
    session.start()
    session.run.start_trace([a("X2.1"), a("R102.1")], 16)
    session.run_scans(2)
    set_switch(session, 1)
    session.run_scans(2)
    samples = session.run.trace_samples()
    assert [s.values for s in samples] == [(0, 0), (1, 1)]
    assert [s.time_ms for s in samples] == [0, 16]
    session.run.stop_trace()
    session.run_scans(4)
    assert session.run.trace_samples() == []


def test_tables_and_inputs_survive_a_reload(session: PlcSession) -> None:
    session.set_timer_preset(1, 960)
    session.set_counter_preset(3, 12)
    session.set_bit(a("X2.1"), 1)
    session.start()
    session.run_scans(1)
    assert session.run.bit(a("R102.1")) == 1
    assert session.load(program_binary("timer_relay.LAD")) == []
    assert not session.run.running
    assert session.run.timer_preset(1) == 960 and session.run.counter(3) == (12, 0)
    assert session.run.bit(a("X2.1")) == 1 and session.run.bit(a("R102.1")) == 0  # cold start


def test_alarms_are_listed_and_reset(qtbot: QtBot, session: PlcSession) -> None:
    assert session.load(program_binary("alarm.LAD")) == []
    contact = "F102.0"  # the example raises A0.0 while the X axis moves
    session.start()
    with qtbot.waitSignal(session.alarms_changed) as blocker:
        session.set_bit(a(contact), 1)
        session.run_scans(1)
    assert blocker.args[0] and all(alarm.active for alarm in blocker.args[0])
    session.set_bit(a(contact), 0)
    session.run_scans(1)
    assert session.run.alarms() and not session.run.alarms()[0].active
    session.reset_alarms()
    assert session.run.alarms() == []


def test_real_time_thread_scans_and_stops(qtbot: QtBot) -> None:
    s = PlcSession(realtime=True, publish_ms=20)
    assert s.load(program_binary("spindle_override.LAD")) == []
    seen: list[PlcStatus] = []
    s.status_changed.connect(seen.append)
    s.start()
    qtbot.waitUntil(lambda: bool(seen) and seen[-1].scan_count >= 5, timeout=5000)
    set_switch(s, 7)
    qtbot.waitUntil(lambda: s.run.snapshot().read(a("R102")) == 0x80, timeout=5000)
    with qtbot.waitSignal(s.running_changed):
        s.stop()
    count = s.run.status().scan_count
    assert not s.run.status().running and s.run.engine.scan_count == count
    assert s.run.status().avg_ms > 0
    qtbot.waitUntil(lambda: not s._timer.isActive())
    assert s.run.engine.scan_count == count
