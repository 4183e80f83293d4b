"""The watch table's rows: what a user typed (name, display format, modify value, checked),
kept per program as JSON, and the rows' modify values turned into stores."""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.symbols import SymbolTable
from ladderworks.core.watch.places import WatchError, WatchPlace, resolve
from ladderworks.core.watch.values import Format, Write, default_format, formats, parse

MAX_ROWS = 1000  # a kept table longer than this is cut (a damaged settings entry)


@dataclass(slots=True)
class WatchRow:
    """One row as the user set it; `fmt` "" shows the place's default format."""

    name: str
    fmt: str = ""
    modify: str = ""
    checked: bool = False


@dataclass(frozen=True, slots=True)
class Watched:
    """A row resolved in a program: its place and the format it is shown in."""

    place: WatchPlace
    fmt: Format


def watched(row: WatchRow, symbols: SymbolTable | None, dialect: str | None) -> Watched:
    """A row's place and format (the row's own when the place has it). WatchError."""
    place = resolve(row.name, symbols, dialect)
    fmt = Format(row.fmt) if row.fmt in set(Format) else None
    if fmt is None or fmt not in formats(place):
        fmt = default_format(place, dialect)
    return Watched(place, fmt)


def modify(rows: list[WatchRow], symbols: SymbolTable | None, dialect: str | None
           ) -> tuple[list[Write], dict[int, Diagnostic]]:
    """The stores the rows' modify values make, and the refusal of each row that has one
    (by its index): rows with an error write nothing, the others all they have."""
    writes: list[Write] = []
    errors: dict[int, Diagnostic] = {}
    for index, row in enumerate(rows):
        try:
            found = watched(row, symbols, dialect)
            writes += parse(found.place, found.fmt, row.modify)
        except WatchError as error:
            errors[index] = error.diagnostic
    return writes, errors


def store(writes: list[Write], set_bit: Callable[[Address, int], None],
          write: Callable[[Address, int, int], None]) -> None:
    """Make the stores through a PLC's machine side (`PlcRun` / `PlcSession`: set_bit, write)."""
    for found in writes:
        if found.width == 0:
            set_bit(found.address, found.value)
        else:
            write(found.address, found.value, found.width)


def rows_text(rows: list[WatchRow]) -> str:
    """The rows as JSON (kept in the settings per program)."""
    return json.dumps([{"name": r.name, "format": r.fmt, "modify": r.modify,
                        "checked": r.checked} for r in rows], ensure_ascii=False)


def rows_from_text(text: str) -> list[WatchRow]:
    """Rows read back from `rows_text`; what is not a row is left out (never an error)."""
    try:
        data = json.loads(text)
    except (ValueError, TypeError):
        return []
    rows: list[WatchRow] = []
    for item in data if isinstance(data, list) else []:
        if not isinstance(item, dict) or not isinstance(item.get("name"), str):
            continue
        fmt = item.get("format", "")
        modify_text = item.get("modify", "")
        rows.append(WatchRow(item["name"], fmt if isinstance(fmt, str) else "",
                             modify_text if isinstance(modify_text, str) else "",
                             item.get("checked") is True))
    return rows[:MAX_ROWS]
