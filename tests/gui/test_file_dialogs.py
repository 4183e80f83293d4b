"""File › Open and the other file choosers: Qt's own dialog shows its columns whole."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from PySide6.QtCore import QEvent, QTimer
from PySide6.QtWidgets import QApplication, QFileDialog, QListView, QTreeView
from pytestqt.qtbot import QtBot

from ladderworks.gui import file_dialogs
from ladderworks.gui.main_window import MainWindow
from ladderworks.paths import EXAMPLES


@pytest.fixture(autouse=True)
def narrow_places(qt_dialog_state: Path) -> Path:
    """Qt's saved state (kept in a temporary folder by conftest) as a dialog once shrunk by
    hand left it: a narrow places list."""
    state = qt_dialog_state / "QtProject.conf"
    state.write_text("[FileDialog]\nsidebarWidth=60\nviewMode=Detail\nshortcuts=file:\n",
                     encoding="utf-8")
    return state


LONG_NAME = "spindle_override_with_long_name.LAD"  # fits a 720-px dialog


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
    places = dialog.findChild(QListView, "sidebar")
    seen["places"] = (places.viewport().width(), places.sizeHintForColumn(0))
    seen["columns"] = [(header.sectionSize(column),
                        max(tree.sizeHintForColumn(column), header.sectionSizeHint(column)))
                       for column in range(header.count()) if not header.isSectionHidden(column)]
    dialog.reject()


@pytest.mark.parametrize("language", ["en", "tr"])
def test_open_dialog_shows_name_size_type_and_date_whole(
        window: MainWindow, qtbot: QtBot, tmp_path: Path, language: str,
        narrow_places: Path) -> None:
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
    places, names = seen["places"]  # type: ignore[misc]
    assert places >= names  # "Bilgisayar" (Computer) whole
    assert seen["size"].boundedTo(seen["room"]) == seen["size"]  # type: ignore[attr-defined]
    QApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)  # the dialog saves its state
    assert "treeViewHeader" in narrow_places.read_text(encoding="utf-8")  # not the user's
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
    QApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)  # its state: to tmp_path
