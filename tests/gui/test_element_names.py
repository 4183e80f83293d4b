"""Readable names: address, symbol and two wrapped comment lines per element; View › Element
names chooses what is shown and is remembered; the user's comment comes before the manual's."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QSettings
from PySide6.QtGui import QAction, QColor, QFont, QFontMetricsF
from PySide6.QtWidgets import QMenu
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.ladder import Coil, Contact
from ladderworks.gui.editor.geometry import NameDisplay, cell_h, default_display, name_display
from ladderworks.gui.editor.label_text import wrapped
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.settings import Settings
from ladderworks.gui.translation import UiLanguage
from ladderworks.paths import EXAMPLES

LONG = "İŞ MİLİ SAĞA DÖN ROLESİ-PROJEYE GÖRE DEĞİŞTİRİLECEK ÇIKIŞ"  # or_triple_and's coil


def _element(window: MainWindow, address: str) -> tuple[int, int, int, Contact | Coil]:
    wanted = parse_address(address)
    for index, net in enumerate(window.editor.networks):
        for (row, col), element in net.elements():
            if isinstance(element, Contact | Coil) and element.address == wanted:
                return index, row, col, element
    raise AssertionError(address)


def _comment_ink_height(window: MainWindow, index: int, row: int, col: int) -> int:
    """Pixel rows from the first to the last row of comment-green text in a cell on screen."""
    view = window.editor
    rect = view.cell_rect(index, row, col)
    view.ensureVisible(rect)
    image = view.viewport().grab().toImage()
    top_left = view.mapFromScene(rect.topLeft())
    bottom_right = view.mapFromScene(rect.bottomRight())
    inked = [y for y in range(top_left.y(), bottom_right.y())
             if any(_is_comment_ink(image.pixelColor(x, y))
                    for x in range(top_left.x(), bottom_right.x()))]
    return inked[-1] - inked[0] + 1 if inked else 0


def _is_comment_ink(colour: QColor) -> bool:
    return colour.green() > colour.red() + 30 and colour.green() > colour.blue() + 30


def _show(window: MainWindow, display: NameDisplay) -> None:
    """View › Element names › `display`, as the user picks it."""
    action = window.findChild(QAction, f"action_names_{display.value}")
    assert action is not None
    action.trigger()


def test_the_default_shows_comments_on_a_tall_screen_only(window: MainWindow) -> None:
    assert default_display(1080) is NameDisplay.COMMENT
    assert default_display(600) is default_display(768) is NameDisplay.SYMBOL
    screen = window.screen().availableGeometry().height()  # the offscreen screen: 800 px
    assert name_display() is default_display(screen)


def test_a_long_comment_is_wrapped_in_two_lines_under_the_symbol(window: MainWindow) -> None:
    window.load(EXAMPLES / "or_triple_and.LAD")
    _show(window, NameDisplay.COMMENT)
    index, row, col, coil = _element(window, "Y0.1")
    assert coil.comment == LONG
    item = window.editor.network_items[index]
    address, symbol, lines = item.label_lines(coil)
    assert address == "Y0.1" and symbol  # Y0.1's name in the manual's table
    assert len(lines) == 2
    assert LONG.startswith(lines[0]) and lines[1].endswith("…")
    assert " ".join(lines).replace("…", "") in LONG  # the words, in order, wrapped
    two = _comment_ink_height(window, index, row, col)
    index, row, col, contact = _element(window, "F1.4")  # "İŞ MİLİ ENABLE": one line
    assert len(item.label_lines(contact)[2]) == 1
    one = _comment_ink_height(window, index, row, col)
    assert 0 < one < two and two >= one + 8  # a second line of text is painted


def test_wrapping_breaks_at_spaces_and_elides_what_does_not_fit(qtbot: QtBot) -> None:
    font = QFont()
    font.setPointSizeF(7.5)
    metrics = QFontMetricsF(font)
    assert wrapped("ACİL STOP", metrics, 78, 2) == ["ACİL STOP"]
    two = wrapped("ACİL STOP BUTONU BASILDI", metrics, 60, 2)
    assert two[0] == "ACİL STOP" and two[1].startswith("BUTONU")
    assert all(metrics.horizontalAdvance(line) <= 60 for line in two)
    long = wrapped("A" * 60, metrics, 60, 2)
    assert len(long) == 2 and long[1].endswith("…")
    assert wrapped("", metrics, 60, 2) == []


def test_the_users_comment_comes_before_the_manuals_name(window: MainWindow,
                                                         tmp_path: Path) -> None:
    path = tmp_path / "estop.LAD"
    path.write_text("%@2-C\nG8.4    ACILSTOP   ACİL STOP BUTONU KAPI AÇIK\n%\n"
                    "%@3\nRD X1.0\nWRT G8.4\nRD X1.1\nWRT G8.5   // KENDİ NOTUM\n%\n", "utf-8")
    window.load(path)
    _show(window, NameDisplay.COMMENT)
    index, _row, _col, coil = _element(window, "G8.4")  # FANUC names it *ESP
    item = window.editor.network_items[index]
    address, symbol, lines = item.label_lines(coil)
    assert (address, symbol) == ("G8.4", "ACILSTOP")
    assert " ".join(lines).startswith("ACİL STOP")  # the program's comment, not the manual's
    index, _row, _col, coil = _element(window, "G8.5")  # FANUC: *SP (feed hold)
    _address, symbol, lines = window.editor.network_items[index].label_lines(coil)
    assert symbol == "*SP" and lines == ["KENDİ NOTUM"]  # the user's words, FANUC's name


def test_view_element_names_changes_the_rows_and_is_remembered(window: MainWindow,
                                                               settings: Settings,
                                                               qtbot: QtBot) -> None:
    window.load(EXAMPLES / "or_triple_and.LAD")
    _show(window, NameDisplay.COMMENT)
    index, row, col, coil = _element(window, "Y0.1")
    full = window.editor.cell_rect(index, row, col).height()
    top_of_next = window.editor.layout_.tops[1]
    action = window.findChild(QAction, "action_names_address")
    assert action is not None
    action.trigger()
    assert name_display() is NameDisplay.ADDRESS and settings.name_display() == "address"
    item = window.editor.network_items[index]
    assert item.label_lines(coil) == ("Y0.1", "", [])
    assert window.editor.cell_rect(index, row, col).height() == cell_h() < full
    assert window.editor.layout_.tops[1] < top_of_next
    assert item.boundingRect().height() == window.editor.layout_.heights[index]
    assert _comment_ink_height(window, index, row, col) == 0
    symbol = window.findChild(QAction, "action_names_symbol")
    symbol.trigger()
    assert item.label_lines(coil)[1] and item.label_lines(coil)[2] == []
    # a new window on the same settings starts with the choice
    language = UiLanguage()
    language.apply("en")
    again = MainWindow(Settings(QSettings(settings.store.fileName(),
                                          QSettings.Format.IniFormat)), language)
    qtbot.addWidget(again)
    assert name_display() is NameDisplay.SYMBOL
    assert again.findChild(QAction, "action_names_symbol").isChecked()


def test_the_element_names_menu_speaks_turkish(window: MainWindow) -> None:
    menu = window.findChild(QMenu, "menu_names")
    assert menu is not None and menu.title() == "Element &names"
    window.set_language("tr")
    assert menu.title() != "Element &names"
    texts = [action.text() for action in menu.actions()]
    assert all(text and "Address" not in text for text in texts)
