"""The cross reference dock: where the program reads and writes an address; a double-click jumps."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from PySide6.QtCore import (
    QAbstractTableModel,
    QCoreApplication,
    QModelIndex,
    QObject,
    QPersistentModelIndex,
    Qt,
    QTimer,
    Signal,
)
from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import (
    QAbstractItemView,
    QDockWidget,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QLineEdit,
    QMainWindow,
    QTableView,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core import dialects
from ladderworks.core.address import Address, AddressError, looks_like_address
from ladderworks.core.dialects.spelling import Spelling, spelling
from ladderworks.core.instructions import spec_for
from ladderworks.core.ladder.model import Coil, Contact, FunctionBox, LadderNetwork
from ladderworks.core.symbols import SymbolTable, resolve
from ladderworks.core.tag_names import TagNames, names_for, network_name
from ladderworks.core.xref import Access, CrossReference, Use, UseKind
from ladderworks.gui.console_menus import ConsoleMenus
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.editor.ladder_model import LadderModel
from ladderworks.gui.editor.view import LadderEditor
from ladderworks.gui.family_words import xref_example
from ladderworks.gui.header_fit import fit_headers
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.symbol_text import name_and_text

translate = QCoreApplication.translate

Index = QModelIndex | QPersistentModelIndex


@dataclass(frozen=True, slots=True)
class ProgramSource:
    """What the dock reads: the console's networks, the program's symbols and dialect."""

    networks: Callable[[], Sequence[LadderNetwork]]
    symbols: Callable[[], SymbolTable | None]
    dialect: Callable[[], str]


def kind_text(use: Use, spelled: Spelling | None = None) -> str:
    """The element in the UI language: `NOT contact`, `MOVW output`, `TMR preset` (the
    instruction as the program's dialect names it: a Delta `TMR timer`, not `DVP.TMR`)."""
    texts = {
        UseKind.CONTACT: lambda: translate("CrossReference", "Contact"),
        UseKind.CONTACT_NOT: lambda: translate("CrossReference", "NOT contact"),
        UseKind.COIL: lambda: translate("CrossReference", "Coil"),
        UseKind.COIL_NOT: lambda: translate("CrossReference", "NOT coil"),
        UseKind.SET: lambda: translate("CrossReference", "SET coil"),
        UseKind.RESET: lambda: translate("CrossReference", "RST coil"),
    }
    if use.kind in texts:
        return texts[use.kind]()
    spec = spec_for(use.instruction) if spelled is not None else None
    name = spelled.name(spec) if spelled is not None and spec is not None else use.instruction
    return f"{name} {use.parameter}"


def access_text(access: Access) -> str:
    """Read, Write or Read and write in the UI language."""
    if access is Access.READ:
        return translate("CrossReference", "Read")
    if access is Access.WRITE:
        return translate("CrossReference", "Write")
    return translate("CrossReference", "Read and write")


def unit_text(unit: str, symbols: SymbolTable | None) -> str:
    """`Level 2`, or a subprogram `P5` with its program symbol."""
    if unit.startswith("L"):
        return translate("CrossReference", "Level {0}").format(unit[1:])
    if unit.startswith("P") and unit[1:].isdigit() and symbols is not None:
        name = symbols.program_symbol(int(unit[1:]))
        return f"{unit} {name}" if name else unit
    return unit


class CrossReferenceModel(QAbstractTableModel):
    """The uses shown: address, symbol, network, label, unit, element, access, comment."""

    COLUMNS = 8

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.uses: list[Use] = []
        self.symbols: SymbolTable | None = None
        self.spelled = spelling(None)  # the program's dialect's spelling (set by the dock)
        self.names = TagNames(None, None)  # an S7 program's tags (set by the dock)
        self.titles: list[str] = []  # the S7 network title of each network

    def show(self, uses: list[Use], symbols: SymbolTable | None) -> None:
        """Replace the rows."""
        self.beginResetModel()
        self.uses = uses
        self.symbols = symbols
        self.endResetModel()

    def rowCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008 (Qt's signature)
        """Number of uses (a flat table)."""
        return 0 if parent.isValid() else len(self.uses)

    def columnCount(self, parent: Index = QModelIndex()) -> int:  # noqa: B008
        """Eight columns."""
        return 0 if parent.isValid() else self.COLUMNS

    def headerData(self, section: int, orientation: Qt.Orientation,
                   role: int = Qt.ItemDataRole.DisplayRole) -> object:
        """Column titles in the UI language."""
        if orientation is not Qt.Orientation.Horizontal or role != Qt.ItemDataRole.DisplayRole:
            return None
        return (translate("CrossReference", "Address"), translate("CrossReference", "Symbol"),
                translate("CrossReference", "Network"), translate("CrossReference", "Label"),
                translate("CrossReference", "Program part"),
                translate("CrossReference", "Element"), translate("CrossReference", "Access"),
                translate("CrossReference", "Comment"))[section]

    def data(self, index: Index, role: int = Qt.ItemDataRole.DisplayRole) -> object:
        """A cell's text (the address column shows the width of a word: `D100:2`)."""
        if not index.isValid() or role not in (Qt.ItemDataRole.DisplayRole,
                                               Qt.ItemDataRole.ToolTipRole):
            return None
        use = self.uses[index.row()]
        column = index.column()
        if self.names.typed and column in (0, 1, 2, 7):
            return self._named(use, column)
        if column == 0:
            if self.spelled.dialect:  # a Delta program: its device (`D500`, `T0`)
                return self.spelled.address(use.address)
            return str(use.address) + (f":{use.width}" if use.width > 1 else "")
        if self.spelled.dialect and column in (1, 7):  # no FANUC signal names for Delta
            return use.comment if column == 7 else ""
        if column == 1 or column == 7:
            named = name_and_text(use.address, self.symbols)
            if column == 1:
                return named[0] if named is not None else ""
            return use.comment or (named[1] if named is not None else "")
        if column == 2:
            return str(use.network + 1)
        if column == 3:
            return use.label
        if column == 4:
            return unit_text(use.unit, self.symbols)
        if column == 5:
            return kind_text(use, self.spelled)
        return access_text(use.access)

    def _named(self, use: Use, column: int) -> str:
        """An S7 program's address (`%MW10`, "" for a DB member), tag, network title and the
        tag's comment."""
        names = self.names
        if column == 0:
            return names.spelled(use.address, names.width_of(use.address, use.width))
        if column == 1:
            return names.name_of(use.address, use.width)
        if column == 2:  # the S7 network as TIA names it: `Network 3: Title`
            title = self.titles[use.network] if use.network < len(self.titles) else ""
            return network_name(use.network + 1, title,
                                translate("CrossReference", "Network"))
        found = self.symbols.lookup(use.address) if self.symbols is not None else None
        return use.comment or (found.comment if found is not None else "")


def ladder_titles(networks: Sequence[LadderNetwork]) -> list[str]:
    """The title of each console network of an S7 program (one drawn network per S7 network:
    its first comment line, "" when untitled)."""
    return [network.comments[0] if network.comments else "" for network in networks]


FIT_ROWS = 200  # rows measured to fit the columns to their contents


class CrossReferenceDock(Retranslating, QDockWidget):
    """An address or symbol field over the list of its uses; `jump_requested` on double-click."""

    jump_requested = Signal(int, object)  # network index, (row, column) or None

    def __init__(self, source: ProgramSource, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("dock_cross_reference")
        self.source = source
        self.at_cursor_action: QAction | None = None  # Tools › Cross reference (install)
        self.builds = 0  # how many times the index was built (once per program revision)
        self._xref: CrossReference | None = None
        self._shape: tuple[int, int] = (0, 0)
        body = QWidget(self)
        self.field_label = QLabel(body)
        self.query = QLineEdit(body)
        self.query.setObjectName("xref_query")
        self.query.setClearButtonEnabled(True)
        self.query.returnPressed.connect(self.refresh)
        self.field_label.setBuddy(self.query)
        self.summary = QLabel(body)
        self.summary.setObjectName("xref_summary")
        self.summary.setWordWrap(True)
        self.model = CrossReferenceModel(self)
        self.table = QTableView(body)
        self.table.setObjectName("xref_list")
        self.table.setModel(self.model)
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.table.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.table.setAlternatingRowColors(True)
        self.table.verticalHeader().hide()
        self.table.verticalHeader().setDefaultSectionSize(self.table.fontMetrics().height() + 6)
        self.table.horizontalHeader().setStretchLastSection(True)
        self.table.horizontalHeader().setSectionResizeMode(
            QHeaderView.ResizeMode.Interactive)
        self.table.activated.connect(self._on_activated)  # double-click or Enter
        top = QHBoxLayout()
        top.addWidget(self.field_label)
        top.addWidget(self.query, 1)
        top.addWidget(self.summary, 2)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addLayout(top)
        layout.addWidget(self.table, 1)
        self.setWidget(body)
        self._refresh_timer = QTimer(self)
        self._refresh_timer.setSingleShot(True)
        self._refresh_timer.setInterval(300)
        self._refresh_timer.timeout.connect(self.refresh)
        self.visibilityChanged.connect(self._on_visibility)
        self._stale_view = True
        self.retranslate()

    def invalidate(self, *_changed: object) -> None:
        """The program changed: the index is built anew when next needed."""
        self._xref = None
        self._stale_view = True
        self.query.setPlaceholderText(xref_example(self.source.dialect()))  # another family
        if self.isVisible():
            self._refresh_timer.start()

    def cross_reference(self) -> CrossReference:
        """The index of the program as it is now (built once per revision)."""
        networks = self.source.networks()
        shape = (id(networks), len(networks))
        if self._xref is None or shape != self._shape:
            self._xref = CrossReference.from_ladder(networks, self.source.dialect())
            self._shape = shape
            self.builds += 1
        return self._xref

    def show_address(self, text: str) -> None:
        """Show the dock with the uses of `text` (an address or a symbol)."""
        self.query.setText(text)
        self.show()
        self.raise_()
        self.refresh()

    def refresh(self) -> None:
        """List the uses of the typed address or symbol (every use when the field is empty)."""
        self._refresh_timer.stop()
        self._stale_view = False
        text = self.query.text().strip()
        symbols = self.source.symbols()
        self.model.spelled = spelling(self.source.dialect())
        names = self.model.names = names_for(symbols, self.source.dialect())
        self.model.titles = ladder_titles(self.source.networks()) if names.typed else []
        self.query.setPlaceholderText(xref_example(self.source.dialect()))
        if not text:
            xref = self.cross_reference()
            shown = [use for use in xref.sorted_uses() if not names.internal(use.address)]
            self.model.show(shown, symbols)
            self.summary.setText(translate("CrossReference", "All addresses — uses: {0}").format(
                len(shown)))
            self._fit_columns()
            return
        try:
            dialect = self.source.dialect()
            address = (names.resolve(text).address if names.typed
                       else dialects.parse_target(text, dialect)[0] if dialects.get(dialect)
                       else resolve(text, symbols))
        except AddressError as error:
            self.model.show([], symbols)
            self.summary.setText(
                diagnostic_text(error.diagnostic) if looks_like_address(text)
                else translate("CrossReference",
                               "'{0}' is neither an address nor a symbol of the program").format(
                                   text))
            return
        uses = [use for use in self.cross_reference().uses_of(address)
                if not names.internal(use.address) and not (  # a tag: its own bit's uses
                    names.typed and address.bit is not None and use.address.bit is not None
                    and use.address != address)]
        self.model.show(uses, symbols)
        self.summary.setText(self._summary_text(address, uses))
        self._fit_columns()

    def _summary_text(self, address: Address, uses: list[Use]) -> str:
        written = (self.model.names.shown(address) if self.model.names.typed
                   else self.model.spelled.address(address))  # a Delta T0, not T1000.0
        if not uses:
            return translate("CrossReference", "{0} is not used in the program").format(written)
        reads = sum(1 for u in uses if u.access is not Access.WRITE)
        writes = sum(1 for u in uses if u.access is not Access.READ)
        return translate("CrossReference", "{0} — uses: {1} (read: {2}, written: {3})").format(
            written, len(uses), reads, writes)

    def _fit_columns(self) -> None:
        """Columns as wide as their title and the rows measured (a huge list: the first
        FIT_ROWS and those in view, measuring every row costs seconds)."""
        self.table.horizontalHeader().setResizeContentsPrecision(FIT_ROWS)
        self.table.resizeColumnsToContents()

    def _on_activated(self, index: QModelIndex) -> None:
        if 0 <= index.row() < len(self.model.uses):
            use = self.model.uses[index.row()]
            self.jump_requested.emit(use.network, use.cell)

    def _on_visibility(self, visible: bool) -> None:
        if visible and self._stale_view:
            self._refresh_timer.start()

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(translate("CrossReference", "Cross reference"))
        if self.at_cursor_action is not None:
            self.at_cursor_action.setText(
                translate("CrossReference", "Cross &reference of this address"))
            self.at_cursor_action.setStatusTip(translate(
                "CrossReference", "List every place the program reads and writes the address"))
        self.field_label.setText(translate("CrossReference", "&Address or symbol:"))
        self.query.setPlaceholderText(xref_example(self.source.dialect()))
        self.model.headerDataChanged.emit(Qt.Orientation.Horizontal, 0,
                                          CrossReferenceModel.COLUMNS - 1)
        if self.model.uses:
            self.model.dataChanged.emit(self.model.index(0, 0), self.model.index(
                len(self.model.uses) - 1, CrossReferenceModel.COLUMNS - 1))
            self._fit_columns()  # "Okuma" is wider than "Read", shown or not
        fit_headers(self.table)
        if self.isVisible():
            self.refresh()


def address_at(network: LadderNetwork, row: int, col: int) -> Address | None:
    """The address of the element at a cell: a contact's or coil's, a box's first address."""
    found = network.element_at(row, col)
    if found is None:
        return None
    element = found[1]
    if isinstance(element, Contact | Coil):
        return element.address
    if isinstance(element, FunctionBox):
        return next((p for p in element.params if isinstance(p, Address)), None)
    return None


def install(window: QMainWindow, menus: ConsoleMenus, editor: LadderEditor,
            beside: QDockWidget) -> CrossReferenceDock:
    """Add the dock (View menu; tabbed with `beside`, the error list: both jump into the
    ladder), Tools › Cross reference and the ladder's context-menu entry."""
    model: LadderModel = editor.model
    source = ProgramSource(networks=lambda: _all_networks(model),
                           symbols=lambda: model.symbols, dialect=lambda: model.dialect)
    dock = CrossReferenceDock(source, window)
    menus.add_dock(dock, "action_dock_cross_reference", Qt.DockWidgetArea.BottomDockWidgetArea)
    dock.hide()
    window.tabifyDockWidget(beside, dock)
    dock.toggleViewAction().triggered.connect(lambda on: dock.raise_() if on else None)
    for changed in (model.document_reset, model.networks_inserted, model.network_removed,
                    model.network_changed, model.networks_changed):
        changed.connect(dock.invalidate)

    def jump(network: int, cell: tuple[int, int] | None) -> None:
        if not 0 <= network < len(editor.networks):
            return
        row, col = cell if cell is not None else (0, 0)
        editor.jump_to(network, row, col)  # in the middle of the view
        editor.setFocus()

    dock.jump_requested.connect(jump)

    def at_cursor() -> None:
        index, row, col = editor.cursor_cell
        networks = editor.networks
        address = address_at(networks[index], row, col) if 0 <= index < len(networks) else None
        if address is not None:
            dock.show_address(spelling(model.dialect).address(address))
        else:
            dock.show()
            dock.raise_()
        dock.query.setFocus()
        dock.query.selectAll()

    action = QAction(window)
    action.setObjectName("action_cross_reference")
    action.setShortcut(QKeySequence("Ctrl+Shift+X"))
    action.triggered.connect(at_cursor)
    menus.add("menu_tools", action, separator=True)
    editor.context_actions = [*editor.context_actions, None, action]
    window.addAction(action)
    dock.at_cursor_action = action  # its texts follow the dock's retranslate()
    dock.retranslate()
    return dock


def _all_networks(model: LadderModel) -> Sequence[LadderNetwork]:
    """Every network of the console: a large program still laying out is finished first."""
    if model.loading:
        model.finish_loading()
    return model.networks
