"""The time chart's record: every trace sample taken so far, read back as held values and edges."""

from __future__ import annotations

from array import array
from bisect import bisect_right
from collections.abc import Iterable
from dataclasses import dataclass

from ladderworks.core import dialects
from ladderworks.core.address import Address
from ladderworks.core.dialects import typed_target
from ladderworks.core.plc.trace import TraceSample
from ladderworks.core.symbols import SymbolTable
from ladderworks.core.tag_names import names_for


@dataclass(frozen=True, slots=True)
class TracedSignal:
    """One lane of the chart: a bit (0/1) or a value of `width` bytes starting at a byte."""

    address: Address
    width: int = 1
    spelled: str = ""  # the address as the program's dialect writes it (`D0`), "" for the PMC's
    type_name: str = ""  # an S7 tag's type (`Time`, `Real`, `Int`): how its values are written

    @property
    def is_bit(self) -> bool:
        """True for a bit lane (drawn 0/1), False for a value lane."""
        return self.address.bit is not None

    @property
    def label(self) -> str:
        """The lane's name as typed in the CSV header: `R1.4`, `R100`, `D10:2` for 2 bytes; a
        dialect's device as the program writes it (`X0`, `D0`)."""
        if self.spelled:
            return self.spelled
        text = str(self.address)
        return text if self.width == 1 else f"{text}:{self.width}"

    @property
    def maximum(self) -> int:
        """The largest value the lane can hold."""
        return 1 if self.is_bit else (1 << (8 * self.width)) - 1


def parse_traced(text: str, symbols: SymbolTable | None = None,
                 dialect: str | None = None) -> TracedSignal:
    """`R1.4`, `R100`, `D10:2` (a 2-byte value), `D20:4`, or a program symbol (`ESKIP`); in a
    Delta program Delta's devices (`X10`, `D0`); raises AddressError (see `parse_target`)."""
    names = names_for(symbols, dialect)
    if names.typed:  # S7: a tag with its type's width (`"Motor".Q`, `"T1".ET`), or `%MW2`
        named = names.resolve(text)
        return TracedSignal(named.address, named.width, named.text, named.type_name)
    target = typed_target(text, symbols.address_of if symbols is not None else None, dialect)
    return traced(target.address, target.width, dialect)


def traced(address: Address, width: int, dialect: str | None = None) -> TracedSignal:
    """The lane of `address` (`width` bytes), labelled in the spelling of `dialect`."""
    if dialects.get(dialect) is None:
        return TracedSignal(address, width)
    return TracedSignal(address, width, dialects.format_address(address, dialect))


class TraceRecord:
    """Samples in the order the engine took them: time, sequence number and one value per lane.

    A value holds from its sample's time until the next sample (sample and hold): that is how
    the chart draws it and how `value_at` reads it.
    """

    def __init__(self, signals: Iterable[TracedSignal] = ()) -> None:
        self.signals: list[TracedSignal] = list(signals)
        self.period_ms = 0
        self.times = array("q")
        self.seqs = array("q")
        self.lanes: list[array[int]] = [array("q") for _ in self.signals]
        self._edges: list[list[tuple[int, int]]] = [[] for _ in self.signals]

    def __len__(self) -> int:
        return len(self.times)

    def clear(self) -> None:
        """Forget every sample (the lanes stay)."""
        self.times = array("q")
        self.seqs = array("q")
        self.lanes = [array("q") for _ in self.signals]
        self._edges = [[] for _ in self.signals]

    def extend(self, samples: Iterable[TraceSample]) -> int:
        """Append samples (oldest first); returns how many were added."""
        added = 0
        for sample in samples:
            if len(sample.values) != len(self.lanes):
                raise ValueError(
                    f"a sample has {len(sample.values)} values for {len(self.lanes)} lanes")
            self.times.append(sample.time_ms)
            self.seqs.append(sample.seq)
            for lane, edges, value in zip(self.lanes, self._edges, sample.values, strict=True):
                if not lane or lane[-1] != value:
                    edges.append((sample.time_ms, value))
                lane.append(value)
            added += 1
        return added

    @property
    def start_ms(self) -> int | None:
        """Time of the first sample."""
        return self.times[0] if self.times else None

    @property
    def end_ms(self) -> int | None:
        """Time at which the last sample stops holding (last sample + one period)."""
        if not self.times:
            return None
        return self.times[-1] + max(self.period_ms, 0)

    def index_at(self, time_ms: float) -> int | None:
        """Index of the sample holding at `time_ms` (None before the first or after the end)."""
        if not self.times or time_ms < self.times[0]:
            return None
        end = self.end_ms
        if end is not None and self.period_ms and time_ms >= end:
            return None
        return bisect_right(self.times, time_ms) - 1

    def value_at(self, lane: int, time_ms: float) -> int | None:
        """The value lane `lane` held at `time_ms` (None outside the record)."""
        index = self.index_at(time_ms)
        return None if index is None else self.lanes[lane][index]

    def edges(self, lane: int) -> list[tuple[int, int]]:
        """Each change of a lane as (time_ms, new value); the first sample counts as a change."""
        return list(self._edges[lane])

    def rising_edges(self, lane: int) -> list[int]:
        """Times at which a lane went from 0 to non-zero (not counting the first sample)."""
        return [time for index, (time, value) in enumerate(self.edges(lane))
                if index > 0 and value]

    def steps(self, lane: int) -> tuple[list[int], list[int]]:
        """A lane as steps: `x` has one more entry than `y`; y[i] holds from x[i] to x[i+1]."""
        found = self.edges(lane)
        if not found:
            return [], []
        xs = [time for time, _value in found]
        ys = [value for _time, value in found]
        end = self.end_ms
        xs.append(end if end is not None and end > xs[-1] else xs[-1] + 1)
        return xs, ys

    def csv_text(self) -> str:
        """The record as CSV, as `ladderworks-cli run --trace` prints it: `time_ms,ADDR,...`."""
        lines = ["time_ms," + ",".join(signal.label for signal in self.signals)]
        for index, time_ms in enumerate(self.times):
            lines.append(f"{time_ms}," + ",".join(str(lane[index]) for lane in self.lanes))
        return "\n".join(lines) + "\n"
