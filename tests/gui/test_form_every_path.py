"""A program's form (encoding, BOM, line ends) survives every path to disk (issue 30, item 3):
a ladder edit; a text-view edit shown as ladder; a text-view edit saved from the text view;
Save As; an autosave copy restored."""

from __future__ import annotations

from datetime import datetime
from pathlib import Path

import pytest
from PySide6.QtCore import QLockFile
from PySide6.QtGui import QTextCursor
from pytestqt.qtbot import QtBot

from ladderworks.gui import file_dialogs
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.recovery import RecoveredCopy
from ladderworks.paths import EXAMPLES
from tests.gui.test_file_form import _invert_first_contact, _save

TURKISH = (EXAMPLES / "or_single.LAD").read_text("utf-8")

# (name, BOM, encoding, line end)
FORMS = [
    ("lf", b"", "utf-8", "\n"),
    ("crlf", b"\xef\xbb\xbf", "utf-8", "\r\n"),
    ("utf16", b"\xff\xfe", "utf-16-le", "\r\n"),
]
PATHS = ["ladder-edit", "text-then-ladder", "text-saved", "save-as", "recovery"]


def _file(tmp_path: Path, bom: bytes, encoding: str, newline: str) -> Path:
    path = tmp_path / "program.LAD"
    path.write_bytes(bom + TURKISH.replace("\n", newline).encode(encoding))
    return path


def _edit_a_line_in_the_text_view(window: MainWindow) -> None:
    """F6, then change `RD F9.6` (the first contact) to `RD.NOT F9.6` as typed."""
    window.actions_by_name["action_show_text"].trigger()
    assert window.model.showing_text
    document = window.text_view.document()
    found = document.find("RD F9.6")
    assert not found.isNull()
    found.insertText("RD.NOT F9.6")
    cursor = QTextCursor(found)
    window.text_view.setTextCursor(cursor)
    assert document.isModified()


def _assert_form(data: bytes, bom: bytes, encoding: str, newline: str) -> None:
    assert data.startswith(bom)
    text = data[len(bom):].decode(encoding)
    assert "RD.NOT F9.6" in text and "ÇÖZÜCÜ" in text  # the edit, the Turkish comment
    lines = text.count("\n")
    assert lines > 3
    if newline == "\r\n":
        assert text.count("\r\n") == lines, "every line ends in CR LF"
    else:
        assert "\r" not in text


@pytest.mark.parametrize("path_to_disk", PATHS)
@pytest.mark.parametrize(("form", "bom", "encoding", "newline"), FORMS,
                         ids=[form[0] for form in FORMS])
def test_the_files_form_survives(window: MainWindow, qtbot: QtBot, tmp_path: Path,
                                 monkeypatch: pytest.MonkeyPatch, path_to_disk: str,
                                 form: str, bom: bytes, encoding: str, newline: str) -> None:
    path = _file(tmp_path, bom, encoding, newline)
    assert window.load(path)
    target = path
    if path_to_disk == "ladder-edit":
        _invert_first_contact(window)
    else:
        _edit_a_line_in_the_text_view(window)
        if path_to_disk != "text-saved":
            window.actions_by_name["action_show_ladder"].trigger()  # F5
            assert not window.model.showing_text
    if path_to_disk == "save-as":
        target = tmp_path / "copy.LAD"
        monkeypatch.setattr(file_dialogs, "save_file_name", lambda *_a, **_k: str(target))
        with qtbot.waitSignal(window.file_saved, timeout=20000):
            window.actions_by_name["action_save_as"].trigger()
    elif path_to_disk == "recovery":
        snapshot = window.recovery_snapshot()
        assert snapshot is not None
        copy_path = tmp_path / "copy.recovered"
        copy_path.write_bytes(snapshot.data)
        _assert_form(snapshot.data, bom, encoding, newline)
        window.model.mark_saved()
        window.text_view.document().setModified(False)
        lock = QLockFile(str(tmp_path / "copy.lock"))
        assert window.restore(RecoveredCopy("k", copy_path, path, datetime.now(), None, lock))
        _save(window, qtbot)
    else:
        _save(window, qtbot)
    _assert_form(target.read_bytes(), bom, encoding, newline)
