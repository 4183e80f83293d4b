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
from ladderworks.core.compiler.binary import Op
from ladderworks.core.plc.functions import NEVER, FunctionContext

# state keys that hold time: they may grow between the two ends of a cycle ("at" is the scan
# a call site last ran in; "elapsed" and "ms" the time a timer has counted)
ACCUMULATORS = frozenset({"elapsed", "ms", "at"})
MAX_PERIOD = 4  # the longest cycle looked for, in scans
MAX_WAIT = 64  # scans between two tries at most, after tries whose states differed
ROUNDS = 2  # a state is compared with the one at the start of one or two rounds before

Clock = tuple[int, int]  # (period, time on) in ms; on while time % period < time on
ClockRelay = tuple[Address, int, int]  # a clock's bit, period and time on
# the states' copies (or the live ones), the edge memories, what was sent, the native
# scan's state words (b"" for the Python scan)
Hidden = tuple[list[dict[str, Any]], dict[Any, bool], tuple[Any, ...], bytes]
# what grew in the dicts, and in the native scan's state words (native/helpers.py's Grown)
Growth = tuple[list[tuple[dict[str, Any], str, int]], Any]


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


# the time from a place in the clocks' and scans' common period to the next clock change,
# by the scan period and the clocks (CycleSkipper._next_change)
_CHANGES: dict[tuple[int, tuple[Clock, ...]], dict[int, int]] = {}

_READ: dict[tuple[int, tuple[ClockRelay, ...], str],
            tuple[tuple[Op, ...], tuple[ClockRelay, ...]]] = {}


def clocks_read(ops: tuple[Op, ...], clocks: Iterable[ClockRelay], dialect: str
                ) -> tuple[ClockRelay, ...]:
    """The clocks whose bit an op reads (or may: an operand on it, a parameter whose extent
    covers its byte, by the instruction table's widths); the others cannot change a scan.
    Kept for the last few programs (a scenario's next engine of the same binary)."""
    clocks = tuple(clocks)
    key = (id(ops), clocks, dialect)
    kept = _READ.get(key)
    if kept is not None and kept[0] is ops:
        return kept[1]
    found = _clocks_read(ops, clocks, dialect)
    if len(_READ) >= 4:
        _READ.pop(next(iter(_READ)))
    _READ[key] = ops, found
    return found


def _clocks_read(ops: Iterable[Op], clocks: tuple[ClockRelay, ...], dialect: str
                 ) -> tuple[ClockRelay, ...]:
    from ladderworks.core.xref import function_operands

    found: set[ClockRelay] = set()
    for op in ops:
        operand = op.operand
        if operand is not None:
            uses = [(operand, 0 if operand.is_bit else 1)]
        elif any(isinstance(value, Address) for value in op.params):
            uses = [(o.address, o.width) for o in function_operands(op.spec, op.params, dialect)]
        else:
            continue
        for clock in clocks:
            bit = clock[0]
            for address, width in uses:
                if address.area is not bit.area:
                    continue
                if (address.byte == bit.byte and (address.bit is None or address.bit == bit.bit)
                        if width <= 1 else address.byte <= bit.byte < address.byte + width):
                    found.add(clock)
    return tuple(clock for clock in clocks if clock in found)


@dataclass(slots=True)
class _Seen:
    """The state after one scan: memory, the states beside it, what its timers said."""

    fingerprint: bytes
    hidden: Hidden
    alarms: int
    at_ms: int  # the scan's time
    wake_ms: int  # the earliest time a timer of the scan said it acts otherwise


class CycleSkipper:
    """Watches the scans of one run (`ScanEngine.advance`) and says how many to skip.

    After each scan it keeps the state (memory as one bytes object, copies of the call sites'
    states that hold anything) of the last `MAX_PERIOD` scans; a scan whose state equals one
    of those (timers' time aside) closes a cycle. A skip that ends inside a cycle puts back
    the state of the cycle's scan at that place (native scans, unmonitored, no call-back
    holding a state). With a native scan (`native`: its
    `skip_*` methods, native/scan.py) the states in its state words are kept as one bytes
    object and moved on there; only the call-backs' states are dicts.
    """

    def __init__(self, areas: Mapping[Area, bytearray], states: tuple[dict[str, Any], ...],
                 ctx: FunctionContext, clocks: tuple[ClockRelay, ...], period_ms: int,
                 divisions: int = 1, unread: tuple[ClockRelay, ...] = (),
                 native: Any = None, monitored: bool = False) -> None:
        self._areas = tuple(areas.values())
        # a skip may end inside a cycle (the state of the cycle's scan at that place put back)
        # where that state is all kept: memory and the native scan's state words, with no
        # call-back's dict and no power flow to put back
        self._phases = native is not None and not monitored
        self.native = native
        self._states = native.callback_states() if native is not None else states
        # a native scan that calls nothing back: its state words are all there is beside
        # memory (its edge memories are among them; nothing else sends or keeps anything)
        self._alone = native is not None and not self._states
        self._pinned: Any = None  # the areas as `_restore` writes them (native/helpers.Areas)
        self._ctx = ctx
        self._clocks = tuple((period, on) for _bit, period, on in clocks)
        # the bits of clocks no op reads, left out of the state (set from the time after a
        # skip): each as its area, its byte and the mask that keeps the others
        self._unread = tuple((areas[bit.area], bit.byte, 0xFF ^ (1 << (bit.bit or 0)))
                             for bit, _period, _on in unread)
        self._period = period_ms
        # the clocks' and the scans' common period, and the time to the next change of a
        # clock from each place in it (`_next_change`)
        self._common = lcm(period_ms, *(period for period, _on in self._clocks))
        self._changes = _CHANGES.setdefault((period_ms, self._clocks), {})
        self._lengths = tuple(p for p in range(1, MAX_PERIOD + 1) if p % divisions == 0)
        # the clocks' common period (in whole level-2 cycles): the state at scans that far
        # apart is compared, and a state that comes back skips whole such periods
        self._round = lcm(*(period for period, _on in self._clocks), period_ms * divisions) \
            if self._clocks else 0
        # the states after the last scans at a round's start (one round, or two: a bit that
        # flips every scan is the other way round after an odd number of scans)
        self._marks: deque[_Seen] = deque(maxlen=ROUNDS)
        self._ring: deque[_Seen] = deque(maxlen=MAX_PERIOD)
        self._track()
        self._wait = 0  # scans before the next try
        self._misses = 0  # tries in a row whose states differed
        # the native scan's states cost little to keep and compare: a try after every scan
        self._max_wait = 0 if native is not None else MAX_WAIT
        self.moved: list[dict[str, Any]] = []  # the states the last skip moved on

    def _track(self) -> None:
        """Copy only the states that hold something: a state never empties within a run (only
        a cold start clears them), so one empty at the end of a cycle was empty all along.
        The states kept so far copied fewer: they are forgotten."""
        self._held = [state for state in self._states if state]
        self._empty = [state for state in self._states if not state]
        self._ring.clear()
        self._marks.clear()

    def _hidden(self, live: bool = False) -> Hidden:
        """The state beside memory: copies of the call sites' states, or the live ones."""
        if self._alone:
            return [], {}, (), self.native.skip_state()
        ctx = self._ctx
        sent = tuple(getattr(value, "writes", None) for value in ctx.extra.values())
        held = list(self._held) if live else [state.copy() for state in self._held]
        words = self.native.skip_state() if self.native is not None else b""
        return held, dict(ctx.edges), sent, words

    def after_scan(self, next_ms: int, limit_ms: int, alarms: int) -> int:
        """Called after each scan (`next_ms` the next scan's time, `alarms` the count of A-area
        changes so far): how many of the scans due before `limit_ms` may be skipped now (their
        timers already moved on)."""
        ctx = self._ctx
        wake, ctx.wake_ms = ctx.wake_ms, NEVER  # what this scan's timers said
        unread = self._unread
        if unread:  # left out for the copy, put back after it
            values = [data[at] for data, at, _keep in unread]
            for data, at, keep in unread:
                data[at] &= keep
            fingerprint = b"".join(self._areas)
            for (data, at, _keep), value in zip(unread, values, strict=True):
                data[at] = value
        else:
            fingerprint = b"".join(self._areas)
        ring = self._ring
        seen = _Seen(fingerprint, self._hidden(), alarms, next_ms - self._period, wake)
        if self._round and seen.at_ms % self._round == 0:  # a round begins: compare
            skipped = self._close_round(seen, limit_ms)
            if skipped:
                return skipped
        if self._wait:
            self._wait -= 1
        else:
            for length in self._lengths:
                if length <= len(ring) and ring[-length].fingerprint == fingerprint:
                    skipped = self._close(length, seen, next_ms, limit_ms)
                    if skipped:
                        return skipped
                    break
        if len(seen.hidden[0]) != len(self._held):  # tracked afresh meanwhile: copy again
            seen = _Seen(fingerprint, self._hidden(), seen.alarms, seen.at_ms, seen.wake_ms)
        ring.append(seen)
        return 0

    def _grown(self, before: Hidden) -> Growth | None:
        """What the time values grew by since `before`, or None when anything else differs."""
        after = self._hidden(live=True)
        growth = _growth(before, after)
        if growth is None:
            return None
        if self.native is None:
            return growth, None
        words = self.native.skip_growth(before[3], after[3])
        return None if words is None else (growth, words)

    def _wakes(self, growth: Growth, last_ms: int) -> list[int]:
        """The wake times of the timers whose time grows (`last_ms` for one without)."""
        found = [state.get("wake", last_ms) for state, key, _step in growth[0] if key != "at"]
        if growth[1]:
            wake = growth[1].wake
            found.append(last_ms if wake is None else wake)
        return found

    def _skip(self, growth: Growth, times: int) -> None:
        """Move each time key on by `times` times its growth; the scans kept are past (a
        round's marks are, too: the next round's start is no longer one round after them)."""
        for state, key, step in growth[0]:
            state[key] += step * times
        if growth[1]:
            self.native.skip_move(growth[1], times)
        self.moved = [state for state, _key, _step in growth[0]]
        self._ring.clear()

    def _close_round(self, seen: _Seen, limit_ms: int) -> int:
        """At a round's first scan: the scans of whole spans of rounds to skip when the state
        at the first scan of one or two rounds before came back (timers aside).

        The clocks repeat every round, so a state that comes back repeats the span for as
        long as no timer whose time grows over it reaches its next tick or preset (its
        "wake", in its state) and the A area changed nowhere in it.
        """
        marks = self._marks
        last_ms = seen.at_ms
        if marks and marks[-1].at_ms != last_ms - self._round:
            marks.clear()  # a skip or a run in between: not consecutive rounds
        for back in range(1, len(marks) + 1):
            mark = marks[-back]
            if mark.alarms != seen.alarms or mark.fingerprint != seen.fingerprint:
                continue
            if any(self._empty):
                self._track()
                return 0
            growth = self._grown(mark.hidden)
            if growth is None:
                continue
            span = back * self._round
            horizon = min([limit_ms, *self._wakes(growth, last_ms)])
            spans = max(0, (horizon - 1 - last_ms) // span)  # a timer that said nothing: 0
            if not spans:
                break
            self._skip(growth, spans)
            return spans * span // self._period
        marks.append(seen)
        return 0

    def _close(self, length: int, seen: _Seen, next_ms: int, limit_ms: int) -> int:
        """The scans to skip when the state `length` scans ago came back (timers aside), no
        clock changed and nothing changed the A area since: whole cycles up to the horizon."""
        ring = self._ring
        first = ring[-length]
        period = self._period
        last_ms = seen.at_ms
        growth = None
        if (seen.alarms == first.alarms
                and self._next_change(first.at_ms) > last_ms):
            if any(self._empty):  # a call site ran for the first time: copy it from now on
                self._track()
            else:
                growth = self._grown(first.hidden)
        if growth is None:
            self._misses += 1
            self._wait = min(self._max_wait, (1 << self._misses) - 1)
            return 0
        self._misses = 0
        wakes = min([seen.wake_ms, *(kept.wake_ms for kept in list(ring)[-length:])])
        horizon = min(wakes, limit_ms, self._next_change(last_ms))
        if self._round:  # the next round's first scan runs: it is compared with this one's
            horizon = min(horizon, last_ms - last_ms % self._round + self._round)
        cycles, rest = divmod(max(0, -(-(horizon - next_ms) // period)), length)
        if rest and not (self._phases and not self._held):
            rest = 0
        if rest:  # the state after `rest` more scans is the one `rest` scans into the cycle
            self._restore(ring[rest - length])
        if cycles or rest:
            self._skip(growth, cycles + (1 if rest else 0))
        return cycles * length + rest

    def _next_change(self, after_ms: int) -> int:
        """`clock_change(after_ms, ...)` with no limit, kept by the place of `after_ms` in the
        clocks' and the scans' common period (where they all repeat)."""
        phase = after_ms % self._common
        delta = self._changes.get(phase)
        if delta is None:
            delta = self._changes[phase] = \
                clock_change(after_ms, self._period, self._clocks, NEVER) - after_ms
        return after_ms + delta

    def _restore(self, seen: _Seen) -> None:
        """Put back memory and the native state words as they were after a scan of the ring
        (the clocks no op reads come back with the relays the engine sets after a skip)."""
        if self._pinned is None:
            from ladderworks.core.plc.native.helpers import Areas

            self._pinned = Areas(self._areas)
        self._pinned.put(seen.fingerprint)
        self.native.skip_restore(seen.hidden[3])


def _growth(before: Hidden, after: Hidden) -> list[tuple[dict[str, Any], str, int]] | None:
    """What each accumulator grew by from `before` to `after` (the states of `after` are the
    live ones), or None when anything else differs."""
    states, edges, sent, _words = before
    live, edges_after, sent_after, _words_after = after
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
