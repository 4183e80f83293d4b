"""Issue 18 item 1, one path: F9 compiles the console's program and loads it into the PLC,
START / STOP are on the main toolbar and in the PLC menu, compiling while running asks."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QMenu, QToolBar
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.address import parse_address
from ladderworks.core.il import Program, print_program
from ladderworks.gui.docks.plc_control import PlcControlDock
from ladderworks.gui.main_window import MainWindow
from tests.gui.conftest import Answers

EXAMPLE = paths.EXAMPLES / "spindle_override.LAD"


def _action(window: MainWindow, name: str) -> QAction:
    action = window.findChild(QAction, name)
    assert action is not None, name
    return action


def _open(window: MainWindow) -> None:
    assert window.load(EXAMPLE)
    window.plc_docks.session.run.realtime = False  # scans on the virtual clock


def test_f9_loads_the_program_and_toolbar_start_runs_it(qtbot: QtBot,
                                                         window: MainWindow) -> None:
    _open(window)
    session = window.plc_docks.session
    start = _action(window, "action_plc_start")
    assert not start.isEnabled()
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert session.run.engine is not None
    assert "loaded into the PLC" in window.statusBar().currentMessage()
    toolbar = window.findChild(QToolBar, "toolbar_main")
    assert toolbar is not None
    assert start in toolbar.actions()
    assert _action(window, "action_plc_stop") in toolbar.actions()
    menu = window.findChild(QMenu, "menu_plc")
    assert menu is not None and start in menu.actions()
    assert len(window.findChildren(QAction, "action_plc_start")) == 1
    assert start.isEnabled()
    start.trigger()
    assert session.run.running
    output = parse_address("R102.1")
    session.run_scans(2)
    assert session.run.bit(output) == 0
    session.set_bit(parse_address("X2.1"), 1)
    session.run_scans(2)
    assert session.run.bit(output) == 1
    _action(window, "action_plc_stop").trigger()
    assert not session.run.running


def _compiled(window: MainWindow, shown: bool) -> tuple[PlcControlDock, Program]:
    """F9 of the example with the PLC control screen shown or hidden: the screen and the
    program compiled."""
    _open(window)
    control = window.plc_docks.control
    control.setVisible(shown)
    _action(window, "action_compile").trigger()
    program, _diagnostics = window.model.program()
    assert program is not None
    return control, program


def test_the_control_screen_shows_the_loaded_program(window: MainWindow) -> None:
    control, program = _compiled(window, shown=False)
    assert control.loaded.text() == "In the PLC: spindle_override.LAD"
    assert control.indicator.text() == "STOPPED"
    assert control.editor.toPlainText() == ""  # hidden: the text waits until it is shown
    control.show()
    assert control.editor.toPlainText() == print_program(program)
    assert "WRT R102.1" in " ".join(control.editor.toPlainText().split())
    assert control.editor.converted_lines == control.editor.blockCount() > 1


def test_a_shown_control_screen_takes_the_loaded_text_at_once(window: MainWindow) -> None:
    control, program = _compiled(window, shown=True)
    assert control.editor.toPlainText() == print_program(program)
    assert control.editor.converted_lines == control.editor.blockCount()


def test_a_hidden_control_screen_compiles_the_loaded_text(window: MainWindow) -> None:
    control, program = _compiled(window, shown=False)
    assert control.program_text() == print_program(program)
    control.stripe_ms = 0
    assert control.compile().ok
    control.set_text("RD X2.1\n")  # a new text drops a text still waiting
    control.show()
    assert control.editor.toPlainText() == "RD X2.1\n"


def test_compile_while_running_asks_and_reloads(window: MainWindow, answers: Answers) -> None:
    _open(window)
    session = window.plc_docks.session
    compile_action = _action(window, "action_compile")
    compile_action.trigger()
    assert session.start()
    first = session.run.binary
    answers.queue.append("cancel")
    compile_action.trigger()
    assert answers.asked[-1][2] == ["reload", "cancel"]
    assert session.run.binary is first and session.run.running
    answers.queue.append("reload")
    compile_action.trigger()
    assert len(answers.asked) == 2
    assert session.run.binary is not first
    assert session.run.running  # runs on with the new program
    session.set_bit(parse_address("X2.1"), 1)
    session.run_scans(2)
    assert session.run.bit(parse_address("R102.1")) == 1


def test_turkish_texts_of_the_one_path(window: MainWindow) -> None:
    _open(window)
    window.set_language("tr")
    tools = window.findChild(QMenu, "menu_tools")
    assert tools is not None and tools.title() == "&Araçlar"
    _action(window, "action_compile").trigger()
    message = window.statusBar().currentMessage()
    assert message.startswith("Derleme bitti: ") and "PLC'ye yüklendi" in message
    assert "compile" not in message.lower()
    assert window.plc_docks.control.loaded.text() == "PLC'deki program: spindle_override.LAD"


def test_a_coil_mixed_in_the_drawing_names_the_other_network(qtbot: QtBot, window: MainWindow,
                                                               tmp_path) -> None:
    """F9 compiles the drawing, which has no source lines: the warning about a coil written
    by WRT and by SET names the network of the other write, not 'line 0'."""
    path = tmp_path / "mixed.LAD"
    path.write_text("%@3\nN00001:\nRD X0.0\nWRT Y0.0\nN00002:\nRD X0.1\nSET Y0.0\n%\n",
                    "utf-8")
    assert window.load(path)
    window.actions_by_name["action_compile"].trigger()
    tree = window.errors.tree
    texts = [tree.topLevelItem(i).text(2) for i in range(tree.topLevelItemCount())]
    assert texts == ["coil Y0.0 is written by WRT and by SET/RST (also in network 1)"]
    assert tree.topLevelItem(0).text(1).startswith("network 2")


def test_check_and_compile_take_unchanged_networks_as_read(
        qtbot: QtBot, window: MainWindow, monkeypatch: pytest.MonkeyPatch) -> None:
    """F7 and F9 code only the networks that changed since the program was read (each
    other network is its instructions as read, as Save writes it): one network edited, one
    coded again, and the same diagnostics as before the edit."""
    from ladderworks.core.ladder import convert

    coded: list[int] = []
    real = convert.network_to_instructions

    def counting(network: object, index: int, dialect: str) -> object:
        coded.append(index)
        return real(network, index, dialect)  # type: ignore[arg-type]

    monkeypatch.setattr(convert, "network_to_instructions", counting)
    _open(window)
    before = window.check()
    assert coded == []
    window.editor.move_cursor(1, 0, 0)
    window.editor.edits.invert_at_cursor()
    after = window.check()
    assert coded == [1]
    assert [d.code for d in after] == [d.code for d in before]
    coded.clear()
    _action(window, "action_compile").trigger()
    assert coded == [1] and window.plc_docks.session.run.binary is not None
