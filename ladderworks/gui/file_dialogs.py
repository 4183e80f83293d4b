"""File choosers for every Open/Save/Export: Qt's own dialog sized so its columns show whole."""

from __future__ import annotations

import re
from pathlib import PurePath

from PySide6.QtCore import QCoreApplication, QSize
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

from ladderworks.core.diagnostics import QT_TRANSLATE_NOOP
from ladderworks.gui.screen_fit import fit_to_screen

translate = QCoreApplication.translate

WANTED = QSize(900, 560)  # name, size, type and date side by side, also in Turkish
_PATTERN = re.compile(r"\(\s*\*\.([^\s*?()]+)")  # `(*.LAD`: the first pattern's extension


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
        # a name typed without an extension takes the chosen filter's (before Qt asks
        # about overwriting, so `name` is asked about as `name.LAD`)
        dialog.setDefaultSuffix(filter_suffix(dialog.selectedNameFilter()))
        dialog.filterSelected.connect(lambda chosen: dialog.setDefaultSuffix(
            filter_suffix(chosen)))
    else:
        dialog.setFileMode(QFileDialog.FileMode.ExistingFile)
    fit_to_screen(dialog, WANTED.expandedTo(dialog.sizeHint()))
    return dialog


def filter_suffix(name_filter: str) -> str:
    """The extension of a filter's first pattern (`Ladder programs (*.LAD *.lad)`: `LAD`);
    "" for a filter of any name (`*`)."""
    match = _PATTERN.search(name_filter)
    return match.group(1) if match else ""


def with_suffix(name: str, name_filter: str) -> str:
    """`name` with the filter's extension added when its file name has none."""
    suffix = filter_suffix(name_filter)
    if not name or not suffix or PurePath(name).suffix:
        return name
    return f"{name}.{suffix}"


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
    """The file the user chose in `dialog`, or "" when cancelled (a name to save without an
    extension takes the chosen filter's, should the dialog not have added it)."""
    files = dialog.selectedFiles() if dialog.exec() == QDialog.DialogCode.Accepted else []
    name_filter = dialog.selectedNameFilter()
    saving = dialog.acceptMode() == QFileDialog.AcceptMode.AcceptSave
    dialog.deleteLater()
    if not files:
        return ""
    return with_suffix(files[0], name_filter) if saving else files[0]


def open_file_name(parent: QWidget | None, caption: str, directory: str, filters: str) -> str:
    """Ask for an existing file to open; "" when cancelled."""
    return _chosen(make_file_dialog(parent, caption, directory, filters, saving=False))


def save_file_name(parent: QWidget | None, caption: str, directory: str, filters: str) -> str:
    """Ask for a file to write (asking before overwriting one); "" when cancelled."""
    return _chosen(make_file_dialog(parent, caption, directory, filters, saving=True))


def open_folder_name(parent: QWidget | None, caption: str, directory: str) -> str:
    """Ask for an existing folder to open (a folder of exports); "" when cancelled."""
    dialog = SizedFileDialog(parent, caption, directory)
    dialog.setFileMode(QFileDialog.FileMode.Directory)
    dialog.setOption(QFileDialog.Option.ShowDirsOnly, True)
    fit_to_screen(dialog, WANTED.expandedTo(dialog.sizeHint()))
    return _chosen(dialog)


# File > Open's filters: each kind of program file with its name patterns (names translated,
# patterns never); the first filter, every program, is their union
OPEN_FILTERS: tuple[tuple[str, str], ...] = (
    (QT_TRANSLATE_NOOP("MainWindow", "Ladder programs"), "*.LAD *.lad"),
    (QT_TRANSLATE_NOOP("MainWindow", "Mnemonic programs"), "*.MOD *.mod *.mnc *.MNC"),
    (QT_TRANSLATE_NOOP("MainWindow", "LADDER-III exports"), "*.txt *.TXT *.mnc *.MNC"),
    (QT_TRANSLATE_NOOP("MainWindow", "Delta DVP instruction lists"),
     "*.txt *.TXT *.dvp *.DVP *.il *.IL *.csv *.CSV"),
    (QT_TRANSLATE_NOOP("MainWindow", "WPLSoft projects"), "*.dvp *.DVP"),
    (QT_TRANSLATE_NOOP("MainWindow", "Fatek WinProladder listings"),
     "*.lst *.LST *.fbs *.FBS *.txt *.TXT"),
    (QT_TRANSLATE_NOOP("MainWindow", "Fatek WinProladder projects"), "*.pdw *.PDW"),
    (QT_TRANSLATE_NOOP("MainWindow", "Siemens S7-1200 SIMATIC SD blocks"), "*.s7dcl *.S7DCL"),
    (QT_TRANSLATE_NOOP("MainWindow", "Siemens S7-1200 SimaticML exports"), "*.xml *.XML"),
)


def open_filters() -> str:
    """File > Open's filter string in the UI language: every program, each kind, all files."""
    patterns: list[str] = []
    for _name, kind in OPEN_FILTERS:
        patterns += [pattern for pattern in kind.split() if pattern not in patterns]
    parts = [f"{translate('MainWindow', 'Ladder and mnemonic programs')} ({' '.join(patterns)})"]
    parts += [f"{translate('MainWindow', name)} ({kind})" for name, kind in OPEN_FILTERS]
    parts.append(f"{translate('MainWindow', 'All files')} (*)")
    return ";;".join(parts)
