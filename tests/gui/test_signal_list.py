"""The signal list dock: search the manual's signals and put one on the element at the cursor."""

from __future__ import annotations

from PySide6.QtWidgets import QApplication
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.ladder import Contact
from ladderworks.core.signals import load_signals
from ladderworks.core.symbols import SymbolTable, add_entry
from ladderworks.gui.main_window import MainWindow
from ladderworks.paths import EXAMPLES


def _row_of(window: MainWindow, address: str) -> int:
    dock = window.signals_dock
    for row in range(dock.table.rowCount()):
        if dock.table.item(row, 0).text() == address:
            return row
    raise AssertionError(f"{address} not listed")


def test_lists_every_signal_and_searches_turkish_words(window: MainWindow,
                                                       qtbot: QtBot) -> None:
    dock = window.signals_dock
    dock.show()  # tabbed behind the palette: the rows are filled when it is shown
    dock.raise_()
    qtbot.waitUntil(lambda: dock.table.rowCount() == len(load_signals()))
    found = dock.show_matches("acil")
    assert str(found[0].address) == "G8.4"
    assert dock.table.item(0, 1).text() == "*ESP"  # FANUC's spelling (active low)
    assert "the seed manual writes ESP" in dock.table.item(0, 1).toolTip()
    assert dock.table.item(0, 2).text() == "EMERGENCY STOP"
    assert dock.table.item(0, 3).text().startswith("ACİL")
    window.signals_dock.query.setText("SPL")
    assert dock.table.item(0, 0).text() == "F0.4"


def test_double_click_sets_the_address_of_the_contact_at_the_cursor(window: MainWindow,
                                                                    qtbot: QtBot) -> None:
    assert window.load(EXAMPLES / "timer_relay.LAD")
    window.editor.move_cursor(0, 0, 0)  # the contact R1.4
    dock = window.signals_dock
    dock.query.setText("G8.4")
    dock.table.cellDoubleClicked.emit(_row_of(window, "G8.4"), 0)
    element = window.editor.networks[0].cells[(0, 0)]
    assert isinstance(element, Contact) and element.address == parse_address("G8.4")
    window.actions_by_name["action_undo"].trigger()
    element = window.editor.networks[0].cells[(0, 0)]
    assert isinstance(element, Contact) and element.address == parse_address("R1.4")


def test_double_click_without_an_element_copies_the_address(window: MainWindow) -> None:
    last = len(window.editor.networks) - 1
    window.editor.move_cursor(last, 0, 3)  # an empty cell
    dock = window.signals_dock
    dock.query.setText("F1.7")
    dock.table.cellDoubleClicked.emit(_row_of(window, "F1.7"), 0)
    assert QApplication.clipboard().text() == "F1.7"


def test_signal_list_is_reachable_and_translated(window: MainWindow, qtbot: QtBot) -> None:
    toggle = window.actions_by_name["action_dock_signals"]
    assert toggle in window.findChild(type(window.menuBar().actions()[0].menu()),
                                      "menu_view").actions()
    with qtbot.waitSignal(window.language_changed):
        window.actions_by_name["action_language_tr"].trigger()
    dock = window.signals_dock
    assert dock.windowTitle() == "Sinyaller"
    dock.query.setText("G8.4")  # in Turkish the Turkish description comes first
    assert dock.table.horizontalHeaderItem(2).text() == "Açıklama"
    assert dock.table.horizontalHeaderItem(3).text() == "İngilizce"
    assert dock.table.item(0, 3).text() == "EMERGENCY STOP"
    assert dock.table.item(0, 2).text().startswith("ACİL")
    with qtbot.waitSignal(window.language_changed):
        window.actions_by_name["action_language_en"].trigger()


def test_program_symbols_sit_under_name_and_description(window: MainWindow) -> None:
    symbols = SymbolTable()
    assert add_entry(symbols, "R100.0", "SPDLRDY", ("SPINDLE READY",))
    dock = window.signals_dock
    dock.set_symbols(symbols)
    dock.query.setText("SPDL")
    headers = [dock.table.horizontalHeaderItem(column).text() for column in range(4)]
    assert headers == ["Address", "Name", "Description", "In Turkish"]
    assert dock.row_texts(0) == ["R100.0", "SPDLRDY", "SPINDLE READY", ""]
    assert dock.table.item(0, 1).font().italic()
    assert dock.table.item(0, 1).toolTip().startswith("Program symbol")
    dock.query.setText("acil")  # a manual's signal: its English under Description, then Turkish
    assert dock.row_texts(0)[2:] == ["EMERGENCY STOP", dock.signal_at_row(0).turkish]
    assert not dock.table.item(0, 1).font().italic()
