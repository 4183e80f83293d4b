"""The signal list dock: search the program's symbols and the F/G/X/Y signals of the manual,
and use one in the ladder."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, Signal
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

from ladderworks.core.address import Address
from ladderworks.core.signals import Signal as PlcSignal
from ladderworks.core.signals import fold, load_signals, search
from ladderworks.core.symbols import Symbol, SymbolTable
from ladderworks.gui.header_fit import fit_headers
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.translation import ui_is_turkish

translate = QCoreApplication.translate

_COLUMNS = 4  # address, name, description in the UI language, description in the other one
# (a program symbol: address, symbol, its comment; the other language is left empty)
MAX_SYMBOL_ROWS = 500  # program symbols listed for one query (a real program has 12,000+)


def _order(found: tuple[Address, Symbol]) -> tuple[str, int, int]:
    address = found[0]
    return address.area.value, address.byte, -1 if address.bit is None else address.bit


def symbol_matches(symbols: SymbolTable, query: str) -> list[tuple[Address, Symbol]]:
    """The program's symbols whose symbol, address or comment contains `query`, best first
    (exact symbol, then symbol prefix, then the rest, by address)."""
    folded = fold(query.strip())
    if not folded:
        return []
    groups: tuple[list[tuple[Address, Symbol]], ...] = ([], [], [])
    for address, entry in symbols.by_address.items():
        name = fold(entry.symbol)
        if name == folded or fold(str(address)) == folded:
            groups[0].append((address, entry))
        elif name.startswith(folded):
            groups[1].append((address, entry))
        elif folded in name or any(folded in fold(c) for c in entry.comments):
            groups[2].append((address, entry))
    return [found for group in groups for found in sorted(group, key=_order)]


class SignalListDock(Retranslating, QDockWidget):
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
        self.table.setTabKeyNavigation(False)  # Tab leaves the table (arrows move in it)
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
        self._addresses: list[Address] = []  # the address of each row (symbols first)
        self.symbols: SymbolTable | None = None  # the open program's `%@2` symbols
        self._stale = True  # rows not filled for the current query/language yet
        self.retranslate()

    def show_matches(self, query: str) -> list[PlcSignal]:
        """Fill the table with the signals matching `query` (all of them when it is empty)."""
        found = list(search(query)) if query.strip() else list(load_signals())
        named = (symbol_matches(self.symbols, query)[:MAX_SYMBOL_ROWS]
                 if self.symbols is not None else [])
        self._shown = found
        self._addresses = [address for address, _entry in named]
        self._addresses += [signal.address for signal in found]
        self._stale = False
        self.table.setUpdatesEnabled(False)
        self.table.clearContents()
        self.table.setRowCount(len(named) + len(found))
        turkish_first = ui_is_turkish()
        rows: list[tuple[tuple[str, ...], str]] = []
        program = translate("SignalList", "Program symbol")
        for address, entry in named:
            comment = " / ".join(entry.comments)
            rows.append(((str(address), entry.symbol, comment, ""),
                         "\n".join(t for t in (program, entry.symbol, *entry.comments) if t)))
        for signal in found:
            own, other = ((signal.turkish, signal.english) if turkish_first
                          else (signal.english, signal.turkish))
            rows.append(((str(signal.address), signal.name, own, other),
                         "\n".join(t for t in (own, other, signal.notes, _star(signal)) if t)))
        for row, (texts, tip) in enumerate(rows):
            for column, text in enumerate(texts):
                item = QTableWidgetItem(text)
                item.setToolTip(tip)
                if row < len(named):  # the program's own symbols: in italics
                    font = item.font()
                    font.setItalic(True)
                    item.setFont(font)
                self.table.setItem(row, column, item)
        for column in range(_COLUMNS - 1):
            self.table.resizeColumnToContents(column)
        self.table.setUpdatesEnabled(True)
        self._show_count()
        return found

    def signal_at_row(self, row: int) -> PlcSignal | None:
        """The manual's signal shown in a row (None for a program symbol's row)."""
        row -= len(self._addresses) - len(self._shown)
        return self._shown[row] if 0 <= row < len(self._shown) else None

    def address_at_row(self, row: int) -> Address | None:
        """The address shown in a row (a program symbol's or a signal's)."""
        return self._addresses[row] if 0 <= row < len(self._addresses) else None

    def row_texts(self, row: int) -> list[str]:
        """The texts of one row (for tests)."""
        items = [self.table.item(row, c) for c in range(_COLUMNS)]
        return [item.text() if item is not None else "" for item in items]

    def set_symbols(self, symbols: SymbolTable | None) -> None:
        """The open program's symbols are searched too (listed before the manual's signals)."""
        self.symbols = symbols
        if not self.query.text().strip():
            return  # an empty query lists the manual's signals only: nothing changes
        if self.isVisible():
            self.show_matches(self.query.text())
        else:
            self._stale = True

    def _on_double_click(self, row: int, _column: int) -> None:
        address = self.address_at_row(row)
        if address is not None:
            self.address_chosen.emit(address)

    def _show_count(self) -> None:
        named = len(self._addresses) - len(self._shown)
        text = translate("SignalList", "{0} signals").format(len(self._shown))
        if named > 0:
            text = translate("SignalList", "{0} program symbols, {1}").format(named, text)
        self.count_label.setText(text)

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(translate("SignalList", "Signals"))
        self.query.setPlaceholderText(
            translate("SignalList", "Address, symbol, name or words, e.g. G8.4, SPL, acil"))
        # A program symbol's comment is its description, whatever language it is written in.
        other = (translate("SignalList", "In English") if ui_is_turkish()
                 else translate("SignalList", "In Turkish"))
        self.table.setHorizontalHeaderLabels([
            translate("SignalList", "Address"),
            translate("SignalList", "Name"),
            translate("SignalList", "Description"),
            other,
        ])
        fit_headers(self.table)
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


def _star(signal: PlcSignal) -> str:
    """What a FANUC `*` name means and where it comes from (empty for the others)."""
    if not signal.seed_name:
        return ""
    return translate("SignalList", "{0}: FANUC's name (* = active low: 0 means on); the seed "
                     "manual writes {1}. Source: {2}").format(
        signal.name, signal.seed_name, signal.source)
