"""The trace sampler: bits and bytes sampled inside the scan loop into a ring buffer."""

from __future__ import annotations

import threading
from collections import deque
from dataclasses import dataclass

from ladderworks.core.address import Address
from ladderworks.core.plc.memory import Memory
from ladderworks.core.plc.scan_state import TraceSpec

DEFAULT_CAPACITY = 100_000


@dataclass(frozen=True, slots=True)
class TraceSample:
    """Values of the traced addresses at one scan: `time_ms` of that scan, `seq` its number."""

    seq: int
    time_ms: int
    values: tuple[int, ...]


class TraceSampler:
    """Samples `addresses` every `period_ms` of virtual time, at the end of a scan.

    A bit address gives 0/1, a byte address its byte (or a `widths[i]`-byte little-endian
    value). The period is met at scan granularity:
    a sample is taken by the first scan at or after each due time. Samples wait in a ring
    buffer of `capacity` until `take()`; `dropped` counts samples the buffer had to overwrite.
    """

    def __init__(self, addresses: list[Address], period_ms: int,
                 capacity: int = DEFAULT_CAPACITY, widths: list[int] | None = None) -> None:
        if period_ms <= 0:
            raise ValueError("the trace period must be at least 1 ms")
        self.addresses = list(addresses)
        self.period_ms = period_ms
        self._buffer: deque[TraceSample] = deque(maxlen=capacity)
        self._lock = threading.Lock()
        self._next_ms: int | None = None
        self._seq = 0
        self.dropped = 0
        widths = widths or [1] * len(self.addresses)
        self.widths = tuple(widths)
        self.ident = id(self)  # the samples of a scan process's copy come back to this one
        self._readers = [(address.area, address.byte, address.bit, width)
                         for address, width in zip(self.addresses, widths, strict=True)]

    def sample(self, memory: Memory, now_ms: int) -> None:
        """Called by the engine after each scan; records a sample when one is due."""
        if self._next_ms is None:
            self._next_ms = now_ms
        if now_ms < self._next_ms:
            return
        while self._next_ms <= now_ms:
            self._next_ms += self.period_ms
        areas = memory.areas
        order = memory.byteorder
        values = tuple(
            (areas[area][byte] >> bit & 1) if bit is not None
            else areas[area][byte] if width == 1
            else int.from_bytes(areas[area][byte:byte + width], order)
            for area, byte, bit, width in self._readers)
        with self._lock:
            if len(self._buffer) == self._buffer.maxlen:
                self.dropped += 1
            self._buffer.append(TraceSample(self._seq, now_ms, values))
            self._seq += 1

    def spec(self) -> TraceSpec:
        """The settings and position: a copy elsewhere samples on from here."""
        with self._lock:
            return TraceSpec(self.ident, tuple(self.addresses), self.period_ms,
                             self._buffer.maxlen or DEFAULT_CAPACITY, self.widths,
                             self._next_ms, self._seq)

    @classmethod
    def from_spec(cls, spec: TraceSpec) -> TraceSampler:
        """A sampler like the one `spec` describes, going on from its position."""
        sampler = cls(list(spec.addresses), spec.period_ms, spec.capacity, list(spec.widths))
        sampler.ident = spec.ident
        sampler.go_on(spec.next_ms, spec.seq)
        return sampler

    def go_on(self, next_ms: int | None, seq: int) -> None:
        """Take the next sample at `next_ms`, numbered `seq` (a copy's position)."""
        with self._lock:
            self._next_ms, self._seq = next_ms, seq

    def extend(self, samples: list[TraceSample]) -> None:
        """Keep samples a copy took (a scan process's), as if taken here."""
        with self._lock:
            for sample in samples:
                if len(self._buffer) == self._buffer.maxlen:
                    self.dropped += 1
                self._buffer.append(sample)
                self._seq = sample.seq + 1

    def take(self) -> list[TraceSample]:
        """Every sample not taken yet, oldest first (the buffer is emptied)."""
        with self._lock:
            samples = list(self._buffer)
            self._buffer.clear()
        return samples

    def __len__(self) -> int:
        return len(self._buffer)
