"""Scans skipped exactly: a program whose whole state repeats every p scans is not scanned
again until something can differ (a timer's tick or preset, a clock relay's edge, the end
of the run asked for); the skipped scans' effect is applied at once. docs/engine.md.

The state is everything a scan reads: every byte of memory, every function call's state
(timers, counters, edges), the DIFU/DIFD edge memories and the count of what the functions
sent out (FUN 94's terminal). A scan is a function of that state, the forces and disabled
elements (fixed while the engine's lock is held), the clock relays and the time the timers
count. So if the state after scan k + p equals the state after scan k, except for the keys in
`ACCUMULATORS` which grew by the same amount in every timer that runs, the scans after k + p
repeat scans k + 1 .. k + p for as long as no timer reaches a tick or its preset (each says
when: `FunctionContext.wake`) and no clock relay changes: those scans are skipped in whole
cycles of p, and the accumulators moved on by what the skipped cycles would have added.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from math import lcm
from typing import Any

from ladderworks.core.address import Address, Area
from ladderworks.core.plc.functions import NEVER, FunctionContext

# state keys that hold time: they may grow between the two ends of a cycle ("at" is the scan
# a call site last ran in; "elapsed" and "ms" the time a timer has counted)
ACCUMULATORS = frozenset({"elapsed", "ms", "at"})
MAX_PERIOD = 4  # the longest cycle looked for, in scans
MAX_WAIT = 64  # scans between two tries at most, after tries whose states differed

Clock = tuple[int, int]  # (period, time on) in ms; on while time % period < time on
ClockRelay = tuple[Address, int, int]  # a clock's bit, period and time on
Hidden = tuple[list[dict[str, Any]], dict[Any, bool], tuple[Any, ...]]


def clock_change(after_ms: int, scan_ms: int, clocks: Iterable[Clock], limit_ms: int) -> int:
    """The first scan time after `after_ms` (scans every `scan_ms`) at which a clock reads
    otherwise than at `after_ms`; `limit_ms` when none does before it."""
    best = limit_ms
    for period, on in clocks:
        was = after_ms % period < on
        stop = min(best, after_ms + lcm(period, scan_ms) + period + 1)  # the pattern repeats
        start = after_ms - after_ms % period
        while start < stop:
            for edge in (start + on, start + period):
                if edge <= after_ms:
                    continue
                scan = after_ms + -(-(edge - after_ms) // scan_ms) * scan_ms  # first at/after
                if scan < best and (scan % period < on) != was:
                    best = scan
            start += period
    return best


@dataclass(slots=True)
class _Trial:
    """A cycle being confirmed: its length, the state at its start (and that scan's time),
    scans still to run."""

    period: int
    fingerprint: bytes
    hidden: Hidden
    alarms: int
    left: int
    started_ms: int
    wake_ms: int  # the earliest wake said in the cycle's scans and the one before them


class CycleSkipper:
    """Watches the scans of one run (`ScanEngine.advance`) and says how many to skip."""

    def __init__(self, areas: Mapping[Area, bytearray], states: tuple[dict[str, Any], ...],
                 ctx: FunctionContext, clocks: tuple[ClockRelay, ...], period_ms: int,
                 divisions: int = 1) -> None:
        self._areas = tuple(areas.values())
        self._states = states
        self._ctx = ctx
        self._clocks = tuple((period, on) for _bit, period, on in clocks)
        offsets, at = {}, 0
        for area, data in areas.items():
            offsets[area], at = at, at + len(data)
        # the clock relays' bytes, left out when looking for a cycle (not when confirming one):
        # a clock's edge that changes nothing else finds the cycle of before it at once
        self._clock_bytes = sorted({offsets[bit.area] + bit.byte for bit, _p, _o in clocks
                                    if bit.area in offsets})
        self._period = period_ms
        self._lengths = tuple(p for p in range(1, MAX_PERIOD + 1) if p % divisions == 0)
        self._ring: deque[bytes] = deque(maxlen=MAX_PERIOD)
        self._trial: _Trial | None = None
        self._wait = 0  # scans before the next try
        self._misses = 0  # tries in a row whose states differed
        self.skipped = 0  # scans skipped in this run
        self.tries = 0  # cycles tried (figures for the benchmark)

    def _fingerprint(self) -> bytes:
        return b"".join(self._areas)

    def _without_clocks(self, fingerprint: bytes) -> bytes:
        if not self._clock_bytes:
            return fingerprint
        masked = bytearray(fingerprint)
        for at in self._clock_bytes:
            masked[at] = 0
        return bytes(masked)

    def _hidden(self, live: bool = False) -> Hidden:
        """The state beside memory: copies of the call sites' states, or the live ones."""
        ctx = self._ctx
        sent = tuple(getattr(value, "writes", None) for value in ctx.extra.values())
        states = list(self._states) if live else [state.copy() for state in self._states]
        return states, dict(ctx.edges), sent

    def after_scan(self, next_ms: int, limit_ms: int, alarms: int) -> int:
        """Called after each scan (`next_ms` the next scan's time, `alarms` the count of A-area
        changes so far): how many of the scans due before `limit_ms` may be skipped now (their
        timers already moved on)."""
        fingerprint = self._fingerprint()
        looked = self._without_clocks(fingerprint)
        ctx = self._ctx
        wake, ctx.wake_ms = ctx.wake_ms, NEVER  # what this scan's timers said
        trial = self._trial
        skipped = 0
        if trial is not None:
            trial.wake_ms = min(trial.wake_ms, wake)
            trial.left -= 1
            if trial.left == 0:
                self._trial = None
                skipped = self._conclude(trial, fingerprint, next_ms, limit_ms, alarms)
        elif self._wait:
            self._wait -= 1
        else:
            ring = self._ring
            for length in self._lengths:
                if length <= len(ring) and ring[-length] == looked:
                    self.tries += 1
                    self._trial = _Trial(length, fingerprint, self._hidden(), alarms, length,
                                         next_ms - self._period, wake)
                    break
        self._ring.append(looked)
        return skipped

    def _conclude(self, trial: _Trial, fingerprint: bytes, next_ms: int, limit_ms: int,
                  alarms: int) -> int:
        """Skip whole cycles when the state came back (timers aside) and nothing changed the
        A area in the cycle; the scans skipped."""
        growth = None
        period = self._period
        last_ms = next_ms - period
        if (fingerprint == trial.fingerprint and alarms == trial.alarms
                and clock_change(trial.started_ms, period, self._clocks, NEVER) > last_ms):
            growth = _growth(trial.hidden, self._hidden(live=True))
        if growth is None:
            self._misses += 1
            self._wait = min(MAX_WAIT, (1 << self._misses) - 1)
            return 0
        self._misses = 0
        horizon = min(trial.wake_ms, limit_ms,
                      clock_change(next_ms - period, period, self._clocks, limit_ms))
        cycles = max(0, -(-(horizon - next_ms) // period)) // trial.period
        if cycles:
            for state, key, step in growth:
                state[key] += step * cycles
            self.skipped += cycles * trial.period
        return cycles * trial.period


def _growth(before: Hidden, after: Hidden) -> list[tuple[dict[str, Any], str, int]] | None:
    """What each accumulator grew by from `before` to `after` (the states of `after` are the
    live ones), or None when anything else differs."""
    states, edges, sent = before
    live, edges_after, sent_after = after
    if edges != edges_after or sent != sent_after:
        return None
    growth = []
    for old, new in zip(states, live, strict=True):
        if old == new:
            continue
        if old.keys() != new.keys():
            return None
        for key, value in new.items():
            was = old[key]
            if value == was:
                continue
            if key not in ACCUMULATORS or type(value) is not int or type(was) is not int:
                return None
            growth.append((new, key, value - was))
    return growth
