"""Edit › Output pins (FO)…: a Fatek box placed in the editor gets its FO1, FO2 … pins from the
dialog's check boxes (one undo step); on a coil the status bar says there is no such box."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtGui import QAction
from pytestqt.qtbot import QtBot

from ladderworks.core.ladder.model import FunctionBox
from ladderworks.core.ladder.output_pins import shown_pins
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.translation import UiLanguage

CMP = "ORG X0\nFUN 17 CMP\n Sa: R0\n Sb: R1\nFO 0\nOUT Y0\nORG X1\nOUT Y1\n"


def _box(window: MainWindow) -> tuple[int, int, FunctionBox]:
    for (row, col), element in window.editor.networks[0].cells.items():
        if isinstance(element, FunctionBox):
            return row, col, element
    raise AssertionError("no box")


def test_the_dialog_shows_the_checked_pins_and_undo_takes_them_away(
        qtbot: QtBot, window: MainWindow, tmp_path: Path) -> None:
    UiLanguage().apply("en")
    path = tmp_path / "cmp.lst"
    path.write_text(CMP)
    assert window.load(path)
    row, col, box = _box(window)
    assert shown_pins(box) == ()
    window.editor.cursor_cell = (0, row, col)
    action = window.findChild(QAction, "action_output_pins")
    assert action is not None and action in window.editor.context_actions
    assert action.text() == "Output pins (FO)…"
    action.trigger()
    dialog = window.editor.edits.output_pins_dialog
    assert dialog is not None and dialog.isVisible()
    assert "FUN 17 CMP" in dialog._label.text()
    dialog.boxes[1].setChecked(True)
    dialog.boxes[2].setChecked(True)
    dialog.accept()
    _row, _col, box = _box(window)
    assert shown_pins(box) == (1, 2) and box.height == 3
    assert window.editor.model.undo_stack.undoText() == "Output pins"
    window.editor.model.undo_stack.undo()
    assert shown_pins(_box(window)[2]) == ()
    window.editor.cursor_cell = (1, 0, window.editor.networks[1].coil_column)
    messages: list[str] = []
    window.editor.message.connect(messages.append)
    action.trigger()
    assert messages and "no function box with FO outputs" in messages[-1]
    language = UiLanguage()  # kept: its translators live as long as it does
    language.apply("tr")
    qtbot.waitUntil(lambda: action.text() == "Çıkış uçları (FO)…")
    language.apply("en")
