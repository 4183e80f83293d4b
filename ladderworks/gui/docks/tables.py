"""The PLC tables dock: timer presets, counters, data table and keep relays, edited while running.

Right-click a table: INSERT fills a form and adds a row, DELETE clears the row under the mouse
(as the seed manual's tables). TMRB presets are fixed in the program and shown read-only
("a normal timer can be changed from the PLC table, TMRB cannot").
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from PySide6.QtCore import QCoreApplication, QEvent, QPoint, Qt, QTimer
from PySide6.QtGui import QAction, QBrush, QColor
from PySide6.QtWidgets import (
    QAbstractItemView,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QDockWidget,
    QFormLayout,
    QLabel,
    QLineEdit,
    QMainWindow,
    QMenu,
    QTableWidget,
    QTableWidgetItem,
    QTabWidget,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.plc.functions.counters import counter_value_address
from ladderworks.gui.docks.dock_menus import add_dock
from ladderworks.gui.docks.table_entries import (
    DATA_WIDTHS,
    MAX_TIMER_MS,
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
    timer_preset,
    timer_rows,
)
from ladderworks.gui.plc_session import PlcSession, PlcSnapshot

translate = QCoreApplication.translate

Row = TimerRow | CounterRow | DataRow | KeepRow
EDITABLE: dict[TableKind, tuple[int, ...]] = {
    TableKind.TIMER: (2,),
    TableKind.COUNTER: (1, 2),
    TableKind.DATA: (2,),
    TableKind.KEEP: (1,),
}
_READ_ONLY = QBrush(QColor("#eeeeee"))


def table_error_text(error: TableError) -> str:
    """A refused value in the current UI language."""
    args = error.args_map
    if error.code == "not-number":
        return translate("PlcTables", "'{0}' is not a number").format(args.get("text", ""))
    if error.code == "range":
        return translate("PlcTables", "{0} is out of range ({1} to {2})").format(
            args.get("value"), args.get("low"), args.get("high")
        )
    if error.code == "width":
        return translate("PlcTables", "{0} bytes: a value has 1, 2 or 4 bytes").format(
            args.get("value")
        )
    if error.code == "bits":
        return translate(
            "PlcTables", "'{0}': type up to 8 binary digits (0 and 1), bit 7 first"
        ).format(args.get("text", ""))
    if error.code == "fixed":
        return translate(
            "PlcTables", "TMRB {0}: its preset is fixed in the program and cannot be changed here"
        ).format(args.get("number"))
    return error.code


def headers(kind: TableKind) -> list[str]:
    """The column titles of a table in the current UI language."""
    if kind is TableKind.TIMER:
        return [
            translate("PlcTables", "No."),
            translate("PlcTables", "Type"),
            translate("PlcTables", "Preset (ms)"),
            translate("PlcTables", "Tick (ms)"),
            translate("PlcTables", "Delay (ms)"),
        ]
    if kind is TableKind.COUNTER:
        return [
            translate("PlcTables", "No."),
            translate("PlcTables", "Preset"),
            translate("PlcTables", "Current value"),
        ]
    if kind is TableKind.DATA:
        return [
            translate("PlcTables", "Address"),
            translate("PlcTables", "Bytes"),
            translate("PlcTables", "Value"),
            translate("PlcTables", "Hex"),
        ]
    return [
        translate("PlcTables", "Address"),
        translate("PlcTables", "Bits 7..0"),
        translate("PlcTables", "Hex"),
    ]


def form_fields(kind: TableKind) -> list[str]:
    """The INSERT form's fields of a table."""
    if kind is TableKind.TIMER:
        return [
            translate("PlcTables", "Timer number (1-100)"),
            translate("PlcTables", "Preset (ms)"),
        ]
    if kind is TableKind.COUNTER:
        return [
            translate("PlcTables", "Counter number (1-20)"),
            translate("PlcTables", "Preset"),
            translate("PlcTables", "Current value"),
        ]
    if kind is TableKind.DATA:
        return [
            translate("PlcTables", "Address (D)"),
            translate("PlcTables", "Bytes"),
            translate("PlcTables", "Value"),
        ]
    return [translate("PlcTables", "Address (K)"), translate("PlcTables", "Bits 7..0")]


def row_key(row: Row) -> tuple[object, ...]:
    """What identifies a row of a table."""
    if isinstance(row, TimerRow):
        return (row.number, row.fixed)
    if isinstance(row, CounterRow):
        return (row.number,)
    if isinstance(row, DataRow):
        return (row.byte, row.width)
    return (row.byte,)


def row_texts(row: Row) -> list[str]:
    """The cells of a row."""
    if isinstance(row, TimerRow):
        return [
            str(row.number),
            "TMRB" if row.fixed else "TMR",
            str(row.preset_ms),
            str(row.tick_ms),
            str(row.effective_ms),
        ]
    if isinstance(row, CounterRow):
        return [str(row.number), str(row.preset), str(row.value)]
    if isinstance(row, DataRow):
        unsigned = row.value & ((1 << (8 * row.width)) - 1)
        return [str(row.address), str(row.width), str(row.value), f"{unsigned:0{2 * row.width}X}h"]
    return [f"K{row.byte}", row.bits, f"{row.value:02X}h"]


class InsertRowDialog(QDialog):
    """The INSERT form of a table: its fields, validated when OK is pressed."""

    def __init__(
        self,
        kind: TableKind,
        accept_texts: Callable[[list[str]], str | None],
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("plcTablesInsertDialog")
        self.kind = kind
        self._accept_texts = accept_texts
        self.setWindowTitle(translate("PlcTables", "INSERT"))
        layout = QVBoxLayout(self)
        form = QFormLayout()
        self.fields: list[QLineEdit | QComboBox] = []
        for index, label in enumerate(form_fields(kind)):
            field: QLineEdit | QComboBox
            if kind is TableKind.DATA and index == 1:
                field = QComboBox(self)
                field.addItems([str(width) for width in DATA_WIDTHS])
            else:
                field = QLineEdit(self)
            field.setObjectName(f"plcTablesField_{index}")
            form.addRow(label, field)
            self.fields.append(field)
        layout.addLayout(form)
        self.error = QLabel(self)
        self.error.setObjectName("plcTablesFormError")
        self.error.setStyleSheet("color:#c00000;")
        self.error.setWordWrap(True)
        layout.addWidget(self.error)
        buttons = QDialogButtonBox(
            QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel, self
        )
        buttons.accepted.connect(self.try_accept)
        buttons.rejected.connect(self.reject)
        layout.addWidget(buttons)

    def set_texts(self, texts: Sequence[str]) -> None:
        """Fill the fields."""
        for field, text in zip(self.fields, texts, strict=False):
            if isinstance(field, QComboBox):
                field.setCurrentText(text)
            else:
                field.setText(text)

    def texts(self) -> list[str]:
        """What the fields hold."""
        return [
            field.currentText() if isinstance(field, QComboBox) else field.text()
            for field in self.fields
        ]

    def try_accept(self) -> None:
        """OK: insert the row, or show why not and stay open."""
        problem = self._accept_texts(self.texts())
        if problem is None:
            self.accept()
        else:
            self.error.setText(problem)


class PlcTablesDock(QDockWidget):
    """Timers (TMR presets; TMRB read-only), counters (CTR), data table (D), keep relays (K)."""

    def __init__(self, session: PlcSession, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("plcTablesDock")
        self.session = session
        self.use = ProgramUse.of(session.binary)
        self.listed_timers: set[int] = set()
        self.listed_counters: set[int] = set()
        self.listed_data: dict[int, int] = {}
        self.listed_keep: set[int] = set()
        self.rows: dict[TableKind, list[Row]] = {kind: [] for kind in TableKind}
        self.insert_dialog: InsertRowDialog | None = None
        self._filling = False
        self._stale: set[TableKind] = set()  # tables to show again even if unchanged
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        self.tabs = QTabWidget(body)
        self.tabs.setObjectName("plcTablesTabs")
        self.tables: dict[TableKind, QTableWidget] = {}
        for kind in TableKind:
            table = QTableWidget(0, len(headers(kind)), self.tabs)
            table.setObjectName(f"plcTable_{kind.value}")
            table.verticalHeader().hide()
            table.setAlternatingRowColors(True)
            table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
            table.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
            table.setEditTriggers(
                QAbstractItemView.EditTrigger.DoubleClicked
                | QAbstractItemView.EditTrigger.EditKeyPressed
                | QAbstractItemView.EditTrigger.AnyKeyPressed
            )
            table.horizontalHeader().setStretchLastSection(True)
            table.setContextMenuPolicy(Qt.ContextMenuPolicy.CustomContextMenu)
            table.customContextMenuRequested.connect(lambda pos, k=kind: self._context_menu(k, pos))
            table.itemChanged.connect(lambda item, k=kind: self._on_item_changed(k, item))
            self.tables[kind] = table
            self.tabs.addTab(table, "")
        layout.addWidget(self.tabs, 1)
        self.message = QLabel(body)
        self.message.setObjectName("plcTablesMessage")
        self.message.setWordWrap(True)
        layout.addWidget(self.message)
        self.insert_action: QAction | None = None  # the last right-click menu's actions
        self.delete_action: QAction | None = None
        self.setWidget(body)
        session.snapshot_ready.connect(self._on_snapshot)
        session.program_loaded.connect(self._on_program)
        self.retranslate()
        self.refresh()

    # -- showing -------------------------------------------------------------------------------

    def _on_program(self, program: BinaryProgram) -> None:
        self.use = ProgramUse.of(program)
        self.refresh()

    def _on_snapshot(self, snapshot: PlcSnapshot) -> None:
        self.refresh(snapshot.areas)

    def current_rows(self, kind: TableKind, areas: Areas) -> list[Row]:
        """The rows a table has for these memory areas."""
        if kind is TableKind.TIMER:
            return list(timer_rows(areas, self.use, self.listed_timers))
        if kind is TableKind.COUNTER:
            return list(counter_rows(areas, self.use, self.listed_counters))
        if kind is TableKind.DATA:
            return list(data_rows(areas, self.use, self.listed_data))
        return list(keep_rows(areas, self.use, self.listed_keep))

    def refresh(self, areas: Areas | None = None) -> None:
        """Show the tables' values now (a cell being edited is left alone)."""
        if areas is None:
            areas = self.session.snapshot().areas
        for kind, table in self.tables.items():
            if table.state() == QAbstractItemView.State.EditingState:
                continue
            rows = self.current_rows(kind, areas)
            self._fill(kind, table, rows)

    def _fill(self, kind: TableKind, table: QTableWidget, rows: list[Row]) -> None:
        same_keys = [row_key(r) for r in rows] == [row_key(r) for r in self.rows[kind]]
        if same_keys and rows == self.rows[kind] and kind not in self._stale:
            return
        self._stale.discard(kind)
        self._filling = True
        try:
            table.setRowCount(len(rows))
            for index, row in enumerate(rows):
                fixed = isinstance(row, TimerRow) and row.fixed
                for column, text in enumerate(row_texts(row)):
                    item = table.item(index, column)
                    if item is None:
                        item = QTableWidgetItem()
                        table.setItem(index, column, item)
                    if item.text() != text:
                        item.setText(text)
                    flags = Qt.ItemFlag.ItemIsEnabled | Qt.ItemFlag.ItemIsSelectable
                    if column in EDITABLE[kind] and not fixed:
                        flags |= Qt.ItemFlag.ItemIsEditable
                        item.setBackground(QBrush())
                    else:
                        item.setBackground(_READ_ONLY)
                    item.setFlags(flags)
                    item.setToolTip(
                        translate("PlcTables", "TMRB: the preset is fixed in the program")
                        if fixed
                        else ""
                    )
            if not same_keys:
                table.resizeColumnsToContents()
        finally:
            self._filling = False
        self.rows[kind] = rows

    def cell_texts(self, kind: TableKind) -> list[list[str]]:
        """What a table shows, row by row."""
        table = self.tables[kind]
        return [
            [table.item(row, column).text() for column in range(table.columnCount())]
            for row in range(table.rowCount())
        ]

    # -- editing -------------------------------------------------------------------------------

    def _on_item_changed(self, kind: TableKind, item: QTableWidgetItem) -> None:
        if self._filling:
            return
        self.edit_cell(kind, item.row(), item.column(), item.text())

    def edit_cell(self, kind: TableKind, row: int, column: int, text: str) -> str | None:
        """Store a value typed in a cell; the translated reason when it is refused (the cell
        then shows the value again)."""
        try:
            target = self.rows[kind][row]
            self._store(kind, target, column, text)
        except TableError as error:
            problem = table_error_text(error)
            self._say(problem, error=True)
            self._refresh_later(kind)  # show the stored value again
            return problem
        self._say("")
        self._refresh_later(kind)
        return None

    def _refresh_later(self, kind: TableKind) -> None:
        """Show the table again: at once, or once a cell's editor has closed when the edit
        is being committed from inside it."""
        self._stale.add(kind)
        if self.tables[kind].state() == QAbstractItemView.State.EditingState:
            QTimer.singleShot(0, self.refresh)
        else:
            self.refresh()

    def _store(self, kind: TableKind, target: Row, column: int, text: str) -> None:
        session = self.session
        if isinstance(target, TimerRow):
            if target.fixed:
                raise TableError("fixed", number=target.number)
            session.set_timer_preset(target.number, timer_preset(text))
        elif isinstance(target, CounterRow):
            value = counter_value(text)
            if column == 1:
                session.set_counter_preset(target.number, value)
            else:
                session.write(counter_value_address(target.number), value, 2)
        elif isinstance(target, DataRow):
            session.write(target.address, data_value(text, target.width), target.width)
        else:
            session.write(Address(Area.K, target.byte), keep_bits(text), 1)

    def insert_texts(self, kind: TableKind, texts: Sequence[str]) -> str | None:
        """INSERT with the form's texts: validate, store, list the row; or the reason not."""
        try:
            self._insert(kind, list(texts) + [""] * 3)
        except TableError as error:
            return table_error_text(error)
        self._say("")
        self._refresh_later(kind)
        return None

    def _insert(self, kind: TableKind, texts: list[str]) -> None:
        session = self.session
        if kind is TableKind.TIMER:
            number = timer_number(texts[0])
            session.set_timer_preset(number, timer_preset(texts[1] or "0"))
            self.listed_timers.add(number)
        elif kind is TableKind.COUNTER:
            number = counter_number(texts[0])
            preset, value = counter_value(texts[1] or "0"), counter_value(texts[2] or "0")
            session.set_counter_preset(number, preset)
            session.write(counter_value_address(number), value, 2)
            self.listed_counters.add(number)
        elif kind is TableKind.DATA:
            width = data_width(texts[1] or "1")
            byte = data_byte(texts[0], width)
            value = data_value(texts[2] or "0", width)
            session.write(Address(Area.D, byte), value, width)
            self.listed_data[byte] = width
        else:
            byte = keep_byte(texts[0])
            session.write(Address(Area.K, byte), keep_bits(texts[1] or "0"), 1)
            self.listed_keep.add(byte)

    def delete_row(self, kind: TableKind, row: int) -> str | None:
        """DELETE: clear the row's value and unlist it (a row the program uses stays, at 0)."""
        target = self.rows[kind][row]
        session = self.session
        if isinstance(target, TimerRow):
            if target.fixed:
                problem = table_error_text(TableError("fixed", number=target.number))
                self._say(problem, error=True)
                return problem
            session.set_timer_preset(target.number, 0)
            self.listed_timers.discard(target.number)
        elif isinstance(target, CounterRow):
            session.set_counter_preset(target.number, 0)
            session.write(counter_value_address(target.number), 0, 2)
            self.listed_counters.discard(target.number)
        elif isinstance(target, DataRow):
            session.write(target.address, 0, target.width)
            self.listed_data.pop(target.byte, None)
        else:
            session.write(Address(Area.K, target.byte), 0, 1)
            self.listed_keep.discard(target.byte)
        self._say("")
        self._refresh_later(kind)
        return None

    # -- the right-click menu ------------------------------------------------------------------

    def context_menu(self, kind: TableKind, row: int) -> QMenu:
        """The right-click menu of a table at `row` (-1: below the rows): INSERT, DELETE."""
        menu = QMenu(self)
        menu.setObjectName("plcTablesMenu")
        self.insert_action = QAction(translate("PlcTables", "INSERT"), menu)
        self.insert_action.setObjectName("action_table_insert")
        self.insert_action.triggered.connect(lambda: self.open_insert_dialog(kind))
        self.delete_action = QAction(translate("PlcTables", "DELETE"), menu)
        self.delete_action.setObjectName("action_table_delete")
        self.delete_action.triggered.connect(lambda: self.delete_row(kind, row))
        self.delete_action.setEnabled(0 <= row < len(self.rows[kind]))
        menu.addAction(self.insert_action)
        menu.addAction(self.delete_action)
        return menu

    def _context_menu(self, kind: TableKind, pos: QPoint) -> None:
        table = self.tables[kind]
        row = table.rowAt(pos.y())
        self.context_menu(kind, row).exec(table.viewport().mapToGlobal(pos))

    def open_insert_dialog(self, kind: TableKind) -> InsertRowDialog:
        """Open the INSERT form of a table (not modal-blocking: OK inserts)."""
        dialog = InsertRowDialog(kind, lambda texts: self.insert_texts(kind, texts), self)
        dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
        self.insert_dialog = dialog
        dialog.open()
        return dialog

    # -- texts -------------------------------------------------------------------------------

    def _say(self, text: str, *, error: bool = False) -> None:
        self.message.setStyleSheet("color:#c00000;" if error else "")
        self.message.setText(text)

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(translate("PlcTables", "PLC tables"))
        titles = {
            TableKind.TIMER: translate("PlcTables", "Timers (TMR)"),
            TableKind.COUNTER: translate("PlcTables", "Counters (CTR)"),
            TableKind.DATA: translate("PlcTables", "Data table (D)"),
            TableKind.KEEP: translate("PlcTables", "Keep relays (K)"),
        }
        for index, kind in enumerate(TableKind):
            self.tabs.setTabText(index, titles[kind])
            self.tables[kind].setHorizontalHeaderLabels(headers(kind))
        self.tables[TableKind.TIMER].setToolTip(
            translate(
                "PlcTables",
                "Presets up to {0} ms; timers 1-8 count in 48 ms ticks, 9-100 and TMRB in 8 ms",
            ).format(MAX_TIMER_MS)
        )

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate on a language change."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)


def install(window: QMainWindow, session: PlcSession) -> PlcTablesDock:
    """Add the PLC tables to the console (hidden; View → PLC tables shows it)."""
    dock = PlcTablesDock(session, window)
    add_dock(window, dock, "action_dock_plc_tables", Qt.DockWidgetArea.RightDockWidgetArea)
    dock.hide()
    return dock
