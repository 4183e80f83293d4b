"""Edit › Find / Replace (Ctrl+F / Ctrl+H): hits move the cursor; Replace all is one undo."""

from __future__ import annotations

import difflib
from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QApplication
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.gui.find_replace import FindReplaceDialog
from ladderworks.gui.main_window import MainWindow
from ladderworks.paths import EXAMPLES
from tests.gui.conftest import type_text
from tests.real_programs import real_bytes

CTRL = Qt.KeyboardModifier.ControlModifier


def _uses(window: MainWindow, text: str) -> list[tuple[int, tuple[int, int]]]:
    address = parse_address(text)
    return [(i, cell) for i, net in enumerate(window.editor.networks)
            for cell, element in sorted(net.cells.items())
            if getattr(element, "address", None) == address]


def _dialog(window: MainWindow, qtbot: QtBot, key: str) -> FindReplaceDialog:
    window.activateWindow()
    window.editor.setFocus()
    qtbot.waitUntil(window.editor.hasFocus)
    qtbot.keyClick(window.editor, key, CTRL)
    dialog = window.find_dialog
    assert dialog is not None
    qtbot.waitUntil(dialog.isVisible)
    return dialog


def test_ctrl_f_finds_each_use_and_moves_the_cursor(window: MainWindow, qtbot: QtBot) -> None:
    window.load(EXAMPLES / "or_double.LAD")
    uses = _uses(window, "R1.0")
    assert len(uses) >= 1
    window.editor.move_cursor(0, 0, 0)
    dialog = _dialog(window, qtbot, "f")
    dialog.find_text.clear()
    type_text(qtbot, dialog.find_text, "R1.0")
    seen = []
    for _ in range(len(uses) + 1):
        qtbot.keyClick(dialog.find_text, Qt.Key.Key_Return)  # ENTER: Find next
        index, row, col = window.editor.cursor_cell
        seen.append((index, (row, col)))
    assert sorted(set(seen)) == uses  # every use, then round again
    assert dialog.message.text().startswith("1 of ") or " of " in dialog.message.text()
    dialog.find_text.setText("Y99.9")
    dialog.find_next_button.click()
    assert dialog.message.text() == "Not found"


def test_replace_all_is_one_ctrl_z(window: MainWindow, qtbot: QtBot) -> None:
    window.load(EXAMPLES / "all_functions.LAD")
    before = [net.copy() for net in window.editor.networks]
    dialog = _dialog(window, qtbot, "h")
    dialog.find_text.setText("R18")
    dialog.replace_text.setText("R118")
    depth = window.editor.undo_stack.index()
    dialog.replace_all_button.click()
    assert "replaced in" in dialog.message.text()
    assert window.editor.undo_stack.index() == depth + 1
    assert window.is_modified()
    texts = [str(p) for net in window.editor.networks for e in net.cells.values()
             for p in getattr(e, "params", ())]
    assert "R118" in texts and "R18" not in texts
    assert dialog.find_next() is None  # the hits are looked for again after an edit
    window.activateWindow()
    window.editor.setFocus()
    qtbot.waitUntil(window.editor.hasFocus)
    qtbot.keyClick(window.editor, "z", CTRL)
    assert window.editor.networks == before
    assert dialog.find_next() is not None
    qtbot.keyClick(window.editor, "y", CTRL)
    assert window.editor.networks != before


def test_replace_all_in_a_real_program_rewrites_only_those_networks(
        window: MainWindow, qtbot: QtBot, tmp_path: Path) -> None:
    source = tmp_path / "estop.txt"
    source.write_bytes(real_bytes("FANUC_X22_FRAG_fc62199_EMERGENCY_STOP"))
    window.load(source)
    dialog = _dialog(window, qtbot, "h")
    dialog.find_text.setText("R5584.2")
    dialog.replace_text.setText("R5590.2")
    assert dialog.replace_all() == 2
    assert window.save()
    old = real_bytes("FANUC_X22_FRAG_fc62199_EMERGENCY_STOP").decode().splitlines()
    new = source.read_bytes().decode().splitlines()
    changed = [line for line in difflib.unified_diff(old, new, lineterm="", n=0)
               if line[:1] in "+-" and not line.startswith(("+++", "---"))]
    assert sum("R5590.2" in line for line in changed if line.startswith("+")) == 2
    assert not any("R5584.2" in line for line in new)
    labels = [i for i, line in enumerate(old) if line.startswith("N0000")]
    touched = {max(k for k in labels if k <= i) for i, line in enumerate(old)
               if line not in new}
    assert {old[k] for k in touched} <= {"N00001:", "N00002:"}


def test_replace_one_replaces_the_hit_at_the_cursor(window: MainWindow, qtbot: QtBot) -> None:
    window.load(EXAMPLES / "or_double.LAD")
    uses = _uses(window, "R1.0")
    window.editor.move_cursor(*((uses[0][0],) + uses[0][1]))
    dialog = _dialog(window, qtbot, "h")
    assert dialog.find_text.text() == "R1.0"  # the address at the cursor
    qtbot.waitUntil(lambda: QApplication.focusWidget() is dialog.replace_text)
    type_text(qtbot, dialog.replace_text, "R5.5")
    dialog.replace_button.click()
    assert _uses(window, "R5.5") == uses[:1]
    assert _uses(window, "R1.0") == uses[1:]


def test_a_wrong_replacement_says_why_in_the_ui_language(window: MainWindow,
                                                         qtbot: QtBot) -> None:
    window.load(EXAMPLES / "or_double.LAD")
    dialog = _dialog(window, qtbot, "h")
    dialog.find_text.setText("R1.0")
    dialog.replace_text.setText("R2")
    assert dialog.replace_all() == 0
    assert dialog.message.text() == "R1.0 and R2: replace a bit with a bit, a byte with a byte"
    window.set_language("tr")
    assert dialog.replace_all() == 0
    assert "bit ile" in dialog.message.text()
    assert dialog.windowTitle() == "Bul ve değiştir"


def test_find_previous_walks_back_and_f3_repeats_the_search(window: MainWindow,
                                                             qtbot: QtBot) -> None:
    window.load(EXAMPLES / "or_double.LAD")
    uses = _uses(window, "R1.0")
    window.editor.move_cursor(0, 0, 0)
    window.find_again(True)  # F3 with nothing searched for yet opens the dialog
    dialog = window.find_dialog
    assert dialog is not None and dialog.isVisible()
    dialog.find_text.setText("R1.0")
    dialog.close()
    window.editor.setFocus()
    forward = []
    for _ in range(len(uses)):
        qtbot.keyClick(window.editor, Qt.Key.Key_F3)
        index, row, col = window.editor.cursor_cell
        forward.append((index, (row, col)))
    assert forward == uses
    backward = []
    for _ in range(len(uses)):
        qtbot.keyClick(window.editor, Qt.Key.Key_F3, Qt.KeyboardModifier.ShiftModifier)
        index, row, col = window.editor.cursor_cell
        backward.append((index, (row, col)))
    # from the last hit back: each earlier one, then round to the last again
    assert backward == [*reversed(uses[:-1]), uses[-1]]
    assert " of " in window.statusBar().currentMessage()
    dialog.find_text.setText("Y99.9")
    assert dialog.find_previous() is None and dialog.message.text() == "Not found"
