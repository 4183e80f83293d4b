"""Issue 38 item 1: File › New asks the PLC family and model (and remembers it); the palette,
the devices typed, the saved text and Save As's filter follow it; Program properties moves a
program to another family when its instructions read back the same there, else says why."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QComboBox
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.dialects import parse_target
from ladderworks.core.il.reading import parse_file
from ladderworks.core.ladder.model import Contact
from ladderworks.gui import file_dialogs
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.program_properties import ProgramPropertiesDialog
from tests.gui.conftest import Drawer


def file_new(qtbot: QtBot, window: MainWindow, family: str | None) -> QComboBox:
    """File › New; pick the family (None: keep what the dialog shows) and press OK."""
    window.actions_by_name["action_new"].trigger()
    dialog = window.new_dialog  # File › New's dialog, shown (not yet closed)
    assert dialog is not None and dialog.isVisible()
    families = dialog.findChild(QComboBox, "new_family")
    if family is not None:
        families.setCurrentIndex(families.findData(family))
    shown = families.currentData()
    with qtbot.waitSignal(dialog.finished):
        qtbot.keyClick(dialog, Qt.Key.Key_Return)
    assert window.model.dialect in (shown, "seed", "fanuc")
    return families


def test_file_new_of_a_delta_program_then_a_fatek_one(
        qtbot: QtBot, window: MainWindow, drawer: Drawer, tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    file_new(qtbot, window, "delta")
    assert window.model.dialect == "delta"
    combo = window.tool_palette.functions
    entries = [combo.itemText(i) for i in range(combo.count())]
    assert any(e.startswith("TMR") for e in entries) and any(e.startswith("END") for e in entries)
    editor = window.editor
    assert len(editor.networks) == 2  # the + network, then END
    coil = editor.networks[0].coil_column
    drawer.element(0, 0, 0, "I", "T0")  # Delta's spelling: a timer's contact
    drawer.element(0, 0, coil, "O", "Y0")
    drawer.line(0, (0, 1), (0, coil))
    contact = editor.networks[0].cells[(0, 0)]
    assert isinstance(contact, Contact) and contact.address == parse_target("T0", "delta",
                                                                            "bit")[0]
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)  # compiled into the PLC as a Delta program
    assert session.run.engine is not None and session.run.program_dialect == "delta"
    assert not [d for d in window.errors.diagnostics() if d.is_error]
    seen: list[str] = []
    target = tmp_path / "first.txt"

    def chosen(_parent: object, _caption: str, directory: str, filters: str) -> str:
        seen.extend([directory, filters])
        return str(target)

    monkeypatch.setattr(file_dialogs, "save_file_name", chosen)
    with qtbot.waitSignal(window.file_saved):
        window.actions_by_name["action_save"].trigger()  # untitled: Save As
    assert seen[0] == "program.txt" and seen[1].startswith("Delta DVP instruction lists")
    assert target.read_text(encoding="utf-8").split() == ["LD", "T0", "OUT", "Y0", "END"]
    assert parse_file(target).program.dialect == "delta"
    families = file_new(qtbot, window, None)  # remembered: Delta again
    assert families.currentData() == "delta" and window.model.dialect == "delta"
    file_new(qtbot, window, "fatek")
    assert window.model.dialect == "fatek"
    drawer.element(0, 0, 0, "I", "TR1")
    contact = window.editor.networks[0].cells[(0, 0)]
    assert isinstance(contact, Contact) and contact.address == parse_target("TR1", "fatek",
                                                                            "bit")[0]


def _properties(qtbot: QtBot, window: MainWindow) -> tuple[ProgramPropertiesDialog, QComboBox]:
    window.actions_by_name["action_program_properties"].trigger()
    dialog = window.properties_dialog
    assert isinstance(dialog, ProgramPropertiesDialog)
    qtbot.waitExposed(dialog)
    combo = dialog.findChild(QComboBox, "properties_model")
    assert combo is not None and combo.isEnabled()
    return dialog, combo


def _choose(combo: QComboBox, key: str) -> None:
    index = combo.findData(key)
    combo.setCurrentIndex(index)
    combo.activated.emit(index)


def test_program_properties_change_the_family_where_the_instructions_allow(
        qtbot: QtBot, window: MainWindow, tmp_path: Path) -> None:
    copy = tmp_path / "t.txt"
    copy.write_bytes((paths.EXAMPLES / "delta" / "timer_t0.txt").read_bytes())
    assert window.load(copy)
    dialog, combo = _properties(qtbot, window)
    _choose(combo, "fatek")  # TMR T0 K10 has no Fatek counterpart written so
    assert "cannot become a Fatek FBs program" in window.last_warning
    assert window.model.dialect == "delta" and combo.currentData() == "delta"
    dialog.close()
    plain = tmp_path / "lamp.txt"
    plain.write_text("LD X0\nANI X1\nOUT Y0\nEND\n", encoding="utf-8")
    assert window.load(plain)
    dialog, combo = _properties(qtbot, window)
    _choose(combo, "fatek")
    assert window.model.dialect == "fatek" and combo.currentData() == "fatek"
    assert window.path is None and window.is_modified()
    dialog.close()
    program = window.model.saved_program()[0]
    assert [i.name for i in program.instructions()] == ["RD", "AND.NOT", "WRT"]
