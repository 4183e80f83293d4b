"""PLC › Modbus server: serve the console's PLC over Modbus/TCP (start/stop, address, clients).

The map served is the program's dialect's own, or a user's CSV map file (`--map` of the CLI)
chosen in the dock; a file's bad lines are listed at their line numbers, translated. An S7
program with global DBs offers them for the holding registers (MB_SERVER's MB_HOLD_REG; the
CLI's `--map DB`), the bit memory %MW being the default.

The server answers from the session's own PlcRun (the memory the docks show), on its own
asyncio thread (core `ModbusServer`); a client's write is published to the docks at once
unless the scan thread runs (its publish timer shows it with the next snapshot).
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QCoreApplication, QTimer, Signal
from PySide6.QtWidgets import (
    QComboBox,
    QDockWidget,
    QFileDialog,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.diagnostics import DiagnosticError
from ladderworks.core.modbus.bridge import PlcBridge, program_dialect
from ladderworks.core.modbus.db_map import chosen_map, data_blocks, db_map
from ladderworks.core.modbus.maps import ModbusMap
from ladderworks.core.modbus.server import (
    DEFAULT_HOST,
    DEFAULT_PORT,
    ModbusServer,
    is_loopback,
    parse_endpoint,
)
from ladderworks.core.symbols import SymbolTable
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.family_words import family_title
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.retranslate import Retranslating

translate = QCoreApplication.translate
FIGURES_MS = 1000  # the clients and requests a second, refreshed once a second


class ModbusDock(Retranslating, QDockWidget):
    """Start and stop the Modbus/TCP server of the running PLC; its address and figures."""

    written = Signal()  # a client wrote (emitted on the server's thread)

    def __init__(self, session: PlcSession, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("modbusDock")
        self.session = session
        self.server: ModbusServer | None = None
        self.error = ""  # why the last start failed
        self.served_file = ""  # the map file served (empty: the dialect's own map)
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        form = QFormLayout()
        self.address_label = QLabel(body)
        self.address = QLineEdit(f"{DEFAULT_HOST}:{DEFAULT_PORT}", body)
        self.address.setObjectName("modbusAddress")
        self.address_label.setBuddy(self.address)
        form.addRow(self.address_label, self.address)
        self.map_label = QLabel(body)
        self.map_file = QLineEdit(body)  # empty: the dialect's own map
        self.map_file.setObjectName("modbusMapFile")
        self.map_label.setBuddy(self.map_file)
        self.map_file.textChanged.connect(lambda _text: self.show_state())
        form.addRow(self.map_label, self.map_file)  # the whole row: its placeholder reads whole
        map_row = QHBoxLayout()
        map_row.addStretch(1)
        self.map_choose = QPushButton(body)
        self.map_choose.setObjectName("modbusMapChoose")
        self.map_choose.clicked.connect(self.choose_map)
        map_row.addWidget(self.map_choose)
        self.map_default = QPushButton(body)
        self.map_default.setObjectName("modbusMapDefault")
        self.map_default.clicked.connect(self.map_file.clear)
        map_row.addWidget(self.map_default)
        form.addRow("", map_row)  # the buttons under the field
        self.holding_label = QLabel(body)
        self.holding = QComboBox(body)  # S7: %MW or a global DB (MB_HOLD_REG)
        self.holding.setObjectName("modbusHolding")
        self.holding_label.setBuddy(self.holding)
        self.holding.currentIndexChanged.connect(lambda _index: self.show_state())
        form.addRow(self.holding_label, self.holding)
        self.served_label = QLabel(body)
        self.served = QLabel(body)
        self.served.setObjectName("modbusServedMap")
        self.served.setWordWrap(True)
        form.addRow(self.served_label, self.served)
        self.clients_label = QLabel(body)
        self.clients = QLabel("0", body)
        self.clients.setObjectName("modbusClients")
        form.addRow(self.clients_label, self.clients)
        self.rate_label = QLabel(body)
        self.rate = QLabel("0", body)
        self.rate.setObjectName("modbusRate")
        form.addRow(self.rate_label, self.rate)
        layout.addLayout(form)
        self.button = QPushButton(body)
        self.button.setObjectName("modbusStartStop")
        self.button.clicked.connect(self.toggle)
        layout.addWidget(self.button)
        self.status = QLabel(body)
        self.status.setObjectName("modbusStatus")
        self.status.setWordWrap(True)
        layout.addWidget(self.status)
        layout.addStretch(1)
        self.setWidget(body)
        self._timer = QTimer(self)
        self._timer.setInterval(FIGURES_MS)
        self._timer.timeout.connect(self.show_figures)
        self.written.connect(self._publish_if_idle)
        session.program_loaded.connect(self._program_loaded)
        session.family_changed.connect(lambda _family: self.retranslate())
        self.retranslate()

    @property
    def running(self) -> bool:
        """True while the server listens."""
        return self.server is not None and self.server.running

    def retranslate(self) -> None:
        """Texts in the UI language."""
        self.setWindowTitle(translate("ModbusDock", "Modbus server"))
        self.address_label.setText(translate("ModbusDock", "&Address (host:port):"))
        self.map_file.setPlaceholderText(translate("ModbusDock", "the {0} map").format(
            family_title(self.session.family)))
        self.map_choose.setText(translate("ModbusDock", "Choose…"))
        self.map_default.setText(translate("ModbusDock", "Dialect's map"))
        self.map_default.setToolTip(translate("ModbusDock", "Serve the program's dialect's"
                                              " own map (docs/modbus.md)"))
        self.holding_label.setText(translate("ModbusDock", "&Holding registers:"))
        self.fill_holding()
        self.clients_label.setText(translate("ModbusDock", "Clients connected:"))
        self.rate_label.setText(translate("ModbusDock", "Requests a second:"))
        self.show_state()

    def toggle(self) -> None:
        """Start the server, or stop it when it runs."""
        if self.running:
            self.stop_server()
        else:
            self.start_server()

    def start_server(self) -> bool:
        """Listen at the address typed; False (the reason shown) when it cannot."""
        self.error = ""
        try:
            host, port = parse_endpoint(self.address.text().strip())
        except ValueError:
            self.error = translate("ModbusDock", "Type the address as host:port, e.g. {0}."
                                   ).format(f"{DEFAULT_HOST}:{DEFAULT_PORT}")
            self.show_state()
            return False
        readable, own_map = self.read_map_file()
        if not readable:
            self.show_state()
            return False
        bridge = PlcBridge(self.session.run, own_map)
        bridge.listeners.append(self.written.emit)
        server = ModbusServer(bridge, host, port)
        try:
            server.start()
        except OSError as problem:
            self.error = translate("ModbusDock", "Cannot listen on {0}: {1}").format(
                f"{host}:{port}", problem.strerror or str(problem))
            self.show_state()
            return False
        self.server = server
        self.served_file = self.map_file.text().strip() if own_map is not None else ""
        server.requests_per_second()
        self._timer.start()
        self.show_state()
        return True

    def choose_map(self) -> None:
        """Pick a CSV map file (served from the next start)."""
        path, _ = QFileDialog.getOpenFileName(
            self, translate("ModbusDock", "Modbus map file"), self.map_file.text(),
            translate("ModbusDock", "Modbus maps (*.csv);;All files (*)"))
        if path:
            self.map_file.setText(path)

    def symbols(self) -> SymbolTable | None:
        """The loaded program's symbol table (None without one)."""
        program = self.session.run.program
        return program.symbols if program is not None else None

    def fill_holding(self) -> None:
        """The holding registers' choices: the bit memory %MW, then each global DB; shown
        only for a program with global DBs."""
        blocks = data_blocks(self.symbols())
        chosen = self.holding.currentData()
        self.holding.blockSignals(True)
        self.holding.clear()
        self.holding.addItem(translate("ModbusDock", "Bit memory (%MW)"), "")
        for name in blocks:
            self.holding.addItem(translate("ModbusDock", "Data block {0}").format(name), name)
        self.holding.setCurrentIndex(max(0, self.holding.findData(chosen)))
        self.holding.blockSignals(False)
        self.holding.setVisible(bool(blocks))
        self.holding_label.setVisible(bool(blocks))
        self.map_label.setText(translate("ModbusDock", "&Map file (CSV) or DB:") if blocks
                               else translate("ModbusDock", "&Map file (CSV):"))

    def read_map_file(self) -> tuple[bool, ModbusMap | None]:
        """(True, the map file's map, a DB's map, or None for the dialect's map when neither
        is named); (False, None), with `error` set to its bad lines, when it cannot be used."""
        path = self.map_file.text().strip()
        block = self.holding.currentData() if self.holding.isVisibleTo(self) else ""
        try:
            if not path:
                return True, db_map(self.symbols(), block) if block else None
            return True, chosen_map(path, program_dialect(self.session.run), self.symbols())
        except OSError as problem:
            self.error = translate("ModbusDock", "Cannot read the map {0}: {1}").format(
                path, problem.strerror or str(problem))
        except DiagnosticError as problem:
            lines = [translate("ModbusDock", "line {0}: {1}").format(
                d.line, diagnostic_text(d)) if d.line else diagnostic_text(d)
                for d in problem.diagnostics]
            self.error = "\n".join([translate("ModbusDock", "The map {0} is not served:"
                                               ).format(path), *lines])
        return False, None

    def served_map_text(self) -> str:
        """Which map the server serves (or would serve): the dialect's own or the file."""
        path = self.served_file if self.running else self.map_file.text().strip()
        block = self.holding.currentData() if self.holding.isVisibleTo(self) else ""
        if path and not Path(path).is_file():  # a DB typed by its name (`--map DB`)
            wanted = f'"{path.strip(chr(34))}"'.lower()
            block = next((b for b in data_blocks(self.symbols()) if b.lower() == wanted), "")
            path = "" if block else path
        if not path and block:
            return translate("ModbusDock", "the {0} map, holding registers in the DB {1}"
                             ).format(family_title(program_dialect(self.session.run)), block)
        if path:
            return translate("ModbusDock", "the file {0}").format(path)
        return translate("ModbusDock", "the {0} map").format(family_title(
            program_dialect(self.session.run) if self.session.run.binary is not None
            else self.session.family))

    def stop_server(self) -> None:
        """Close the clients' connections and stop listening."""
        if self.server is not None:
            self.server.stop()
            self.server = None
        self._timer.stop()
        self.show_state()

    def show_figures(self) -> None:
        """Clients connected and requests a second now."""
        server = self.server
        self.clients.setText(str(server.clients if server is not None else 0))
        rate = server.requests_per_second() if server is not None else 0.0
        self.rate.setText(f"{rate:.0f}")

    def show_state(self) -> None:
        """The button, the address field and the status line for the state now."""
        running = self.running
        self.button.setText(translate("ModbusDock", "Stop server") if running
                            else translate("ModbusDock", "Start server"))
        self.address.setEnabled(not running)
        for widget in (self.map_file, self.map_choose, self.map_default, self.holding):
            widget.setEnabled(not running)
        self.served_label.setText(translate("ModbusDock", "Map served:") if running
                                  else translate("ModbusDock", "Map to serve:"))
        self.served.setText(self.served_map_text())
        server = self.server
        if server is not None and running:
            text = translate("ModbusDock", "Listening on {0}:{1} (Modbus/TCP, any unit id),"
                             " map: {2}.").format(server.host, server.port,
                                                  server.bridge.map.name)
            if not is_loopback(server.host):
                text += " " + translate("ModbusDock", "Other computers on the network can"
                                        " read and write this PLC.")
        elif self.error:
            text = self.error
        else:
            text = translate("ModbusDock", "Stopped. An HMI on this computer connects to {0}"
                             " once started.").format(self.address.text().strip())
        self.status.setText(text)
        self.show_figures()

    def _program_loaded(self, _binary: object) -> None:
        """A new program: serve it with its dialect's map, or the map file read again for
        its dialect (the server stops, the reason shown, when the file does not fit it)."""
        self.fill_holding()
        if self.server is None:
            self.show_state()
            return
        readable, own_map = self.read_map_file()
        if not readable:
            self.stop_server()
            return
        self.server.bridge.use(own_map)
        self.served_file = self.map_file.text().strip() if own_map is not None else ""
        self.show_state()

    def _publish_if_idle(self) -> None:
        """Show a client's write now unless the scan thread's publish timer will."""
        if not self.session.run.threaded:
            self.session.publish()
