"""PLC › Modbus server: serve the console's PLC over Modbus/TCP (start/stop, address, clients).

The server answers from the session's own PlcRun (the memory the docks show), on its own
asyncio thread (core `ModbusServer`); a client's write is published to the docks at once
unless the scan thread runs (its publish timer shows it with the next snapshot).
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QTimer, Signal
from PySide6.QtWidgets import (
    QDockWidget,
    QFormLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.modbus.bridge import PlcBridge
from ladderworks.core.modbus.server import (
    DEFAULT_HOST,
    DEFAULT_PORT,
    ModbusServer,
    is_loopback,
    parse_endpoint,
)
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
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        form = QFormLayout()
        self.address_label = QLabel(body)
        self.address = QLineEdit(f"{DEFAULT_HOST}:{DEFAULT_PORT}", body)
        self.address.setObjectName("modbusAddress")
        self.address_label.setBuddy(self.address)
        form.addRow(self.address_label, self.address)
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
        self.retranslate()

    @property
    def running(self) -> bool:
        """True while the server listens."""
        return self.server is not None and self.server.running

    def retranslate(self) -> None:
        """Texts in the UI language."""
        self.setWindowTitle(translate("ModbusDock", "Modbus server"))
        self.address_label.setText(translate("ModbusDock", "&Address (host:port):"))
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
        bridge = PlcBridge(self.session.run)  # the loaded program's dialect's map
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
        server.requests_per_second()
        self._timer.start()
        self.show_state()
        return True

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
        """A new program: serve it with its dialect's map."""
        if self.server is not None:
            self.server.bridge.use()
            self.show_state()

    def _publish_if_idle(self) -> None:
        """Show a client's write now unless the scan thread's publish timer will."""
        if not self.session.run.threaded:
            self.session.publish()
