"""The real-time runner: scans on a thread, keeps statistics, stops into the safe state."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

from ladderworks.core.plc.runner import RealTimeRunner, ScanStats
from tests.core.plc.conftest import at, bit, engine_for


def wait_until(condition: Callable[[], bool]) -> bool:
    """Poll `condition` for up to 10 s."""
    pause = threading.Event()
    for _ in range(5000):
        if condition():
            return True
        pause.wait(0.002)
    return False


def test_runner_scans_until_stopped_and_leaves_outputs_off() -> None:
    engine = engine_for("RD X0.0\nWRT Y0.0\nRD X0.0\nWRT K0.0", period_ms=1)
    engine.memory.set_bit(at("X0.0"), 1)
    trace = engine.start_trace([at("Y0.0")], 1)
    runner = RealTimeRunner(engine)
    assert runner.stats() == ScanStats()
    runner.start()
    assert wait_until(lambda: engine.scan_count >= 5)
    runner.stop()
    assert not runner.running
    stats = runner.stats()
    assert stats.scans == engine.scan_count >= 5
    assert 0 <= stats.min_ms <= stats.avg_ms <= stats.max_ms
    assert 0 < stats.cpu_avg_ms <= stats.avg_ms * 1.5  # CPU time of the scan thread
    assert 0 <= stats.late_max_ms < 1000
    assert bit(engine, "Y0.0") == 0  # the safe state
    assert bit(engine, "K0.0") == 1  # kept
    samples = trace.take()
    assert [s.seq for s in samples] == list(range(len(samples)))  # none lost
    assert [s.time_ms for s in samples] == list(range(len(samples)))
    assert all(s.values == (1,) for s in samples)


def test_runner_can_restart_and_reset_its_figures() -> None:
    engine = engine_for("RD X0.0\nWRT Y0.0", period_ms=1)
    runner = RealTimeRunner(engine)
    runner.start()
    runner.start()  # already running: nothing happens
    assert wait_until(lambda: engine.scan_count >= 2)
    runner.stop()
    runner.reset_stats()
    assert runner.stats().scans == 0
    runner.start()
    assert wait_until(lambda: runner.stats().scans >= 2)
    runner.stop()
    assert runner.stats().scans >= 2


def test_runner_says_when_the_next_scan_is_due() -> None:
    engine = engine_for("RD X0.0\nWRT Y0.0", period_ms=1000)
    runner = RealTimeRunner(engine)
    assert runner.due_in() == 0  # not started
    runner.start()
    assert wait_until(lambda: engine.scan_count >= 1 and runner.due_in() > 0)
    assert 0.5 < runner.due_in() <= 1.0  # a second's period: the next scan is most of it away
    runner.stop()


def test_runner_counts_the_scans_cpu_time_apart_from_a_wait() -> None:
    engine = engine_for("RD X0.0\nWRT Y0.0", period_ms=20)
    runner = RealTimeRunner(engine)
    original = engine.scan

    def scan_then_sleep() -> None:  # a scan that waits 5 ms (as for the interpreter's lock)
        original()
        time.sleep(0.005)

    engine.scan = scan_then_sleep  # type: ignore[method-assign]
    runner.start()
    assert wait_until(lambda: runner.stats().scans >= 3)
    runner.stop()
    stats = runner.stats()
    assert stats.avg_ms >= 5 > stats.cpu_avg_ms * 2
