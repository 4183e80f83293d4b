"""PlcTableModel: one PLC table (by its spec) over the session's memory, edited in place."""

from __future__ import annotations

from PySide6.QtCore import (
    QAbstractTableModel,
    QModelIndex,
    QPersistentModelIndex,
    Qt,
    Signal,
)
from PySide6.QtGui import QBrush, QColor

from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.gui.docks.table_entries import Areas, ProgramUse, TableError
from ladderworks.gui.docks.table_specs import Row, TableSpec
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.symbol_text import tooltip

Index = QModelIndex | QPersistentModelIndex
_READ_ONLY = QBrush(QColor("#eeeeee"))
_LIT = QBrush(QColor("#b8e8b8"))  # a contact that is on


class PlcTableModel(QAbstractTableModel):
    """Rows from the spec; a typed value is stored through the spec and shown at once.

    Updates from snapshots insert, remove or change rows in place (a whole row at a time), so a
    cell being edited keeps its editor and its text."""

    refused = Signal(object)  # the TableError (the dock translates it)
    stored = Signal()

    def __init__(self, spec: TableSpec, session: PlcSession) -> None:
        super().__init__()
        self.spec = spec
        self.session = session
        self.use = ProgramUse.of(session.run.binary)
        self.last_error: TableError | None = None
        self._headers = spec.headers(session)
        self._rows: list[Row] = spec.rows(session.run.snapshot().areas, self.use, session)

    # -- reading -------------------------------------------------------------------------

    @property
    def rows(self) -> list[Row]:
        """The rows shown."""
        return list(self._rows)

    def rowCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        """Rows shown."""
        return 0 if parent.isValid() else len(self._rows)

    def columnCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        """Columns of the spec."""
        return 0 if parent.isValid() else len(self._headers)

    def headerData(self, section: int, orientation: Qt.Orientation,
                   role: int = Qt.ItemDataRole.DisplayRole) -> object:
        """Column titles."""
        if (orientation == Qt.Orientation.Horizontal and role == Qt.ItemDataRole.DisplayRole
                and 0 <= section < len(self._headers)):
            return self._headers[section]
        return None

    def data(self, index: Index, role: int = Qt.ItemDataRole.DisplayRole) -> object:
        """Cell text, grey background when read-only, tooltip."""
        if not index.isValid() or index.row() >= len(self._rows):
            return None
        row = self._rows[index.row()]
        if role in (Qt.ItemDataRole.DisplayRole, Qt.ItemDataRole.EditRole):
            texts = self.spec.texts(row, self.session)
            text = texts[index.column()] if index.column() < len(texts) else ""
            if role == Qt.ItemDataRole.DisplayRole and index.column() == 0:
                symbol = self._symbol(row)
                return f"{text} {symbol}" if symbol else text
            return text
        if role == Qt.ItemDataRole.BackgroundRole:
            if self.spec.lit(row, index.column()):
                return _LIT
            editable = self.spec.editable(row, index.column(), self.session)
            return None if editable else _READ_ONLY
        if role == Qt.ItemDataRole.ToolTipRole:
            address = getattr(row, "address", None)
            named = (tooltip(address, self.session.symbols)
                     if address is not None and self._symbol(row) else "")
            return "\n".join(t for t in (named, self.spec.tooltip(row)) if t) or None
        return None

    def _symbol(self, row: Row) -> str:
        """The program's symbol of a row's address (D, K ... rows), or ""."""
        address = getattr(row, "address", None)
        symbols = self.session.symbols
        return symbols.symbol(address) if symbols is not None and address is not None else ""

    def flags(self, index: Index) -> Qt.ItemFlag:
        """Editable cells as the spec says."""
        flags = Qt.ItemFlag.ItemIsEnabled | Qt.ItemFlag.ItemIsSelectable
        if index.isValid() and index.row() < len(self._rows) and self.spec.editable(
                self._rows[index.row()], index.column(), self.session):
            flags |= Qt.ItemFlag.ItemIsEditable
        return flags

    def texts(self) -> list[list[str]]:
        """What the table shows, row by row."""
        return [self.spec.texts(row, self.session) for row in self._rows]

    # -- writing -------------------------------------------------------------------------

    def setData(self, index: Index, value: object, role: int = Qt.ItemDataRole.EditRole) -> bool:
        """Store a typed value through the spec; False (and `refused`) when it is refused."""
        if role != Qt.ItemDataRole.EditRole or not index.isValid():
            return False
        try:
            self.spec.store(self.session, self._rows[index.row()], index.column(), str(value))
        except TableError as error:
            self.last_error = error
            self.refused.emit(error)
            self.update()  # the cell shows the stored value again
            return False
        self.last_error = None
        self.update()
        self.stored.emit()
        return True

    def run(self, action: str, argument: object) -> TableError | None:
        """INSERT (`argument`: the form's texts) or DELETE (`argument`: a row number)."""
        try:
            if action == "insert":
                assert isinstance(argument, list)
                self.spec.insert(self.session, argument)
            else:
                assert isinstance(argument, int)
                self.spec.delete(self.session, self._rows[argument])
        except TableError as error:
            return error
        self.update()
        return None

    # -- following the PLC ---------------------------------------------------------------

    def set_program(self, program: BinaryProgram | None, use: ProgramUse | None = None) -> None:
        """A new program: new rows and (for timers of another dialect) new columns. `use` is
        ProgramUse.of(program) when the caller has it (the dock's four tables share one)."""
        self.beginResetModel()
        self.use = use if use is not None else ProgramUse.of(program)
        self._headers = self.spec.headers(self.session)
        self._rows = self.spec.rows(self.session.run.snapshot().areas, self.use, self.session)
        self.endResetModel()

    def retranslate(self) -> None:
        """Column titles in the current UI language."""
        self._headers = self.spec.headers(self.session)
        if self._headers:
            self.headerDataChanged.emit(Qt.Orientation.Horizontal, 0, len(self._headers) - 1)

    def update(self, areas: Areas | None = None) -> None:
        """Show these memory areas (now's when None): rows in and out, changed rows redrawn."""
        if areas is None:
            areas = self.session.run.snapshot().areas
        rows = self.spec.rows(areas, self.use, self.session)
        key = self.spec.key
        wanted = {key(row) for row in rows}
        for at in reversed(range(len(self._rows))):
            if key(self._rows[at]) not in wanted:
                self.beginRemoveRows(QModelIndex(), at, at)
                del self._rows[at]
                self.endRemoveRows()
        present = {key(row) for row in self._rows}
        for at, row in enumerate(rows):
            if key(row) not in present:
                self.beginInsertRows(QModelIndex(), at, at)
                self._rows.insert(at, row)
                self.endInsertRows()
        last = len(self._headers) - 1
        for at, row in enumerate(rows):
            if self._rows[at] != row:
                self._rows[at] = row
                # a whole row: the view then leaves an open editor's text alone
                self.dataChanged.emit(self.index(at, 0), self.index(at, max(last, 1)))
