"""Save writes the file's own form (encoding, BOM, line ends, unmodified lines); drafts kept."""

from __future__ import annotations

import difflib
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from ladderworks.core.il import parse_bytes
from ladderworks.gui import file_dialogs
from ladderworks.gui.main_window import MainWindow
from ladderworks.paths import EXAMPLES
from tests.gui.conftest import Answers, Drawer
from tests.real_programs import real_programs_dir

REAL = real_programs_dir() / "FANUC_STUDER_X22_P036.txt"
TURKISH = (EXAMPLES / "or_single.LAD").read_text("utf-8")


def _save(window: MainWindow, qtbot: QtBot) -> None:
    """File > Save, waiting for the file to be written."""
    with qtbot.waitSignal(window.file_saved, timeout=20000):
        window.actions_by_name["action_save"].trigger()


def _save_as(window: MainWindow, qtbot: QtBot, monkeypatch: pytest.MonkeyPatch,
             target: Path) -> None:
    """File > Save As, choosing `target` in the dialog."""
    monkeypatch.setattr(file_dialogs, "save_file_name",
                        lambda *_a, **_k: str(target))
    with qtbot.waitSignal(window.file_saved, timeout=20000):
        window.actions_by_name["action_save_as"].trigger()


def _invert_first_contact(window: MainWindow, network: int = 0) -> None:
    """Edit > NOT on the network's first cell (an edit a user makes with the mouse)."""
    window.editor.move_cursor(network, 0, 0)
    window.actions_by_name["action_invert"].trigger()
    assert window.is_modified()


def test_real_program_saves_byte_for_byte(window: MainWindow, qtbot: QtBot,
                                          monkeypatch: pytest.MonkeyPatch,
                                          tmp_path: Path) -> None:
    assert window.load(REAL)
    target = tmp_path / "copy.txt"
    _save_as(window, qtbot, monkeypatch, target)
    assert target.read_bytes() == REAL.read_bytes()


def test_an_edited_network_changes_only_its_lines(window: MainWindow, qtbot: QtBot,
                                                  monkeypatch: pytest.MonkeyPatch,
                                                  tmp_path: Path) -> None:
    original = REAL.read_bytes()
    source = parse_bytes(original).program.source
    assert source is not None
    network = 3
    assert window.load(REAL)
    _invert_first_contact(window, network)
    target = tmp_path / "edited.txt"
    _save_as(window, qtbot, monkeypatch, target)
    old = original.decode("utf-8").splitlines()
    new = target.read_bytes().decode("utf-8").splitlines()
    start, stop = source.spans[network]
    changed = [(tag, i1, i2) for tag, i1, i2, _j1, _j2 in
               difflib.SequenceMatcher(None, old, new, autojunk=False).get_opcodes()
               if tag != "equal"]
    assert changed
    assert all(start <= i1 and i2 <= stop for _tag, i1, i2 in changed), (changed, start, stop)
    assert len(new) == len(old)


def test_bom_and_crlf_are_kept(window: MainWindow, qtbot: QtBot, tmp_path: Path) -> None:
    path = tmp_path / "bom.LAD"
    path.write_bytes(b"\xef\xbb\xbf" + TURKISH.replace("\n", "\r\n").encode("utf-8"))
    assert window.load(path)
    _invert_first_contact(window)
    _save(window, qtbot)
    data = path.read_bytes()
    assert data.startswith(b"\xef\xbb\xbf")
    assert data.count(b"\n") == data.count(b"\r\n") > 3
    assert b"RD.NOT F9.6" in data and "ÇÖZÜCÜ".encode() in data


def test_utf16_is_kept(window: MainWindow, qtbot: QtBot, tmp_path: Path) -> None:
    path = tmp_path / "wide.LAD"
    original = b"\xff\xfe" + TURKISH.encode("utf-16-le")
    path.write_bytes(original)
    assert window.load(path)
    assert window.encoding == "utf-16-le"
    _invert_first_contact(window)
    _save(window, qtbot)
    data = path.read_bytes()
    assert data.startswith(b"\xff\xfe")
    text = data[2:].decode("utf-16-le")
    assert "RD.NOT F9.6" in text and "ÇÖZÜCÜ" in text


def test_a_character_cp1254_lacks_asks_and_never_writes_a_question_mark(
        window: MainWindow, drawer: Drawer, answers: Answers, tmp_path: Path) -> None:
    path = tmp_path / "turkish.LAD"
    original = TURKISH.encode("cp1254")
    path.write_bytes(original)
    assert window.load(path)
    assert window.encoding == "cp1254"
    drawer.element(1, 0, 0, "I", "X2.3 // 中")  # a drawing not finished: saved as a draft
    answers.queue = ["cancel"]
    window.actions_by_name["action_save"].trigger()
    assert answers.asked[0][2] == ["utf8", "cancel"]
    assert "中" in answers.asked[0][1] and "cp1254" in answers.asked[0][1]
    assert path.read_bytes() == original  # declined: nothing written
    assert window.is_modified()
    answers.queue = ["utf8"]
    with drawer.qtbot.waitSignal(window.file_saved):
        window.actions_by_name["action_save"].trigger()
    text = path.read_bytes().decode("utf-8")  # the whole file is UTF-8 now
    assert "中" in text and "ÇÖZÜCÜ" in text and "?" not in text
    assert window.encoding == "utf-8"


def test_a_few_invalid_bytes_open_as_utf8_show_and_are_kept(
        window: MainWindow, qtbot: QtBot, tmp_path: Path) -> None:
    path = tmp_path / "damaged.LAD"
    data = TURKISH.encode("utf-8").replace(b"M00 KOD", b"M00 \xff\xfeKOD")
    path.write_bytes(data)
    assert window.load(path)
    assert window.encoding == "utf-8"  # not cp1254 because of two bad bytes
    warnings = [d for d in window.errors.diagnostics() if d.code == "invalid-bytes"]
    assert [(d.line, d.args["count"]) for d in warnings] == [(5, 2)]
    assert window.errors.isVisible()
    _invert_first_contact(window)
    _save(window, qtbot)
    saved = path.read_bytes()
    assert b"M00 \xff\xfeKOD" in saved and "ÇÖZÜCÜ".encode() in saved
    assert b"RD.NOT F9.6" in saved


DAMAGED = (b'%@3\r\n//@grid LADDERWORKS-GRID 1 {"columns": Infinity, "rows": 1e400}\r\n'
           b'RD X0.0\r\nWRT Y0.0\r\n%\r\n')


def test_a_damaged_draft_is_shown_as_text_and_saved_unchanged(
        window: MainWindow, qtbot: QtBot, tmp_path: Path) -> None:
    path = tmp_path / "draft.LAD"
    path.write_bytes(DAMAGED)
    assert window.load(path)
    found = [d for d in window.errors.diagnostics() if d.code == "damaged-draft"]
    assert [d.line for d in found] == [2]
    assert window.pages.currentWidget() is window.editor
    comments = [c for net in window.editor.networks for c in net.comments]
    assert any("Infinity" in c for c in comments)  # kept, shown as the network's text
    assert not window.is_modified()
    _save(window, qtbot)
    assert path.read_bytes() == DAMAGED


def test_invalid_bytes_in_a_file_shown_as_text_are_visible_and_kept(
        window: MainWindow, qtbot: QtBot, monkeypatch: pytest.MonkeyPatch,
        tmp_path: Path) -> None:
    path = tmp_path / "broken.LAD"
    path.write_bytes("%@3\r\nRD X2.1 // ÇÖZÜCÜ \xff\r\nAND Q9.9\r\nWRT Y0.0\r\n%\r\n"
                     .encode("utf-8", errors="surrogateescape").replace(b"\xc3\xbf", b"\xff"))
    assert window.load(path)
    assert window.pages.currentWidget() is window.text_view
    shown = window.text_view.toPlainText().splitlines()[1]
    assert shown.startswith("RD X2.1 // ÇÖZÜCÜ ") and len(shown) == len("RD X2.1 // ÇÖZÜCÜ ") + 1
    target = tmp_path / "elsewhere.LAD"
    _save_as(window, qtbot, monkeypatch, target)  # the broken file itself is never overwritten
    assert target.read_bytes() == path.read_bytes()
