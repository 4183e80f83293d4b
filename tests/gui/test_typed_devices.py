"""Issue 38 item 2: every device a dialect's contact or coil takes is typed in its cell (Delta's
T0 and C0 contacts, S; Fatek's T, C, TR), and what the dialect refuses is refused in place."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.dialects import parse_target
from ladderworks.core.ladder.model import Coil, Contact
from ladderworks.gui.main_window import MainWindow


def _type(qtbot: QtBot, window: MainWindow, cell: tuple[int, int, int], text: str) -> str:
    """Open the address of a cell as a double click does, type `text`, ENTER: the message."""
    editor = window.editor
    editor.inline.open_address(*cell)
    editor.inline_editor.setText(text)
    qtbot.keyClick(editor.inline_editor, Qt.Key.Key_Return)
    return editor.inline_message.text() if editor.inline_message.isVisible() else ""


def _coil_cell(window: MainWindow, index: int) -> tuple[int, int, int]:
    network = window.model.networks[index]
    row, col = next(cell for cell, element in network.cells.items()
                    if isinstance(element, Coil))
    return index, row, col


def test_delta_timer_and_counter_contacts_are_typed_and_a_coil_refuses_x(
        qtbot: QtBot, window: MainWindow, tmp_path: Path) -> None:
    copy = tmp_path / "t.txt"
    copy.write_bytes((paths.EXAMPLES / "delta" / "timer_t0.txt").read_bytes())
    assert window.load(copy)
    for text in ("T0", "C0", "S3", "C235"):
        assert _type(qtbot, window, (0, 0, 0), text) == "", text
        contact = window.model.networks[0].cells[(0, 0)]
        assert isinstance(contact, Contact)
        assert contact.address == parse_target(text, "delta", "bit")[0]
    coil = _coil_cell(window, 1)
    message = _type(qtbot, window, coil, "X0")
    assert "X0" in message and "Y, M, S" in message  # the reader's own refusal, in place
    assert window.model.networks[1].cells[coil[1:]].address == parse_target("Y0", "delta")[0]
    assert _type(qtbot, window, (0, 0, 0), "D0") != ""  # a DVP has no bit of a D register
    assert window.save_to(copy)
    assert window.load(copy) and window.model.dialect == "delta"  # drawn again, not text
    assert isinstance(window.model.networks[0].cells[(0, 0)], Contact)
    assert copy.read_text(encoding="utf-8").splitlines()[1] == "LD\tC235"


def test_fatek_timer_counter_and_temporary_relay_contacts_are_typed(
        qtbot: QtBot, window: MainWindow, tmp_path: Path) -> None:
    copy = tmp_path / "c.lst"
    copy.write_bytes((paths.EXAMPLES / "fatek" / "conveyor.lst").read_bytes())
    assert window.load(copy)
    for text in ("T50", "C0", "TR1", "X8"):
        assert _type(qtbot, window, (0, 0, 0), text) == "", text
        contact = window.model.networks[0].cells[(0, 0)]
        assert isinstance(contact, Contact)
        assert contact.address == parse_target(text, "fatek", "bit")[0]
    assert "R0" in _type(qtbot, window, (0, 0, 0), "R0")
    coil = _coil_cell(window, 0)
    assert "T50" in _type(qtbot, window, coil, "T50")
