"""File › Open and the other file choosers: Qt's own dialog shows its columns whole."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication, QFileDialog, QTreeView
from pytestqt.qtbot import QtBot

from ladderworks.gui import file_dialogs
from ladderworks.gui.main_window import MainWindow
from ladderworks.paths import EXAMPLES

LONG_NAME = "spindle_override_with_a_long_name.LAD"


def _columns_when_listed(seen: dict[str, object]) -> None:
    """Once the modal file dialog lists its folder, note its columns and cancel it."""
    dialog = QApplication.activeModalWidget()
    tree = dialog.findChild(QTreeView, "treeView") if isinstance(dialog, QFileDialog) else None
    if tree is None or tree.model().rowCount(tree.rootIndex()) == 0 or not seen.get("waited"):
        seen["waited"] = tree is not None and tree.model().rowCount(tree.rootIndex()) > 0
        QTimer.singleShot(100, lambda: _columns_when_listed(seen))
        return
    assert isinstance(dialog, QFileDialog)
    header = tree.header()
    seen["size"] = dialog.size()
    seen["room"] = dialog.screen().availableGeometry().size()
    seen["viewport"] = tree.viewport().width()
    seen["columns"] = [(header.sectionSize(column),
                        max(tree.sizeHintForColumn(column), header.sectionSizeHint(column)))
                       for column in range(header.count()) if not header.isSectionHidden(column)]
    dialog.reject()


@pytest.mark.parametrize("language", ["en", "tr"])
def test_open_dialog_shows_name_size_type_and_date_whole(
        window: MainWindow, qtbot: QtBot, tmp_path: Path, language: str) -> None:
    program = tmp_path / LONG_NAME
    shutil.copy(EXAMPLES / "spindle_override.LAD", program)
    assert window.load(program)
    window.set_language(language)
    seen: dict[str, object] = {}
    QTimer.singleShot(0, lambda: _columns_when_listed(seen))
    window.actions_by_name["action_open"].trigger()  # returns when the dialog is cancelled
    assert "columns" in seen
    columns = seen["columns"]
    assert isinstance(columns, list) and len(columns) == 4
    viewport = int(str(seen["viewport"]))
    for width, needed in columns:  # name, size, type and date: each as wide as its texts
        assert width >= needed, columns
    assert sum(width for width, _needed in columns) <= viewport, columns
    assert seen["size"].boundedTo(seen["room"]) == seen["size"]  # type: ignore[attr-defined]
    window.set_language("en")


def test_save_dialog_keeps_title_filters_and_suggested_name(window: MainWindow) -> None:
    dialog = file_dialogs.make_file_dialog(window, "Save program", "/tmp/program.LAD",
                                           "Ladder programs (*.LAD *.lad);;All files (*)",
                                           saving=True)
    assert dialog.windowTitle() == "Save program"
    assert dialog.acceptMode() == QFileDialog.AcceptMode.AcceptSave
    assert dialog.nameFilters() == ["Ladder programs (*.LAD *.lad)", "All files (*)"]
    assert dialog.directory().absolutePath() == "/tmp"
    assert dialog.width() >= 700  # not Qt's 632 × 408
    dialog.deleteLater()
