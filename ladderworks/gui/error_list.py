"""The error list dock: diagnostics of the last open, check or compile; double-click jumps."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, Signal
from PySide6.QtWidgets import QDockWidget, QTreeWidget, QTreeWidgetItem, QWidget

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.retranslate import Retranslating


def location_text(diagnostic: Diagnostic) -> str:
    """Where the diagnostic is: network and cell, or line and column."""
    if diagnostic.network is not None and diagnostic.cell is not None:
        row, column = diagnostic.cell
        return QCoreApplication.translate(
            "ErrorList", "network {0}, row {1}, column {2}").format(
            diagnostic.network + 1, row + 1, column + 1)
    if diagnostic.network is not None:
        return QCoreApplication.translate("ErrorList", "network {0}").format(
            diagnostic.network + 1)
    if diagnostic.line:
        return QCoreApplication.translate("ErrorList", "line {0}, column {1}").format(
            diagnostic.line, diagnostic.column)
    return ""


class ErrorListDock(Retranslating, QDockWidget):
    """A dock listing diagnostics; `activated` is emitted on double-click."""

    activated = Signal(object)  # Diagnostic
    diagnostics_changed = Signal(list)  # the diagnostics now listed

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("dock_errors")
        self.tree = QTreeWidget(self)
        self.tree.setObjectName("error_list")
        self.tree.setColumnCount(3)
        self.tree.setRootIsDecorated(False)
        self.tree.setAlternatingRowColors(True)
        self.tree.itemActivated.connect(self._on_activated)
        self.tree.itemDoubleClicked.connect(self._on_activated)
        self.setWidget(self.tree)
        self._diagnostics: list[Diagnostic] = []
        self.retranslate()

    def diagnostics(self) -> list[Diagnostic]:
        """The diagnostics shown."""
        return list(self._diagnostics)

    def set_diagnostics(self, diagnostics: list[Diagnostic]) -> None:
        """Show these diagnostics (replacing the list)."""
        self._diagnostics = list(diagnostics)
        self._fill()
        self.diagnostics_changed.emit(self.diagnostics())

    def _fill(self) -> None:
        self.tree.clear()
        for diagnostic in self._diagnostics:
            severity = (QCoreApplication.translate("ErrorList", "Error") if diagnostic.is_error
                        else QCoreApplication.translate("ErrorList", "Warning"))
            item = QTreeWidgetItem([severity, location_text(diagnostic),
                                    diagnostic_text(diagnostic)])
            self.tree.addTopLevelItem(item)
        for column in range(2):
            self.tree.resizeColumnToContents(column)

    def _on_activated(self, item: QTreeWidgetItem, _column: int = 0) -> None:
        index = self.tree.indexOfTopLevelItem(item)
        if 0 <= index < len(self._diagnostics):
            self.activated.emit(self._diagnostics[index])

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(QCoreApplication.translate("ErrorList", "Errors"))
        self.tree.setHeaderLabels([
            QCoreApplication.translate("ErrorList", "Kind"),
            QCoreApplication.translate("ErrorList", "Where"),
            QCoreApplication.translate("ErrorList", "Message"),
        ])
        self._fill()
