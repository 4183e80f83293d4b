"""On-line mode in the console: power flow on the drawing, disable / force, the force list."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.address import parse_address
from ladderworks.gui.main_window import MainWindow
from tests.gui.plc_docks_help import plc_docks, set_switch

SPINDLE = paths.EXAMPLES / "spindle_override.LAD"


def online_window(window: MainWindow):
    """The spindle program drawn, compiled from the console, started and on-line."""
    assert window.load(SPINDLE)
    docks = plc_docks(window)
    docks.control.stripe_ms = 0
    assert docks.control.take_console_program() and docks.control.compile().ok
    assert docks.session.start()
    docks.online.actions["action_plc_online"].trigger()
    assert docks.online.online
    return docks


def test_online_shows_power_on_the_console_drawing(qtbot: QtBot, window: MainWindow) -> None:
    docks = online_window(window)
    set_switch(docks.session, 0)
    docks.session.step(8)
    power = docks.online.live.overlays[0].power  # RD.NOT X2.1 / AND.NOT X2.3 / AND.NOT X2.5
    assert {(0, 0), (0, 1), (0, 2)} <= power.closed
    assert power.coils == {(0, window.editor.networks[0].coil_column)}
    set_switch(docks.session, 1)
    docks.session.step(8)
    assert docks.online.live.overlays[0].power.coils == set()


def test_disable_and_force_change_the_engine_and_the_force_list(qtbot: QtBot,
                                                                window: MainWindow) -> None:
    docks = online_window(window)
    session, online, force_list = docks.session, docks.online, docks.force_list
    set_switch(session, 0)
    session.step(8)
    assert session.run.bit(parse_address("R102.0")) == 1
    window.editor.cursor_cell = (0, 0, 0)  # select RD.NOT X2.1
    op = online.disable_selected()
    assert op == 0
    session.step(8)
    assert session.run.bit(parse_address("R102.0")) == 0  # the passive contact is open
    assert force_list.table.rowCount() == 1
    assert force_list.table.item(0, 0).text() == "PASSIVE"
    assert "RD.NOT X2.1" in force_list.table.item(0, 1).text()
    assert (0, 0) in online.live.overlays[0].power.disabled
    online.force_selected(1)  # force X2.1 = 1: the switch reads position 1
    assert force_list.table.rowCount() == 2
    assert force_list.table.item(0, 0).text() == "FORCED"
    assert force_list.table.item(0, 1).text() == "X2.1 FP_Din_1"  # the address and its name
    assert force_list.table.item(0, 2).text() == "1"
    assert (0, 0) in online.live.overlays[0].power.forced
    button = force_list.table.cellWidget(1, 3)
    assert isinstance(button, QPushButton)
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)  # one click: active again
    session.step(8)
    bit = session.run.bit
    assert bit(parse_address("R102.1")) == 1 and bit(parse_address("R102.0")) == 0
    assert force_list.table.rowCount() == 1
    qtbot.mouseClick(force_list.table.cellWidget(0, 3), Qt.MouseButton.LeftButton)
    session.step(8)
    assert force_list.table.rowCount() == 0
    assert session.run.bit(parse_address("R102.0")) == 1  # X2.1 back to the switch's 0


def test_editing_takes_the_view_off_line(qtbot: QtBot, window: MainWindow) -> None:
    docks = online_window(window)
    messages: list[str] = []
    window.editor.message.connect(messages.append)
    window.editor.cursor_cell = (0, 0, 0)
    window.actions_by_name["action_invert"].trigger()  # the NOT tool on RD.NOT X2.1
    assert window.editor.undo_stack.count() == 1
    assert not docks.online.online
    assert not docks.online.actions["action_plc_online"].isChecked()
    assert any("Off-line" in m for m in messages)
    docks.online.actions["action_plc_online"].trigger()  # the drawing differs now
    assert not docks.online.online
    assert "not the program in the PLC" in messages[-1]


def test_the_release_buttons_are_in_view_in_a_narrow_dock(qtbot: QtBot) -> None:
    """The force list in its default place on a 1024×600 panel (some 290 px, in Turkish): each
    row's Release button is in view; the signal column gives way (its text elided)."""
    from ladderworks.core.address import parse_address
    from ladderworks.gui.docks.force_list import ForceListDock
    from ladderworks.gui.translation import UiLanguage
    from tests.gui.plc_examples import running_session

    language = UiLanguage()
    language.apply("tr")
    session = running_session("spindle_override.LAD")
    try:
        dock = ForceListDock(session)
        qtbot.addWidget(dock)
        dock.resize(290, 240)
        dock.show()
        qtbot.waitExposed(dock)
        session.force(parse_address("X2.1"), 1)
        session.force(parse_address("G30.0"), 0)
        table = dock.table
        qtbot.waitUntil(lambda: table.rowCount() == 2)
        for row in range(2):
            button = table.cellWidget(row, 3)
            right = button.mapTo(table.viewport(), button.rect().topRight()).x()
            qtbot.waitUntil(lambda b=button: b.isVisible())
            assert 0 < right <= table.viewport().width(), (right, table.viewport().width())
            assert button.width() >= button.fontMetrics().horizontalAdvance(button.text())
        assert table.columnWidth(0) >= table.fontMetrics().horizontalAdvance("ZORLANMIŞ")
    finally:
        language.apply("en")
        session.stop()
