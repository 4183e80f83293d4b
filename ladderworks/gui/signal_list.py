"""The signal list dock: search the F/G/X/Y signals of the manual and use one in the ladder."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QEvent, Signal
from PySide6.QtGui import QShowEvent
from PySide6.QtWidgets import (
    QAbstractItemView,
    QDockWidget,
    QHeaderView,
    QLabel,
    QLineEdit,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.signals import Signal as PlcSignal
from ladderworks.core.signals import load_signals, search
from ladderworks.gui.translation import ui_is_turkish

translate = QCoreApplication.translate

_COLUMNS = 4  # address, name, English, Turkish


class SignalListDock(QDockWidget):
    """A searchable table of every named signal; double-click picks one."""

    address_chosen = Signal(object)  # the Address of the chosen signal

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("dock_signals")
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        self.query = QLineEdit(body)
        self.query.setObjectName("signals_query")
        self.query.setClearButtonEnabled(True)
        self.query.textChanged.connect(self.show_matches)
        self.count_label = QLabel(body)
        self.table = QTableWidget(0, _COLUMNS, body)
        self.table.setObjectName("signals_table")
        self.table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.table.verticalHeader().hide()
        header = self.table.horizontalHeader()
        # Interactive, sized once after each fill: ResizeToContents would re-measure every
        # column on every inserted item (quadratic, tens of seconds for the 1,064 signals).
        header.setSectionResizeMode(QHeaderView.ResizeMode.Interactive)
        header.setStretchLastSection(True)
        self.table.cellDoubleClicked.connect(self._on_double_click)
        layout.addWidget(self.query)
        layout.addWidget(self.count_label)
        layout.addWidget(self.table, 1)
        self.setWidget(body)
        self._shown: list[PlcSignal] = []
        self._stale = True  # rows not filled for the current query/language yet
        self.retranslate()

    def show_matches(self, query: str) -> list[PlcSignal]:
        """Fill the table with the signals matching `query` (all of them when it is empty)."""
        found = list(search(query)) if query.strip() else list(load_signals())
        self._shown = found
        self._stale = False
        self.table.setUpdatesEnabled(False)
        self.table.clearContents()
        self.table.setRowCount(len(found))
        turkish_first = ui_is_turkish()
        for row, signal in enumerate(found):
            own, other = ((signal.turkish, signal.english) if turkish_first
                          else (signal.english, signal.turkish))
            tip = "\n".join(t for t in (own, other, signal.notes) if t)
            for column, text in enumerate((str(signal.address), signal.name, own, other)):
                item = QTableWidgetItem(text)
                item.setToolTip(tip)
                self.table.setItem(row, column, item)
        for column in range(_COLUMNS - 1):
            self.table.resizeColumnToContents(column)
        self.table.setUpdatesEnabled(True)
        self._show_count()
        return found

    def signal_at_row(self, row: int) -> PlcSignal | None:
        """The signal shown in a row."""
        return self._shown[row] if 0 <= row < len(self._shown) else None

    def _on_double_click(self, row: int, _column: int) -> None:
        signal = self.signal_at_row(row)
        if signal is not None:
            self.address_chosen.emit(signal.address)

    def _show_count(self) -> None:
        self.count_label.setText(
            translate("SignalList", "{0} signals").format(len(self._shown)))

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(translate("SignalList", "Signals"))
        self.query.setPlaceholderText(
            translate("SignalList", "Address, name or words, e.g. G8.4, SPL, acil"))
        english, turkish = translate("SignalList", "English"), translate("SignalList", "Turkish")
        self.table.setHorizontalHeaderLabels([
            translate("SignalList", "Address"),
            translate("SignalList", "Name"),
            *((turkish, english) if ui_is_turkish() else (english, turkish)),
        ])
        self.table.setToolTip(translate(
            "SignalList", "Double-click: use the address for the contact or coil at the cursor"))
        # The description columns follow the language: refill now if shown, else when shown.
        if self.isVisible():
            self.show_matches(self.query.text())
        else:
            self._stale = True
            self._show_count()

    def showEvent(self, event: QShowEvent) -> None:
        """Fill the table when the dock is first shown (or after a change while hidden)."""
        if self._stale:
            self.show_matches(self.query.text())
        super().showEvent(event)

    def changeEvent(self, event: QEvent) -> None:
        """Retranslate on a language change."""
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)

