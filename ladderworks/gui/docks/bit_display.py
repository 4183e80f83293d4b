"""The PLC bit display (PLC BIT GÖSTERİMİ): byte addresses typed in boxes, shown live as 8 bits."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QPoint, Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import (
    QDockWidget,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QMenu,
    QPushButton,
    QScrollArea,
    QToolButton,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core import dialects
from ladderworks.core.address import INPUT_AREAS, Address, AddressError, parse_address
from ladderworks.core.plc.forcing import ForceEntry
from ladderworks.core.tag_names import TagNames, names_for
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.docks.snapshot_gate import SnapshotGate
from ladderworks.gui.plc_session import PlcSession, PlcSnapshot
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.symbol_text import tooltip

translate = QCoreApplication.translate

BOX_COUNT = 8
MAX_TEXT = 64  # characters of a box: an S7 tag's name (`"IEC_Timer_0_DB".Q`)
NAMED_WIDTH = 160  # pixels of a box in a program named by tags
_ON = "background:#2e9e44;color:white;"
_OFF = "background:#e4e4e4;color:#555;"
_FORCED = "border:2px solid #e07000;font-weight:bold;"
_PLAIN = "border:1px solid #999;"


class BitButton(QToolButton):
    """One bit of a displayed byte: 0/1, green when on, an orange frame when forced."""

    def __init__(self, row: int, bit: int, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.row = row
        self.bit = bit
        self.setObjectName(f"bitDisplayBit_{row}_{bit}")
        self.setFixedSize(28, 26)
        self.setText("·")
        self.setContextMenuPolicy(Qt.ContextMenuPolicy.CustomContextMenu)

    def show_value(self, value: int | None, forced: bool | None) -> None:
        """Show 0/1 (None: nothing shown) and whether the bit is forced (and to what); the
        style sheet is set only when it changes (each set restyles the button: ~0.3 ms)."""
        text = "·" if value is None else str(value)
        if text != self.text():
            self.setText(text)
        style = (_ON if value else _OFF) + (_FORCED if forced is not None else _PLAIN)
        style = f"QToolButton{{{style}}}"
        if style != self.styleSheet():
            self.setStyleSheet(style)


class BitRow:
    """One box: the address typed, its 8 bit buttons (16 for a word: an S7 `%MW2` or Int tag),
    hex and decimal, and its error text."""

    def __init__(self, dock: BitDisplayDock, index: int, grid: QGridLayout) -> None:
        parent = grid.parentWidget()
        self.index = index
        self.address: Address | None = None
        self.value: int | None = None
        self.width = 1  # bytes shown: 1, or 2 for a word
        self.signed = False  # an Int tag's decimal is signed
        self.edit = QLineEdit(parent)
        self.edit.setObjectName(f"bitDisplayAddress_{index}")
        self.edit.setMaxLength(MAX_TEXT)
        self.edit.setFixedWidth(72)
        self.edit.editingFinished.connect(lambda: dock.apply_row(self))
        self.bits = [BitButton(index, bit, parent) for bit in range(16)]
        for bit_button in self.bits:
            bit_button.clicked.connect(lambda _c=False, b=bit_button: dock.toggle_bit(b))
            bit_button.customContextMenuRequested.connect(
                lambda pos, b=bit_button: dock.bit_menu(b, pos)
            )
        self.hex_label = QLabel(parent)
        self.hex_label.setObjectName(f"bitDisplayHex_{index}")
        self.hex_label.setMinimumWidth(40)
        self.dec_label = QLabel(parent)
        self.dec_label.setObjectName(f"bitDisplayDec_{index}")
        self.dec_label.setMinimumWidth(36)
        self.error = QLabel(parent)
        self.error.setObjectName(f"bitDisplayError_{index}")
        self.error.setStyleSheet("color:#c00000;")
        self.error.setWordWrap(True)
        self.error.hide()
        row = index + 1
        grid.addWidget(self.edit, row, 0)
        for bit_button in self.bits:  # bit 15 (a word's) on the left, then bit 7 … 0
            grid.addWidget(bit_button, row, 16 - bit_button.bit)
            bit_button.setVisible(bit_button.bit < 8)
        grid.addWidget(self.hex_label, row, 17)
        grid.addWidget(self.dec_label, row, 18)
        grid.addWidget(self.error, row, 1, 1, 18)

    @property
    def shown_bits(self) -> list[BitButton]:
        """The buttons of the bits shown: 8, or 16 for a word."""
        return self.bits[:8 * self.width]

    def set_error(self, text: str) -> None:
        """Show `text` in place of the bits ('' hides the error and shows the bits)."""
        self.error.setText(text)
        self.error.setVisible(bool(text))
        for widget in (*self.bits, self.hex_label, self.dec_label):
            widget.setVisible(not text and (not isinstance(widget, BitButton)
                                            or widget.bit < 8 * self.width))

    def bit_texts(self) -> str:
        """The bits shown, bit 7 first (`01000100`), or '' when nothing is shown."""
        return "" if self.value is None else f"{self.value:0{8 * self.width}b}"


class BitDisplayDock(Retranslating, QDockWidget):
    """Type a byte address (X12, G30, R102 ...) in a box and START: its 8 bits, live.

    STOP freezes what is shown. A click on a bit of an input (X, F) forces it to the other
    value through the force list; its right-click menu forces 1 / 0 or releases the force.
    """

    def __init__(self, session: PlcSession, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("bitDisplayDock")
        self.session = session
        self.live = False
        self._forced: dict[Address, bool] = {}
        body = QWidget(self)
        outer = QVBoxLayout(body)
        buttons = QHBoxLayout()
        self.start_button = QPushButton(body)
        self.start_button.setObjectName("bitDisplayStart")
        self.start_button.clicked.connect(self.start)
        self.stop_button = QPushButton(body)
        self.stop_button.setObjectName("bitDisplayStop")
        self.stop_button.clicked.connect(self.stop)
        self.state_label = QLabel(body)
        self.state_label.setObjectName("bitDisplayState")
        buttons.addWidget(self.start_button)
        buttons.addWidget(self.stop_button)
        buttons.addWidget(self.state_label, 1)
        outer.addLayout(buttons)
        grid_holder = QWidget(body)
        grid = QGridLayout(grid_holder)
        grid.setHorizontalSpacing(3)
        self.headers: list[QLabel] = []  # bit 0 … 15
        self.address_header = QLabel(grid_holder)
        grid.addWidget(self.address_header, 0, 0)
        for bit in range(16):
            label = QLabel(str(bit), grid_holder)
            label.setAlignment(Qt.AlignmentFlag.AlignCenter)
            label.setVisible(bit < 8)
            grid.addWidget(label, 0, 16 - bit)
            self.headers.append(label)
        self.hex_header = QLabel(grid_holder)
        self.dec_header = QLabel(grid_holder)
        grid.addWidget(self.hex_header, 0, 17)
        grid.addWidget(self.dec_header, 0, 18)
        self.rows = [BitRow(self, index, grid) for index in range(BOX_COUNT)]
        grid.setColumnStretch(19, 1)
        grid.setRowStretch(BOX_COUNT + 1, 1)  # a tall dock: the room below the boxes
        self._scroll = scroll = QScrollArea(body)
        scroll.setWidgetResizable(True)
        scroll.setWidget(grid_holder)
        outer.addWidget(scroll, 1)
        self.setWidget(body)
        self.gate = SnapshotGate(self, self._on_snapshot, session)  # shown, in budget
        session.snapshot_ready.connect(self.gate.offer)
        self.visibilityChanged.connect(lambda _shown: self.gate.flush())
        session.forces_changed.connect(self._on_forces)
        session.symbols_changed.connect(lambda _symbols: self.retranslate())  # S7: tag texts
        self._on_forces(session.run.forces())
        self.retranslate()

    # -- START / STOP ----------------------------------------------------------------------

    def start(self) -> None:
        """Read every box and show the bytes live."""
        for row in self.rows:
            self._parse(row)
        self.live = True
        self._update_state()
        self._on_snapshot(self.session.run.snapshot())

    def stop(self) -> None:
        """Freeze what is shown."""
        self.live = False
        self._update_state()

    def set_address(self, index: int, text: str) -> None:
        """Type `text` into box `index` (as ENTER would: shown at once when live)."""
        row = self.rows[index]
        row.edit.setText(text)
        self.apply_row(row)

    def apply_row(self, row: BitRow) -> None:
        """A box was edited: take its address (shown at once when live)."""
        self._parse(row)
        if self.live:
            self._show_row(row, self.session.run.snapshot())

    def _spelled(self, address: Address) -> str:
        """A row's byte as the loaded program writes it: `R0`, or Delta's `D0`, `M0` (a byte
        of bit devices by its first bit)."""
        dialect = self.session.run.program_dialect
        found = dialects.get(dialect)
        if found is None:
            return str(address)
        return found.devices.format(address) or found.format_address(address.with_bit(0))

    def _parse(self, row: BitRow) -> None:
        text = row.edit.text().strip()
        row.address = None
        row.value = None
        row.width, row.signed = 1, False
        names = names_for(self.session.symbols, self.session.run.program_dialect)
        row.edit.setFixedWidth(NAMED_WIDTH if names.typed else 72)
        if not text:
            row.set_error("")
            self._show_row(row, None)
            return
        if names.typed:  # S7: a tag or an absolute address, a word shown whole
            self._parse_named(row, names, text)
            return
        try:
            if dialects.get(self.session.run.program_dialect) is not None:  # Delta: M0 shows M0..M7
                found = dialects.parse_target(text, self.session.run.program_dialect, None)[0]
                address = Address(found.area, found.byte)
            else:
                address = parse_address(text, want_bit=False)
        except AddressError as error:
            named = (self.session.symbols.address_of(text)
                     if self.session.symbols is not None else None)
            if named is None:
                row.set_error(diagnostic_text(error.diagnostic))
                self._show_row(row, None)
                return
            address = Address(named.area, named.byte)  # a symbol: its byte is shown
        row.address = address
        row.edit.setText(self._spelled(address))
        row.set_error("")
        self._set_tooltips(row)

    def _parse_named(self, row: BitRow, names: TagNames, text: str) -> None:
        """A box of an S7 program: `"Start"` (its byte), `%MW2` or an Int tag (a word)."""
        try:
            named = names.resolve(text)
        except AddressError as error:
            row.set_error(diagnostic_text(error.diagnostic))
            self._show_row(row, None)
            return
        if named.address.bit is None and named.width > 2:
            row.set_error(translate("BitDisplay", "{0} has {1} bytes: a box shows a byte or a"
                                    " word (the time chart shows any value)").format(
                                        named.text, named.width))
            self._show_row(row, None)
            return
        row.address = Address(named.address.area, named.address.byte)
        row.width = 2 if named.address.bit is None and named.width == 2 else 1
        row.signed = named.type_name.lower() in ("int", "sint")
        row.edit.setText(named.text)
        row.set_error("")
        self._set_tooltips(row)
        for header in self.headers[8:]:
            header.setVisible(any(r.width == 2 for r in self.rows))
        self._fit_width()  # a word's 8 more bits

    def bit_of(self, row: BitRow, bit: int) -> Address | None:
        """The address of bit `bit` of a row (of a word: its byte in the memory's order)."""
        if row.address is None:
            return None
        if row.width == 1:
            return row.address.with_bit(bit)
        high_first = self.session.run.memory.byteorder == "big"
        byte = row.address.byte + ((bit < 8) if high_first else (bit >= 8))
        return Address(row.address.area, byte, bit % 8)

    # -- showing ---------------------------------------------------------------------------

    def _on_snapshot(self, snapshot: PlcSnapshot) -> None:
        if not self.live:
            return
        for row in self.rows:
            self._show_row(row, snapshot)

    def _show_row(self, row: BitRow, snapshot: PlcSnapshot | None) -> None:
        address = row.address
        value = (snapshot.read(address, row.width) if address is not None and snapshot is not None
                 else None)
        row.value = value
        for button in row.shown_bits:
            bit = self.bit_of(row, button.bit)
            forced = self._forced.get(bit) if bit is not None else None
            button.show_value(None if value is None else value >> button.bit & 1, forced)
        row.hex_label.setText("" if value is None else f"{value:0{2 * row.width}X}h")
        top = 1 << (8 * row.width)
        shown = value - top if value is not None and row.signed and value >= top >> 1 else value
        row.dec_label.setText("" if shown is None else str(shown))

    def _on_forces(self, entries: list[ForceEntry]) -> None:
        self._forced = {
            entry.address: bool(entry.value)
            for entry in entries
            if entry.kind == "force" and entry.address is not None
        }
        for row in self.rows:
            if row.address is not None:
                self._set_tooltips(row)
                for button in row.shown_bits:
                    value = None if row.value is None else row.value >> button.bit & 1
                    bit = self.bit_of(row, button.bit)
                    button.show_value(value, self._forced.get(bit) if bit is not None else None)

    def _refresh_tooltips(self) -> None:
        for row in self.rows:
            self._set_tooltips(row)

    def _set_tooltips(self, row: BitRow) -> None:
        for button in row.bits:
            bit = self.bit_of(row, button.bit) if button.bit < 8 * row.width else None
            button.setToolTip("" if bit is None else self.bit_tooltip(bit))

    def bit_tooltip(self, address: Address) -> str:
        """The signal name and descriptions of a bit, whether it can be forced, and its force."""
        lines = [tooltip(address, self.session.symbols, self.session.run.program_dialect)]
        forced = self._forced.get(address)
        if forced is not None:
            lines.append(translate("BitDisplay", "Forced to {0}").format(int(forced)))
        if address.area in INPUT_AREAS:
            lines.append(
                translate("BitDisplay", "Click: force to the other value; right-click: force menu")
            )
        return "\n".join(lines)

    # -- forcing ---------------------------------------------------------------------------

    def _bit_address(self, button: BitButton) -> Address | None:
        address = self.bit_of(self.rows[button.row], button.bit)
        if address is None or address.area not in INPUT_AREAS:
            return None
        return address

    def toggle_bit(self, button: BitButton) -> None:
        """Force an input bit to the value other than the one it has (or is forced to)."""
        address = self._bit_address(button)
        if address is None:
            return
        if self.session.run.engine is None:
            self.state_label.setText(translate("BitDisplay", "Load a program to force inputs"))
            return
        current = self._forced.get(address)
        if current is None:
            current = bool(self.session.run.bit(address))
        self.session.force(address, not current)

    def bit_menu(self, button: BitButton, pos: QPoint) -> None:
        """Right-click on an input bit: force 1, force 0, release."""
        address = self._bit_address(button)
        if address is None or self.session.run.engine is None:
            return
        menu = QMenu(self)
        menu.setObjectName("bitDisplayForceMenu")
        for name, text, slot in (
            (
                "action_bit_force_1",
                translate("BitDisplay", "Force to 1"),
                lambda: self.session.force(address, True),
            ),
            (
                "action_bit_force_0",
                translate("BitDisplay", "Force to 0"),
                lambda: self.session.force(address, False),
            ),
            (
                "action_bit_release",
                translate("BitDisplay", "Release the force"),
                lambda: self.session.release(address),
            ),
        ):
            action = QAction(text, menu)
            action.setObjectName(name)
            action.triggered.connect(slot)
            menu.addAction(action)
        menu.exec(button.mapToGlobal(pos))

    # -- language --------------------------------------------------------------------------

    def _update_state(self) -> None:
        self.state_label.setText(
            translate("BitDisplay", "Live") if self.live else translate("BitDisplay", "Stopped")
        )
        self.start_button.setEnabled(True)
        self.stop_button.setEnabled(self.live)

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(translate("BitDisplay", "PLC bit display"))
        self.start_button.setText(translate("BitDisplay", "START"))
        self.stop_button.setText(translate("BitDisplay", "STOP"))
        typed = names_for(self.session.symbols, self.session.run.program_dialect).typed
        self.address_header.setText(translate("BitDisplay", "Tag or address") if typed
                                    else translate("BitDisplay", "Byte"))
        self.hex_header.setText(translate("BitDisplay", "Hex"))
        self.dec_header.setText(translate("BitDisplay", "Dec"))
        for row in self.rows:
            row.edit.setPlaceholderText(translate("BitDisplay", "e.g. \"Start\", %MW2") if typed
                                        else translate("BitDisplay", "e.g. X12"))
            if row.edit.text().strip():
                self._parse(row)
                if self.live:
                    self._show_row(row, self.session.run.snapshot())
        self._update_state()
        self._fit_width()

    def _fit_width(self) -> None:
        """Ask for the width the rows need in this language, so no column is cut off."""
        holder = self._scroll.widget()
        if holder is None:  # no widget before setWidget (ours is set in __init__)
            return
        holder.adjustSize()
        bar = self._scroll.verticalScrollBar().sizeHint().width()
        frame = 2 * self._scroll.frameWidth()
        self._scroll.setMinimumWidth(holder.minimumSizeHint().width() + bar + frame)
