"""Trace files: our CSV (`time_ms,ADDR,...`) and FANUC LADDER-III's signal-trace result.

LADDER-III writes `Data, ADDR1, ADDR2, ...` then one row per sample: the frame count and one
value per address. Frame 0 is the trigger (or, without one, the last sample), so the frames
before it are negative. Values are 0/1 for bits; a byte lane (our extension) writes its value.
"""

from __future__ import annotations

from dataclasses import dataclass

from ladderworks.core.address import AddressError, parse_address
from ladderworks.core.il.textform import split_lines

LADDER3_ID = "Data"


@dataclass(slots=True)
class TraceTable:
    """A trace read from or written to a file: lane labels, sample times and one column each."""

    labels: list[str]
    times: list[int]
    columns: list[list[int]]


class TraceFileError(ValueError):
    """A trace file that cannot be read: `line` (1-based) and a reason."""

    def __init__(self, line: int, reason: str) -> None:
        self.line = line
        self.reason = reason
        super().__init__(f"line {line}: {reason}")


def ladder3_text(table: TraceTable, trigger_index: int | None = None) -> str:
    """The LADDER-III trace result text; frame 0 at `trigger_index` (default: last sample)."""
    zero = len(table.times) - 1 if trigger_index is None else trigger_index
    lines = [", ".join([LADDER3_ID, *table.labels])]
    for index in range(len(table.times)):
        values = [str(column[index]) for column in table.columns]
        lines.append(", ".join([str(index - zero), *values]))
    return "\r\n".join(lines) + "\r\n"


def csv_text(table: TraceTable) -> str:
    """Our CSV: `time_ms,ADDR,...`, one row per sample."""
    lines = ["time_ms," + ",".join(table.labels)]
    for index, time_ms in enumerate(table.times):
        lines.append(f"{time_ms}," + ",".join(str(c[index]) for c in table.columns))
    return "\n".join(lines) + "\n"


def _rows(text: str) -> list[tuple[int, list[str]]]:
    return [(number, [field.strip() for field in line.split(",")])
            for number, line in enumerate(split_lines(text), start=1) if line.strip()]


def read_trace(text: str, period_ms: int) -> TraceTable:
    """A LADDER-III trace result (frames × `period_ms`, the first at 0 ms) or our CSV."""
    rows = _rows(text)
    if not rows:
        raise TraceFileError(1, "the file is empty")
    number, header = rows[0]
    kind = header[0].lower()
    if kind not in (LADDER3_ID.lower(), "time_ms"):
        raise TraceFileError(number, f"expected '{LADDER3_ID}, ADDR...' or 'time_ms,ADDR...'")
    labels = [label for label in header[1:] if label]
    if not labels:
        raise TraceFileError(number, "no address in the header")
    _check_labels(labels, number)
    stamps: list[int] = []
    columns: list[list[int]] = [[] for _ in labels]
    for number, fields in rows[1:]:
        if len(fields) < len(labels) + 1:
            raise TraceFileError(number, f"expected {len(labels) + 1} fields")
        try:
            stamps.append(int(fields[0]))
            for column, field in zip(columns, fields[1:len(labels) + 1], strict=True):
                column.append(int(field, 0))
        except ValueError:
            raise TraceFileError(number, "not a number") from None
    if kind == "time_ms":
        return TraceTable(labels, stamps, columns)
    first = stamps[0] if stamps else 0
    return TraceTable(labels, [(frame - first) * period_ms for frame in stamps], columns)


def _check_labels(labels: list[str], line: int) -> None:
    for label in labels:
        spelled, _colon, _width = label.partition(":")
        try:
            parse_address(spelled)
        except AddressError:
            raise TraceFileError(line, f"'{label}' is not an address") from None
