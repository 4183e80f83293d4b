"""The force list: every forced signal and passive (disabled) element, released with one click;
a bit forced by its address or name (an S7 tag `"Start"`, `"Motor".Q`) typed over the list."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import (
    QDockWidget,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QLineEdit,
    QPushButton,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core import dialects
from ladderworks.core.address import Address, AddressError
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.il.program import Instruction
from ladderworks.core.plc.forcing import ForceEntry
from ladderworks.core.symbols import resolve
from ladderworks.core.tag_names import names_for, network_titles
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.header_fit import fit_headers
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.symbol_text import labelled

translate = QCoreApplication.translate


class ForceListDock(Retranslating, QDockWidget):
    """Forced bits and passive elements of the running program, each with a Release button."""

    def __init__(self, session: PlcSession, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("forceListDock")
        self.session = session
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        top = QHBoxLayout()
        self.target_label = QLabel(body)
        self.target = QLineEdit(body)  # a bit by address or name, forced by the buttons
        self.target.setObjectName("forceListTarget")
        self.target_label.setBuddy(self.target)
        self.force_buttons = []
        top.addWidget(self.target_label)
        top.addWidget(self.target, 1)
        for value in (1, 0):
            button = QPushButton(body)
            button.setObjectName(f"forceListForce{value}")
            button.clicked.connect(lambda _checked=False, v=value: self.force_typed(v))
            top.addWidget(button)
            self.force_buttons.append(button)
        layout.addLayout(top)
        self.table = QTableWidget(0, 4, body)
        self.table.setObjectName("forceListTable")
        self.table.verticalHeader().hide()
        self.table.setTabKeyNavigation(False)  # Tab leaves the dock (issue 18: no Tab trap)
        # kind, value and Release as wide as they need; the signal column gives way (its
        # text elided, whole in the tooltip), so Release stays in view in a narrow dock
        header = self.table.horizontalHeader()
        header.setStretchLastSection(False)
        for column, mode in enumerate((QHeaderView.ResizeMode.ResizeToContents,
                                       QHeaderView.ResizeMode.Stretch,
                                       QHeaderView.ResizeMode.ResizeToContents,
                                       QHeaderView.ResizeMode.ResizeToContents)):
            header.setSectionResizeMode(column, mode)
        self.table.setEditTriggers(QTableWidget.EditTrigger.NoEditTriggers)
        layout.addWidget(self.table, 1)
        bottom = QHBoxLayout()
        self.summary = QLabel(body)
        self.summary.setObjectName("forceListSummary")
        self.release_all_button = QPushButton(body)
        self.release_all_button.setObjectName("forceListReleaseAll")
        self.release_all_button.clicked.connect(session.release_all)
        bottom.addWidget(self.summary, 1)
        bottom.addWidget(self.release_all_button)
        layout.addLayout(bottom)
        self.setWidget(body)
        self.entries: list[ForceEntry] = []
        session.forces_changed.connect(self.show_entries)
        session.program_loaded.connect(lambda _binary: self.show_entries(session.run.forces()))
        self.retranslate()

    def retranslate(self) -> None:
        """Texts in the UI language."""
        self.setWindowTitle(translate("ForceList", "Forced and passive"))
        self.table.setHorizontalHeaderLabels([
            translate("ForceList", "Kind"), translate("ForceList", "Signal / element"),
            translate("ForceList", "Value"), ""])
        fit_headers(self.table)
        self.release_all_button.setText(translate("ForceList", "Release all"))
        self.target_label.setText(translate("ForceList", "&Bit:"))
        self.target.setPlaceholderText(translate("ForceList", "an address or a tag"))
        self.force_buttons[0].setText(translate("ForceList", "Force to 1"))
        self.force_buttons[1].setText(translate("ForceList", "Force to 0"))
        self.show_entries(self.entries)

    def typed_bit(self) -> Address | None:
        """The bit typed over the list (its address or name), None with the reason shown."""
        text = self.target.text().strip()
        dialect = self.session.run.program_dialect
        names = names_for(self.session.symbols, dialect)
        try:
            address = (names.resolve(text).address if names.typed
                       else dialects.parse_target(text, dialect, "bit")[0]
                       if dialects.get(dialect) else resolve(text, self.session.symbols))
        except AddressError as error:
            self.summary.setText(diagnostic_text(error.diagnostic))
            return None
        if address.bit is None:
            self.summary.setText(translate("ForceList", "{0} is not a bit: only bits are"
                                           " forced").format(text))
            return None
        return address

    def force_typed(self, value: int) -> bool:
        """Force the bit typed over the list to `value`; False (the reason shown) when it is
        no bit of the program or no program is loaded."""
        if self.session.run.engine is None:
            self.summary.setText(translate("ForceList", "Load a program to force its bits"))
            return False
        address = self.typed_bit()
        if address is None:
            return False
        self.session.force(address, value)
        return True

    def describe(self, entry: ForceEntry) -> tuple[str, str, str]:
        """(kind, what, value) shown for one entry."""
        spelled = spelling(self.session.run.program_dialect)
        names = names_for(self.session.symbols, self.session.run.program_dialect)
        if entry.kind == "force" and names.typed and entry.address is not None:
            where = f"{names.spelled(entry.address)} {names.name_of(entry.address)}".strip()
            return (translate("ForceList", "FORCED"), where, str(int(bool(entry.value))))
        if entry.kind == "force":
            where = ("" if entry.address is None else spelled.address(entry.address)
                     if spelled.dialect else labelled(entry.address, self.session.symbols))
            return (translate("ForceList", "FORCED"), where,
                    str(int(bool(entry.value))))
        binary = self.session.run.binary
        text = f"op {entry.op}"
        if binary is not None and entry.op is not None and entry.op < len(binary.ops):
            op = binary.ops[entry.op]
            code = spelled.instruction(Instruction(op.name, op.operand, op.params))
            text = translate("ForceList", "network {0}, line {1}: {2}").format(
                op.source.network + 1, op.source.line, code)
            program = self.session.run.program
            titles = network_titles(program) if names.typed and program is not None else []
            if op.source.network < len(titles):  # S7: the network's title
                text = f"{text} ({titles[op.source.network]})"
        return translate("ForceList", "PASSIVE"), text, ""

    def show_entries(self, entries: list[ForceEntry]) -> None:
        """Fill the table."""
        self.entries = list(entries)
        self.table.setRowCount(len(entries))
        for row, entry in enumerate(entries):
            for col, text in enumerate(self.describe(entry)):
                item = QTableWidgetItem(text)
                item.setToolTip(text)
                self.table.setItem(row, col, item)
            button = QPushButton(translate("ForceList", "Release"), self.table)
            button.setObjectName(f"forceListRelease_{row}")
            button.clicked.connect(lambda _checked=False, e=entry: self.release(e))
            self.table.setCellWidget(row, 3, button)
        self.summary.setText(translate("ForceList", "{0} forced, {1} passive").format(
            sum(1 for e in entries if e.kind == "force"),
            sum(1 for e in entries if e.kind != "force")))
        self.release_all_button.setEnabled(bool(entries))

    def release(self, entry: ForceEntry) -> None:
        """Release one force or make one element act again."""
        if entry.kind == "force" and entry.address is not None:
            self.session.release(entry.address)
        elif entry.op is not None:
            self.session.enable(entry.op)
