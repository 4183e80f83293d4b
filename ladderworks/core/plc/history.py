"""Time travel: a bounded history of every scan's memory and power flow (changes only).

The engine calls `record(engine)` after each scan while a history is attached. Scans are kept
in segments: a keyframe (a full copy of every area and of the power flow) every
`keyframe_every` scans, then per scan only the 64-byte blocks that changed. When the bytes
kept pass `budget_bytes`, the oldest segment goes. `frame(scan)` rebuilds any kept scan;
`why(address, scan)` finds the scan where a bit last changed and the contacts that changed it.
"""

from __future__ import annotations

from bisect import bisect_right
from collections import deque
from dataclasses import dataclass, field
from typing import Protocol

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.instructions import Combine, Write
from ladderworks.core.plc.memory import Memory


class ScanSource(Protocol):
    """What the history reads of the engine whose scans it keeps (`engine.ScanEngine`)."""

    program: BinaryProgram
    memory: Memory
    now_ms: int
    scan_count: int

    @property
    def power_flow(self) -> bytearray:
        """The last scan's result of every op, one byte per op."""


BLOCK = 64
KEYFRAME_EVERY = 256
DEFAULT_BUDGET = 200 * 1024 * 1024
_ENTRY_OVERHEAD = 200  # bytes of Python objects per kept scan, beyond the data (measured)
_BLOCK_OVERHEAD = 90  # per changed block (tuple, bytes object header)
FLOW = "flow"  # the key of the power flow among the areas of a delta

Delta = tuple[tuple[Area | str, int, bytes], ...]


@dataclass(frozen=True, slots=True)
class HistoryFrame:
    """The PLC right after scan `scan` (run at `time_ms`): every area and the power flow."""

    scan: int
    time_ms: int
    areas: dict[Area, bytes]
    power_flow: bytes


@dataclass(frozen=True, slots=True)
class Why:
    """Where a bit changed: the scan, its time, the new value and the contacts' op indices."""

    scan: int
    time_ms: int
    value: int
    writers: tuple[int, ...]  # the coils (ops) that write the bit
    contacts: tuple[int, ...]  # the contacts of their networks whose bit changed then


@dataclass(slots=True)
class _Segment:
    scan: int
    time_ms: int
    areas: dict[Area | str, bytes]
    scans: list[int] = field(default_factory=list)  # the scans after the keyframe
    times: list[int] = field(default_factory=list)
    deltas: list[Delta] = field(default_factory=list)
    size: int = 0

    @property
    def last(self) -> int:
        return self.scans[-1] if self.scans else self.scan


def _changed_blocks(new: bytes | bytearray, old: bytearray) -> list[int]:
    """Offsets of the BLOCK-byte blocks in which `new` differs from `old`."""
    diff = int.from_bytes(new, "little") ^ int.from_bytes(old, "little")
    offsets = []
    mask = (1 << (8 * BLOCK)) - 1
    while diff:
        byte = ((diff & -diff).bit_length() - 1) >> 3
        offset = byte - byte % BLOCK
        offsets.append(offset)
        diff &= ~(mask << (8 * offset))
    return offsets


class ScanHistory:
    """The last scans of one engine, within `budget_bytes` (see the module text)."""

    def __init__(self, budget_bytes: int = DEFAULT_BUDGET,
                 keyframe_every: int = KEYFRAME_EVERY) -> None:
        self.budget_bytes = budget_bytes
        self.keyframe_every = keyframe_every
        self.segments: deque[_Segment] = deque()
        self.size = 0
        self._current: dict[Area | str, bytearray] = {}

    # -- recording -------------------------------------------------------------------------

    def record(self, engine: ScanSource) -> None:
        """Keep the state after the scan just run (called by the engine, under its lock)."""
        scan, now = engine.scan_count, engine.now_ms
        sources: dict[Area | str, bytearray] = {k: v for k, v in engine.memory.areas.items()}
        sources[FLOW] = engine.power_flow
        segment = self.segments[-1] if self.segments else None
        if (segment is None or scan - segment.scan >= self.keyframe_every
                or len(self._current) != len(sources)
                or len(self._current[FLOW]) != len(sources[FLOW])):
            self._keyframe(scan, now, sources)
        else:
            changes = []
            for key, data in sources.items():
                old = self._current[key]
                if data != old:
                    for offset in _changed_blocks(data, old):
                        block = bytes(data[offset:offset + BLOCK])
                        old[offset:offset + BLOCK] = block
                        changes.append((key, offset, block))
            size = _ENTRY_OVERHEAD + sum(len(b) + _BLOCK_OVERHEAD for _k, _o, b in changes)
            segment.scans.append(scan)
            segment.times.append(now)
            segment.deltas.append(tuple(changes))
            segment.size += size
            self.size += size
        while self.size > self.budget_bytes and len(self.segments) > 1:
            self.size -= self.segments.popleft().size

    def _keyframe(self, scan: int, now: int, sources: dict[Area | str, bytearray]) -> None:
        self._current = {key: bytearray(data) for key, data in sources.items()}
        areas = {key: bytes(data) for key, data in sources.items()}
        size = _ENTRY_OVERHEAD + sum(len(data) + 40 for data in areas.values())
        self.segments.append(_Segment(scan, now, areas, size=size))
        self.size += size

    def clear(self) -> None:
        """Forget every scan."""
        self.segments.clear()
        self.size = 0
        self._current = {}

    # -- reading ---------------------------------------------------------------------------

    @property
    def first_scan(self) -> int | None:
        """The oldest scan kept."""
        return self.segments[0].scan if self.segments else None

    @property
    def last_scan(self) -> int | None:
        """The newest scan kept."""
        return self.segments[-1].last if self.segments else None

    def __len__(self) -> int:
        return sum(1 + len(s.scans) for s in self.segments)

    def _segment(self, scan: int) -> _Segment | None:
        for segment in reversed(self.segments):
            if segment.scan <= scan:
                return segment if scan <= segment.last else None
        return None

    def scan_at(self, time_ms: float) -> int | None:
        """The last kept scan run at or before `time_ms` (the first kept one if before it)."""
        if not self.segments:
            return None
        for segment in reversed(self.segments):
            if segment.time_ms <= time_ms:
                index = bisect_right(segment.times, time_ms)
                return segment.scans[index - 1] if index else segment.scan
        return self.segments[0].scan

    def frame(self, scan: int) -> HistoryFrame | None:
        """The state right after `scan`, or None when it is not kept."""
        segment = self._segment(scan)
        if segment is None:
            return None
        state = {key: bytearray(data) for key, data in segment.areas.items()}
        time_ms = segment.time_ms
        for at, when, delta in zip(segment.scans, segment.times, segment.deltas, strict=True):
            if at > scan:
                break
            time_ms = when
            for key, offset, block in delta:
                state[key][offset:offset + len(block)] = block
        flow = bytes(state.pop(FLOW))
        return HistoryFrame(scan, time_ms, {key: bytes(data) for key, data in state.items()
                                            if isinstance(key, Area)}, flow)

    def bit_changes(self, address: Address) -> list[tuple[int, int, int]]:
        """Every kept scan where a bit changed: (scan, time_ms, new value), oldest first."""
        assert address.bit is not None
        found: list[tuple[int, int, int]] = []
        value: int | None = None
        for segment in self.segments:
            now = segment.areas[address.area][address.byte] >> address.bit & 1
            if value is not None and now != value:
                found.append((segment.scan, segment.time_ms, now))
            value = now
            for at, when, delta in zip(segment.scans, segment.times, segment.deltas,
                                       strict=True):
                for key, offset, block in delta:
                    if key is address.area and offset <= address.byte < offset + len(block):
                        now = block[address.byte - offset] >> address.bit & 1
                        if now != value:
                            found.append((at, when, now))
                            value = now
        return found

    def why(self, engine: ScanSource, address: Address, scan: int) -> Why | None:
        """The last change of a bit at or before `scan`, with the coils that write it and the
        contacts of their networks whose bit changed in that scan (None if it never changed)."""
        changes = [c for c in self.bit_changes(address) if c[0] <= scan]
        if not changes:
            return None
        at, when, value = changes[-1]
        earlier, before, after = self.frame(at - 2), self.frame(at - 1), self.frame(at)
        ops = engine.program.ops
        writers = tuple(i for i, op in enumerate(ops) if op.operand == address
                        and op.spec.write is not Write.NONE)
        networks = {ops[i].source.network for i in writers}
        contacts: list[int] = []
        if before is not None and after is not None:
            frames = [f for f in (earlier, before, after) if f is not None]
            for index, op in enumerate(ops):
                operand = op.operand
                if (op.source.network not in networks or op.spec.combine is Combine.NONE
                        or operand is None or operand.bit is None or operand == address):
                    continue  # a self-holding contact never explains its own coil
                flowed = before.power_flow[index] != after.power_flow[index]
                # the value the scan read: before it ran or, if written earlier in it, after
                values = {f.areas[operand.area][operand.byte] >> operand.bit & 1 for f in frames}
                if len(values) > 1 and (flowed or not any(after.power_flow)):
                    contacts.append(index)
        return Why(at, when, value, writers, tuple(contacts))
