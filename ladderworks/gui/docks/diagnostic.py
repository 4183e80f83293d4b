"""PLC TEŞHİS: the running program as ladder, look only, power flow drawn live."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QCoreApplication, QEvent, QRectF, Qt, QTimer, Signal
from PySide6.QtGui import QBrush, QColor, QPainter, QPaintEvent, QTransform, QWheelEvent
from PySide6.QtWidgets import (
    QCheckBox,
    QDockWidget,
    QGraphicsScene,
    QGraphicsView,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QToolButton,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.address import Address, AddressError, parse_address
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.il.program import Program
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.model import Cell, Coil, Contact, FunctionBox, LadderNetwork
from ladderworks.core.symbols import SymbolTable
from ladderworks.core.tag_names import names_for
from ladderworks.gui.docks.cell_map import binary_networks, program_matches, program_of
from ladderworks.gui.docks.diagnostic_items import YieldingNetworkItem
from ladderworks.gui.docks.live_ladder import LivePower
from ladderworks.gui.docks.snapshot_gate import SnapshotGate
from ladderworks.gui.editor.geometry import (
    Layout,
    cell_h,
    cell_origin,
    network_width,
    typical_width,
)
from ladderworks.gui.editor.label_text import CommentedAddresses, shows_comment
from ladderworks.gui.editor.lazy_items import LazyItems
from ladderworks.gui.editor.network_item import NetworkItem
from ladderworks.gui.live_text import set_live_text
from ladderworks.gui.plc_session import PlcSession, PlcSnapshot
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.settings import Settings
from ladderworks.gui.symbol_text import name_and_text

translate = QCoreApplication.translate

VIEW_SCALE = 0.62  # the first zoom: a dock is narrower than the console
ZOOM_MIN, ZOOM_MAX = 0.3, 2.0
ZOOM_STEP = 1.25  # one button press or wheel notch


class DiagnosticView(QGraphicsView):
    """A read-only ladder view: the console's network drawings with live overlays."""

    zoom_changed = Signal(float)  # the new zoom factor

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("diagnosticView")
        self.scene_ = QGraphicsScene(self)
        self.scene_.setBackgroundBrush(QBrush(QColor("#ffffff")))
        self.setScene(self.scene_)
        self.setAlignment(Qt.AlignmentFlag.AlignLeft | Qt.AlignmentFlag.AlignTop)
        self.setRenderHint(QPainter.RenderHint.Antialiasing, True)
        self.setViewportUpdateMode(QGraphicsView.ViewportUpdateMode.MinimalViewportUpdate)
        self.setDragMode(QGraphicsView.DragMode.ScrollHandDrag)
        self.live = LivePower(self.scene_)
        self.network_items = LazyItems(self._make_item)  # made when shown
        self.symbols: SymbolTable | None = None  # the program's symbols, named under addresses
        self.networks: list[LadderNetwork] = []
        self.spelling = spelling(None)  # how the shown program writes addresses
        self.comments = CommentedAddresses(self.describe_address)  # asked once per address
        self.layout_ = Layout(self.commented)
        self.paints = 0  # viewport paint events (the benchmark's repaint rate)
        # called before the view and each network paint (the dock: a due scan goes first)
        self.before_paint: Callable[[], None] = lambda: None
        self.set_zoom(VIEW_SCALE)

    def zoom(self) -> float:
        """The drawing's scale (1.0 = as in the console at 100 %)."""
        return self.transform().m11()

    def set_zoom(self, factor: float) -> None:
        """Scale the drawing by `factor`, kept within ZOOM_MIN..ZOOM_MAX."""
        factor = min(max(factor, ZOOM_MIN), ZOOM_MAX)
        if abs(factor - self.zoom()) > 1e-6:
            self.setTransform(QTransform.fromScale(factor, factor))
        self.zoom_changed.emit(factor)

    def fit_width(self) -> None:
        """Zoom out (never in) until the typical network's coils are in the view's width."""
        room = self.viewport().width() - 4
        typical = typical_width(self.networks)
        if self.networks and room > 0 and typical * self.zoom() > room:
            self.set_zoom(room / typical)

    def zoom_by(self, steps: int) -> None:
        """Zoom in (`steps` > 0) or out by whole steps."""
        self.set_zoom(self.zoom() * ZOOM_STEP ** steps)

    def wheelEvent(self, event: QWheelEvent) -> None:
        """Ctrl+wheel zooms about the mouse; the wheel alone scrolls."""
        if not event.modifiers() & Qt.KeyboardModifier.ControlModifier:
            super().wheelEvent(event)
            return
        delta = event.angleDelta().y()
        if delta:
            anchor = self.transformationAnchor()
            self.setTransformationAnchor(QGraphicsView.ViewportAnchor.AnchorUnderMouse)
            self.zoom_by(1 if delta > 0 else -1)
            self.setTransformationAnchor(anchor)
        event.accept()

    def show_networks(self, networks: list[LadderNetwork], binary: BinaryProgram,
                      ops: list[list[int]]) -> None:
        """Draw `networks` (coded as `ops` of `binary`) with power overlays; a network's item
        is made when first shown (a real program has 10,000+ networks)."""
        self.live.detach()
        for _index, item in self.network_items.made():
            self.scene_.removeItem(item)
        self.networks = networks
        self.spelling = spelling(binary.dialect)  # a Delta program's: Delta's spelling
        self.comments.forget()  # the symbols may have changed with the program
        self.layout_ = Layout(self.commented)
        self.layout_.rebuild(networks)
        self.network_items.reset(len(networks))
        self.live.attach(networks, self.layout_, binary, ops)
        width = max((network_width(network) for network in networks), default=600.0)
        self.scene_.setSceneRect(QRectF(0, 0, width, max(self.layout_.total_height(), cell_h())))

    def _make_item(self, index: int) -> NetworkItem:
        item = YieldingNetworkItem(self.networks[index], index + 1, self.describe_address)
        item.before_paint = lambda: self.before_paint()
        item.spelling = self.spelling
        item.setPos(0, self.layout_.tops[index])
        self.scene_.addItem(item)
        return item

    def make_visible_items(self) -> None:
        """Make the items of the networks in (and just around) the viewport."""
        if not self.networks or not self.layout_.tops:
            return
        shown = self.visible_rect()
        for index in self.layout_.shown(shown.top() - cell_h(), shown.bottom() + cell_h()):
            self.network_items[index]

    def paintEvent(self, event: QPaintEvent) -> None:
        """Make the visible networks' items, then paint."""
        self.make_visible_items()
        self.before_paint()
        super().paintEvent(event)

    def relayout(self) -> None:
        """The rows changed height (View › Element names): restack the networks."""
        self.comments.forget()
        self.layout_ = Layout(self.commented)
        self.layout_.rebuild(self.networks)
        for index, item in self.network_items.made():
            item.refresh()
            item.setPos(0, self.layout_.tops[index])
        self.live.restack(self.layout_)
        rect = self.scene_.sceneRect()
        self.scene_.setSceneRect(QRectF(0, 0, rect.width(),
                                        max(self.layout_.total_height(), cell_h())))
        self.viewport().update()

    def describe_address(self, address: object) -> tuple[str, str] | None:
        """(symbol, comment) of the program, else (signal name, description) of the manual
        (a Delta program's addresses are no FANUC signals: none; an S7 program's: its tag)."""
        if self.spelling.dialect:
            names = names_for(self.symbols, self.spelling.dialect)
            name = names.name_of(address) if isinstance(address, Address) else ""
            if not name or not isinstance(address, Address):
                return None
            found = self.symbols.lookup(address) if self.symbols is not None else None
            return name, found.comment if found is not None else ""
        return name_and_text(address, self.symbols)

    def commented(self, network: LadderNetwork) -> bool:
        """True when an element of `network` has a comment to show (its rows are taller)."""
        return shows_comment(network, self.comments)

    def visible_rect(self) -> QRectF:
        """The part of the scene on screen."""
        return self.mapToScene(self.viewport().rect()).boundingRect()

    def cell_rect(self, network: int, cell: Cell) -> QRectF:
        """Scene rectangle of a cell."""
        rows = self.layout_.rows[network]
        x, y = cell_origin(self.networks[network], *cell, rows)
        return QRectF(x, y + self.layout_.tops[network], 96.0, rows.height)

    def viewportEvent(self, event: QEvent) -> bool:
        """Count paints (the benchmark reports the repaint rate)."""
        if event.type() == QEvent.Type.Paint:
            self.paints += 1
        return super().viewportEvent(event)


class DiagnosticDock(Retranslating, QDockWidget):
    """PLC TEŞHİS (PLC diagnostic): watch the ladder while the PLC runs; no editing."""

    why_requested = Signal(object)  # the Address in the search box (time travel answers)
    live_requested = Signal()

    def __init__(self, session: PlcSession, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("plcDiagnosticDock")
        self.session = session
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        bar = QHBoxLayout()
        self.search = QLineEdit(body)
        self.search.setObjectName("diagnosticSearch")
        self.search.setMinimumWidth(110)
        self.search.returnPressed.connect(self.find_next)
        self.find_button = QPushButton(body)
        self.find_button.setObjectName("diagnosticFind")
        self.find_button.clicked.connect(self.find_next)
        self.written_button = QPushButton(body)
        self.written_button.setObjectName("diagnosticWhereWritten")
        self.written_button.clicked.connect(self.where_written)
        self.follow = QCheckBox(body)
        self.follow.setObjectName("diagnosticFollow")
        self.state = QLabel(body)
        self.state.setObjectName("diagnosticState")
        # time travel (gui/docks/time_travel.py): "why" and one click back to live
        self.past: PlcSnapshot | None = None
        self.why_button = QPushButton(body)
        self.why_button.setObjectName("diagnosticWhy")
        self.why_button.clicked.connect(self._why)
        self.why_button.hide()
        self.live_button = QPushButton(body)
        self.live_button.setObjectName("diagnosticLive")
        self.live_button.clicked.connect(self.back_to_live)
        self.live_button.hide()
        for widget in (self.search, self.find_button, self.written_button, self.follow):
            bar.addWidget(widget)
        bar.addStretch(1)
        self.zoom_out_button = QToolButton(body)
        self.zoom_out_button.setObjectName("diagnosticZoomOut")
        self.zoom_out_button.setText("−")
        self.zoom_label = QLabel(body)
        self.zoom_label.setObjectName("diagnosticZoom")
        self.zoom_in_button = QToolButton(body)
        self.zoom_in_button.setObjectName("diagnosticZoomIn")
        self.zoom_in_button.setText("+")

        layout.addLayout(bar)
        # the state grows with the run (scan 1234567, PAST … at … ms): a row of its own,
        # wrapped, so a long run never widens the dock and squeezes the ladder beside it
        self.state.setWordWrap(True)
        self.message = QLabel(body)
        self.message.setObjectName("diagnosticMessage")
        self.message.setWordWrap(True)
        state_row = QHBoxLayout()  # with the search's message: no row more than before
        state_row.addWidget(self.state, 2)  # "RUNNING — scan 1234" on one line
        state_row.addWidget(self.message, 1)
        state_row.addWidget(self.why_button)
        state_row.addWidget(self.live_button)
        for part in (self.zoom_out_button, self.zoom_label, self.zoom_in_button):
            state_row.addWidget(part)  # here: the search row is full in Turkish at 520 px
        layout.addLayout(state_row)
        self.view = DiagnosticView(body)
        layout.addWidget(self.view, 1)
        self.view.zoom_changed.connect(self._show_zoom)
        self.zoom_out_button.clicked.connect(lambda: self.view.zoom_by(-1))
        self.zoom_in_button.clicked.connect(lambda: self.view.zoom_by(1))
        self._show_zoom(self.view.zoom())
        self.setWidget(body)
        self.setMinimumWidth(340)  # as the control screen: its tab group leaves the ladder room
        self.hits: list[tuple[int, Cell]] = []
        self.hit_index = -1
        self._monitoring = False
        self._snapshot: PlcSnapshot | None = None
        # the shown program's networks as laid out, by what each was laid out from
        self._laid: dict[tuple[object, ...], LadderNetwork] = {}
        session.program_loaded.connect(self._on_program)
        self.gate = SnapshotGate(self, self._show_snapshot, session)  # in budget
        self.view.before_paint = self.gate.yield_to_scan
        session.snapshot_ready.connect(self._on_snapshot)
        session.forces_changed.connect(lambda _entries: self._repaint())
        self.visibilityChanged.connect(self._on_visible)
        self.view.verticalScrollBar().valueChanged.connect(lambda _v: self._repaint())
        self.view.horizontalScrollBar().valueChanged.connect(lambda _v: self._repaint())
        self.retranslate()
        if session.run.binary is not None:
            self._on_program(session.run.binary)

    def retranslate(self) -> None:
        """Texts in the UI language."""
        self.setWindowTitle(translate("PlcDiagnostic", "PLC DIAGNOSTIC"))
        self.search.setPlaceholderText(translate("PlcDiagnostic", "Address, e.g. R102.0"))
        self.find_button.setText(translate("PlcDiagnostic", "Find"))
        self.written_button.setText(translate("PlcDiagnostic", "Where written"))
        self.follow.setText(translate("PlcDiagnostic", "Follow"))
        self.why_button.setText(translate("PlcDiagnostic", "Why?"))
        self.why_button.setToolTip(translate(
            "PlcDiagnostic", "Go to the scan where the address last changed and mark the "
            "contacts that changed it"))
        self.live_button.setText(translate("PlcDiagnostic", "Back to live"))
        self.zoom_out_button.setToolTip(translate("PlcDiagnostic", "Zoom out (Ctrl+wheel)"))
        self.zoom_in_button.setToolTip(translate("PlcDiagnostic", "Zoom in (Ctrl+wheel)"))
        self._show_zoom(self.view.zoom())  # "62 %" / "%62"
        self.follow.setToolTip(translate(
            "PlcDiagnostic", "Keep the searched address in view while the PLC runs"))
        self._show_state()

    def remember_zoom(self, settings: Settings) -> None:
        """Start at the zoom `settings` saved, and save every change there."""
        self.view.set_zoom(settings.diagnostic_zoom(VIEW_SCALE))
        self.view.zoom_changed.connect(settings.set_diagnostic_zoom)

    def _show_zoom(self, factor: float) -> None:
        self.zoom_label.setText(translate("PlcDiagnostic", "{0} %").format(round(factor * 100)))
        self.zoom_out_button.setEnabled(factor > ZOOM_MIN + 1e-6)
        self.zoom_in_button.setEnabled(factor < ZOOM_MAX - 1e-6)

    # -- the program -------------------------------------------------------------------

    def _on_program(self, binary: BinaryProgram) -> None:
        program = self.session.run.program
        if program is None or not program_matches(program, binary):
            program = program_of(binary)
        networks = self._lay_out(program)
        self.view.symbols = self.session.symbols
        first = not self.view.networks  # the first program shown in an open dock: fitted
        self.view.show_networks(networks, binary, binary_networks(binary))
        if first and self.isVisible():
            QTimer.singleShot(0, self.view.fit_width)
        self.hits = []
        self.hit_index = -1
        self._repaint()

    def _lay_out(self, program: Program) -> list[LadderNetwork]:
        """Each network of `program` laid out; one the program shown before has (every field
        of every instruction, and the comments, the same) is reused, not laid out again."""
        known = self._laid
        self._laid = {}
        networks: list[LadderNetwork] = []
        for net in program.networks:
            # plain tuples: every field counts (an Instruction's == ignores its line), and
            # their hash is C's (F9 again after an edit re-lays out only what changed)
            key = (tuple(map(tuple, net.instructions)), tuple(net.comments))
            laid = known.get(key)
            if laid is None:
                laid = layout_network(net.instructions, net.comments)
            self._laid[key] = laid
            networks.append(laid)
        return networks

    def _on_visible(self, visible: bool) -> None:
        if visible != self._monitoring:
            self._monitoring = visible
            self.session.run.monitor(visible)
        if visible:
            # the network's coils in the dock's width, once the dock has its width
            QTimer.singleShot(0, self.view.fit_width)
            self._repaint()

    def _on_snapshot(self, snapshot: PlcSnapshot) -> None:
        self._snapshot = snapshot
        if self.past is None:
            self.gate.offer(snapshot)

    def _show_snapshot(self, snapshot: PlcSnapshot) -> None:
        self._snapshot = snapshot
        if self.past is not None:
            return
        self._repaint()
        if self.follow.isChecked() and self.hits:
            network, cell = self.hits[max(self.hit_index, 0)]
            self.view.ensureVisible(self.view.cell_rect(network, cell), 40, 40)

    def _repaint(self) -> None:
        snapshot = self.past or self._snapshot or self.session.run.snapshot()
        forced = (self.session.run.engine.force_table.forced()
                  if self.session.run.engine is not None else {})
        self.view.live.update(snapshot, forced, self.view.visible_rect())
        self._show_state()

    def _show_state(self) -> None:
        status = self.session.run.status()
        self.state.setStyleSheet("")
        if self.past is not None:
            self.state.setText(translate(
                "PlcDiagnostic", "PAST — scan {0} at {1} ms (not live)").format(
                    self.past.scan_count, self.past.now_ms))
            self.state.setStyleSheet("background:#ffe08a; color:#6b3e00; font-weight:bold;")
            return
        if not status.loaded:
            text = translate("PlcDiagnostic", "No program loaded")
        elif status.running:
            text = translate("PlcDiagnostic", "RUNNING — scan {0}").format(status.scan_count)
        else:
            text = translate("PlcDiagnostic", "STOPPED")
        self.state.setText(text)

    # -- time travel ---------------------------------------------------------------------

    def show_past(self, snapshot: PlcSnapshot) -> None:
        """Show an earlier scan's power flow and values, marked as the past."""
        self.past = snapshot
        self.live_button.show()
        self._repaint()

    def back_to_live(self) -> None:
        """Show the running PLC again."""
        was_past = self.past is not None
        self.past = None
        self.live_button.hide()
        self._repaint()
        if was_past:
            self.live_requested.emit()

    def mark_ops(self, ops: tuple[int, ...] | list[int]) -> None:
        """Mark the cells of these ops (the contacts "why" found) and show the first."""
        hits = [found for op in ops if (found := self.view.live.cell_of(op)) is not None]
        self.hits = hits
        self.hit_index = -1
        self._mark(hits)
        if hits:
            self._go_next("")

    def _why(self) -> None:
        address = self._address()
        if address is not None:
            self.why_requested.emit(address)

    # -- search --------------------------------------------------------------------------

    def _address(self) -> Address | None:
        text = self.search.text().strip()
        try:
            address = parse_address(text)
        except AddressError:
            set_live_text(self.message, lambda: translate(
                "PlcDiagnostic", "'{0}' is not an address").format(text))
            return None
        self.message.setText("")
        return address

    def _cells_with(self, address: Address, coils_only: bool) -> list[tuple[int, Cell]]:
        found: list[tuple[int, Cell]] = []
        for index, network in enumerate(self.view.networks):
            for cell, element in network.elements():
                if isinstance(element, Coil):
                    hit = element.address == address
                elif coils_only:
                    hit = False
                elif isinstance(element, Contact):
                    hit = element.address == address
                else:
                    hit = isinstance(element, FunctionBox) and any(
                        p == address or (isinstance(p, Address) and p.area is address.area
                                         and p.byte == address.byte) for p in element.params)
                if hit:
                    found.append((index, cell))
        return found

    def _mark(self, hits: list[tuple[int, Cell]]) -> None:
        for _index, overlay in self.view.live.overlays.made():
            if overlay.marked:
                overlay.marked = set()
                overlay.update()
        for network, cell in hits:
            overlay = self.view.live.overlays[network]
            overlay.marked.add(cell)
            overlay.update()

    def find_next(self) -> None:
        """Find the address in the ladder; again: the next place."""
        address = self._address()
        if address is None:
            return
        hits = self._cells_with(address, coils_only=False)
        if hits != self.hits:
            self.hits = hits
            self.hit_index = -1
            self._mark(hits)
        self._go_next(translate("PlcDiagnostic", "'{0}' is not in the program").format(address))

    def where_written(self) -> None:
        """Jump to the coil that writes the address."""
        address = self._address()
        if address is None:
            return
        self.hits = self._cells_with(address, coils_only=True)
        self.hit_index = -1
        self._mark(self.hits)
        self._go_next(translate("PlcDiagnostic", "No coil writes {0}").format(address))

    def _go_next(self, not_found: str) -> None:
        if not self.hits:
            self.message.setText(not_found)
            return
        self.hit_index = (self.hit_index + 1) % len(self.hits)
        network, cell = self.hits[self.hit_index]
        self.view.centerOn(self.view.cell_rect(network, cell).center())
        number, count = self.hit_index + 1, len(self.hits)
        set_live_text(self.message, lambda: translate(
            "PlcDiagnostic", "{0} of {1}: network {2}").format(number, count, network + 1))
        self._repaint()
