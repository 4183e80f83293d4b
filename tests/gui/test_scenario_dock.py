"""PLC › Run scenario (results at their lines, jump to the time chart) and Record scenario."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QMenu
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.plc.scenario import parse_scenario, run_scenario
from ladderworks.core.plc.session import PlcRun
from ladderworks.gui.docks.scenario import RECORD, RUN, ScenarioDock
from ladderworks.gui.docks.time_chart import TimeChartDock
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.translation import UiLanguage
from tests.gui.plc_examples import running_session, running_text

LATCH = "%@3\nRD X2.1\nOR Y0.0\nAND.NOT X2.2\nWRT Y0.0\nRD X2.3\nWRT Y0.1\nMOVB X40 Y1\n%\n"


def docks(qtbot: QtBot, session: PlcSession) -> tuple[ScenarioDock, TimeChartDock]:
    UiLanguage().apply("en")
    chart = TimeChartDock(session)
    dock = ScenarioDock(session, chart=chart)
    qtbot.addWidget(chart)
    qtbot.addWidget(dock)
    return dock, chart


def test_run_shows_each_check_and_jumps_to_the_failing_time(qtbot: QtBot,
                                                           tmp_path: Path) -> None:
    session = running_session("timer_relay.LAD")
    dock, chart = docks(qtbot, session)
    path = tmp_path / "relay.csv"
    path.write_text("PMC SIGNAL DATA\nSET,0,T0,1000,DWORD\nSET,0,R1.4,1\n"
                    "EXPECT,952,R1.7,0\nEXPECT,8,R1.7,0\n")
    with qtbot.waitSignal(dock.finished) as blocker:
        dock.run_file(path)
    result = blocker.args[0]
    assert [c.passed for c in result.checks] == [True, False]
    rows = [dock.checks.topLevelItem(i) for i in range(dock.checks.topLevelItemCount())]
    assert [(r.text(0), r.text(5)) for r in rows] == [("4", "passed"), ("5", "FAILED")]
    assert "1 of 2 checks failed" in dock.message.text()
    assert dock.failing_times() == [960]
    assert chart.time_cursor.value() == 960  # the chart's cursor is at the first failure
    chart.set_cursor(0)
    dock.checks.itemActivated.emit(rows[1], 0)
    assert chart.time_cursor.value() == 960
    assert chart.cursor_values()["R1.7"] == 1  # the chart shows the scenario's own run
    assert session.run.engine is not None and session.run.engine.now_ms == 0  # live PLC untouched
    session.stop()


def test_record_while_forcing_then_replay_gives_the_same_outputs(qtbot: QtBot) -> None:
    session = running_text(LATCH)
    dock, _chart = docks(qtbot, session)
    dock.start_recording()
    assert dock.actions_by_name[RECORD].isChecked()
    session.run_scans(3)
    session.set_bit(parse_address("X2.1"), 1)
    session.run_scans(2)
    session.set_bit(parse_address("X2.1"), 0)
    session.force(parse_address("X2.3"), 1)
    session.write(parse_address("X40"), 0x33)
    session.run_scans(5)
    session.force(parse_address("X2.2"), 1)
    session.run_scans(2)
    session.release(parse_address("X2.2"))
    session.run_scans(2)
    text = dock.stop_recording()
    assert "FORCE,0,X2.3,1" in text and "RELEASE," in text
    assert session.run.engine is not None
    live_y = bytes(session.run.memory.areas[parse_address("Y0").area])
    with qtbot.waitSignal(dock.finished) as blocker:
        dock.run_text(text, "recorded.csv")
    assert blocker.args[0].passed, blocker.args[0].failures()
    replay = PlcRun(period_ms=session.run.period_ms)
    assert session.run.binary is not None and replay.load(session.run.binary) == []
    run_scenario(replay, parse_scenario(text))
    assert bytes(replay.memory.areas[parse_address("Y0").area]) == live_y
    assert replay.engine is not None and replay.engine.now_ms == session.run.engine.now_ms
    session.stop()


def test_plc_menu_has_run_and_record(window: MainWindow) -> None:
    menu = window.findChild(QMenu, "menu_plc")
    assert menu is not None
    names = [action.objectName() for action in menu.actions()]
    assert RUN in names and RECORD in names
    assert isinstance(window.plc_docks.others["scenario"], ScenarioDock)


def test_the_result_column_is_in_view_in_a_narrow_dock(qtbot: QtBot) -> None:
    """The columns fit their contents, so a 420-px dock shows passed / FAILED without
    scrolling (100-px columns pushed it out of view even at 1920×1080); an error line of
    the file spans the row rather than widening the first column."""
    session = running_session("spindle_override.LAD")
    dock, _chart = docks(qtbot, session)
    dock.resize(420, 300)
    dock.show()
    qtbot.waitExposed(dock)
    with qtbot.waitSignal(dock.finished):
        dock.run_text("PMC SIGNAL DATA\nSET,0,X2.1,1\nEXPECT,16,R102,2\nNOT A LINE\n")
    tree = dock.checks
    header = tree.header()
    last = header.count() - 1
    right = header.sectionViewportPosition(last) + header.sectionSizeHint(last)
    assert right <= tree.viewport().width(), (right, tree.viewport().width())
    for row in range(tree.topLevelItemCount()):
        item = tree.topLevelItem(row)
        if item.data(0, Qt.ItemDataRole.UserRole) is None:  # an error of the file
            assert item.isFirstColumnSpanned()
    session.stop()


def test_a_bad_line_of_the_scenario_is_said_in_turkish(qtbot: QtBot) -> None:
    """The file's problems are listed in the UI language with their line, not as the CLI's
    English `name:4:1: scenario-command ...`."""
    session = running_session("spindle_override.LAD")
    dock, _chart = docks(qtbot, session)
    language = UiLanguage()  # kept: its translators live as long as it does
    language.apply("tr")
    try:
        with qtbot.waitSignal(dock.finished):
            dock.run_text("PMC SIGNAL DATA\nSET,0,X2.1,1\nNOT A LINE\n")
        text = dock.checks.topLevelItem(0).text(0)
        assert text.startswith("satır 3")
        assert "scenario-command" not in text and "unknown command" not in text
        assert "NOT A LINE" in text
    finally:
        language.apply("en")
        session.stop()


def test_a_recording_names_the_plc_program_and_a_run_warns_of_another(
        qtbot: QtBot, tmp_path: Path) -> None:
    session = running_text(LATCH)
    dock, _chart = docks(qtbot, session)
    dock.program_path = tmp_path / "programs" / "latch.LAD"
    dock.start_recording()
    session.set_bit(parse_address("X2.1"), 1)
    session.run_scans(2)
    text = dock.stop_recording()
    saved = tmp_path / "scenarios" / "latch.scenario.csv"
    saved.parent.mkdir()
    assert dock.save(saved, text)
    lines = saved.read_text(encoding="utf-8").splitlines()
    assert lines[:2] == ["PMC SIGNAL DATA", "PROGRAM,../programs/latch.LAD"]
    with qtbot.waitSignal(dock.finished) as blocker:
        dock.run_file(saved)
    assert blocker.args[0].passed  # no warning: the same program
    assert dock.checks.topLevelItemCount() == len(blocker.args[0].checks)
    dock.program_path = tmp_path / "programs" / "other.LAD"
    language = UiLanguage()
    language.apply("tr")
    try:
        with qtbot.waitSignal(dock.finished) as blocker:
            dock.run_file(saved)
        assert blocker.args[0].passed  # a warning: it runs on the PLC's program
        text = dock.checks.topLevelItem(0).text(0)
        assert text.startswith("satır 2") and "PLC'ye yüklenmiş" in text, text
    finally:
        language.apply("en")
        session.stop()
