"""The error list: its count of errors and warnings, and hiding the warnings."""

from __future__ import annotations

from pytestqt.qtbot import QtBot

from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.gui.error_list import ErrorListDock
from ladderworks.gui.main_window import MainWindow

ERROR = Diagnostic("missing-start", {}, 1, 1)
WARNINGS = [Diagnostic("coil-twice", {"address": "R1.0"}, line, 1, Severity.WARNING)
            for line in (3, 9)]


def test_hiding_warnings_keeps_the_errors_and_their_jump(qtbot: QtBot) -> None:
    dock = ErrorListDock()
    qtbot.addWidget(dock)
    dock.set_diagnostics([WARNINGS[0], ERROR, WARNINGS[1]])
    assert dock.summary.text() == "Errors: 1   Warnings: 2"
    assert dock.tree.topLevelItemCount() == 3
    dock.show_warnings.setChecked(False)
    assert dock.tree.topLevelItemCount() == 1
    assert "%@3" in dock.tree.topLevelItem(0).text(2)
    with qtbot.waitSignal(dock.activated) as jumped:
        dock.tree.itemDoubleClicked.emit(dock.tree.topLevelItem(0), 0)
    assert jumped.args == [ERROR]  # the row's own diagnostic, not the list's first
    dock.show_warnings.setChecked(True)
    assert dock.tree.topLevelItemCount() == 3
    assert dock.diagnostics() == [WARNINGS[0], ERROR, WARNINGS[1]]  # all, whatever is shown


def test_the_choice_speaks_turkish(window: MainWindow) -> None:
    window.errors.set_diagnostics([ERROR, *WARNINGS])
    window.set_language("tr")
    assert window.errors.show_warnings.text() == "Uyarıları göster"
    assert window.errors.summary.text() == "Hata: 1   Uyarı: 2"
    window.errors.set_diagnostics([ERROR])
    assert not window.errors.show_warnings.isEnabled()  # nothing to hide
