"""The alarm panel: an A bit raises its AlarmMsg.dat message with its time; RESET clears it."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QRect, Qt
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.gui.docks import alarms as alarm_panel
from ladderworks.gui.docks.alarms import AlarmDock, plc_time_text
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.translation import UiLanguage
from tests.gui.plc_examples import running_session
from tests.gui.test_new_program import file_new
from tests.real_programs import real_programs_dir

MOVING = parse_address("F102.0")  # MV1, X axis moving: the example writes A0.0


@pytest.fixture
def panel(qtbot: QtBot) -> Iterator[tuple[PlcSession, AlarmDock]]:
    """The alarm example running on the virtual clock, with the alarm panel."""
    UiLanguage().apply("en")
    session = running_session("alarm.LAD")
    dock = AlarmDock(session)
    qtbot.addWidget(dock)
    dock.show()
    yield session, dock
    session.stop()


def test_alarm_bit_raises_its_message_and_reset_clears_it(
        qtbot: QtBot, panel: tuple[PlcSession, AlarmDock]) -> None:
    session, dock = panel
    assert dock.alarm_file == alarm_panel.DEFAULT_ALARM_FILE
    assert dock.shown_rows() == []
    session.run_scans(125)  # 1 s
    session.set_bit(MOVING, 1)
    session.run_scans(1)
    qtbot.waitUntil(lambda: len(dock.shown_rows()) == 1)
    (row,) = dock.shown_rows()
    (alarm,) = dock.alarms()
    assert row[:3] == ["000", "A0.0", plc_time_text(alarm.raised_ms)]
    assert alarm.raised_ms == 1000  # the time of the scan that wrote A0.0, from the engine
    assert row[2].startswith("0:01.00")
    assert row[4] == "X EKSENİ HAREKET EDİYOR / X AXIS IS MOVING"
    dock.reset()  # the bit is still 1: the alarm stays, as on the CNC
    assert len(dock.shown_rows()) == 1
    session.set_bit(MOVING, 0)
    session.run_scans(1)
    qtbot.waitUntil(lambda: not dock.alarms()[0].active)
    assert len(dock.shown_rows()) == 1  # shown until RESET
    dock.reset_action.trigger()
    qtbot.waitUntil(lambda: dock.shown_rows() == [])


def test_newest_first(qtbot: QtBot, panel: tuple[PlcSession, AlarmDock]) -> None:
    session, dock = panel
    for byte_bit in ("A1.3", "A0.5"):  # messages 011 and 005, raised 80 ms apart
        session.set_bit(parse_address(byte_bit), 1)
        session.run_scans(10)
    qtbot.waitUntil(lambda: len(dock.shown_rows()) == 2)
    rows = dock.shown_rows()
    assert [row[0] for row in rows] == ["005", "011"]
    assert rows[0][4].startswith("YAĞLAMA YAĞI SEVİYESİ DÜŞÜK")
    assert rows[1][4].startswith("KAPI AÇIK")


def test_alarm_file_action_and_missing_messages(
        qtbot: QtBot, panel: tuple[PlcSession, AlarmDock], tmp_path: Path) -> None:
    session, dock = panel
    mine = tmp_path / "AlarmMsg.dat"
    mine.write_text("000 MY OWN TEXT\nA0.1 SECOND\nbad line here\n", encoding="utf-8")
    assert dock.load_file(mine)
    assert "AlarmMsg.dat: 2 messages" in dock.file_label.text()
    assert "1 lines with problems" in dock.file_label.text()
    assert "line 3" in dock.file_label.toolTip()
    session.set_bit(MOVING, 1)
    session.set_bit(parse_address("A5.0"), 1)  # message 040: not in this file
    session.run_scans(1)
    qtbot.waitUntil(lambda: len(dock.shown_rows()) == 2)
    texts = {row[0]: row[4] for row in dock.shown_rows()}
    assert texts == {"000": "MY OWN TEXT", "040": "(no message 040 in the alarm file)"}
    assert not dock.load_file(tmp_path / "missing.dat")
    assert "Cannot read missing.dat" in dock.file_label.text()


def test_the_window_puts_its_actions_in_the_menus(window: MainWindow) -> None:
    dock = window.plc_docks.alarms
    file_menu = window.menus.menus["menu_file"]
    names = [action.objectName() for action in file_menu.actions()]
    assert "action_alarm_file" in names
    assert names.index("action_alarm_file") < names.index("action_quit")
    view = window.menus.menus["menu_view"]
    assert "action_dock_alarms" in [action.objectName() for action in view.actions()]
    plc = window.menus.menus["menu_plc"]
    assert dock.reset_action in plc.actions()
    assert window.actions_by_name["action_alarm_reset"] is dock.reset_action
    assert dock.objectName() == "alarmDock" and dock.isVisible()  # shown by default


SPINDLE = "%@3\nRD X0.0\nWRT A0.0\n%\n%@4\nA0.0\t1000 SPINDLE ALARM\n%\n"
PLAIN = "%@3\nRD X0.0\nWRT A0.0\n%\n"
A0 = parse_address("A0.0")


def _f9(qtbot: QtBot, window: MainWindow) -> None:
    """PLC › Compile (F9): the console's program into the PLC."""
    with qtbot.waitSignal(window.plc_docks.session.program_loaded, timeout=30_000):
        window.actions_by_name["action_compile"].trigger()


def test_the_texts_are_the_loaded_programs_until_another_is_loaded(
        qtbot: QtBot, window: MainWindow, tmp_path: Path) -> None:
    dock = window.plc_docks.alarms
    table = window.plc_docks.session.run.alarm_table
    sample = table.text_for(A0)
    assert sample and "SPINDLE" not in sample  # the sample AlarmMsg.dat before any load
    spindle, plain = tmp_path / "spindle.LAD", tmp_path / "plain.LAD"
    spindle.write_text(SPINDLE, encoding="utf-8")
    plain.write_text(PLAIN, encoding="utf-8")
    assert window.load(spindle)
    assert dock.session.run.alarm_table.text_for(A0) == sample  # opened, not loaded: unchanged
    _f9(qtbot, window)
    assert dock.program_messages == 1
    assert dock.session.run.alarm_table.text_for(A0) == "1000 SPINDLE ALARM"
    file_new(qtbot, window, None)  # File › New: the PLC still runs it
    assert dock.session.run.alarm_table.text_for(A0) == "1000 SPINDLE ALARM"
    assert window.load(plain)  # File › Open of a program without messages
    assert dock.session.run.alarm_table.text_for(A0) == "1000 SPINDLE ALARM"
    assert "(%@4): 1" in dock.file_label.text()
    _f9(qtbot, window)  # now the PLC has a program without `%@4`: the sample file's texts
    assert dock.program_messages == 0
    assert dock.session.run.alarm_table.text_for(A0) == sample


def test_s41_alarm_keeps_its_programs_text_after_file_new(qtbot: QtBot, window: MainWindow
                                                         ) -> None:
    assert window.load(real_programs_dir() / "FANUC_STUDER_S41_F036.txt")
    _f9(qtbot, window)
    a05 = parse_address("A0.5")
    table = window.plc_docks.session.run.alarm_table
    assert window.plc_docks.session.run.alarm_table.text_for(a05) == "1999 STUDER OPTIONS NOT SET"
    file_new(qtbot, window, None)
    assert window.plc_docks.session.run.alarm_table is table
    assert table.text_for(a05) == "1999 STUDER OPTIONS NOT SET"


def test_turkish(qtbot: QtBot, panel: tuple[PlcSession, AlarmDock]) -> None:
    _session, dock = panel
    language = UiLanguage()
    try:
        language.apply("tr")
        qtbot.waitUntil(lambda: dock.windowTitle() == "ALARMLAR")
        assert dock.reset_action.text() == "RESET"
        assert dock.tree.headerItem().text(4) == "Mesaj"
    finally:
        language.apply("en")


def test_a_narrow_dock_leaves_the_message_readable(
        qtbot: QtBot, panel: tuple[PlcSession, AlarmDock]) -> None:
    session, dock = panel
    dock.resize(290, 170)  # the dock's width on a 1024×600 panel
    session.set_bit(MOVING, 1)
    session.run_scans(1)
    qtbot.waitUntil(lambda: len(dock.shown_rows()) == 1)
    tree = dock.tree
    qtbot.waitUntil(lambda: tree.viewport().width() < 290)
    header = tree.header()
    shown = [column for column in range(alarm_panel.COLUMNS) if not tree.isColumnHidden(column)]
    assert sum(header.sectionSize(column) for column in shown) <= tree.viewport().width()
    message = header.sectionSize(alarm_panel.MESSAGE)
    metrics = tree.fontMetrics()
    assert message >= metrics.averageCharWidth() * alarm_panel.MESSAGE_CHARS
    item = tree.topLevelItem(0)
    text = item.text(alarm_panel.MESSAGE)
    wrapped = metrics.boundingRect(QRect(0, 0, message - 8, 10000), Qt.TextFlag.TextWordWrap,
                                   text)
    assert tree.visualItemRect(item).height() >= wrapped.height()  # every line shows
    assert item.toolTip(alarm_panel.MESSAGE) == text == "X EKSENİ HAREKET EDİYOR / X AXIS IS MOVING"
    assert "Seen at" in item.toolTip(2)  # the clock, when its column is hidden
    dock.resize(900, 170)
    qtbot.waitUntil(lambda: not any(tree.isColumnHidden(c) for c in range(alarm_panel.COLUMNS)))
    assert header.sectionSize(alarm_panel.MESSAGE) > 500  # a wide dock: all of it on one line
