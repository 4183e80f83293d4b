"""Nothing drawn is lost: a network that cannot be coded yet is saved as a draft and reopened."""

from __future__ import annotations

from pathlib import Path

from ladderworks.core.il import parse
from ladderworks.gui.main_window import MainWindow
from tests.gui.conftest import Drawer


def test_unfinished_network_is_saved_as_drawn_and_reopens(window: MainWindow, drawer: Drawer,
                                                          tmp_path: Path) -> None:
    # a finished rung, then one still being drawn: a contact with no coil yet
    coil = window.editor.networks[0].coil_column
    drawer.element(0, 0, 0, "I", "X2.1")
    drawer.element(0, 0, coil, "O", "Y0.0")
    drawer.line(0, (0, 1), (0, coil))
    drawer.element(1, 0, 0, "I", "X2.3 // yarım kaldı")
    drawn = [net for net in window.editor.networks if not net.is_empty()]
    assert len(drawn) == 2
    program, diagnostics = window.editor.program()
    assert program is None  # not compilable ...
    assert [d.code for d in diagnostics if d.is_error] == ["empty-network"]

    target = tmp_path / "draft.LAD"
    with drawer.qtbot.waitSignal(window.file_saved):
        assert window.save_to(target)  # ... but saved all the same
    text = target.read_text("utf-8")
    assert "//@grid " in text
    saved = parse(text)
    assert saved.ok and saved.program.step_count() == 2  # the finished rung is real code
    assert window.errors.tree.topLevelItemCount() >= 1  # the error is listed, not hidden

    assert window.load(target)
    reopened = [net for net in window.editor.networks if not net.is_empty()]
    assert reopened == drawn
