"""The watch table (İzleme tablosu), as TIA Portal's: names or addresses typed in rows, each
shown live in a display format and modified with "Modify now"; the rows kept per program.

The rows' names are the open program's (an S7 tag `"Start"`, `#Timer.ET`, a DB member; a PMC
symbol) or addresses in its family's spelling (`%MW2`, `X0.1`, `D0`): core/watch does the
work, this dock shows it. docs/plc-utilities.md, "Watch table".
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QCoreApplication, QEvent, QObject, QPoint, Qt, QTimer
from PySide6.QtGui import QAction, QBrush, QColor, QKeyEvent
from PySide6.QtWidgets import (
    QAbstractItemView,
    QComboBox,
    QDockWidget,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QMainWindow,
    QMenu,
    QPushButton,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il.program import Program
from ladderworks.core.plc.session import PlcSnapshot
from ladderworks.core.symbols import SymbolTable
from ladderworks.core.watch.places import WatchError
from ladderworks.core.watch.rows import (
    Watched,
    WatchRow,
    modify,
    rows_from_text,
    rows_text,
    store,
    watched,
)
from ladderworks.core.watch.values import Format, Memory, formats, show
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.docks.snapshot_gate import SnapshotGate
from ladderworks.gui.docks.table_cell_error import CellError
from ladderworks.gui.docks.watch_texts import FORMAT_NAMES, format_name
from ladderworks.gui.header_fit import fit_headers
from ladderworks.gui.live_text import set_live_text
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.settings import Settings
from ladderworks.gui.tools import icon

translate = QCoreApplication.translate

NAME, ADDRESS, FORMAT, MONITOR, MODIFY = range(5)
_ERROR = QColor("#c00000")
_BAD_CELL = QColor("#ffd6d6")
_EDITABLE = (Qt.ItemFlag.ItemIsSelectable | Qt.ItemFlag.ItemIsEnabled
             | Qt.ItemFlag.ItemIsEditable)
_SHOWN = Qt.ItemFlag.ItemIsSelectable | Qt.ItemFlag.ItemIsEnabled

__all__ = ["FORMAT_NAMES", "WatchTableDock"]


class WatchTableDock(Retranslating, QDockWidget):
    """Rows of names/addresses with their live value, display format and modify value."""

    def __init__(self, session: PlcSession, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("watchTableDock")
        self.session = session
        self.settings: Settings | None = None
        self.key: str | None = None  # the program's file: where its rows are kept
        self.symbols: SymbolTable | None = None
        self.dialect: str | None = None
        self.rows: list[WatchRow] = []
        self.found: list[Watched | WatchError] = []
        self.modify_errors: dict[int, Diagnostic] = {}  # a refused modify value's reason
        self._filling = False
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        bar = QHBoxLayout()
        self.modify_button = QPushButton(body)
        self.modify_button.setObjectName("watchModifyNow")
        self.modify_button.clicked.connect(lambda _checked=False: self.modify_now())
        self.delete_button = QPushButton(body)
        self.delete_button.setObjectName("watchDeleteRows")
        self.delete_button.clicked.connect(self.delete_selected)
        self.message = QLabel(body)
        self.message.setObjectName("watchMessage")
        self.message.setWordWrap(True)
        bar.addWidget(self.modify_button)
        bar.addWidget(self.delete_button)
        bar.addWidget(self.message, 1)
        layout.addLayout(bar)
        self.table = QTableWidget(0, 5, body)
        self.table.setObjectName("watchTable")
        self.table.verticalHeader().setDefaultSectionSize(
            self.table.fontMetrics().height() + 10)
        self.table.setTabKeyNavigation(False)  # Tab leaves the dock (no Tab trap)
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.table.setEditTriggers(QAbstractItemView.EditTrigger.DoubleClicked
                                   | QAbstractItemView.EditTrigger.EditKeyPressed
                                   | QAbstractItemView.EditTrigger.AnyKeyPressed)
        header = self.table.horizontalHeader()
        header.setSectionResizeMode(QHeaderView.ResizeMode.Interactive)
        header.setStretchLastSection(True)
        self.table.setContextMenuPolicy(Qt.ContextMenuPolicy.CustomContextMenu)
        self.table.customContextMenuRequested.connect(self._menu)
        self.table.itemChanged.connect(self._item_changed)
        self.table.installEventFilter(self)  # Delete: the selected rows go
        self.cell_error = CellError(self.table)
        self.cell_error.setObjectName("watchCellError")
        layout.addWidget(self.table, 1)
        self.setWidget(body)
        self.gate = SnapshotGate(self, self._show_values, session)  # shown, in budget
        session.snapshot_ready.connect(self.gate.offer)
        self.visibilityChanged.connect(lambda _shown: self.refresh())
        self.visibilityChanged.connect(lambda shown: shown and QTimer.singleShot(
            0, self._claim_width))
        self.retranslate()
        self._fill()

    # -- texts -----------------------------------------------------------------------------

    def retranslate(self) -> None:
        """Texts in the UI language."""
        self.setWindowTitle(translate("WatchTable", "Watch table"))
        self.toggleViewAction().setIcon(icon("watch_table"))
        self.toggleViewAction().setToolTip(translate(
            "WatchTable", "Watch table: tags and addresses, live, modified on request"))
        self.table.setHorizontalHeaderLabels([
            translate("WatchTable", "Name"), translate("WatchTable", "Address"),
            translate("WatchTable", "Display format"), translate("WatchTable", "Monitor value"),
            translate("WatchTable", "Modify value")])
        self.modify_button.setText(translate("WatchTable", "Modify now"))
        self.modify_button.setToolTip(translate(
            "WatchTable", "Write the modify values of the checked rows (none checked: of the "
            "selected rows) into the PLC now"))
        self.delete_button.setText(translate("WatchTable", "Delete rows"))
        self._fill()
        self._fit_columns()

    def _fit_columns(self) -> None:
        """Each column as wide as its title and its texts (no cut header, no cut name); a
        refusal's long text in Address is cut at a third of the view (whole in its tooltip)."""
        self.table.resizeColumnsToContents()
        widest = max(self.table.viewport().width() // 3, 160)
        if self.table.columnWidth(ADDRESS) > widest:
            self.table.setColumnWidth(ADDRESS, widest)
        fit_headers(self.table)

    def _claim_width(self) -> None:
        """Beside another dock in its row (the error list), as wide as its columns need, up
        to two thirds of the window: the names and values whole, not behind a scroll bar."""
        window = self.parentWidget()
        if not isinstance(window, QMainWindow) or self.isFloating():
            return
        table = self.table
        if table.horizontalHeader().length() <= table.viewport().width():
            return
        wanted = (table.horizontalHeader().length() + table.verticalHeader().width()
                  + table.verticalScrollBar().sizeHint().width() + 2 * table.frameWidth()
                  + self.width() - table.width() + 16)
        wanted = min(wanted, window.width() * 2 // 3)
        if self.width() >= wanted:
            return
        # the docks beside it in its row give the room (Qt gives a tabbed dock alone less)
        tabbed = window.tabifiedDockWidgets(self)
        beside = [dock for dock in window.findChildren(QDockWidget)
                  if dock is not self and dock not in tabbed and dock.isVisible()
                  and not dock.isFloating()
                  and window.dockWidgetArea(dock) == window.dockWidgetArea(self)
                  and dock.geometry().top() == self.geometry().top()]
        room = sum(dock.width() for dock in beside) - (wanted - self.width())
        total = sum(dock.width() for dock in beside) or 1
        window.resizeDocks([*beside, self], [*(dock.width() * room // total for dock in beside),
                                             wanted], Qt.Orientation.Horizontal)

    # -- the program and where its rows are kept -------------------------------------------

    def keep_in(self, settings: Settings) -> None:
        """Keep each program's rows in `settings` (the main window's)."""
        self.settings = settings

    def use_program(self, path: Path | None, program: Program) -> None:
        """The console shows `program` (from `path`): its names, its family, its rows."""
        self.symbols = program.symbols
        self.dialect = program.dialect
        key = str(path.resolve()) if path is not None else None
        if key != self.key or key is None:
            self.key = key
            text = self.settings.watch_rows(key) if self.settings and key else ""
            self.rows = rows_from_text(text) if text else []
        self.modify_errors.clear()
        self.message.clear()
        self._fill()

    def _save(self) -> None:
        if self.settings is not None and self.key is not None:
            self.settings.set_watch_rows(self.key, rows_text(self.rows))

    # -- rows ----------------------------------------------------------------------------

    def add_row(self, name: str, fmt: str = "", modify_value: str = "") -> int:
        """Add a row (as typed in the last, empty row); its index."""
        self.rows.append(WatchRow(name.strip(), fmt, modify_value))
        self._save()
        self._fill()
        return len(self.rows) - 1

    def set_modify(self, index: int, text: str, checked: bool | None = None) -> None:
        """Type `text` as row `index`'s modify value (and check it or not)."""
        item = self.table.item(index, MODIFY)
        if item is None:
            return
        item.setText(text)
        if checked is not None:
            item.setCheckState(Qt.CheckState.Checked if checked else Qt.CheckState.Unchecked)

    def set_format(self, index: int, fmt: Format) -> None:
        """Show row `index` in `fmt` (when its place has that format)."""
        box = self.table.cellWidget(index, FORMAT)
        if isinstance(box, QComboBox):
            at = box.findData(fmt.value)
            if at >= 0:
                box.setCurrentIndex(at)

    def delete_selected(self) -> None:
        """Delete the selected rows."""
        chosen = sorted({index.row() for index in self.table.selectedIndexes()
                         if index.row() < len(self.rows)}, reverse=True)
        for row in chosen:
            del self.rows[row]
        if chosen:
            self.modify_errors.clear()
            self._save()
            self._fill()

    def _fill(self) -> None:
        """Build the table from the rows (and the empty row that adds one)."""
        self._filling = True
        self.cell_error.hide()
        self.found = []
        for index in range(self.table.rowCount()):  # the old boxes go at once, not later
            old = self.table.cellWidget(index, FORMAT)
            if old is not None:
                old.hide()
                self.table.removeCellWidget(index, FORMAT)
        self.table.setRowCount(len(self.rows) + 1)
        for index, row in enumerate(self.rows):
            try:
                self.found.append(watched(row, self.symbols, self.dialect))
            except WatchError as error:
                self.found.append(error)
            self._fill_row(index, row)
        self._fill_new_row(len(self.rows))
        self._filling = False
        self.refresh()
        self._fit_columns()
        if self.isVisible():  # the columns grew: the dock too, when its row has room
            QTimer.singleShot(0, self._claim_width)

    def _fill_row(self, index: int, row: WatchRow) -> None:
        found = self.found[index]
        name = QTableWidgetItem(row.name)
        name.setFlags(_EDITABLE)
        self.table.setItem(index, NAME, name)
        if isinstance(found, WatchError):
            why = diagnostic_text(found.diagnostic)
            address = QTableWidgetItem(why)
            address.setForeground(QBrush(_ERROR))
            address.setToolTip(why)
        else:
            address = QTableWidgetItem(found.place.spelled)
            address.setToolTip(found.place.type_name)
        address.setFlags(_SHOWN)
        self.table.setItem(index, ADDRESS, address)
        self.table.setCellWidget(index, FORMAT, self._format_box(index, found))
        monitor = QTableWidgetItem("")
        monitor.setFlags(_SHOWN)
        self.table.setItem(index, MONITOR, monitor)
        value = QTableWidgetItem(row.modify)
        value.setFlags(_EDITABLE | Qt.ItemFlag.ItemIsUserCheckable)
        value.setCheckState(Qt.CheckState.Checked if row.checked else Qt.CheckState.Unchecked)
        value.setToolTip(translate("WatchTable", "Checked: written by Modify now"))
        problem = self.modify_errors.get(index)
        if problem is not None:
            value.setBackground(QBrush(_BAD_CELL))
            value.setToolTip(diagnostic_text(problem))
        self.table.setItem(index, MODIFY, value)

    def _fill_new_row(self, index: int) -> None:
        add = QTableWidgetItem("")
        add.setFlags(_EDITABLE)
        add.setToolTip(translate("WatchTable", "Type a name or an address to add a row"))
        add.setData(Qt.ItemDataRole.UserRole, "new")
        self.table.setItem(index, NAME, add)
        hint = QTableWidgetItem(translate("WatchTable", "<Add new>"))
        hint.setFlags(Qt.ItemFlag.ItemIsEnabled)
        hint.setForeground(QBrush(QColor("#808080")))
        self.table.setItem(index, ADDRESS, hint)
        self.table.removeCellWidget(index, FORMAT)
        for column in (FORMAT, MONITOR, MODIFY):
            empty = QTableWidgetItem("")
            empty.setFlags(Qt.ItemFlag.ItemIsEnabled)
            self.table.setItem(index, column, empty)

    def _format_box(self, index: int, found: Watched | WatchError) -> QComboBox:
        box = QComboBox(self.table)
        box.setObjectName(f"watchFormat_{index}")
        if isinstance(found, WatchError):
            box.setEnabled(False)
            return box
        for fmt in formats(found.place):
            box.addItem(format_name(fmt), fmt.value)
        box.setCurrentIndex(max(box.findData(found.fmt.value), 0))
        box.currentIndexChanged.connect(lambda _at, i=index, b=box: self._format_chosen(i, b))
        return box

    def _format_chosen(self, index: int, box: QComboBox) -> None:
        if index >= len(self.rows) or self._filling:
            return
        self.rows[index].fmt = str(box.currentData())
        found = self.found[index]
        if isinstance(found, Watched):
            self.found[index] = Watched(found.place, Format(self.rows[index].fmt))
        self._save()
        self.refresh()

    def _item_changed(self, item: QTableWidgetItem) -> None:
        if self._filling:
            return
        index, column = item.row(), item.column()
        if index >= len(self.rows):
            typed = item.text()
            if column == NAME and typed.strip():  # once the editor has closed
                QTimer.singleShot(0, lambda: self.add_row(typed))
            return
        row = self.rows[index]
        if column == NAME:
            if not item.text().strip():  # a name erased: the row goes
                del self.rows[index]
            else:
                row.name = item.text().strip()
            self.modify_errors.pop(index, None)
            self._save()
            QTimer.singleShot(0, self._fill)  # once the editor has closed
        elif column == MODIFY:
            row.modify = item.text()
            row.checked = item.checkState() == Qt.CheckState.Checked
            self._save()

    def eventFilter(self, watched_object: QObject, event: QEvent) -> bool:
        """Delete in the table (not while a cell is edited) deletes the selected rows, not
        what the window's Delete shortcut would (the ladder's element)."""
        if (watched_object is self.table and isinstance(event, QKeyEvent)
                and event.key() == Qt.Key.Key_Delete
                and self.table.state() != QAbstractItemView.State.EditingState):
            if event.type() == QEvent.Type.ShortcutOverride:
                event.accept()  # the key comes here as a key press
                return True
            if event.type() == QEvent.Type.KeyPress:
                self.delete_selected()
                return True
        return super().eventFilter(watched_object, event)

    def _menu(self, pos: QPoint) -> None:
        index = self.table.rowAt(pos.y())
        if not 0 <= index < len(self.rows):
            return
        menu = QMenu(self.table)
        now = QAction(translate("WatchTable", "Modify now"), menu)
        now.triggered.connect(lambda: self.modify_now([index]))
        delete = QAction(translate("WatchTable", "Delete row"), menu)
        delete.triggered.connect(lambda: self._delete(index))
        menu.addAction(now)
        menu.addAction(delete)
        menu.popup(self.table.viewport().mapToGlobal(pos))

    def _delete(self, index: int) -> None:
        if index < len(self.rows):
            del self.rows[index]
            self.modify_errors.clear()
            self._save()
            self._fill()

    # -- modify --------------------------------------------------------------------------

    def modify_now(self, indices: list[int] | None = None) -> int:
        """Write the modify values of `indices`, else of the checked rows, else of the
        selected ones; a refused value is said at its cell. The values written."""
        if not indices:
            indices = [i for i, row in enumerate(self.rows) if row.checked]
        if not indices:
            indices = sorted({index.row() for index in self.table.selectedIndexes()
                              if index.row() < len(self.rows)})
        if not indices:
            set_live_text(self.message, lambda: translate(
                "WatchTable", "Check the rows to modify (or select one), then Modify now"))
            return 0
        writes, errors = modify([self.rows[i] for i in indices], self.symbols, self.dialect)
        store(writes, self._set_bit, self.session.write)
        self.modify_errors = {indices[at]: why for at, why in errors.items()}
        self._fill()
        written, refused = len(indices) - len(errors), len(errors)
        if self.modify_errors:
            QTimer.singleShot(0, self._show_first_error)  # once the columns are laid out
            set_live_text(self.message, lambda: translate(
                "WatchTable", "Values written: {0}, refused: {1}").format(written, refused))
        else:
            set_live_text(self.message, lambda: translate(
                "WatchTable", "Values written: {0}").format(written))
        return written

    def _show_first_error(self) -> None:
        """The first refused value's reason under its cell."""
        if self.modify_errors:
            first = min(self.modify_errors)
            if first < len(self.rows):
                across = self.table.horizontalScrollBar().value()
                self.table.scrollTo(self.table.model().index(first, MODIFY))  # its row
                self.table.horizontalScrollBar().setValue(across)  # the names stay in view
                self.cell_error.show_at(self.table.model().index(first, MODIFY),
                                        diagnostic_text(self.modify_errors[first]))

    def _set_bit(self, address: Address, value: int) -> None:
        self.session.set_bit(address, value)

    # -- monitor values ------------------------------------------------------------------

    def refresh(self) -> None:
        """Show the PLC's values now (a row added, a format chosen, the dock shown)."""
        if self.isVisible():
            self._show_values(self.session.run.snapshot())

    def _show_values(self, snapshot: PlcSnapshot) -> None:
        memory = Memory(snapshot.bit, snapshot.read)
        for index, found in enumerate(self.found):
            item = self.table.item(index, MONITOR)
            if item is None or isinstance(found, WatchError):
                continue
            try:
                text = show(found.place, found.fmt, memory)
            except (KeyError, IndexError):  # an area the PLC's memory does not have
                text = ""
            if item.text() != text:
                self.table.blockSignals(True)
                item.setText(text)
                self.table.blockSignals(False)
                wanted = self.table.fontMetrics().horizontalAdvance(text) + 16
                if wanted > self.table.columnWidth(MONITOR):  # a longer value: whole
                    self.table.setColumnWidth(MONITOR, wanted)
                    QTimer.singleShot(0, self._claim_width)
