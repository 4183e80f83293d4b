"""What moves between the IDE's engine and a scan process: an engine's state and its setup."""

from __future__ import annotations

import threading
import time
from dataclasses import dataclass
from typing import Any

from ladderworks.core.address import Address
from ladderworks.core.plc.forcing import ForceTable

POLL_S = 0.0001  # how often a thread of the IDE's looks whether the scan process's lock is free


@dataclass(slots=True)
class ScanState:
    """What an engine's next scan depends on besides memory: clock, call-site states, edges."""

    now_ms: int
    scan_count: int
    first_scan: bool
    states: list[dict[str, Any]]  # one per op (the call sites' timers, counters, edges)
    edges: dict[tuple[str, int], bool]  # DIFU/DIFD memories, by number
    alarm_bits: bytes  # the A area the last scan left (a change is logged)


@dataclass(frozen=True, slots=True)
class TraceSpec:
    """A trace sampler's settings and where it is: a sampler like it is made elsewhere."""

    ident: int  # which sampler of the IDE's the samples go to
    addresses: tuple[Address, ...]
    period_ms: int
    capacity: int
    widths: tuple[int, ...]
    next_ms: int | None
    seq: int


@dataclass(frozen=True, slots=True)
class ScanSetup:
    """What a user sets on a running PLC: forces, disabled elements, the trace."""

    forced: dict[Address, bool]
    disabled: dict[int, int]  # op index -> source line
    trace: TraceSpec | None

    def force_table(self) -> ForceTable:
        """A force table holding these forces and disabled elements."""
        table = ForceTable()
        for address, value in self.forced.items():
            table.force(address, value)
        for op, line in self.disabled.items():
            table.disable(op, line)
        return table


def _take(shared: Any, blocking: bool, timeout: float) -> bool:
    """Take the scan process's lock without waiting for it inside the call: a blocking wait
    gives up the interpreter's lock, and a thread that got the process's lock could then wait
    for the interpreter while another thread of the IDE's holds it in a long call, the scan
    process waiting all that time. Polled, the lock is only ever taken with the interpreter."""
    end = None if timeout < 0 else time.perf_counter() + timeout
    while not shared.acquire(False):
        if not blocking or (end is not None and time.perf_counter() > end):
            return False
        time.sleep(POLL_S)
    return True


class ScanLock:
    """The engine's lock: a thread lock and, while a scan process runs, that process's lock.

    The same object for the engine's whole life, so a thread that waits for it while the scan
    moves to or from a process still gets both locks it needs."""

    def __init__(self) -> None:
        self._local = threading.RLock()
        self.shared: Any = None  # the scan process's lock (multiprocessing RLock) or None
        self._taken = threading.local()

    def acquire(self, blocking: bool = True, timeout: float = -1) -> bool:
        """Take the lock (as threading.RLock.acquire); False if not taken in time."""
        if not self._local.acquire(blocking, timeout):
            return False
        shared = self.shared
        if shared is not None and not _take(shared, blocking, timeout):
            self._local.release()
            return False
        stack = getattr(self._taken, "stack", None)
        if stack is None:
            stack = self._taken.stack = []
        stack.append(shared)
        return True

    @property
    def local(self) -> threading.RLock:
        """The thread lock alone: for what only this process's threads share (the scan
        process's output the IDE keeps)."""
        return self._local

    def release(self) -> None:
        """Give the lock back."""
        shared = self._taken.stack.pop()
        if shared is not None:
            shared.release()
        self._local.release()

    def __enter__(self) -> ScanLock:
        self.acquire()
        return self

    def __exit__(self, *exc: object) -> None:
        self.release()
