"""Trace files: LADDER-III's signal-trace result and our CSV, written and read back."""

from __future__ import annotations

import pytest

from ladderworks.core.plc.trace_file import (
    TraceFileError,
    TraceTable,
    csv_text,
    ladder3_text,
    read_trace,
)

TABLE = TraceTable(["X2.1", "R1.7", "D10:2"], [0, 8, 16, 24], [[0, 1, 1, 0], [0, 0, 1, 1],
                                                               [0, 300, 300, 7]])


def test_ladder3_rows_end_at_frame_zero() -> None:
    text = ladder3_text(TABLE)
    assert text.splitlines() == ["Data, X2.1, R1.7, D10:2", "-3, 0, 0, 0", "-2, 1, 0, 300",
                                 "-1, 1, 1, 300", "0, 0, 1, 7"]
    assert ladder3_text(TABLE, trigger_index=1).splitlines()[1].startswith("-1, ")


@pytest.mark.parametrize("write", [ladder3_text, csv_text])
def test_round_trip(write: object) -> None:
    table = read_trace(write(TABLE), 8)  # type: ignore[operator]
    assert (table.labels, table.times, table.columns) == (TABLE.labels, TABLE.times,
                                                          TABLE.columns)


def test_frames_become_times_at_the_period() -> None:
    table = read_trace("Data, X0000.0\n-2, 1\n-1, 0\n0, 1\n", 16)
    assert (table.times, table.columns) == ([0, 16, 32], [[1, 0, 1]])


@pytest.mark.parametrize(("text", "line"), [
    ("", 1), ("Frames, X0.0\n", 1), ("Data, Q9\n", 1), ("Data, X0.0\n0\n", 2),
    ("Data, X0.0\n\n-1, x\n", 3),
])
def test_errors_name_their_line(text: str, line: int) -> None:
    with pytest.raises(TraceFileError) as caught:
        read_trace(text, 8)
    assert caught.value.line == line
