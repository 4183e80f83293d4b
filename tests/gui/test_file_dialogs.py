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


def _type_name_when_shown(name: str, seen: dict[str, object], name_filter: str = "") -> None:
    """Once the modal save dialog is up: pick `name_filter` (if given), type `name`, accept."""
    dialog = QApplication.activeModalWidget()
    if not isinstance(dialog, QFileDialog):
        QTimer.singleShot(50, lambda: _type_name_when_shown(name, seen, name_filter))
        return
    if name_filter:
        dialog.selectNameFilter(name_filter)
        dialog.filterSelected.emit(name_filter)  # what choosing it in the combo sends
    dialog.selectFile(name)  # as typed in its name field
    seen["shown"] = True
    dialog.accept()


@pytest.mark.parametrize(("filters", "chosen", "typed", "expected"), [
    ("Ladder programs (*.LAD *.lad);;All files (*)", "", "latch_timer", "latch_timer.LAD"),
    ("Mnemonic programs (*.MOD);;All files (*)", "", "latch_timer", "latch_timer.MOD"),
    ("PDF files (*.pdf)", "", "report", "report.pdf"),
    ("CSV files (*.csv)", "", "trace", "trace.csv"),
    ("PNG pictures (*.png)", "", "chart", "chart.png"),
    ("Scenario files (*.csv);;All files (*)", "", "run", "run.csv"),
    ("Ladder programs (*.LAD *.lad);;All files (*)", "All files (*)", "notes", "notes"),
    ("Ladder programs (*.LAD *.lad);;All files (*)", "", "old.lad", "old.lad"),
])
def test_save_dialog_adds_the_chosen_filters_extension(
        window: MainWindow, tmp_path: Path, filters: str, chosen: str, typed: str,
        expected: str) -> None:
    seen: dict[str, object] = {}
    QTimer.singleShot(0, lambda: _type_name_when_shown(typed, seen, chosen))
    name = file_dialogs.save_file_name(window, "Save", str(tmp_path / "x"), filters)
    assert seen.get("shown")
    assert name == str(tmp_path / expected)


def test_save_as_ladder_filter_writes_a_file_open_lists(window: MainWindow, tmp_path: Path
                                                       ) -> None:
    assert window.load(EXAMPLES / "spindle_override.LAD")
    folder = tmp_path / "saved"
    folder.mkdir()
    seen: dict[str, object] = {}
    QTimer.singleShot(0, lambda: _type_name_when_shown(str(folder / "latch_timer"), seen))
    window.actions_by_name["action_save_as"].trigger()
    assert seen.get("shown")
    assert [p.name for p in folder.iterdir() if not p.name.endswith(".prm")] == [
        "latch_timer.LAD"]
    assert window.path == folder / "latch_timer.LAD"


def test_filter_suffix_reads_the_first_pattern() -> None:
    assert file_dialogs.filter_suffix("Ladder programs (*.LAD *.lad)") == "LAD"
    assert file_dialogs.filter_suffix("All files (*)") == ""
    assert file_dialogs.with_suffix("/a.b/name", "CSV files (*.csv)") == "/a.b/name.csv"
