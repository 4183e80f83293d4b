"""The console window: objectNames, language switching, files, compile and the error list."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from PySide6.QtCore import QLocale, Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QDockWidget, QMenu, QToolBar
from pytestqt.qtbot import QtBot

from ladderworks.core.il import parse_file
from ladderworks.gui import app
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.settings import Settings
from ladderworks.gui.translation import UiLanguage
from ladderworks.paths import CHECKOUT, EXAMPLES

BROKEN = "%@3\nRD X2.1\nAND Q9.9\nWRT Y0.0\n%\n"


def documented_names() -> set[str]:
    text = (CHECKOUT / "docs" / "ui.md").read_text("utf-8")
    return set(re.findall(r"`([a-z][a-z0-9_]*)`", text))


def test_every_action_and_dock_has_an_object_name_listed_in_ui_md(window: MainWindow) -> None:
    names = documented_names()
    reachable: list[QAction] = []
    menus = [a.menu() for a in window.menuBar().actions()]
    while menus:
        menu = menus.pop()
        for action in menu.actions():
            if action.menu() is not None:
                menus.append(action.menu())
            elif not action.isSeparator():
                reachable.append(action)
    unnamed = [a.text() for a in reachable if not a.objectName()]
    assert not unnamed, unnamed
    undocumented = sorted({a.objectName() for a in reachable} - names
                          - {f"action_recent_{i}" for i in range(8)})
    assert not undocumented, f"menu actions not in docs/ui.md: {undocumented}"
    console = (window, window.tool_palette, window.errors,
               window.findChild(QToolBar, "toolbar_main"))
    own = [a for a in window.findChildren(QAction) if a.parent() in console
           and a.objectName().startswith(("action_", "tool_"))]
    assert len(own) > 40
    missing = sorted(a.objectName() for a in own if a.objectName() not in names
                     and not a.objectName().startswith("action_recent_"))
    assert not missing, f"not in docs/ui.md: {missing}"
    for dock in window.findChildren(QDockWidget):
        assert dock.objectName()
    assert {"dock_palette", "dock_errors", "ladder_view", "text_view"} <= names
    for menu in window.menuBar().findChildren(QMenu):
        if menu.title():
            assert menu.objectName() in names, menu.title()


def test_menus_in_order(window: MainWindow) -> None:
    titles = [a.text().replace("&", "") for a in window.menuBar().actions()]
    assert titles == ["File", "Edit", "View", "PLC", "Tools", "Language", "Help"]


def test_language_switches_live_and_is_remembered(window: MainWindow, settings: Settings,
                                                  qtbot: QtBot) -> None:
    with qtbot.waitSignal(window.language_changed):
        window.actions_by_name["action_language_tr"].trigger()
    assert window.actions_by_name["action_save"].text() == "&Kaydet"
    select = window.tool_actions[next(iter(window.tool_actions))]
    assert (select.iconText(), select.text()) == ("SEÇİM", "SEÇİM\tS")  # the key in menus
    titles = [a.text().replace("&", "") for a in window.menuBar().actions()]
    assert titles[:3] == ["Dosya", "Düzen", "Görünüm"]
    assert window.errors.windowTitle() == "Hatalar"
    assert window.tool_palette.functions.itemText(1) == "TMR — ZAMANLAYICI"  # 0: group title
    assert settings.language() == "tr"
    with qtbot.waitSignal(window.language_changed):
        window.actions_by_name["action_language_en"].trigger()
    assert window.actions_by_name["action_save"].text() == "&Save"
    assert settings.language() == "en"


def test_first_start_follows_the_system_locale(qtbot: QtBot, settings: Settings,
                                               monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(app, "system_language", lambda: "tr")
    assert settings.language() is None
    win = app.create_window(settings)
    qtbot.addWidget(win)
    assert win.language.current == "tr"
    assert win.actions_by_name["action_open"].text() == "&Aç..."
    assert QLocale().language() == QLocale.Language.Turkish
    settings.set_language("en")
    again = app.create_window(settings)
    qtbot.addWidget(again)
    assert again.language.current == "en"
    UiLanguage().apply("en")


def test_open_an_example_shows_it_as_ladder(window: MainWindow) -> None:
    assert window.load(EXAMPLES / "spindle_override.LAD")
    assert window.pages.currentWidget() is window.editor
    assert len(window.editor.networks) == 17  # 16 networks and the empty one to draw in
    program, diagnostics = window.editor.program()
    assert diagnostics == []
    assert program == parse_file(EXAMPLES / "spindle_override.LAD").program
    assert window.settings.recent_files()[0] == str(EXAMPLES / "spindle_override.LAD")
    assert window.recent_actions[0].text() == str(EXAMPLES / "spindle_override.LAD")


def test_the_status_bar_describes_the_program_just_opened(window: MainWindow,
                                                          tmp_path: Path) -> None:
    """The cell under the cursor is the new program's, not the one the last program had
    there; a file shown as text names no cell."""
    assert window.load(EXAMPLES / "spindle_override.LAD")
    window.editor.move_cursor(1, 0, 0)
    assert "X2.1" in window.cell_label.text()
    assert window.load(EXAMPLES / "timer_relay.LAD")
    assert "X2.1" not in window.cell_label.text()
    assert window.cell_label.text() == window.editor.describe_cell(
        *window.editor.cursor_cell)
    window.editor.move_cursor(0, 0, 0)
    assert "R1.4" in window.cell_label.text()
    broken = tmp_path / "broken.LAD"
    broken.write_text(BROKEN, encoding="utf-8")
    assert window.load(broken)
    assert window.cell_label.text() == ""

def test_a_file_with_errors_opens_as_text_and_is_never_overwritten(
        window: MainWindow, tmp_path: Path, qtbot: QtBot) -> None:
    broken = tmp_path / "broken.LAD"
    broken.write_text(BROKEN, encoding="utf-8")
    assert window.load(broken)
    assert window.pages.currentWidget() is window.text_view
    assert window.text_view.toPlainText() == BROKEN
    codes = [d.code for d in window.errors.diagnostics()]
    assert codes == ["unknown-area"]
    assert "Q9.9" in window.errors.tree.topLevelItem(0).text(2)
    window.text_view.appendPlainText("// edited")
    assert not window.save()
    assert broken.read_text("utf-8") == BROKEN
    assert "not overwritten" in window.last_warning
    item = window.errors.tree.topLevelItem(0)
    window.errors.tree.itemDoubleClicked.emit(item, 0)
    assert window.text_view.cursor_line() == 3
    other = tmp_path / "fixed.LAD"
    assert window.save_to(other)
    assert other.read_text("utf-8").endswith("// edited\n")


def test_fixing_the_text_shows_it_as_ladder(window: MainWindow, tmp_path: Path) -> None:
    broken = tmp_path / "broken.LAD"
    broken.write_text(BROKEN, encoding="utf-8")
    window.load(broken)
    window.text_view.selectAll()
    window.text_view.insertPlainText(BROKEN.replace("Q9.9", "R9.1"))
    window.actions_by_name["action_show_ladder"].trigger()
    assert window.pages.currentWidget() is window.editor
    assert window.is_modified()
    assert window.save()
    assert "AND R9.1" in broken.read_text("utf-8")


def test_save_is_atomic_and_keeps_cp1254(window: MainWindow, tmp_path: Path) -> None:
    source = (EXAMPLES / "or_single.LAD").read_text("utf-8")
    (tmp_path / "files").mkdir()
    path = tmp_path / "files" / "turkish.LAD"
    path.write_bytes(source.encode("cp1254"))
    window.load(path)
    assert window.encoding == "cp1254"
    window.editor.move_cursor(0, 0, 0)
    window.actions_by_name["action_invert"].trigger()
    assert window.save()
    data = path.read_bytes()
    assert "RD.NOT F9.6".encode("cp1254") in data
    assert "ÇÖZÜCÜ".encode("cp1254") in data
    assert [p.name for p in path.parent.iterdir()] == ["turkish.LAD"]  # no temporary left


def test_export_and_import_mod(window: MainWindow, tmp_path: Path) -> None:
    window.load(EXAMPLES / "rising_edge.LAD")
    mod = tmp_path / "rising.MOD"
    assert window.export_mod(mod)
    assert parse_file(mod).program == parse_file(EXAMPLES / "rising_edge.LAD").program
    window.new_file()
    assert window.import_mod(mod)
    assert window.path is None
    assert window.editor.program()[0] == parse_file(mod).program


def test_compile_lists_errors_and_double_click_jumps_to_the_cell(
        window: MainWindow, qtbot: QtBot) -> None:
    window.load(EXAMPLES / "timer_relay.LAD")
    assert window.compile() is not None
    assert "Compile finished" in window.statusBar().currentMessage()
    editor = window.editor
    editor.move_cursor(0, 0, editor.networks[0].columns)
    editor.edits.delete_at_cursor()  # the coil goes: the timer's W1 leads nowhere
    editor.move_cursor(0, 0, 0)
    editor.edits.delete_at_cursor()  # and the contact: nothing drives ACT
    assert window.compile() is None
    diagnostics = window.errors.diagnostics()
    located = [d for d in diagnostics if d.network is not None and d.cell is not None]
    assert located
    target = located[0]
    index = diagnostics.index(target)
    item = window.errors.tree.topLevelItem(index)
    window.errors.tree.itemDoubleClicked.emit(item, 0)
    assert editor.cursor_cell == (target.network, *target.cell)
    assert editor.network_items[target.network].error_cells


def test_new_after_changes_starts_empty(window: MainWindow) -> None:
    window.load(EXAMPLES / "or_double.LAD")
    window.editor.undo_stack.setClean()
    window.new_file()
    assert window.editor.is_empty()
    assert window.windowTitle().startswith("Untitled")


def test_close_with_unsaved_changes_asks(window: MainWindow,
                                         monkeypatch: pytest.MonkeyPatch) -> None:
    from PySide6.QtWidgets import QMessageBox

    window.load(EXAMPLES / "or_double.LAD")
    window.editor.move_cursor(0, 0, 0)
    window.editor.edits.invert_at_cursor()
    assert window.windowTitle().startswith("or_double.LAD*")
    asked: list[str] = []

    def answer(*args: object, **_kwargs: object) -> QMessageBox.StandardButton:
        asked.append(str(args[1]))
        return QMessageBox.StandardButton.Cancel

    monkeypatch.setattr(QMessageBox, "question", answer)
    assert not window.close()
    assert asked == ["Unsaved changes"]
    assert window.isVisible()
    _ = Qt
