"""A real FANUC 31i-A export (X22) opened from File › Open: ladder with labels and symbols,
Program properties, symbols in the signal list, editor, docks and tables, `%@4` alarms."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtWidgets import QApplication, QMessageBox
from pytestqt.qtbot import QtBot

from ladderworks.core.address import Address, Area, parse_address
from ladderworks.core.il import Program, parse
from ladderworks.core.ladder import Contact
from ladderworks.gui import file_dialogs
from ladderworks.gui.docks.tables import TableKind
from ladderworks.gui.editor.labelled_item import LabelledNetworkItem
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.settings import Settings
from ladderworks.gui.tools import Tool
from ladderworks.gui.translation import UiLanguage
from tests.real_programs import real_programs_dir

X22 = "FANUC_STUDER_X22_P036"
ESKIP = parse_address("X21.7")


def _x22() -> Path:
    return real_programs_dir() / f"{X22}.txt"


@pytest.fixture(scope="module")
def opened(qapp: QApplication, tmp_path_factory: pytest.TempPathFactory
           ) -> Iterator[tuple[MainWindow, list[str]]]:
    """One window (English) with X22 opened through File › Open (parsed once: it is large)."""
    folder = tmp_path_factory.mktemp("real")
    settings = Settings(QSettings(str(folder / "s.ini"), QSettings.Format.IniFormat))
    language = UiLanguage()
    language.apply("en")
    window = MainWindow(settings, language)
    window.resize(1200, 800)
    window.show()
    filters: list[str] = []

    def choose(*args: object) -> str:
        filters.append(str(args[3]))
        return str(_x22())

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(file_dialogs, "open_file_name", choose)
        patch.setattr(QMessageBox, "question", staticmethod(
            lambda *_a, **_k: (_ for _ in ()).throw(AssertionError("unexpected question"))))
        window.actions_by_name["action_open"].trigger()
        filters.append(str(window.editor.loading))  # a large program lays out in the background
        yield window, filters
        window.plc_docks.session.stop()
        window.editor.undo_stack.setClean()
        window.parameters.reset()  # the D197 the tables test set: nothing to save
        window.close()
        window.deleteLater()


def _cell_of(window: MainWindow, address: Address) -> tuple[int, int, int]:
    for index, network in enumerate(window.editor.networks):
        for (row, col), element in network.elements():
            if isinstance(element, Contact) and element.address == address:
                return index, row, col
    raise AssertionError(f"{address} not in the ladder")


def test_open_lists_mnemonic_files_and_shows_the_ladder_with_labels(
        qtbot: QtBot, opened: tuple[MainWindow, list[str]]) -> None:
    window, filters = opened
    assert filters[1] == "True"  # the first networks were shown before all were laid out
    qtbot.waitUntil(lambda: not window.editor.loading, timeout=60000)
    assert filters and all(f"*.{ext}" in filters[0] for ext in ("mnc", "LAD", "MOD", "txt"))
    assert "All files (*)" in filters[0]
    assert window.pages.currentWidget() is window.editor
    assert f"{X22}.txt" in window.windowTitle()
    editor = window.editor
    assert len(editor.networks) > 3000
    assert editor.networks[4].label == "N00004"
    assert "N00004" in editor.describe_cell(4, 0, 0)
    assert isinstance(editor.network_items[4], LabelledNetworkItem)  # paints N00004 under `N5`
    # only the networks on screen have graphics items
    QApplication.processEvents()
    editor.viewport().repaint()
    assert 0 < editor.network_items.made_count() < 100


def test_the_ladder_shows_x21_7_with_its_symbol_eskip(
        qtbot: QtBot, opened: tuple[MainWindow, list[str]]) -> None:
    window, _ = opened
    editor = window.editor
    index, row, col = _cell_of(window, ESKIP)
    editor.setFocus()
    editor.move_cursor(index, row, col)
    qtbot.keyClick(editor, Qt.Key.Key_Right)
    qtbot.keyClick(editor, Qt.Key.Key_Left)
    status = window.findChild(type(window.cell_label), "status_cell")
    assert status is not None and "X21.7" in status.text() and "ESKIP" in status.text()
    qtbot.mouseMove(editor.viewport(), editor.cell_point(index, row, col))
    qtbot.waitUntil(lambda: editor.viewport().toolTip().startswith("X21.7  ESKIP"))
    item = editor.network_items[index]
    assert item.describe(ESKIP) == ("ESKIP", "")  # drawn under the address
    # the program's symbol (here the same name as the manual's) comes first
    assert editor.describe_address(parse_address("G8.4"))[0] == "*ESP"


def test_program_properties_show_title_sections_and_text_form(
        qtbot: QtBot, opened: tuple[MainWindow, list[str]]) -> None:
    window, _ = opened
    window.actions_by_name["action_program_properties"].trigger()
    dialog = window.properties_dialog
    qtbot.waitExposed(dialog)
    title = dialog.texts("properties_title")
    lines = _x22().read_text("ascii").splitlines()
    section = lines[lines.index("%@1") + 1:lines.index("%", lines.index("%@1"))]
    written = dict(line.split(" ", 1) for line in section)  # `2 name`: read from ../shared
    assert ["2", "Machine-tool name", written["2"].strip()] in title
    assert ["7", "Date", written["7"].strip()] in title
    assert [row[0] for row in title] == [str(n) for n in range(1, 11)]
    general = dict((row[0], row[1]) for row in dialog.texts("properties_general"))
    assert general["PMC model"] == "FANUC Series 30i-A PMC (memory-B)"
    assert general["Line ends"] == "LF" and general["Byte order mark"] == "no"
    assert general["Symbols (%@2)"] == "12820"
    assert ["2", "BINARY"] in dialog.texts("properties_system")
    assert ["X03", "1", "0", "1", "/6"] in dialog.texts("properties_io")
    headers = [row[0] for row in dialog.texts("properties_sections")]
    assert headers == ["%@0", "%@1", "%@2-C", "%@4", "%@5"]
    dialog.close()


def test_signal_list_finds_a_program_symbol(
        qtbot: QtBot, opened: tuple[MainWindow, list[str]]) -> None:
    window, _ = opened
    dock = window.signals_dock
    dock.show()
    dock.raise_()
    dock.query.clear()
    qtbot.keyClicks(dock.query, "ESKIP")
    assert dock.row_texts(0)[:2] == ["X21.7", "ESKIP"]
    assert dock.address_at_row(0) == ESKIP
    assert "program symbols" in dock.count_label.text()
    dock.query.clear()
    qtbot.keyClicks(dock.query, "X21.7")
    assert dock.row_texts(0)[:2] == ["X21.7", "ESKIP"]


def test_typing_a_symbol_as_the_address_puts_its_address(
        qtbot: QtBot, opened: tuple[MainWindow, list[str]]) -> None:
    window, _ = opened
    editor = window.editor
    editor.finish_loading()
    last = len(editor.networks) - 1
    editor.setFocus()
    editor.move_cursor(last, 0, 0)
    qtbot.keyClick(editor, "I")
    assert window.current_tool() is Tool.INPUT
    qtbot.keyClick(editor, Qt.Key.Key_Space)
    assert editor.inline_editor.isVisible()
    qtbot.keyClicks(editor.inline_editor, "ESKIP")
    qtbot.keyClick(editor.inline_editor, Qt.Key.Key_Return)
    found = editor.networks[last].element_at(0, 0)
    assert found is not None and isinstance(found[1], Contact)
    assert found[1].address == ESKIP
    editor.undo_stack.setIndex(0)
    assert editor.networks[-1].is_empty()


def test_alarm_panel_shows_the_programs_message(
        qtbot: QtBot, opened: tuple[MainWindow, list[str]]) -> None:
    window, _ = opened
    session = window.plc_docks.session
    dock = window.plc_docks.others["alarms"]
    assert "(%@4)" not in dock.file_label.text()  # opened, not loaded into the PLC
    session.run.realtime = False
    # X22 itself does not compile yet: a small program with X22's messages goes into the PLC
    small = parse("%@3\nRD X0.0\nWRT R0.0\n%\n").program
    origin = window.document.origin
    assert origin is not None
    small.messages = origin.messages
    compiled = session.load_program(small)
    assert compiled.binary is not None
    assert "(%@4): 2" in dock.file_label.text()
    assert session.start()
    session.set_bit(parse_address("A0.1"), 1)
    session.run_scans(1)
    rows = dock.shown_rows()
    assert rows and rows[0][1] == "A0.1" and rows[0][4] == "1000 STUDER ERRORMESSAGE"
    # symbols in the force list and the PLC tables
    session.force(ESKIP, True)
    force_list = window.plc_docks.force_list
    qtbot.waitUntil(lambda: any(force_list.describe(e)[1] == "X21.7 ESKIP"
                                for e in force_list.entries))
    session.release(ESKIP)
    tables = window.plc_docks.others["tables"]
    assert tables.insert_texts(TableKind.DATA, ["D197", "1", "5"]) is None
    model = tables.models[TableKind.DATA]
    shown = [model.data(model.index(r, 0)) for r in range(model.rowCount())]
    assert "D197 OFCON#" in shown
    session.stop()
    # a program without %@4 goes back to the alarm file
    dock.use_program(Program())
    assert "(%@4)" not in dock.file_label.text()


def test_bit_display_takes_and_shows_symbols(opened: tuple[MainWindow, list[str]]) -> None:
    window, _ = opened
    bits = window.plc_docks.others["bit_display"]
    bits.set_address(0, "ESKIP")
    row = bits.rows[0]
    assert row.address == Address(Area.X, 21)
    assert "ESKIP" in row.bits[7].toolTip()


def test_time_chart_takes_a_symbol_and_names_its_lane(opened: tuple[MainWindow, list[str]]) -> None:
    window, _ = opened
    chart = window.plc_docks.others["time_chart"]
    chart.signals_edit.setText("ESKIP R0.0")
    signals = chart.parse_signals()
    assert signals is not None and signals[0].address == ESKIP
    assert chart.lane_name(signals[0]) == "X21.7 ESKIP"
