"""The scan process: real-time scans in a process of their own leave exactly what the same
scans in the IDE leave, and everything a user sets or reads on a running PLC still works."""

from __future__ import annotations

import os
import subprocess
import sys
import threading
from collections.abc import Callable, Iterator

import pytest

from ladderworks import paths
from ladderworks.core import dialects
from ladderworks.core.address import Address, parse_address
from ladderworks.core.dialects.fatek.ascii_files import load_ascii_files
from ladderworks.core.il import parse, parse_file
from ladderworks.core.plc import scan_process
from ladderworks.core.plc.history import ScanHistory
from ladderworks.core.plc.process_runner import ProcessRunner
from ladderworks.core.plc.runner import RealTimeRunner
from ladderworks.core.plc.session import PlcRun

# A timer oscillator (R1.0 pulses every 3 ms), an edge (DIFU) counted into R3, an alarm that
# follows the oscillator, the 200 ms clock, and X0.0 through to Y0.0.
PROGRAM = """%@3
RD.NOT R1.0
TMR 1
WRT R1.0
RD R1.0
DIFU 1
WRT R2.0
RD R2.0
WRT R2.1
RD R1.0
WRT A0.1
RD R9091.5
WRT Y0.1
RD X0.0
WRT Y0.0
%
"""
PRESET = 3  # ms: the timer's preset (seed programs: ms)


def at(text: str) -> Address:
    """An address from its spelling."""
    return parse_address(text)


def wait_until(condition: Callable[[], bool], seconds: float = 20) -> bool:
    """Poll `condition` for up to `seconds`."""
    pause = threading.Event()
    for _ in range(int(seconds / 0.002)):
        if condition():
            return True
        pause.wait(0.002)
    return False


def make(realtime: bool, text: str = PROGRAM) -> PlcRun:
    """A run of `text` at 1 ms scans (real time in the scan process, or the virtual clock)."""
    run = PlcRun(realtime=realtime, period_ms=1, scan_process=realtime)
    assert run.load_program(parse(text).program).binary is not None
    run.set_timer_preset(1, PRESET)
    return run


@pytest.fixture
def live() -> Iterator[PlcRun]:
    """A run scanning in its scan process."""
    run = make(True)
    assert run.start()
    assert in_process(run), run.process_error
    yield run
    run.close()


def in_process(run: PlcRun) -> bool:
    """Wait until the scans have moved into the scan process (a thread scans until it has
    built the program; `status()` moves them)."""
    return wait_until(lambda: run.status().running and isinstance(run._runner, ProcessRunner))


def scans(run: PlcRun) -> int:
    """The scans run so far."""
    return run.status().scan_count


def same(run: PlcRun, reference: PlcRun) -> None:
    """Memory, every call site's state, the edges, the clock and the A-area log are equal."""
    assert run.engine is not None and reference.engine is not None
    assert run.snapshot().areas == reference.snapshot().areas
    assert run.engine.export_state() == reference.engine.export_state()
    assert run.engine.alarm_changes == reference.engine.alarm_changes


def test_scans_in_the_process_leave_what_the_same_scans_here_leave(live: PlcRun) -> None:
    """The first leg began on a thread while the process built the program (`live`)."""
    reference = make(False)
    reference.start()
    counts = []
    for _ in range(3):  # three runs in the process, with scans here between them
        assert wait_until(lambda: scans(live) >= (counts[-1] if counts else 0) + 150)
        live.stop()
        assert live.engine is not None and not live.engine.parked
        counts.append(live.engine.scan_count)
        reference.run_scans(counts[-1] - reference.engine.scan_count)  # type: ignore[union-attr]
        reference.stop()
        same(live, reference)
        live.realtime = reference.realtime = False
        live.start()
        reference.start()
        live.run_scans(7)
        reference.run_scans(7)
        same(live, reference)
        live.stop()
        reference.start()  # stopped as the live run was
        reference.stop()
        reference.start()
        live.realtime = True
        assert live.start() and isinstance(live._runner, ProcessRunner)  # built: at once
    assert counts[0] >= 150 and live.engine is not None
    assert live.read(at("R3")) == 0  # nothing wrote it
    assert live.engine.alarm_changes > 10  # A0.1 follows the oscillator


def test_what_the_ide_writes_and_forces_acts_on_the_next_scans(live: PlcRun) -> None:
    live.set_bit(at("X0.0"), 1)
    assert wait_until(lambda: live.bit(at("Y0.0")) == 1)
    live.force(at("X0.0"), 0)
    assert wait_until(lambda: live.bit(at("Y0.0")) == 0)
    live.set_bit(at("X0.0"), 1)  # the machine's value is held while forced
    count = scans(live)
    assert wait_until(lambda: scans(live) > count + 20)
    assert live.bit(at("Y0.0")) == 0
    live.release(at("X0.0"))
    assert wait_until(lambda: live.bit(at("Y0.0")) == 1)
    assert live.engine is not None
    read_x = live.engine.program.op_at_line(PROGRAM.splitlines().index("RD X0.0") + 1)
    assert read_x is not None
    live.disable(read_x)  # PASİF: the contact is open
    assert wait_until(lambda: live.bit(at("Y0.0")) == 0)
    live.enable(read_x)
    assert wait_until(lambda: live.bit(at("Y0.0")) == 1)
    live.stop()
    assert all(isinstance(data, bytearray) for data in live.memory.areas.values())
    assert live.bit(at("Y0.0")) == 0  # the safe state
    assert live.bit(at("X0.0")) == 1  # the machine's input is kept


def test_a_monitored_snapshot_is_one_scan_with_its_power_flow(live: PlcRun) -> None:
    live.monitor(True)
    assert wait_until(lambda: live.snapshot().power_flow != b"")
    for _ in range(5):
        snapshot = live.snapshot()
        assert snapshot.monitored and snapshot.scan_count > 0
        reference = make(False)
        reference.monitor(True)
        reference.start()
        reference.run_scans(snapshot.scan_count)
        expected = reference.snapshot()
        assert snapshot.areas == expected.areas
        assert snapshot.power_flow == expected.power_flow
        assert snapshot.now_ms == expected.now_ms
    live.monitor(False)
    assert not live.snapshot().monitored


def test_trace_samples_and_alarms_come_back_from_the_process(live: PlcRun) -> None:
    trace = live.start_trace([at("R1.0"), at("A0.1")], 1)
    assert trace is not None
    assert wait_until(lambda: len(trace) >= 100)
    live.stop()
    samples = live.trace_samples()
    assert [s.seq for s in samples] == list(range(len(samples)))  # none lost
    times = [s.time_ms for s in samples]
    assert times == list(range(times[0], times[0] + len(times)))
    assert {s.values for s in samples} == {(0, 0), (1, 1)}
    assert live.update_alarms()
    live.start()  # the trace goes on where it was
    assert wait_until(lambda: len(trace) >= 20)
    more = live.trace_samples()
    assert more[0].seq == samples[-1].seq + 1 and more[0].time_ms > samples[-1].time_ms


def test_time_travel_moves_the_scans_into_the_ide(live: PlcRun) -> None:
    assert live.engine is not None
    assert wait_until(lambda: scans(live) > 50)
    live.monitor(True)
    live.engine.history = ScanHistory()
    assert isinstance(live._runner, RealTimeRunner)  # every scan recorded here
    count = scans(live)
    assert wait_until(lambda: scans(live) > count + 20)
    assert live.engine.history.last_scan is not None
    assert live.engine.history.last_scan >= count


def test_a_load_while_running_stops_and_builds_the_new_program(live: PlcRun) -> None:
    other = PROGRAM.replace("WRT Y0.0", "WRT Y0.2")
    assert live.load_program(parse(other).program).binary is not None
    assert not live.running
    live.set_bit(at("X0.0"), 1)
    assert live.start()  # on a thread while the process builds it (unless already built)
    assert wait_until(lambda: live.bit(at("Y0.2")) == 1)
    assert in_process(live)
    assert live.bit(at("Y0.2")) == 1
    assert live.bit(at("Y0.0")) == 0


def test_a_process_gone_stops_the_plc_and_the_next_start_makes_another(live: PlcRun) -> None:
    live.set_bit(at("X0.0"), 1)
    assert wait_until(lambda: live.bit(at("Y0.0")) == 1)
    process = live._slot.process
    assert process is not None
    process.process.kill()
    process.process.join(10)
    assert not live.status().running  # the safe state
    assert live.process_error
    assert live.bit(at("Y0.0")) == 0 and live.bit(at("X0.0")) == 1
    assert live.start() and live.running and in_process(live)
    assert live._slot.process is not process
    assert wait_until(lambda: live.bit(at("Y0.0")) == 1)
    live.stop()
    assert all(isinstance(data, bytearray) for data in live.memory.areas.values())


def test_fun_94_text_comes_back_and_the_ascii_files_follow_the_ide() -> None:
    """004: X0 0 -> 1 with X1, X2 at 0 prints the report through Port 1; the ASCII files
    given while the process scans are the ones it sends."""
    path = paths.EXAMPLES / "fatek" / "production_report.lst"
    files = load_ascii_files(path)
    reference = PlcRun(period_ms=10)
    reference.use_ascii_files(files.files)
    assert reference.load_program(parse_file(path).program).binary is not None
    run = PlcRun(realtime=True, period_ms=10, scan_process=True)
    try:
        assert run.load_program(parse_file(path).program).binary is not None
        assert run.start() and in_process(run)
        run.use_ascii_files(files.files)
        x0 = dialects.parse_target("X0", "fatek")[0]
        count = scans(run)
        assert wait_until(lambda: scans(run) > count + 3)
        run.set_bit(x0, 1)
        assert wait_until(lambda: run.ascii_terminal.writes == 1)
        reference.start()
        reference.run_scans(2)
        reference.set_bit(x0, 1)
        reference.run_scans(2)
        assert reference.ascii_terminal.text() != ""
        assert run.ascii_terminal.text() == reference.ascii_terminal.text()
    finally:
        run.close()



_PRIORITY = """
import os
from ladderworks.core.plc import scan_process
before = (os.sched_getscheduler(0), os.getpriority(os.PRIO_PROCESS, 0))
got = scan_process.raise_priority()
during = (os.sched_getscheduler(0), os.getpriority(os.PRIO_PROCESS, 0))
scan_process.normal_priority()
after = (os.sched_getscheduler(0), os.getpriority(os.PRIO_PROCESS, 0))
print(got == "normal", during == before, after == before)
"""


@pytest.mark.skipif(not hasattr(os, "sched_getscheduler"), reason="Linux's scheduler calls")
@pytest.mark.parametrize("asked", ["", "normal"])
def test_the_scan_process_priority_is_raised_while_it_scans_and_given_back(asked: str) -> None:
    """`raise_priority` gets what the system grants (nothing when told "normal", or where
    nothing is granted) and `normal_priority` gives it back; in a child process, so the
    test's own priority is never touched."""
    env = dict(os.environ, LADDERWORKS_SCAN_PRIORITY=asked)
    done = subprocess.run([sys.executable, "-c", _PRIORITY], env=env, capture_output=True,
                          text=True, check=True)
    normal, unchanged, restored = done.stdout.split()
    assert restored == "True"
    assert unchanged == normal  # raised exactly when it says so
    if asked == "normal":
        assert normal == "True"


def test_the_scan_process_gives_up_its_priority_while_scans_run_long_and_takes_it_again() -> None:
    """Three scans longer than the period, late with no scan on time between: back to normal
    priority (once); a scan on time starts the count again, a late one that was not long is
    not counted; after a second of scans on time (125 at 8 ms) the priority is raised again,
    and the next long row lowers it again."""
    pace = scan_process.Pace()
    assert [pace.after_scan(True, True) for _ in range(2)] == [None, None]
    assert pace.after_scan(False, False) is None  # on time: the row starts again
    assert [pace.after_scan(True, True) for _ in range(2)] == [None, None]
    assert pace.after_scan(True, False) is None  # late after a short scan: not counted
    assert pace.after_scan(True, True) == "lower"
    assert [pace.after_scan(True, True) for _ in range(5)] == [None] * 5  # lowered once
    changes = [pace.after_scan(False, False) for _ in range(scan_process.ON_TIME_SCANS)]
    assert changes == [None] * (scan_process.ON_TIME_SCANS - 1) + ["raise"]
    assert pace.after_scan(False, False) is None
    assert [pace.after_scan(True, True) for _ in range(3)] == [None, None, "lower"]
