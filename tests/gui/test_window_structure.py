"""The window's structure: actions from the table, typed docks, one way to retranslate."""

from __future__ import annotations

import ast
import inspect
from pathlib import Path

from PySide6.QtCore import SignalInstance
from PySide6.QtGui import QKeySequence
from PySide6.QtWidgets import QDockWidget, QWidget
from pytestqt.qtbot import QtBot

import ladderworks.gui
from ladderworks.gui.actions_table import ACTIONS, CONTEXT_MENU, LADDER_SHOWN, MENUS
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.retranslate import Retranslating
from tests.gui.conftest import Drawer

GUI = Path(ladderworks.gui.__file__).parent


def test_every_table_action_is_built_with_its_key_menu_and_toolbar_place(
        window: MainWindow) -> None:
    menus = window.menus.menus
    toolbar = window.menus.toolbar.actions()
    for spec in ACTIONS:
        action = window.actions_by_name[spec.name]
        assert action.objectName() == spec.name
        first = spec.shortcut[0] if isinstance(spec.shortcut, tuple) else spec.shortcut
        if first is not None:
            assert action.shortcut() == QKeySequence(first), spec.name
        if spec.menu is not None:
            assert action in menus[spec.menu].actions(), spec.name
        assert (action in toolbar) == (spec.toolbar is not None), spec.name
        assert action.isCheckable() == spec.checkable
    assert [m.name for m in MENUS if m.parent is None] == [
        a.menu().objectName() for a in window.menuBar().actions()]
    assert window.recent_menu.menuAction() in menus["menu_file"].actions()
    named = [window.actions_by_name[name] if name else None for name in CONTEXT_MENU]
    assert window.editor.context_actions[:len(named)] == named


def test_redo_has_ctrl_y_ctrl_shift_z_and_the_platforms_key(window: MainWindow) -> None:
    keys = window.actions_by_name["action_redo"].shortcuts()
    assert keys[:2] == [QKeySequence("Ctrl+Y"), QKeySequence("Ctrl+Shift+Z")]
    assert len(keys) == len(set(k.toString() for k in keys))  # each once
    for key in QKeySequence.keyBindings(QKeySequence.StandardKey.Redo):
        assert key in keys


def test_separators_fall_between_the_groups_of_a_menu(window: MainWindow) -> None:
    edit = window.menus.menus["menu_edit"].actions()
    names = ["-" if a.isSeparator() else a.objectName() for a in edit]
    assert names[:4] == ["action_undo", "action_redo", "-", "action_cut"]
    assert names.index("action_edit_element") == names.index("action_delete") + 2


def test_a_table_slot_runs_the_windows_method(window: MainWindow, qtbot: QtBot) -> None:
    with qtbot.waitSignal(window.language_changed):
        window.actions_by_name["action_language_tr"].trigger()  # argument "tr"
    assert window.language.current == "tr"
    assert window.actions_by_name["action_language_tr"].isChecked()
    assert window.menus.toolbar.windowTitle() == "Ana araç çubuğu"
    with qtbot.waitSignal(window.language_changed):
        window.actions_by_name["action_language_en"].trigger()
    assert not window.actions_by_name["action_language_tr"].isChecked()


def test_grid_actions_are_enabled_only_while_the_ladder_is_shown(
        window: MainWindow, drawer: Drawer) -> None:
    grid = [spec.name for spec in ACTIONS if spec.enabled_when == LADDER_SHOWN]
    assert "action_cut" in grid and "action_zoom_in" in grid
    assert all(window.actions_by_name[name].isEnabled() for name in grid)
    window.actions_by_name["action_show_text"].trigger()
    assert window.pages.currentWidget() is window.text_view
    assert not any(window.actions_by_name[name].isEnabled() for name in grid)
    assert window.actions_by_name["action_show_ladder"].isEnabled()
    window.actions_by_name["action_show_ladder"].trigger()
    assert all(window.actions_by_name[name].isEnabled() for name in grid)


def test_undo_and_redo_follow_the_undo_stack(window: MainWindow, drawer: Drawer) -> None:
    undo, redo = window.actions_by_name["action_undo"], window.actions_by_name["action_redo"]
    assert not undo.isEnabled() and not redo.isEnabled()
    drawer.element(0, 0, 0, "I", "X0.0")
    assert undo.isEnabled() and not redo.isEnabled()
    while undo.isEnabled():  # placing the contact and typing its address
        undo.trigger()
    assert window.editor.networks[0].element_at(0, 0) is None
    assert redo.isEnabled()
    while redo.isEnabled():
        redo.trigger()
    found = window.editor.networks[0].element_at(0, 0)
    assert found is not None and str(getattr(found[1], "address", "")) == "X0.0"


def _qt_base_names(cls: type) -> set[str]:
    names: set[str] = set()
    for base in cls.__mro__:
        if base.__module__.startswith("PySide6"):
            names.update(dir(base))
    return names


def test_no_attribute_of_the_window_or_a_dock_hides_a_qt_method(window: MainWindow) -> None:
    owners: list[QWidget] = [window, *window.findChildren(QDockWidget)]
    hidden = []
    for owner in owners:
        qt = _qt_base_names(type(owner))
        hidden += [f"{type(owner).__name__}.{name}" for name, value in vars(owner).items()
                   if name in qt and not isinstance(value, SignalInstance)]  # Qt's own signals
    assert hidden == []


def test_the_plc_docks_are_typed_fields_built_with_their_dependencies(
        window: MainWindow) -> None:
    docks = window.plc_docks
    assert docks.online.editor is window.editor
    assert docks.time_travel.online is docks.online
    assert docks.time_travel.chart is docks.time_chart
    assert docks.scenario.chart is docks.time_chart
    for dock in (docks.control, docks.diagnostic, docks.bit_display, docks.tables,
                 docks.alarms, docks.time_chart, docks.scenario, docks.force_list):
        assert dock.session is docks.session
        assert window.dockWidgetArea(dock) != 0
    assert window.parameters.session is docks.session


def test_one_retranslation_mechanism(window: MainWindow, qtbot: QtBot) -> None:
    docks = [d for d in window.findChildren(QDockWidget)]
    assert all(isinstance(d, Retranslating) for d in docks), [
        type(d).__name__ for d in docks if not isinstance(d, Retranslating)]
    assert isinstance(window, Retranslating)
    with qtbot.waitSignal(window.language_changed):
        window.set_language("tr")
    plc = window.plc_docks
    assert plc.control.windowTitle() == "PLC KONTROL EKRANI"
    assert plc.force_list.windowTitle() != "Forced and passive"
    assert plc.online.actions["action_plc_online"].text() != "On-line mode"
    assert plc.time_travel.action.text() != "Keep scan history (time travel)"
    assert window.actions_by_name["action_save"].text() == "&Kaydet"
    with qtbot.waitSignal(window.language_changed):
        window.set_language("en")
    assert plc.online.actions["action_plc_online"].text() == "On-line mode"
    assert plc.time_travel.action.text() == "Keep scan history (time travel)"


def test_no_widget_has_its_own_language_change_handler() -> None:
    """LanguageChange is handled once, in gui/retranslate.py (the editor's view and its
    names menu too)."""
    handlers = []
    for path in sorted(GUI.rglob("*.py")):
        if path.name == "retranslate.py":
            continue
        tree = ast.parse(path.read_text("utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.FunctionDef) and node.name in ("changeEvent", "eventFilter"):
                text = ast.get_source_segment(path.read_text("utf-8"), node) or ""
                if "LanguageChange" in text:
                    handlers.append(f"{path.relative_to(GUI)}:{node.name}")
    assert handlers == []
    assert "LanguageChange" in inspect.getsource(Retranslating.changeEvent)
