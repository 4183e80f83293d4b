"""Autosave and recovery: unsaved work is copied, and offered back after a crash or a kill."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import threading
from datetime import datetime
from pathlib import Path

import pytest
from PySide6.QtCore import QDateTime, QLocale
from pytestqt.qtbot import QtBot

from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.recovery import INTERVAL_VARIABLE, recovery_folder
from ladderworks.gui.settings import Settings
from ladderworks.gui.translation import UiLanguage
from ladderworks.paths import CHECKOUT, EXAMPLES
from tests.gui.conftest import Answers, _forget_changes
from tests.gui.test_file_form import _invert_first_contact, _save

SOURCE = (EXAMPLES / "or_single.LAD").read_bytes()
SAVED_AT = "2026-11-24T03:00:00+00:00"


def _copies(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.glob("*") if not p.name.endswith(".lock"))


def test_unsaved_work_is_copied_and_removed_on_save(window: MainWindow, qtbot: QtBot,
                                                    tmp_path: Path) -> None:
    path = tmp_path / "machine.LAD"
    path.write_bytes(SOURCE)
    assert window.load(path)
    _invert_first_contact(window)
    with qtbot.waitSignal(window.autosaver.copied, timeout=10000) as copied:
        window.autosaver.pause.setInterval(10)  # the pause after a structural edit
        window.actions_by_name["action_invert"].trigger()
        window.actions_by_name["action_invert"].trigger()
    copy = Path(copied.args[0])
    assert copy.parent == recovery_folder()
    assert b"RD.NOT F9.6" in copy.read_bytes()
    meta = json.loads(copy.with_suffix(".json").read_text("utf-8"))
    assert meta["original"] == str(path) and meta["saved_at"]
    _save(window, qtbot)
    assert _copies(recovery_folder()) == []  # a clean save removes the copy


def test_the_copy_goes_when_the_window_closes_cleanly(window: MainWindow, qtbot: QtBot,
                                                      tmp_path: Path) -> None:
    window.editor.move_cursor(0, 0, 0)
    window.load(EXAMPLES / "or_single.LAD")
    _invert_first_contact(window)
    with qtbot.waitSignal(window.autosaver.copied, timeout=10000):
        window.autosaver.save_now()
    assert len(_copies(recovery_folder())) == 2  # the program and its description
    _forget_changes(window)
    window.close()
    assert _copies(recovery_folder()) == []
    assert list(recovery_folder().glob("*.lock")) == []


def _second_window(qtbot: QtBot, settings: Settings) -> MainWindow:
    language = UiLanguage()
    language.apply("en")
    win = MainWindow(settings, language)
    qtbot.addWidget(win, before_close_func=_forget_changes)
    return win


def test_kill_after_an_unsaved_edit_then_recover(qtbot: QtBot, window: MainWindow,
                                                 answers: Answers, settings: Settings,
                                                 data_folder: Path, tmp_path: Path) -> None:
    path = tmp_path / "machine.LAD"
    path.write_bytes(SOURCE)
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", XDG_DATA_HOME=str(data_folder),
               XDG_CONFIG_HOME=str(tmp_path / "config"), PYTHONPATH=str(CHECKOUT))
    env[INTERVAL_VARIABLE] = "200"
    log = tmp_path / "child.log"
    with log.open("w") as errors, subprocess.Popen(
            [sys.executable, "-m", "tests.gui.recovery_child", str(path)], cwd=CHECKOUT,
            env=env, stdout=subprocess.PIPE, stderr=errors, text=True) as child:
        watchdog = threading.Timer(60, child.kill)  # a child that never copies fails the test
        watchdog.start()
        try:
            assert child.stdout is not None
            line = child.stdout.readline()  # blocks until the child has written its copy
            assert line.startswith("COPIED "), (line, log.read_text())
            os.kill(child.pid, signal.SIGKILL)
            assert child.wait() == -signal.SIGKILL
        finally:
            watchdog.cancel()
            child.kill()
    assert path.read_bytes() == SOURCE  # the edit was never saved

    answers.queue = ["restore"]
    restored = _second_window(qtbot, settings)
    assert restored.offer_recovery()
    title, text, keys = answers.asked[0]
    assert title == "Recover unsaved work"
    assert keys == ["restore", "discard", "later"] and str(path) in text
    assert restored.path == path and restored.is_modified()
    program = restored.editor.program()[0]
    assert program is not None and program.instructions()[0].name == "RD.NOT"  # the edit
    with qtbot.waitSignal(restored.file_saved):
        restored.actions_by_name["action_save"].trigger()
    assert b"RD.NOT F9.6" in path.read_bytes()
    assert _copies(recovery_folder()) == []


@pytest.mark.parametrize("answer", ["discard", "later"])
def test_a_recovered_copy_can_be_discarded_or_kept_for_later(
        qtbot: QtBot, window: MainWindow, answers: Answers, settings: Settings,
        tmp_path: Path, answer: str) -> None:
    folder = recovery_folder()
    folder.mkdir(parents=True)
    (folder / "1-dead.LAD").write_bytes(SOURCE)
    (folder / "1-dead.json").write_text(json.dumps(
        {"original": None, "saved_at": SAVED_AT, "disk": None}))
    answers.queue = [answer]
    assert not window.offer_recovery()
    moment = QDateTime.fromSecsSinceEpoch(int(datetime.fromisoformat(SAVED_AT).timestamp()))
    assert "Untitled" in answers.asked[0][1]  # what ...
    assert QLocale().toString(moment, QLocale.FormatType.ShortFormat) in answers.asked[0][1]
    assert not window.is_modified()
    expected = [] if answer == "discard" else ["1-dead.LAD", "1-dead.json"]
    assert _copies(folder) == expected


def test_a_changed_pmc_parameter_is_copied_and_restored(qtbot: QtBot, window: MainWindow,
                                                        answers: Answers, settings: Settings,
                                                        tmp_path: Path) -> None:
    from ladderworks.core.address import parse_address

    path = tmp_path / "machine.LAD"
    path.write_bytes(SOURCE)
    assert window.load(path)
    window.autosaver.pause.setInterval(10)
    with qtbot.waitSignal(window.autosaver.copied, timeout=10000) as copied:
        window.parameters.session.set_parameter(parse_address("D10"), 42)
    assert "D10" in Path(copied.args[0] + ".prm").read_text("utf-8")
    # this window's session is gone as if killed: its lock is released, its copy stays
    window.recovery._lock.unlock()  # type: ignore[union-attr]
    answers.queue = ["restore"]
    restored = _second_window(qtbot, settings)
    assert restored.offer_recovery()
    assert restored.parameters.session.run.parameters.get(parse_address("D10")) == 42
    assert restored.is_modified() and restored.path == path
