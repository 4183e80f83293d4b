"""File › Program properties chooses the program's PMC model (issue 30, item 9): one list of
models, the ranges follow, the model is kept in the file; an unchanged file saves as read."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QComboBox
from pytestqt.qtbot import QtBot

from ladderworks.core.il.program import FANUC, SEED
from ladderworks.core.models import MODELS
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.program_properties import ProgramPropertiesDialog
from tests.gui.conftest import Drawer, type_text
from tests.gui.test_file_form import _save

SEED_TEXT = "%@3\nRD X0.0\nWRT Y0.0\n%\n"
MARK = "// LADDERWORKS PMC MODEL: fanuc\n"


def _dialog(window: MainWindow, qtbot: QtBot) -> tuple[ProgramPropertiesDialog, QComboBox]:
    window.actions_by_name["action_program_properties"].trigger()
    dialog = window.properties_dialog
    assert isinstance(dialog, ProgramPropertiesDialog)
    qtbot.waitExposed(dialog)
    combo = dialog.findChild(QComboBox, "properties_model")
    assert combo is not None
    return dialog, combo


def _choose(combo: QComboBox, key: str) -> None:
    index = combo.findData(key)
    assert index >= 0
    combo.setCurrentIndex(index)
    combo.activated.emit(index)  # what picking it in the list sends


def test_the_model_is_chosen_and_kept_in_the_file(window: MainWindow, qtbot: QtBot,
                                                   tmp_path: Path) -> None:
    path = tmp_path / "lamp.LAD"
    path.write_text(SEED_TEXT, encoding="utf-8")
    assert window.load(path)
    dialog, combo = _dialog(window, qtbot)
    assert [combo.itemData(i) for i in range(combo.count())] == list(MODELS)  # every family
    assert combo.currentData() == SEED and combo.isEnabled()
    assert combo.itemText(combo.findData(FANUC)) == "FANUC Series 30i-A PMC (memory-B)"
    _choose(combo, FANUC)
    general = dict((row[0], row[1]) for row in dialog.texts("properties_general"))
    assert general["PMC model"] == "FANUC Series 30i-A PMC (memory-B)"
    dialog.close()
    assert window.is_modified() and window.model.dialect == FANUC
    _save(window, qtbot)
    assert path.read_text(encoding="utf-8") == MARK + SEED_TEXT  # one comment line more
    assert window.load(path)
    assert window.program_info.dialect == FANUC
    dialog, combo = _dialog(window, qtbot)
    assert combo.currentData() == FANUC
    _choose(combo, SEED)  # back to the framing's default: the line goes
    dialog.close()
    _save(window, qtbot)
    assert path.read_text(encoding="utf-8") == SEED_TEXT


def test_the_ranges_follow_the_model(window: MainWindow, qtbot: QtBot, tmp_path: Path) -> None:
    path = tmp_path / "alarm.LAD"
    path.write_text("%@3\nRD X0.0\nWRT A100.0\n%\n", encoding="utf-8")
    window.load(path)
    assert [d.code for d in window.errors.diagnostics()] == ["byte-range"]  # A0-A99: seed
    path.write_text(MARK + "%@3\nRD X0.0\nWRT A100.0\n%\n", encoding="utf-8")
    assert window.load(path)
    assert window.errors.diagnostics() == []
    assert [d for d in window.check() if d.is_error] == []


def test_a_new_program_takes_the_model_chosen(window: MainWindow, qtbot: QtBot,
                                              tmp_path: Path) -> None:
    dialog, combo = _dialog(window, qtbot)
    _choose(combo, FANUC)
    dialog.close()
    assert window.model.dialect == FANUC
    program = window.model.saved_program()[0]
    assert program.dialect == FANUC


def test_an_unchanged_marked_file_saves_byte_for_byte(window: MainWindow, qtbot: QtBot,
                                                      tmp_path: Path) -> None:
    path = tmp_path / "marked.LAD"
    data = (MARK + SEED_TEXT).replace("\n", "\r\n").encode("utf-8")
    path.write_bytes(data)
    assert window.load(path)
    window.model.mark_modified()
    _save(window, qtbot)
    assert path.read_bytes() == data


def test_the_plc_tables_take_the_map_of_the_model_in_the_plc(
        window: MainWindow, qtbot: QtBot, tmp_path: Path) -> None:
    from ladderworks.gui.docks.table_entries import TableKind
    from tests.gui.test_pmc_parameters import tables_of

    tables = tables_of(window)
    for text, keep in ((SEED_TEXT, "'K900': byte number out of range for area K (0-99)"),
                       (MARK + SEED_TEXT, None)):
        path = tmp_path / "lamp.LAD"
        path.write_text(text, encoding="utf-8")
        assert window.load(path)
        with qtbot.waitSignal(window.plc_docks.session.program_loaded, timeout=20_000):
            window.actions_by_name["action_compile"].trigger()
        assert tables.insert_texts(TableKind.KEEP, ["K900", "1"]) == keep
        assert tables.insert_texts(TableKind.KEEP, ["K500", "1"]) is not None  # in no map
        assert tables.insert_texts(TableKind.KEEP, ["K9", "1"]) is None
        window.model.mark_saved()
        window.parameters.saved = window.parameters.session.run.parameters.copy()


def test_typing_an_address_follows_the_model(window: MainWindow, qtbot: QtBot,
                                             drawer: Drawer) -> None:
    drawer.key("O")
    drawer.click(0, 0, 10)  # a coil: its address typed in place
    editor = window.editor.inline_editor
    type_text(qtbot, editor, "A100.0")
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    assert "'A100.0': byte number out of range for area A (0-99)" in \
        window.editor.inline_message.text()  # a new program is a seed one: A0-A99
    editor.clear()
    type_text(qtbot, editor, "A99.0")
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    assert not editor.isVisible()
    window.set_pmc_model(FANUC)
    drawer.click(0, 0, 10)
    qtbot.waitUntil(editor.isVisible)
    editor.clear()
    type_text(qtbot, editor, "A100.0")
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    assert not editor.isVisible()  # the 30i's A area
    found = window.editor.networks[0].element_at(0, 10)
    assert found is not None and str(found[1].address) == "A100.0"  # type: ignore[union-attr]


def test_a_model_registered_later_shows_in_the_list(window: MainWindow, qtbot: QtBot,
                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    from ladderworks.core.models import FANUC_PMC, PmcModel
    monkeypatch.setitem(MODELS, "fanuc-0i", PmcModel("fanuc-0i", "FANUC 0i-F PMC", FANUC_PMC))
    dialog, combo = _dialog(window, qtbot)
    assert [combo.itemText(i) for i in range(combo.count())][-1] == "FANUC 0i-F PMC"
    dialog.close()


def test_a_program_of_an_unknown_model_shows_it_read_only(
        window: MainWindow, qtbot: QtBot, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every registered family's models are offered (issue 38); an unknown one is shown alone."""
    window.program_info.dialect = "nosuch"
    dialog, combo = _dialog(window, qtbot)
    assert [combo.itemText(i) for i in range(combo.count())] == ["nosuch"]
    assert not combo.isEnabled()
    dialog.close()
