"""An S7-1200 SD block (and its SimaticML XML twin) in the IDE: File › Open with its folder's
tag table, compiled with F9, run, a tag set, a coil seen; saved back byte for byte."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from pytestqt.qtbot import QtBot

from ladderworks.core.dialects.s7.devices import parse_absolute
from ladderworks.gui.main_window import MainWindow
from tests.gui.conftest import Answers

EXAMPLES = Path(__file__).resolve().parents[2] / "resources" / "examples" / "s7"
XML_EXAMPLES = EXAMPLES.parent / "s7-xml"


@pytest.mark.parametrize(("examples", "name"), [(EXAMPLES, "Main.s7dcl"),
                                                (XML_EXAMPLES, "Main.xml")])
def test_an_s7_block_opens_runs_and_saves_as_read(qtbot: QtBot, window: MainWindow,
                                                   tmp_path: Path, examples: Path,
                                                   name: str) -> None:
    """The same block as SIMATIC SD and as SimaticML XML."""
    folder = tmp_path / "jumps"
    shutil.copytree(examples / "jumps", folder)
    path = folder / name
    assert window.load(path)
    assert window.editor.networks
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert session.run.engine is not None
    start = window.findChild(QAction, "action_plc_start")
    assert start is not None
    start.trigger()
    motor, _ = parse_absolute("%Q0.2")
    session.run_scans(2)
    assert session.run.bit(motor) == 0
    session.set_bit(parse_absolute("%I0.2")[0], 1)  # "Start"
    session.run_scans(2)
    assert session.run.bit(motor) == 1
    assert window.save()
    assert path.read_bytes() == (examples / "jumps" / name).read_bytes()


def test_a_deleted_s7_network_is_saved_and_a_change_s7_cannot_hold_keeps_the_file(
        window: MainWindow, tmp_path: Path, answers: Answers) -> None:
    folder = tmp_path / "timers"
    shutil.copytree(EXAMPLES / "timers", folder)
    path = folder / "Main.s7dcl"
    assert window.load(path)
    window.editor.move_cursor(1, 0, 0)
    window.actions_by_name["action_delete_network"].trigger()
    assert window.save()
    saved = path.read_bytes()
    assert b"MLC_t2" not in saved and b"MLC_t1" in saved  # its region gone, the rest kept
    blank = window.editor.model.blank_index()
    window.editor.edits.open_function_dialog(blank, 0, 2, "S7.TON")  # operands left <???>
    dialog = window.editor.edits.operand_dialog
    assert dialog is not None
    dialog.accept()
    answers.queue.append("cancel")
    assert not window.save()
    assert "<???>" in answers.asked[-1][1]
    assert path.read_bytes() == saved
    assert window.recovery_snapshot() is not None  # the autosave copy does not fail either
