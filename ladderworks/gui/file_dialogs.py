"""File choosers for every Open/Save/Export: Qt's own dialog sized so its columns show whole."""

from __future__ import annotations

from PySide6.QtCore import QSize
from PySide6.QtGui import QShowEvent
from PySide6.QtWidgets import (
    QDialog,
    QFileDialog,
    QHeaderView,
    QListView,
    QSplitter,
    QTreeView,
    QWidget,
)

from ladderworks.gui.screen_fit import fit_to_screen

WANTED = QSize(900, 560)  # name, size, type and date side by side, also in Turkish


class SizedFileDialog(QFileDialog):
    """Qt's file dialog with its columns and places list sized once it is shown (after Qt
    has restored what it saved of its last use)."""

    def showEvent(self, event: QShowEvent) -> None:
        """Size the columns and the places list as the dialog appears."""
        super().showEvent(event)
        _fit_columns(self)
        _widen_places(self)


def make_file_dialog(parent: QWidget | None, caption: str, directory: str, filters: str,
                     saving: bool) -> QFileDialog:
    """A file dialog for opening or saving, as large as its columns need and the screen has."""
    dialog = SizedFileDialog(parent, caption, directory, filters)
    if saving:
        dialog.setAcceptMode(QFileDialog.AcceptMode.AcceptSave)
        dialog.setFileMode(QFileDialog.FileMode.AnyFile)
    else:
        dialog.setFileMode(QFileDialog.FileMode.ExistingFile)
    fit_to_screen(dialog, WANTED.expandedTo(dialog.sizeHint()))
    return dialog


def _fit_columns(dialog: QFileDialog) -> None:
    """Size, type and date as wide as their texts; the name takes the rest."""
    tree = dialog.findChild(QTreeView, "treeView")
    if tree is not None:  # Qt's own dialog (a native one sizes itself)
        header = tree.header()
        header.setSectionResizeMode(0, QHeaderView.ResizeMode.Stretch)
        for column in range(1, header.count()):
            header.setSectionResizeMode(column, QHeaderView.ResizeMode.ResizeToContents)


def _widen_places(dialog: QFileDialog) -> None:
    """The places list (Computer, home…) as wide as its names, up to a fifth of the dialog."""
    places = dialog.findChild(QListView, "sidebar")
    splitter = dialog.findChild(QSplitter, "splitter")
    if places is None or splitter is None or splitter.count() != 2:
        return
    wanted = places.sizeHintForColumn(0) + 2 * places.frameWidth() + 8
    width = min(max(wanted, places.width()), dialog.width() // 5)
    total = sum(splitter.sizes()) or dialog.width()
    splitter.setSizes([width, max(total - width, 0)])


def _chosen(dialog: QFileDialog) -> str:
    """The file the user chose in `dialog`, or "" when cancelled."""
    files = dialog.selectedFiles() if dialog.exec() == QDialog.DialogCode.Accepted else []
    dialog.deleteLater()
    return files[0] if files else ""


def open_file_name(parent: QWidget | None, caption: str, directory: str, filters: str) -> str:
    """Ask for an existing file to open; "" when cancelled."""
    return _chosen(make_file_dialog(parent, caption, directory, filters, saving=False))


def save_file_name(parent: QWidget | None, caption: str, directory: str, filters: str) -> str:
    """Ask for a file to write (asking before overwriting one); "" when cancelled."""
    return _chosen(make_file_dialog(parent, caption, directory, filters, saving=True))
