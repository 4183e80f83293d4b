"""The file questions are real message boxes whose buttons answer with their keys."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication, QMessageBox
from pytestqt.qtbot import QtBot

from ladderworks.gui import questions


@pytest.mark.parametrize("key", ["reload", "keep", "save_as", "cancel"])
def test_a_button_answers_with_its_key(qtbot: QtBot, key: str) -> None:
    def press() -> None:
        box = QApplication.activeModalWidget()
        assert isinstance(box, QMessageBox) and box.objectName() == "question_box"
        button = next(b for b in box.buttons() if b.objectName() == f"button_{key}")
        button.click()

    QTimer.singleShot(0, press)
    assert questions.changed_outside(None, Path("machine.LAD")) == key


def test_escape_declines(qtbot: QtBot) -> None:
    def escape() -> None:
        box = QApplication.activeModalWidget()
        assert box is not None
        box.reject()

    QTimer.singleShot(0, escape)
    assert questions.read_only(None, Path("machine.LAD")) in (None, "cancel")
