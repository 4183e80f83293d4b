"""On-line mode follows the program in the PLC (issue 38, item 4): a LADDER-III program goes
on-line, another program's drawing drops the last one's power flow, and loading another
program asks what becomes of the forces."""

from __future__ import annotations

from pathlib import Path

from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.address import parse_address
from ladderworks.gui.docks.power_overlay import PowerOverlay
from ladderworks.gui.main_window import MainWindow
from tests.gui.conftest import Answers
from tests.gui.plc_docks_help import plc_docks
from tests.gui.test_new_program import file_new

SPINDLE = paths.EXAMPLES / "spindle_override.LAD"
DELTA_TIMER = paths.EXAMPLES / "delta" / "timer_t0.txt"
# a LADDER-III network as S41_F036 has it: G1010 is in the 30i's map, not in the seed's
LADDER_III = "%@3\nN00000:\nRD R9091.1\nSUB 44\nG10\nG1010\nN00001:\nRD X0.0\nWRT Y0.0\n%\n"


def _f9(qtbot: QtBot, window: MainWindow) -> None:
    with qtbot.waitSignal(window.plc_docks.session.program_loaded, timeout=20_000):
        window.actions_by_name["action_compile"].trigger()


def _online(window: MainWindow) -> bool:
    window.actions_by_name["action_plc_start"].trigger()
    window.plc_docks.online.actions["action_plc_online"].trigger()
    return window.plc_docks.online.online


def _overlays(window: MainWindow) -> list[PowerOverlay]:
    return [item for item in window.editor.scene().items() if isinstance(item, PowerOverlay)]


def test_a_ladder_iii_program_goes_on_line_after_f9_and_start(
        qtbot: QtBot, window: MainWindow, tmp_path: Path) -> None:
    path = tmp_path / "level1.txt"
    path.write_text(LADDER_III, encoding="utf-8")
    assert window.load(path)
    plc_docks(window)
    _f9(qtbot, window)
    assert _online(window)  # was: "the drawing is not the program in the PLC"
    window.plc_docks.session.step(16)
    window.plc_docks.online.refresh()
    assert _overlays(window)


def test_another_program_takes_the_last_ones_power_flow_away(
        qtbot: QtBot, window: MainWindow, answers: Answers) -> None:
    assert window.load(DELTA_TIMER)
    plc_docks(window)
    _f9(qtbot, window)
    assert _online(window)
    window.plc_docks.session.step(16)
    window.plc_docks.online.refresh()
    assert _overlays(window)  # T0=0 beside the TMR box, green rails
    assert window.load(SPINDLE)
    assert not window.plc_docks.online.online
    assert not _overlays(window)
    answers.queue.append("reload")  # the PLC runs the Delta program
    _f9(qtbot, window)
    assert _online(window)
    window.plc_docks.online.refresh()
    assert _overlays(window)
    file_new(qtbot, window, None)  # File › New, OK
    assert not window.plc_docks.online.online
    assert not _overlays(window)  # no stray labels nor rails on the empty page


def test_loading_another_program_asks_about_the_forces(
        qtbot: QtBot, window: MainWindow, answers: Answers) -> None:
    assert window.load(SPINDLE)
    session = plc_docks(window).session
    _f9(qtbot, window)
    session.force(parse_address("X2.1"), 1)
    _f9(qtbot, window)  # the same program again (edit, F9): the forces stay, no question
    assert not answers.asked
    assert [entry.kind for entry in session.run.forces()] == ["force"]
    assert window.load(DELTA_TIMER)
    answers.queue.append("keep")
    _f9(qtbot, window)
    assert len(answers.asked) == 1 and "1 signal(s) are forced" in answers.asked[0][1]
    assert [str(entry.address) for entry in session.run.forces()] == ["X2.1"]
    assert window.load(SPINDLE)
    answers.queue.append("release")
    _f9(qtbot, window)
    assert len(answers.asked) == 2
    assert session.run.forces() == []
    assert window.plc_docks.force_list.table.rowCount() == 0
