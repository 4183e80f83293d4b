"""Every input kept by the fuzz tests (tests/data/fuzz) opens in the console without a
traceback: a program that does not parse is shown as text with its errors listed."""

from __future__ import annotations

from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from ladderworks.gui.main_window import MainWindow

CRASHERS = sorted((Path(__file__).resolve().parent.parent / "data" / "fuzz").glob("*"))


@pytest.mark.parametrize("crasher", CRASHERS, ids=lambda p: p.name)
def test_a_kept_crasher_opens_as_ladder_or_as_text_with_its_errors(
        qtbot: QtBot, window: MainWindow, crasher: Path) -> None:
    assert CRASHERS
    assert window.load(crasher)
    errors = [d for d in window.errors.diagnostics() if d.is_error]
    if crasher.name.startswith("not-a-program"):  # said once, not as dozens of errors
        assert errors[0].code == "not-a-program" and len(errors) <= 3
    if errors:
        assert window.pages.currentWidget() is window.text_view
        assert window.errors.isVisible()
        assert window.text_view.toPlainText()  # the file's text, to fix in place
    else:
        assert window.pages.currentWidget() is window.editor
