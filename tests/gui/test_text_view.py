"""The text view of a file with errors: a line-number gutter, the error lines marked, jumps."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtGui import QColor
from pytestqt.qtbot import QtBot

from ladderworks.gui.docks.mnemonic_editor import ERROR_LINE
from ladderworks.gui.main_window import MainWindow

BROKEN = "%@3\nRD X2.1\nAND Q9.9\nWRT Y0.0\nRD X2.2\nAND Q7.7\nWRT Y0.1\n%\n"


def _open_broken(window: MainWindow, tmp_path: Path) -> None:
    path = tmp_path / "broken.LAD"
    path.write_text(BROKEN, encoding="utf-8")
    assert window.load(path)
    assert window.pages.currentWidget() is window.text_view


def _tinted_lines(window: MainWindow) -> list[int]:
    return sorted(selection.cursor.blockNumber() + 1
                  for selection in window.text_view.extraSelections()
                  if selection.format.background().color() == ERROR_LINE)


def test_a_file_with_errors_shows_line_numbers_and_its_error_lines(
        window: MainWindow, tmp_path: Path, qtbot: QtBot) -> None:
    _open_broken(window, tmp_path)
    view = window.text_view
    gutter = view.numbers
    assert gutter.isVisible()
    assert view.viewportMargins().left() == view.number_width() == gutter.width() > 0
    assert view.error_lines() == [3, 6]
    assert _tinted_lines(window) == [3, 6]
    # the numbers of the error lines are painted red, the others grey
    picture = gutter.grab().toImage()
    line_height = view.blockBoundingRect(view.document().firstBlock()).height()

    def reds(line: int) -> int:
        top = round(view.contentOffset().y() + (line - 1) * line_height)
        count = 0
        for y in range(top, top + round(line_height)):
            for x in range(gutter.width()):
                colour = QColor(picture.pixel(x, y))
                count += colour.red() > 150 and colour.green() < 100 and colour.blue() < 100
        return count

    assert reds(3) > 0 and reds(6) > 0
    assert reds(2) == 0 and reds(4) == 0


def test_jumping_from_the_error_list_goes_to_the_line(
        window: MainWindow, tmp_path: Path) -> None:
    _open_broken(window, tmp_path)
    second = window.errors.tree.topLevelItem(1)
    window.errors.tree.itemDoubleClicked.emit(second, 0)
    assert window.text_view.cursor_line() == 6


def test_fixed_text_loses_its_marks(window: MainWindow, tmp_path: Path) -> None:
    _open_broken(window, tmp_path)
    window.text_view.setPlainText(BROKEN.replace("Q9.9", "R9.1").replace("Q7.7", "R7.7"))
    assert window.show_as_ladder()
    window.show_as_text()
    assert window.text_view.error_lines() == []
    assert _tinted_lines(window) == []
