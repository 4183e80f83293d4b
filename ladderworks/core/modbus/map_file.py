"""A user's own Modbus map: a CSV file of rows `TABLE,START,COUNT,PLC ADDRESS,ACCESS[,WIDTH]`.

Blank lines and lines starting with `#` are skipped, and so is a first line naming the columns
(`table,start,...`). START and COUNT are decimal or `0x` hexadecimal; PLC ADDRESS is spelled
as the program's dialect spells it (`X2.0`, `D100` in a PMC program; `M0`, `D10` in a Delta
one). Every bad line is reported at its line number (docs/modbus.md).
"""

from __future__ import annotations

import csv
from pathlib import Path

from ladderworks.core.diagnostics import Diagnostic, DiagnosticError, Refused
from ladderworks.core.il.textform import split_lines
from ladderworks.core.modbus.cells import Cells, cells_for
from ladderworks.core.modbus.maps import LAST_ADDRESS, Access, MapRow, ModbusMap, Table

_TABLE_NAMES: dict[str, Table] = {
    **{table.value: table for table in Table},
    "coil": Table.COILS, "discrete_inputs": Table.DISCRETE, "holding_registers": Table.HOLDING,
    "input_registers": Table.INPUT,
}


def _number(text: str, lo: int, hi: int) -> int:
    """A decimal or 0x-hexadecimal whole number from lo to hi."""
    clean = text.strip()
    try:
        value = int(clean, 16) if clean.lower().startswith("0x") else int(clean, 10)
    except ValueError:
        raise Refused("modbus-map-number", text=clean, lo=lo, hi=hi) from None
    if not lo <= value <= hi:
        raise Refused("modbus-map-number", text=clean, lo=lo, hi=hi)
    return value


def parse_row(cells: list[str], line: int, elements: Cells) -> MapRow:
    """One row from its cells (Refused, with a diagnostic, when a cell is wrong); its PLC
    elements are checked by `elements` (the program's dialect's)."""
    if len(cells) not in (5, 6):
        raise Refused("modbus-map-columns", count=len(cells))
    table = _TABLE_NAMES.get(cells[0].strip().lower())
    if table is None:
        raise Refused("modbus-map-table", text=cells[0].strip())
    start = _number(cells[1], 0, LAST_ADDRESS)
    count = _number(cells[2], 1, LAST_ADDRESS + 1)
    if start + count - 1 > LAST_ADDRESS:
        raise Refused("modbus-map-end", start=start, count=count)
    access_text = cells[4].strip().lower()
    if access_text not in ("r", "rw"):
        raise Refused("modbus-map-access", text=cells[4].strip())
    access = Access(access_text)
    if access is Access.READ_WRITE and not table.writable:
        raise Refused("modbus-map-read-only", table=table.value)
    width = _number(cells[5], 1, 2) if len(cells) == 6 else 1
    if width != 1 and table.bits:
        raise Refused("modbus-map-bit-width", table=table.value)
    row = MapRow(table, start, count, cells[3].strip(), access, width, line)
    elements.check(row)
    return row


def parse_map(text: str, name: str = "map", dialect: str = "seed") -> ModbusMap:
    """A map from CSV text for programs of `dialect`; DiagnosticError with every bad line's
    diagnostic."""
    elements = cells_for(dialect)
    rows: list[MapRow] = []
    problems: list[Diagnostic] = []
    reader = csv.reader(split_lines(text))
    for number, cells in enumerate(reader, start=1):
        if not cells or not "".join(cells).strip() or cells[0].lstrip().startswith("#"):
            continue
        if not rows and not problems and cells[0].strip().lower() == "table":
            continue  # the column names
        try:
            row = parse_row(cells, number, elements)
        except DiagnosticError as error:
            problems.extend(Diagnostic(d.code, d.args, line=number, column=1)
                            for d in error.diagnostics)
            continue
        other = ModbusMap(name, tuple(rows)).overlap(row)
        if other is not None:
            problems.append(Diagnostic("modbus-map-overlap", {
                "table": row.table.value, "start": row.start, "end": row.end - 1,
                "other": other.line}, line=number, column=1))
            continue
        rows.append(row)
    if not rows and not problems:
        problems.append(Diagnostic("modbus-map-empty", {}, line=1, column=1))
    if problems:
        raise DiagnosticError(problems)
    return ModbusMap(name, tuple(rows))


def read_map(path: str | Path, dialect: str = "seed") -> ModbusMap:
    """A map from a CSV file (UTF-8, a BOM allowed); OSError or DiagnosticError."""
    return parse_map(Path(path).read_text(encoding="utf-8-sig"), str(path), dialect)
