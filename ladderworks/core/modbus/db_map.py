"""A map whose holding registers are a data block's bytes, as MB_SERVER's MB_HOLD_REG pointing at
a global DB: register n is the DB's bytes 2n and 2n + 1 (big-endian, as S7 stores them).

An S7 program's global DBs have no fixed offsets (optimized): their members lie where
LadderWorks laid them out (`core/dialects/s7/layout.py`), in member order, so register n is
the n-th word of that layout. The coils, discrete inputs and input registers stay the
dialect's (%Q, %I, %IW), as MB_SERVER keeps them whatever MB_HOLD_REG points at.
"""

from __future__ import annotations

from pathlib import Path

from ladderworks.core.diagnostics import Refused
from ladderworks.core.modbus.map_file import read_map
from ladderworks.core.modbus.maps import Access, MapRow, ModbusMap, Table, default_map
from ladderworks.core.symbols import SymbolTable


def data_blocks(symbols: SymbolTable | None) -> list[str]:
    """The names of a program's global DBs (`"DB_Modbus"`), as TIA writes them, in order."""
    if symbols is None:
        return []
    return [name for name, (type_name, _size) in symbols.types.items()
            if type_name == "Struct" and name.startswith('"') and name.count('"') == 2
            and name.endswith('"')]


def db_map(symbols: SymbolTable | None, name: str, dialect: str = "s7") -> ModbusMap:
    """The dialect's map with its holding registers replaced by the DB `name` (quoted or not);
    Refused `modbus-map-db` when the program has no such global DB."""
    wanted = f'"{name.strip().strip(chr(34))}"'
    found = next((db for db in data_blocks(symbols) if db.lower() == wanted.lower()), None)
    if found is None or symbols is None:
        raise Refused("modbus-map-db", name=name.strip(),
                      names=", ".join(data_blocks(symbols)) or "-")
    first = symbols.address_of(found)
    _type, size = symbols.types[found]
    if first is None:  # a DB laid out but with no member named: no register
        raise Refused("modbus-map-db", name=name.strip(), names=found)
    base = default_map(dialect)
    rows = [row for row in base.rows if row.table is not Table.HOLDING]
    count = max(1, (size + 1) // 2)
    rows.append(MapRow(Table.HOLDING, 0, count, f"D{first.byte}", Access.READ_WRITE, 2))
    return ModbusMap(f"{base.name} {found}", tuple(rows))


def chosen_map(text: str, dialect: str, symbols: SymbolTable | None) -> ModbusMap | None:
    """`--map TEXT`: None for "" (the dialect's own), a CSV file's map, or (when no such file
    exists and the program has global DBs) a DB's map. OSError or DiagnosticError."""
    text = text.strip()
    if not text:
        return None
    if Path(text).is_file() or not data_blocks(symbols):
        return read_map(text, dialect)
    return db_map(symbols, text, dialect)
