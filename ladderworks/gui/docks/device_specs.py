"""The device tables of a Delta or Fatek program (timers, counters, registers): one spec each.

As WPLSoft's and WinProladder's device monitors: the devices the program uses (and those the
user adds with INSERT, a device or a range `D0-D9`), their values live from the PLC, a current
value or a register typed in a cell written into the PLC between two scans. What each dialect
has (letters, bases, which rows set a preset) is its `core/dialects/<d>/tables.py`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

from PySide6.QtCore import QCoreApplication

from ladderworks.core import dialects
from ladderworks.core.address import AddressError
from ladderworks.core.dialects.device_tables import (
    DeviceRow,
    DeviceTables,
    Place,
    ProgramDevices,
    Table,
    device_range,
    program_devices,
    read_rows,
    table_letters,
    table_places,
)
from ladderworks.gui.docks.table_entries import (
    Areas,
    ProgramUse,
    TableError,
    TableKind,
    data_value,
)
from ladderworks.gui.docks.table_specs import Row, TableSpec
from ladderworks.gui.plc_session import PlcSession

translate = QCoreApplication.translate

_VALUE_COLUMN = {Table.TIMERS: 3, Table.COUNTERS: 3, Table.REGISTERS: 1}


def hex_value(text: str, width: int) -> int:
    """A value typed in hex (`1F`, `H1F`, `1Fh`, `0x1F`), 0 .. FFFF (FFFFFFFF for 4 bytes)."""
    spelled = text.strip().replace("_", "").replace(" ", "")
    upper = spelled.upper()
    digits = upper.removeprefix("0X").removeprefix("H").removesuffix("H")
    try:
        value = int(digits, 16)
    except ValueError:
        raise TableError("not-a-number", text=text.strip()) from None
    return data_value(str(value), width)


# the last program's devices: the three tables of a dock read them once (key: binary, dialect)
_LAST: list[tuple[object, str, ProgramDevices]] = []


def _devices_of(binary: object, name: str) -> ProgramDevices:
    """What a loaded program uses (its dialect's `program_devices`), found once per load."""
    if _LAST and _LAST[0][0] is binary and _LAST[0][1] == name:
        return _LAST[0][2]
    dialect = dialects.get(name)
    tables = dialect.device_tables() if dialect is not None else None
    ops = getattr(binary, "ops", None)
    used = (program_devices(tables, dialect.devices, ops)
            if tables is not None and dialect is not None and ops is not None
            else ProgramDevices())
    _LAST[:] = [(binary, name, used)]
    return used


@dataclass
class DeviceSpec(TableSpec):
    """A table of a dialect's devices: columns, rows from the PLC memory, edits written to it."""

    table: ClassVar[Table]
    kind: ClassVar[TableKind]
    listed: set[tuple[str, int]] = field(default_factory=set)
    _program: object = None  # the binary `_used` was read from
    _dialect: str = ""
    _used: ProgramDevices = field(default_factory=ProgramDevices)
    # the places of the rows, and the devices used and listed they were found for
    _places: list[Place] = field(default_factory=list)
    _placed: tuple[object, frozenset[tuple[str, int]]] = (None, frozenset())

    # -- what the dialect has ------------------------------------------------------------

    @staticmethod
    def dialect_tables(session: PlcSession) -> DeviceTables | None:
        """The device tables of the loaded program's dialect (None: a PMC program)."""
        dialect = dialects.get(session.run.program_dialect)
        return dialect.device_tables() if dialect is not None else None

    def letters(self, session: PlcSession) -> tuple[str, ...]:
        """The device letters this table lists for the loaded program."""
        tables = self.dialect_tables(session)
        return table_letters(self.table, tables) if tables is not None else ()

    def _devices_used(self, session: PlcSession) -> ProgramDevices:
        binary = session.run.binary
        name = session.run.program_dialect
        if binary is not self._program or name != self._dialect:
            if name != self._dialect:
                self.listed.clear()  # another dialect's devices
            self._program, self._dialect = binary, name
            self._used = _devices_of(binary, name)
        return self._used

    # -- the TableSpec interface -----------------------------------------------------------

    def headers(self, session: PlcSession) -> list[str]:
        """The column titles."""
        device = translate("PlcTables", "Device")
        value = translate("PlcTables", "Value")  # the current value (short: a narrow dock)
        contact = translate("PlcTables", "Contact")
        preset = translate("PlcTables", "Preset")
        if self.table is Table.TIMERS:
            return [device, translate("PlcTables", "Base"), preset, value, contact]
        if self.table is Table.COUNTERS:
            return [device, translate("PlcTables", "Type"), preset, value, contact]
        return [device, translate("PlcTables", "Value"), translate("PlcTables", "Hex")]

    def form_fields(self, session: PlcSession) -> list[str]:
        """One field: the devices to add."""
        letter = (self.letters(session) or ("D",))[0]
        return [translate("PlcTables", "Devices ({0}0 or a range {0}0-{0}9)").format(letter)]

    def rows(self, areas: Areas, use: ProgramUse, session: PlcSession) -> list[Row]:
        """The devices the program uses and those listed, with their values in `areas`."""
        dialect = dialects.get(session.run.program_dialect)
        tables = dialect.device_tables() if dialect is not None else None
        used = self._devices_used(session)
        if tables is None or dialect is None:
            return []
        if self._placed[0] is not used or self._placed[1] != self.listed:
            self._placed = (used, frozenset(self.listed))  # another program or list
            self._places = table_places(self.table, tables, dialect.devices, used, self.listed)
        return list(read_rows(self._places, tables, dialect.devices, areas))

    def key(self, row: Row) -> tuple[object, ...]:
        """The device."""
        assert isinstance(row, DeviceRow)
        return (row.device,)

    def texts(self, row: Row, session: PlcSession) -> list[str]:
        """The cells of a row."""
        assert isinstance(row, DeviceRow)
        mask = (1 << (8 * row.width)) - 1
        if self.table is Table.REGISTERS:
            return [row.device, str(row.value), f"{row.value & mask:0{2 * row.width}X}"]
        on = translate("PlcTables", "ON") if row.contact else translate("PlcTables", "OFF")
        preset = ""
        if row.preset is not None:
            preset = (f"{row.preset.text} = {row.preset.value}" if row.preset.register
                      else row.preset.text)
        if self.table is Table.TIMERS:
            kind = translate("PlcTables", "{0} ms").format(row.base_ms)
        else:
            kind = (translate("PlcTables", "{0}-bit up/down") if row.up_down
                    else translate("PlcTables", "{0}-bit up")).format(8 * row.width)
        return [row.device, kind, preset, str(row.value), on]

    def editable(self, row: Row, column: int, session: PlcSession) -> bool:
        """The current value (and a register's hex)."""
        if self.table is Table.REGISTERS:
            return column in (1, 2)
        return column == _VALUE_COLUMN[self.table]

    def store(self, session: PlcSession, row: Row, column: int, text: str) -> None:
        """Write a typed value into the PLC (between two scans)."""
        assert isinstance(row, DeviceRow)
        if not self.editable(row, column, session):  # the view never offers it
            return
        if self.table is Table.REGISTERS and column == 2:
            value = hex_value(text, row.width)
        else:
            spelled = text.strip()  # as WPLSoft: K100 (decimal), H1F (hex), or 100
            if spelled.upper().startswith("H"):
                value = hex_value(spelled[1:], row.width)
            else:
                value = data_value(spelled[1:] if spelled.upper().startswith("K") else spelled,
                                   row.width)
        session.write(row.address, value, row.width)

    def insert(self, session: PlcSession, texts: list[str]) -> None:
        """List a device or a range of devices."""
        dialect = dialects.get(session.run.program_dialect)
        tables = dialect.device_tables() if dialect is not None else None
        if tables is None or dialect is None:
            raise TableError("device-not-in-table", text=texts[0].strip(), letters="-")
        try:
            self.listed.update(device_range(self.table, tables, dialect.devices, texts[0]))
        except AddressError as error:
            diagnostic = error.diagnostics[0]
            raise TableError(diagnostic.code, **diagnostic.args) from None

    def delete(self, session: PlcSession, row: Row) -> None:
        """Unlist a device (one the program uses stays listed)."""
        assert isinstance(row, DeviceRow)
        self.listed.discard((row.letter, row.number))

    def lit(self, row: Row, column: int) -> bool:
        """The contact column of a timer or counter that is on."""
        return isinstance(row, DeviceRow) and column == 4 and bool(row.contact)

    def tooltip(self, row: Row) -> str:
        """A timer whose base a relay switches says so."""
        if isinstance(row, DeviceRow) and row.table is Table.TIMERS and self._dialect:
            dialect = dialects.get(self._dialect)
            tables = dialect.device_tables() if dialect is not None else None
            switch = tables.switched_bases.get(row.number) if tables is not None else None
            if switch is not None:
                return translate("PlcTables", "{0} on: {1} ms a count").format(*switch)
        return ""


@dataclass
class DeviceTimerSpec(DeviceSpec):
    """Timers: base, preset (its instruction's constant or register), value, contact."""

    table: ClassVar[Table] = Table.TIMERS
    kind: ClassVar[TableKind] = TableKind.DEVICE_TIMERS


@dataclass
class DeviceCounterSpec(DeviceSpec):
    """Counters: 16/32-bit, up or up/down, preset, value, contact."""

    table: ClassVar[Table] = Table.COUNTERS
    kind: ClassVar[TableKind] = TableKind.DEVICE_COUNTERS


@dataclass
class RegisterSpec(DeviceSpec):
    """Registers (Delta D; Fatek R and D): signed value and hex, both editable."""

    table: ClassVar[Table] = Table.REGISTERS
    kind: ClassVar[TableKind] = TableKind.REGISTERS


def device_specs() -> list[DeviceSpec]:
    """A fresh spec of each device table, in tab order."""
    return [DeviceTimerSpec(), DeviceCounterSpec(), RegisterSpec()]
