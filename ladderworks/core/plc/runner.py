"""The real-time runner: a plain thread that scans an engine at its period on the wall clock."""

from __future__ import annotations

import threading
import time
from dataclasses import dataclass

from ladderworks.core.plc.engine import ScanEngine


@dataclass(frozen=True, slots=True)
class ScanStats:
    """Scan-time figures in ms: how long the logic took, and how often a period was missed."""

    scans: int = 0
    min_ms: float = 0.0
    avg_ms: float = 0.0
    max_ms: float = 0.0
    overruns: int = 0  # scans that started late because the previous one ran past its period
    cpu_avg_ms: float = 0.0  # the scan thread's CPU time per scan (the rest of a scan's time
    # it waited: for the interpreter's lock, held by another thread, or for a processor)
    late_max_ms: float = 0.0  # the latest start after a scan's due time (waiting to wake up)


class Figures:
    """Scan-time figures as they accumulate (seconds): what `ScanStats` is made of."""

    def __init__(self) -> None:
        self.count, self.total, self.low, self.high = 0, 0.0, float("inf"), 0.0
        self.overruns, self.cpu, self.late = 0, 0.0, 0.0

    def add(self, took: float, cpu: float, late: float, overrun: bool) -> None:
        """Count one scan: its duration, its CPU time, how late it began, and an overrun."""
        self.count += 1
        self.total += took
        self.cpu += cpu
        self.late = max(self.late, late)
        self.low = min(self.low, took)
        self.high = max(self.high, took)
        self.overruns += overrun

    def values(self) -> tuple[int, float, float, float, int, float, float]:
        """Count, total, min, max, overruns, CPU, latest start (the scan process's header)."""
        low = self.low if self.count else 0.0
        return self.count, self.total, low, self.high, self.overruns, self.cpu, self.late


def stats_of(count: int, total: float, low: float, high: float, overruns: int, cpu: float,
             late: float) -> ScanStats:
    """The figures in ms from `Figures.values()`."""
    if not count:
        return ScanStats()
    return ScanStats(count, low * 1e3, total / count * 1e3, high * 1e3, overruns,
                     cpu / count * 1e3, late * 1e3)


class RealTimeRunner:
    """Scans `engine` every `engine.period_ms` of wall-clock time until `stop()`.

    The engine's virtual clock still advances one period per scan, so timers run at real
    speed as long as the scans keep up; a scan that finishes after its next start time counts
    as an overrun and the schedule restarts from now (scans are never bunched to catch up).
    """

    def __init__(self, engine: ScanEngine) -> None:
        self.engine = engine
        self._thread: threading.Thread | None = None
        self._stop = threading.Event()
        self._lock = threading.Lock()
        self._figures = Figures()
        self._next_start = 0.0  # perf_counter time the next scan is due
        self._scanning = False

    def due_in(self) -> float:
        """Seconds until the next scan starts: 0 while one runs or is late (the GUI thread
        times its long updates just after a scan, so the two do not wait for each other)."""
        if self._scanning:
            return 0.0
        return max(0.0, self._next_start - time.perf_counter())

    @property
    def running(self) -> bool:
        """True while the scan thread runs."""
        return self._thread is not None and self._thread.is_alive()

    def start(self) -> None:
        """Start scanning (no-op if already running)."""
        if self.running:
            return
        self._stop.clear()
        self._thread = threading.Thread(target=self._loop, name="plc-scan", daemon=True)
        self._thread.start()

    def stop(self, safe: bool = True) -> None:
        """Stop scanning and put the outputs in the safe state (every Y = 0; not `safe`:
        left as they are, the scans going on elsewhere)."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
            self._thread = None
        if safe:
            self.engine.stop()

    def stats(self) -> ScanStats:
        """The scan-time figures so far."""
        with self._lock:
            return stats_of(*self._figures.values())

    def reset_stats(self) -> None:
        """Start the figures afresh."""
        with self._lock:
            self._figures = Figures()

    def _loop(self) -> None:
        period = self.engine.period_ms / 1000.0
        next_start = time.perf_counter()
        while not self._stop.is_set():
            self._scanning = True
            began = time.perf_counter()
            due = next_start
            cpu = time.thread_time()
            self.engine.scan()
            cpu = time.thread_time() - cpu
            took = time.perf_counter() - began
            next_start += period
            self._next_start = next_start
            self._scanning = False
            now = time.perf_counter()
            late = now > next_start
            with self._lock:
                self._figures.add(took, cpu, began - due, late)
            if late:
                next_start = self._next_start = now
            else:
                self._stop.wait(next_start - now)
