"""The error list dock: diagnostics of the last open, check or compile; double-click jumps."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QDockWidget,
    QHBoxLayout,
    QLabel,
    QTreeWidget,
    QTreeWidgetItem,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.header_fit import fit_headers
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
    """A dock listing diagnostics, with their count and a choice to hide the warnings (a real
    program's hundreds of double coils); `activated` is emitted on double-click."""

    activated = Signal(object)  # Diagnostic
    diagnostics_changed = Signal(list)  # the diagnostics now listed

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("dock_errors")
        body = QWidget(self)
        self.summary = QLabel(body)
        self.summary.setObjectName("error_summary")
        self.show_warnings = QCheckBox(body)
        self.show_warnings.setObjectName("show_warnings")
        self.show_warnings.setChecked(True)
        self.show_warnings.toggled.connect(lambda _on: self._fill())
        top = QHBoxLayout()
        top.setContentsMargins(4, 2, 4, 0)
        top.addWidget(self.summary, 1)
        top.addWidget(self.show_warnings)
        self.tree = QTreeWidget(body)
        self.tree.setObjectName("error_list")
        self.tree.setColumnCount(3)
        self.tree.setRootIsDecorated(False)
        self.tree.setAlternatingRowColors(True)
        self.tree.itemActivated.connect(self._on_activated)
        self.tree.itemDoubleClicked.connect(self._on_activated)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(2)
        layout.addLayout(top)
        layout.addWidget(self.tree)
        self.setWidget(body)
        self._diagnostics: list[Diagnostic] = []
        self._shown: list[Diagnostic] = []  # the rows of the tree, in order
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
        errors = sum(1 for diagnostic in self._diagnostics if diagnostic.is_error)
        warnings = len(self._diagnostics) - errors
        self.summary.setText(QCoreApplication.translate(
            "ErrorList", "Errors: {0}   Warnings: {1}").format(errors, warnings))
        self.show_warnings.setEnabled(warnings > 0)
        self._shown = [diagnostic for diagnostic in self._diagnostics
                       if diagnostic.is_error or self.show_warnings.isChecked()]
        for diagnostic in self._shown:
            severity = (QCoreApplication.translate("ErrorList", "Error") if diagnostic.is_error
                        else QCoreApplication.translate("ErrorList", "Warning"))
            item = QTreeWidgetItem([severity, location_text(diagnostic),
                                    diagnostic_text(diagnostic)])
            self.tree.addTopLevelItem(item)
        for column in range(2):
            self.tree.resizeColumnToContents(column)

    def _on_activated(self, item: QTreeWidgetItem, _column: int = 0) -> None:
        index = self.tree.indexOfTopLevelItem(item)
        if 0 <= index < len(self._shown):
            self.activated.emit(self._shown[index])

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(QCoreApplication.translate("ErrorList", "Errors"))
        self.show_warnings.setText(QCoreApplication.translate("ErrorList", "Show warnings"))
        self.tree.setHeaderLabels([
            QCoreApplication.translate("ErrorList", "Kind"),
            QCoreApplication.translate("ErrorList", "Where"),
            QCoreApplication.translate("ErrorList", "Message"),
        ])
        fit_headers(self.tree)
        self._fill()
