"""The PLC tables dock: timer presets, counters, data table and keep relays, edited while running.

Each tab is a QTableView over a `PlcTableModel` driven by the table's spec (`table_specs.py`).
Right-click a table: INSERT fills a form and adds a row, DELETE clears the row under the mouse
(as the seed manual's tables). TMRB presets are fixed in the program and shown read-only
("a normal timer can be changed from the PLC table, TMRB cannot"). Every value set here is a
PMC parameter: saved with the program (`PROGRAM.LAD.prm`).
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from PySide6.QtCore import QCoreApplication, QPoint, Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import (
    QAbstractItemView,
    QDockWidget,
    QLabel,
    QMenu,
    QTableView,
    QTabWidget,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core import dialects
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.docks import snapshot_gate
from ladderworks.gui.docks.device_specs import DeviceSpec, device_specs
from ladderworks.gui.docks.snapshot_gate import SnapshotGate
from ladderworks.gui.docks.table_cell_error import RetypeDelegate
from ladderworks.gui.docks.table_entries import ProgramUse, TableError, TableKind
from ladderworks.gui.docks.table_forms import DeviceAdder, InsertRowDialog
from ladderworks.gui.docks.table_model import PlcTableModel
from ladderworks.gui.docks.table_specs import Row, TableSpec, table_specs
from ladderworks.gui.header_fit import fit_headers
from ladderworks.gui.plc_session import PlcSession, PlcSnapshot
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.translation import ui_is_turkish

translate = QCoreApplication.translate


class PlcTablesDock(Retranslating, QDockWidget):
    """Timers (TMR presets; TMRB read-only), counters (CTR), data table (D), keep relays (K)."""

    def __init__(self, session: PlcSession, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("plcTablesDock")
        self.session = session
        self.specs: dict[TableKind, TableSpec] = {
            spec.kind: spec for spec in [*table_specs(), *device_specs()]}
        self.models: dict[TableKind, PlcTableModel] = {}
        self.tables: dict[TableKind, QTableView] = {}
        self.insert_dialog: InsertRowDialog | None = None
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        self.tabs = QTabWidget(body)
        self.tabs.setObjectName("plcTablesTabs")
        self.device_tabs = QTabWidget(body)  # a Delta/Fatek program's timers, counters, registers
        self.device_tabs.setObjectName("plcDeviceTabs")
        self.device_tabs.hide()
        self._unfitted: set[TableKind] = set()  # tables whose columns wait to be fitted
        self._stale: set[TableKind] = set()  # tables that missed a snapshot (not shown)
        for kind, spec in self.specs.items():
            model = PlcTableModel(spec, session)
            model.setParent(self)
            model.refused.connect(self._refused)
            model.stored.connect(lambda: self._say(""))
            self.models[kind] = model
            tabs = self._tabs_of(kind)
            self.tables[kind] = self._make_view(kind, model, tabs)
            tabs.addTab(self.tables[kind], "")
        layout.addWidget(self.tabs, 1)
        self.adder = DeviceAdder(body)  # any device, as WPLSoft's device monitor
        self.adder.add_requested.connect(self.add_devices)
        self.adder.hide()
        layout.addWidget(self.adder)
        layout.addWidget(self.device_tabs, 1)
        self.dialect_note = QLabel(body)  # a dialect program without device tables
        self.dialect_note.setObjectName("plcTablesDialectNote")
        self.dialect_note.setWordWrap(True)
        self.dialect_note.setAlignment(Qt.AlignmentFlag.AlignTop | Qt.AlignmentFlag.AlignLeft)
        self.dialect_note.hide()
        layout.addWidget(self.dialect_note, 1)
        self.message = QLabel(body)
        self.message.setObjectName("plcTablesMessage")
        self.message.setWordWrap(True)
        layout.addWidget(self.message)
        self.insert_action: QAction | None = None  # the last right-click menu's actions
        self.delete_action: QAction | None = None
        self.setWidget(body)
        # only the table shown takes snapshots, within its share of the GUI thread
        self.gate = SnapshotGate(self, self._show_snapshot, session)
        session.snapshot_ready.connect(self._on_snapshot)
        session.program_loaded.connect(self._on_program)
        self.tabs.currentChanged.connect(lambda _index: self._shown_changed())
        self.device_tabs.currentChanged.connect(lambda _index: self._shown_changed())
        self.visibilityChanged.connect(lambda _shown: self._shown_changed())
        self.retranslate()

    def _tabs_of(self, kind: TableKind) -> QTabWidget:
        """The tab widget a table is in: the PMC's, or the dialect devices'."""
        return self.device_tabs if isinstance(self.specs[kind], DeviceSpec) else self.tabs

    def _make_view(self, kind: TableKind, model: PlcTableModel, tabs: QTabWidget) -> QTableView:
        table = QTableView(tabs)
        table.setModel(model)
        table.setObjectName(f"plcTable_{kind.value}")
        table.verticalHeader().hide()
        table.setTabKeyNavigation(False)  # Tab leaves the dock (issue 18: no Tab trap)
        table.setAlternatingRowColors(True)
        table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        table.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        table.setEditTriggers(
            QAbstractItemView.EditTrigger.DoubleClicked
            | QAbstractItemView.EditTrigger.EditKeyPressed
            | QAbstractItemView.EditTrigger.AnyKeyPressed
        )
        table.horizontalHeader().setStretchLastSection(True)
        table.setItemDelegate(RetypeDelegate(table, lambda: self._reason(model)))
        table.setContextMenuPolicy(Qt.ContextMenuPolicy.CustomContextMenu)
        table.customContextMenuRequested.connect(lambda pos: self._context_menu(kind, pos))
        model.modelReset.connect(lambda: self._fit_columns(kind))
        model.rowsInserted.connect(lambda: self._fit_columns(kind))
        table.resizeColumnsToContents()
        return table

    # -- showing -------------------------------------------------------------------------------

    def _fit_columns(self, kind: TableKind) -> None:
        """Columns as wide as their contents; a hidden table's wait until it is shown (each
        fit reads every cell: ~0.3 s of F9 for a real program's tables in a hidden dock)."""
        table = self.tables.get(kind)
        if table is None:  # a signal while the view is being made
            return
        if table.isVisible():
            self._unfitted.discard(kind)
            table.resizeColumnsToContents()
            header = table.horizontalHeader()  # the last column fills the width again
            header.setStretchLastSection(False)
            header.setStretchLastSection(True)
        else:
            self._unfitted.add(kind)

    def _current_kind(self) -> TableKind | None:
        shown = self.device_tabs if self.device_tabs.isVisibleTo(self) else self.tabs
        return next((k for k, table in self.tables.items()
                     if table is shown.currentWidget()), None)

    def _shown_changed(self) -> None:
        """Another tab, or the dock shown or hidden: the table shown catches up."""
        kind = self._current_kind()
        if kind is None or not self.isVisible():
            return
        self.gate.flush()  # a snapshot held back: the table shown takes a new one
        self._catch_up(kind)
        if kind in self._unfitted:  # it missed a fit while hidden
            self._fit_columns(kind)

    def _on_program(self, program: BinaryProgram) -> None:
        use = ProgramUse.of(program)  # once, not once a table: ~80 ms for 38k ops
        for model in self.models.values():
            model.set_program(program, use)
        self._stale.clear()
        dialect = dialects.get(self.session.run.program_dialect)
        devices = dialect.device_tables() if dialect is not None else None
        self.tabs.setVisible(dialect is None)  # the tables are PMC parameters
        self.device_tabs.setVisible(devices is not None)  # WPLSoft's / WinProladder's
        self.adder.setVisible(devices is not None)
        self.adder.say("")
        self.dialect_note.setVisible(dialect is not None and devices is None)
        self.retranslate()  # the timer columns follow the program's dialect

    def _on_snapshot(self, snapshot: PlcSnapshot) -> None:
        self._stale.update(self.models)
        self.gate.offer(snapshot)

    def _show_snapshot(self, snapshot: PlcSnapshot) -> None:
        """The table shown takes the snapshot (every table did before the gate)."""
        kinds = list(self.models) if snapshot_gate.UPDATE_ALWAYS else [self._current_kind()]
        for kind in kinds:
            if kind is not None:
                self._stale.discard(kind)
                self.models[kind].update(snapshot.areas)

    def _catch_up(self, kind: TableKind) -> None:
        """A table that missed snapshots reads the memory now."""
        if kind in self._stale:
            self._stale.discard(kind)
            self.models[kind].update()

    def refresh(self) -> None:
        """Show the tables' values now."""
        self._stale.clear()
        for model in self.models.values():
            model.update()

    def rows(self, kind: TableKind) -> list[Row]:
        """The rows a table shows (brought up to date when it missed snapshots)."""
        self._catch_up(kind)
        return self.models[kind].rows

    def cell_texts(self, kind: TableKind) -> list[list[str]]:
        """What a table shows, row by row (brought up to date when it missed snapshots)."""
        self._catch_up(kind)
        return self.models[kind].texts()

    # -- editing -------------------------------------------------------------------------------

    def edit_cell(self, kind: TableKind, row: int, column: int, text: str) -> str | None:
        """Store a value typed in a cell; the translated reason when it is refused (the cell
        then shows the stored value again)."""
        self._catch_up(kind)
        model = self.models[kind]
        if model.setData(model.index(row, column), text):
            return None
        return diagnostic_text(model.last_error.diagnostic) if model.last_error else None

    @staticmethod
    def _reason(model: PlcTableModel) -> str:
        """Why the model refused the last value typed, translated ("" when it did not)."""
        return diagnostic_text(model.last_error.diagnostic) if model.last_error else ""

    def _refused(self, error: TableError) -> None:
        self._say(diagnostic_text(error.diagnostic), error=True)

    def _outcome(self, error: TableError | None) -> str | None:
        if error is None:
            self._say("")
            return None
        problem = diagnostic_text(error.diagnostic)
        self._say(problem, error=True)
        return problem

    def insert_texts(self, kind: TableKind, texts: Sequence[str]) -> str | None:
        """INSERT with the form's texts: validate, store, list the row; or the reason not."""
        error = self.models[kind].run("insert", list(texts) + [""] * 3)
        if error is not None:
            return diagnostic_text(error.diagnostic)
        self._say("")
        return None

    def add_devices(self, text: str) -> str | None:
        """Add the devices typed (`D500`, `T5`, `D0-D9`, several with commas) each to the
        table that holds it, that table shown; the reason (under the field) when refused."""
        device_kinds = [k for k, spec in self.specs.items() if isinstance(spec, DeviceSpec)]
        for item in (part for part in re.split(r"[,;\s]+", text.strip()) if part):
            letter = re.match(r"[A-Za-z]*", item).group(0).upper()  # type: ignore[union-attr]
            kind = next((k for k in device_kinds if letter in self._letters(k)), None)
            if kind is None:
                letters = [ch for k in device_kinds for ch in self._letters(k)]
                problem = translate("PlcTables", "'{0}' is not a device of these tables (use "
                                    "{1}); watch a bit in the bit display").format(
                                        item, ", ".join(dict.fromkeys(letters)))
                self.adder.say(problem)
                return problem
            error = self.models[kind].run("insert", [item, "", "", ""])
            if error is not None:
                problem = diagnostic_text(error.diagnostic)
                self.adder.say(problem)
                return problem
            self.device_tabs.setCurrentWidget(self.tables[kind])
        self.adder.say("")
        self.adder.field.clear()
        return None

    def delete_row(self, kind: TableKind, row: int) -> str | None:
        """DELETE: clear the row's value and unlist it (a row the program uses stays, at 0)."""
        return self._outcome(self.models[kind].run("delete", row))

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
        self.delete_action.setEnabled(0 <= row < self.models[kind].rowCount())
        menu.addAction(self.insert_action)
        menu.addAction(self.delete_action)
        return menu

    def _context_menu(self, kind: TableKind, pos: QPoint) -> None:
        table = self.tables[kind]
        row = table.rowAt(pos.y())
        self.context_menu(kind, row).exec(table.viewport().mapToGlobal(pos))

    def open_insert_dialog(self, kind: TableKind) -> InsertRowDialog:
        """Open the INSERT form of a table (not modal-blocking: OK inserts)."""
        fields = self.specs[kind].form_fields(self.session)
        dialog = InsertRowDialog(kind, fields, lambda texts: self.insert_texts(kind, texts),
                                 self)
        dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
        self.insert_dialog = dialog
        dialog.open()
        return dialog

    # -- texts -------------------------------------------------------------------------------

    def _letters(self, kind: TableKind) -> tuple[str, ...]:
        spec = self.specs[kind]
        return spec.letters(self.session) if isinstance(spec, DeviceSpec) else ()

    def _say(self, text: str, *, error: bool = False) -> None:
        self.message.setStyleSheet("color:#c00000;" if error else "")
        self.message.setText(text)

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(translate("PlcTables", "PLC tables"))
        dialect = dialects.get(self.session.run.program_dialect)
        if dialect is not None:
            self.dialect_note.setText(translate(
                "PlcTables",
                "A {0} program has no PMC parameter tables: its timer and counter presets "
                "are written in its instructions. Watch its T, C and D devices in the bit "
                "display and the time chart.").format(
                    dialect.title_tr if ui_is_turkish() else dialect.title))
        titles = {
            TableKind.TIMER: translate("PlcTables", "Timers (TMR)"),
            TableKind.COUNTER: translate("PlcTables", "Counters (CTR)"),
            TableKind.DATA: translate("PlcTables", "Data table (D)"),
            TableKind.KEEP: translate("PlcTables", "Keep relays (K)"),
            TableKind.DEVICE_TIMERS: translate("PlcTables", "Timers (T)"),
            TableKind.DEVICE_COUNTERS: translate("PlcTables", "Counters (C)"),
            TableKind.REGISTERS: translate("PlcTables", "Registers ({0})").format(
                ", ".join(self._letters(TableKind.REGISTERS)) or "D"),
        }
        self.adder.retranslate()
        for kind in self.specs:
            tabs = self._tabs_of(kind)
            tabs.setTabText(tabs.indexOf(self.tables[kind]), titles[kind])
            self.models[kind].retranslate()
            fit_headers(self.tables[kind])  # the titles in the new language, whole
        layout = self.session.run.timers
        self.tables[TableKind.TIMER].setToolTip(
            translate(
                "PlcTables",
                "Presets up to {0} ms; timers 1-8 count in 48 ms ticks, 9-100 and TMRB in 8 ms",
            ).format(layout.max_preset) if not layout.has_precision else translate(
                "PlcTables",
                "Presets in ticks (up to {0}); the precision code sets the tick: "
                "0 default (48 ms for 1-8, else 8 ms), 1 = 1 ms, 2 = 10 ms, 3 = 100 ms, "
                "4 = 1 s, 5 = 1 min",
            ).format(layout.max_preset)
        )
