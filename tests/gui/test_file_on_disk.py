"""The file on disk: changed outside, read-only, symlinks, file modes, atomic saves."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from ladderworks.gui import file_dialogs
from ladderworks.gui.files import default_mode
from ladderworks.gui.main_window import MainWindow
from ladderworks.paths import EXAMPLES
from tests.gui.conftest import Answers
from tests.gui.test_file_form import _invert_first_contact, _save

SOURCE = (EXAMPLES / "or_single.LAD").read_bytes()
OTHER = SOURCE.replace(b"OR R11.1", b"OR R11.2")  # what another program writes


def _program(tmp_path: Path, name: str = "machine.LAD") -> Path:
    path = tmp_path / name
    path.write_bytes(SOURCE)
    return path


def _changed_outside(window: MainWindow, qtbot: QtBot, path: Path) -> None:
    """Another program rewrites the file; the window notices."""
    with qtbot.waitSignal(window.document.changed_outside, timeout=10000):
        path.write_bytes(OTHER)
    assert "changed by another program" in window.statusBar().currentMessage()


def _choose_in_save_dialog(monkeypatch: pytest.MonkeyPatch, target: Path) -> None:
    monkeypatch.setattr(file_dialogs, "save_file_name",
                        lambda *_a, **_k: str(target))


@pytest.mark.parametrize("answer", ["cancel", "keep", "reload", "save_as"])
def test_a_file_changed_outside_asks_before_anything_is_written(
        window: MainWindow, qtbot: QtBot, answers: Answers, tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch, answer: str) -> None:
    path = _program(tmp_path)
    assert window.load(path)
    _invert_first_contact(window)
    _changed_outside(window, qtbot, path)
    other = tmp_path / "mine.LAD"
    _choose_in_save_dialog(monkeypatch, other)
    answers.queue = [answer]
    result = window.save()
    assert answers.asked[0][2] == ["reload", "keep", "save_as", "cancel"]
    assert "machine.LAD" in answers.asked[0][1]
    if answer == "cancel":
        assert not result and path.read_bytes() == OTHER and window.is_modified()
    elif answer == "keep":
        assert result and b"RD.NOT F9.6" in path.read_bytes()
        assert not window.is_modified()
    elif answer == "reload":
        assert not result and path.read_bytes() == OTHER
        assert not window.is_modified()
        program = window.editor.program()[0]
        assert program is not None
        assert "R11.2" in [str(i.operand) for i in program.instructions()]
    else:
        assert result and path.read_bytes() == OTHER
        assert b"RD.NOT F9.6" in other.read_bytes() and window.path == other
    assert len(answers.asked) == 1


def test_a_file_touched_but_not_changed_asks_nothing(window: MainWindow, qtbot: QtBot,
                                                     tmp_path: Path) -> None:
    path = _program(tmp_path)
    assert window.load(path)
    _invert_first_contact(window)
    os.utime(path, (1, 1))
    _save(window, qtbot)  # no question (the window fixture fails on one)
    assert b"RD.NOT F9.6" in path.read_bytes()


def test_a_read_only_file_is_never_replaced(window: MainWindow, qtbot: QtBot,
                                            answers: Answers, tmp_path: Path,
                                            monkeypatch: pytest.MonkeyPatch) -> None:
    path = _program(tmp_path)
    path.chmod(0o444)
    assert window.load(path)
    _invert_first_contact(window)
    answers.queue = ["cancel"]
    window.actions_by_name["action_save"].trigger()
    assert "read-only" in answers.asked[0][1] and answers.asked[0][2] == ["save_as", "cancel"]
    assert path.read_bytes() == SOURCE and stat.S_IMODE(path.stat().st_mode) == 0o444
    assert window.is_modified()
    other = tmp_path / "writable.LAD"
    _choose_in_save_dialog(monkeypatch, other)
    answers.queue = ["save_as"]
    with qtbot.waitSignal(window.file_saved):
        window.actions_by_name["action_save"].trigger()
    assert path.read_bytes() == SOURCE
    assert b"RD.NOT F9.6" in other.read_bytes() and window.path == other


def test_saving_through_a_symlink_keeps_the_link(window: MainWindow, qtbot: QtBot,
                                                 tmp_path: Path) -> None:
    (tmp_path / "real").mkdir()
    target = _program(tmp_path / "real")
    target.chmod(0o640)
    link = tmp_path / "link.LAD"
    link.symlink_to(target)
    assert window.load(link)
    _invert_first_contact(window)
    _save(window, qtbot)
    assert link.is_symlink() and link.resolve() == target.resolve()
    assert b"RD.NOT F9.6" in target.read_bytes()
    assert stat.S_IMODE(target.stat().st_mode) == 0o640  # an existing file keeps its mode
    assert sorted(p.name for p in target.parent.iterdir()) == ["machine.LAD"]  # no temporary


def test_a_new_file_gets_the_normal_mode(window: MainWindow, qtbot: QtBot, tmp_path: Path,
                                         monkeypatch: pytest.MonkeyPatch) -> None:
    old = os.umask(0o022)
    try:
        assert default_mode() == 0o644
        target = tmp_path / "new.LAD"
        _choose_in_save_dialog(monkeypatch, target)
        window.editor.move_cursor(0, 0, 0)
        with qtbot.waitSignal(window.file_saved):
            window.actions_by_name["action_save"].trigger()  # untitled: Save As
        assert stat.S_IMODE(target.stat().st_mode) == 0o644
    finally:
        os.umask(old)


def test_the_questions_speak_turkish(window: MainWindow, answers: Answers,
                                     tmp_path: Path) -> None:
    path = _program(tmp_path)
    path.chmod(0o444)
    assert window.load(path)
    window.set_language("tr")
    _invert_first_contact(window)
    answers.queue = ["cancel"]
    window.actions_by_name["action_save"].trigger()
    title, text, _keys = answers.asked[0]
    assert title == "Salt okunur dosya" and "salt okunurdur" in text
    assert answers.labels[0] == ["Farklı Kaydet...", "İptal"]
    assert path.read_bytes() == SOURCE


def test_export_never_replaces_a_read_only_file(window: MainWindow, tmp_path: Path) -> None:
    assert window.load(EXAMPLES / "or_single.LAD")
    target = tmp_path / "out.MOD"
    target.write_bytes(b"old")
    target.chmod(0o444)
    assert not window.export_mod(target)
    assert target.read_bytes() == b"old" and "read-only" in window.last_warning
