"""PLC › Native scan (machine code): the scan's code the PLC compiles a program to, remembered."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QObject
from PySide6.QtGui import QAction

from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.settings import Settings

translate = QCoreApplication.translate
ACTION = "action_plc_native_scan"


class ScanBackendChoice(QObject):
    """A checkable action: checked, each program loaded from then on scans as native code
    (llvmlite; docs/engine.md), else as generated Python; the choice is kept in the settings."""

    def __init__(self, session: PlcSession, settings: Settings,
                 parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.session = session
        self.settings = settings
        self.action = QAction(self)
        self.action.setObjectName(ACTION)
        self.action.setCheckable(True)
        backend = settings.scan_backend()
        session.run.backend = backend
        self.action.setChecked(backend == "native")
        self.action.toggled.connect(self.choose)
        self.retranslate()

    def retranslate(self) -> None:
        """Texts in the UI language."""
        self.action.setText(translate("ScanBackend", "Native scan (machine code)"))
        self.action.setToolTip(translate(
            "ScanBackend", "Compile the program loaded next (F9, Compile) to machine code: "
            "it scans many times faster. Where that cannot be done, the Python scan runs and "
            "the PLC control screen says why."))

    def choose(self, native: bool) -> None:
        """Use the native scan (True) or the Python one for the programs loaded from now on."""
        backend = "native" if native else "python"
        self.session.run.backend = backend
        self.settings.set_scan_backend(backend)
