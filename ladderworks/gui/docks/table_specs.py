"""One spec per PLC table (timers, counters, data table, keep relays): columns, rows, edits.

A spec says everything that differs between the tables; the model and the dock never ask
which table they show. Values the user sets go to the session as PMC parameters.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

from PySide6.QtCore import QCoreApplication

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects.device_tables import DeviceRow
from ladderworks.core.instructions import Numbered, numbered_row
from ladderworks.core.plc.functions.counters import counter_value_address
from ladderworks.gui.docks.table_entries import (
    Areas,
    CounterRow,
    DataRow,
    KeepRow,
    ProgramUse,
    TableError,
    TableKind,
    TimerRow,
    counter_number,
    counter_rows,
    counter_value,
    data_byte,
    data_rows,
    data_value,
    data_width,
    keep_bits,
    keep_byte,
    keep_rows,
    timer_number,
    timer_precision,
    timer_preset,
    timer_rows,
)
from ladderworks.gui.plc_session import PlcSession

translate = QCoreApplication.translate

Row = TimerRow | CounterRow | DataRow | KeepRow | DeviceRow  # DeviceRow: gui/docks/device_specs
# The instruction a timer row stands for, by `TimerRow.fixed`: TMR, TMRB.
_TIMER_NAMES = {False: numbered_row(Numbered.TIMER).name,
                True: numbered_row(Numbered.FIXED_TIMER).name}


@dataclass
class TableSpec:
    """What a table shows and how its cells and INSERT / DELETE store values (base class)."""

    kind: ClassVar[TableKind]

    def headers(self, session: PlcSession) -> list[str]:
        """The column titles in the current UI language."""
        raise NotImplementedError

    def form_fields(self, session: PlcSession) -> list[str]:
        """The INSERT form's field labels."""
        raise NotImplementedError

    def rows(self, areas: Areas, use: ProgramUse, session: PlcSession) -> list[Row]:
        """The rows for these memory areas, sorted by key."""
        raise NotImplementedError

    def key(self, row: Row) -> tuple[object, ...]:
        """What identifies a row."""
        raise NotImplementedError

    def texts(self, row: Row, session: PlcSession) -> list[str]:
        """The cells of a row."""
        raise NotImplementedError

    def editable(self, row: Row, column: int, session: PlcSession) -> bool:
        """True when the user may type into this cell."""
        raise NotImplementedError

    def store(self, session: PlcSession, row: Row, column: int, text: str) -> None:
        """Store a typed value; raises TableError when refused."""
        raise NotImplementedError

    def insert(self, session: PlcSession, texts: list[str]) -> None:
        """INSERT: store the form's values and list the row; raises TableError."""
        raise NotImplementedError

    def delete(self, session: PlcSession, row: Row) -> None:
        """DELETE: clear the row's values and unlist it; raises TableError."""
        raise NotImplementedError

    def tooltip(self, row: Row) -> str:
        """A cell's tooltip."""
        return ""

    def lit(self, row: Row, column: int) -> bool:
        """True when the cell shows a contact that is on (drawn green)."""
        return False


@dataclass
class TimerSpec(TableSpec):
    """TMR presets (T area, by the program's dialect) and the fixed TMRB presets."""

    kind: ClassVar[TableKind] = TableKind.TIMER
    listed: set[int] = field(default_factory=set)

    def headers(self, session: PlcSession) -> list[str]:
        """No., Type, Preset, [Precision,] Tick, Delay."""
        layout = session.run.timers
        preset = (translate("PlcTables", "Preset (ticks)") if layout.has_precision
                  else translate("PlcTables", "Preset (ms)"))
        precision = [translate("PlcTables", "Precision")] if layout.has_precision else []
        return [translate("PlcTables", "No."), translate("PlcTables", "Type"), preset,
                *precision, translate("PlcTables", "Tick (ms)"),
                translate("PlcTables", "Delay (ms)")]

    def form_fields(self, session: PlcSession) -> list[str]:
        """Timer number and preset."""
        layout = session.run.timers
        preset = (translate("PlcTables", "Preset (ticks)") if layout.has_precision
                  else translate("PlcTables", "Preset (ms)"))
        return [translate("PlcTables", "Timer number (1-{0})").format(layout.count), preset]

    def rows(self, areas: Areas, use: ProgramUse, session: PlcSession) -> list[Row]:
        """Every TMR used, listed or set, then every TMRB."""
        return list(timer_rows(areas, use, self.listed, session.run.timers))

    def key(self, row: Row) -> tuple[object, ...]:
        """Number and TMR/TMRB."""
        assert isinstance(row, TimerRow)
        return (row.number, row.fixed)

    def texts(self, row: Row, session: PlcSession) -> list[str]:
        """No., type, preset, [precision,] tick, delay."""
        assert isinstance(row, TimerRow)
        precision = [str(row.precision)] if session.run.timers.has_precision else []
        return [str(row.number), _TIMER_NAMES[row.fixed], str(row.preset), *precision,
                str(row.tick_ms), str(row.delay_ms)]

    def editable(self, row: Row, column: int, session: PlcSession) -> bool:
        """The preset (and the FANUC precision) of a TMR."""
        assert isinstance(row, TimerRow)
        columns = (2, 3) if session.run.timers.precision_address(row.number) else (2,)
        return not row.fixed and column in columns

    def store(self, session: PlcSession, row: Row, column: int, text: str) -> None:
        """A new preset or precision code."""
        assert isinstance(row, TimerRow)
        if row.fixed:
            raise TableError("preset-fixed", number=row.number)
        layout = session.run.timers
        where = layout.precision_address(row.number)
        if column == 3 and where is not None:
            session.set_parameter(where, timer_precision(text), 2)
        else:
            session.set_timer_preset(row.number, timer_preset(text, layout))

    def insert(self, session: PlcSession, texts: list[str]) -> None:
        """Timer number + preset."""
        layout = session.run.timers
        number = timer_number(texts[0], layout)
        session.set_timer_preset(number, timer_preset(texts[1] or "0", layout))
        self.listed.add(number)

    def delete(self, session: PlcSession, row: Row) -> None:
        """Preset 0; TMRB refused."""
        assert isinstance(row, TimerRow)
        if row.fixed:
            raise TableError("preset-fixed", number=row.number)
        session.set_timer_preset(row.number, 0)
        self.listed.discard(row.number)

    def tooltip(self, row: Row) -> str:
        """TMRB rows say why they cannot be edited."""
        if isinstance(row, TimerRow) and row.fixed:
            return translate("PlcTables", "TMRB: the preset is fixed in the program")
        return ""


@dataclass
class CounterSpec(TableSpec):
    """CTR presets and current values (C area)."""

    kind: ClassVar[TableKind] = TableKind.COUNTER
    listed: set[int] = field(default_factory=set)

    def headers(self, session: PlcSession) -> list[str]:
        """No., Preset, Current value."""
        return [translate("PlcTables", "No."), translate("PlcTables", "Preset"),
                translate("PlcTables", "Current value")]

    def form_fields(self, session: PlcSession) -> list[str]:
        """Counter number, preset, value."""
        return [translate("PlcTables", "Counter number (1-20)"), translate("PlcTables", "Preset"),
                translate("PlcTables", "Current value")]

    def rows(self, areas: Areas, use: ProgramUse, session: PlcSession) -> list[Row]:
        """Every CTR used, listed or set."""
        return list(counter_rows(areas, use, self.listed))

    def key(self, row: Row) -> tuple[object, ...]:
        """The number."""
        assert isinstance(row, CounterRow)
        return (row.number,)

    def texts(self, row: Row, session: PlcSession) -> list[str]:
        """No., preset, value."""
        assert isinstance(row, CounterRow)
        return [str(row.number), str(row.preset), str(row.value)]

    def editable(self, row: Row, column: int, session: PlcSession) -> bool:
        """Preset and value."""
        return column in (1, 2)

    def store(self, session: PlcSession, row: Row, column: int, text: str) -> None:
        """A new preset or current value."""
        assert isinstance(row, CounterRow)
        value = counter_value(text)
        if column == 1:
            session.set_counter_preset(row.number, value)
        else:
            session.set_parameter(counter_value_address(row.number), value, 2)

    def insert(self, session: PlcSession, texts: list[str]) -> None:
        """Number, preset, value."""
        number = counter_number(texts[0])
        preset, value = counter_value(texts[1] or "0"), counter_value(texts[2] or "0")
        session.set_counter_preset(number, preset)
        session.set_parameter(counter_value_address(number), value, 2)
        self.listed.add(number)

    def delete(self, session: PlcSession, row: Row) -> None:
        """Preset and value 0."""
        assert isinstance(row, CounterRow)
        session.set_counter_preset(row.number, 0)
        session.set_parameter(counter_value_address(row.number), 0, 2)
        self.listed.discard(row.number)


@dataclass
class DataSpec(TableSpec):
    """Values of the data table (D area), 1, 2 or 4 bytes."""

    kind: ClassVar[TableKind] = TableKind.DATA
    listed: dict[int, int] = field(default_factory=dict)

    def headers(self, session: PlcSession) -> list[str]:
        """Address, Bytes, Value, Hex."""
        return [translate("PlcTables", "Address"), translate("PlcTables", "Bytes"),
                translate("PlcTables", "Value"), translate("PlcTables", "Hex")]

    def form_fields(self, session: PlcSession) -> list[str]:
        """Address, bytes, value."""
        return [translate("PlcTables", "Address (D)"), translate("PlcTables", "Bytes"),
                translate("PlcTables", "Value")]

    def rows(self, areas: Areas, use: ProgramUse, session: PlcSession) -> list[Row]:
        """Every D value used or listed."""
        return list(data_rows(areas, use, self.listed))

    def key(self, row: Row) -> tuple[object, ...]:
        """Byte and width."""
        assert isinstance(row, DataRow)
        return (row.byte, row.width)

    def texts(self, row: Row, session: PlcSession) -> list[str]:
        """Address, width, signed value, hex."""
        assert isinstance(row, DataRow)
        unsigned = row.value & ((1 << (8 * row.width)) - 1)
        return [str(row.address), str(row.width), str(row.value),
                f"{unsigned:0{2 * row.width}X}h"]

    def editable(self, row: Row, column: int, session: PlcSession) -> bool:
        """The value."""
        return column == 2

    def store(self, session: PlcSession, row: Row, column: int, text: str) -> None:
        """A new value."""
        assert isinstance(row, DataRow)
        session.set_parameter(row.address, data_value(text, row.width), row.width)

    def insert(self, session: PlcSession, texts: list[str]) -> None:
        """Address, width, value."""
        width = data_width(texts[1] or "1")
        byte = data_byte(texts[0], width, session.run.dialect)
        session.set_parameter(Address(Area.D, byte), data_value(texts[2] or "0", width), width)
        self.listed[byte] = width

    def delete(self, session: PlcSession, row: Row) -> None:
        """Value 0."""
        assert isinstance(row, DataRow)
        session.set_parameter(row.address, 0, row.width)
        self.listed.pop(row.byte, None)


@dataclass
class KeepSpec(TableSpec):
    """Keep-relay bytes (K area) as 8 bits."""

    kind: ClassVar[TableKind] = TableKind.KEEP
    listed: set[int] = field(default_factory=set)

    def headers(self, session: PlcSession) -> list[str]:
        """Address, Bits 7..0, Hex."""
        return [translate("PlcTables", "Address"), translate("PlcTables", "Bits 7..0"),
                translate("PlcTables", "Hex")]

    def form_fields(self, session: PlcSession) -> list[str]:
        """Address, bits."""
        return [translate("PlcTables", "Address (K)"), translate("PlcTables", "Bits 7..0")]

    def rows(self, areas: Areas, use: ProgramUse, session: PlcSession) -> list[Row]:
        """Every K byte used, listed or non-zero."""
        return list(keep_rows(areas, use, self.listed))

    def key(self, row: Row) -> tuple[object, ...]:
        """The byte."""
        assert isinstance(row, KeepRow)
        return (row.byte,)

    def texts(self, row: Row, session: PlcSession) -> list[str]:
        """Address, bits, hex."""
        assert isinstance(row, KeepRow)
        return [f"K{row.byte}", row.bits, f"{row.value:02X}h"]

    def editable(self, row: Row, column: int, session: PlcSession) -> bool:
        """The bits."""
        return column == 1

    def store(self, session: PlcSession, row: Row, column: int, text: str) -> None:
        """New bits."""
        assert isinstance(row, KeepRow)
        session.set_parameter(Address(Area.K, row.byte), keep_bits(text), 1)

    def insert(self, session: PlcSession, texts: list[str]) -> None:
        """Address, bits."""
        byte = keep_byte(texts[0], session.run.dialect)
        session.set_parameter(Address(Area.K, byte), keep_bits(texts[1] or "0"), 1)
        self.listed.add(byte)

    def delete(self, session: PlcSession, row: Row) -> None:
        """Byte 0."""
        assert isinstance(row, KeepRow)
        session.set_parameter(Address(Area.K, row.byte), 0, 1)
        self.listed.discard(row.byte)


def table_specs() -> list[TableSpec]:
    """A fresh spec of each table, in tab order."""
    return [TimerSpec(), CounterSpec(), DataSpec(), KeepSpec()]
