"""Place SET/RST coils and FANUC PMC boxes with the palette, fill their tables, check the text."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLabel, QLineEdit
from pytestqt.qtbot import QtBot

from ladderworks.core.il import parse, print_program
from ladderworks.core.instructions import PMC_ORDER, Write, lookup
from ladderworks.core.ladder.model import Coil, FunctionBox
from ladderworks.gui.function_dialog import FunctionDialog
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.tools import Tool
from tests.gui.conftest import Drawer, type_text

COIL = 10  # the coil column of a new network


def open_box(d: Drawer, name: str, row: int, col: int) -> FunctionDialog:
    """Choose `name` in the palette's function list, click a cell: the property table."""
    combo = d.window.tool_palette.functions
    combo.setCurrentIndex(combo.findData(name))  # what choosing it in the drop-down does
    d.key("F")  # the function tool (already chosen when the list changed)
    assert d.window.current_tool() is Tool.FUNCTION
    d.click(0, row, col)
    dialog = d.view.edits.function_dialog
    assert dialog is not None and dialog.spec.name == name
    d.qtbot.waitUntil(dialog.isVisible)
    return dialog


def fill(d: Drawer, dialog: FunctionDialog, values: list[str]) -> None:
    """Type each value into its row of the table (ENTER after each), then press OK."""
    table = dialog.table
    for row, text in enumerate(values):
        table.setCurrentCell(row, 1)
        d.qtbot.keyClick(table, Qt.Key.Key_F2)  # edit the cell
        editors = [e for e in table.findChildren(QLineEdit) if e.isVisible()]
        assert len(editors) == 1
        type_text(d.qtbot, editors[0], text)
        d.qtbot.keyClick(editors[0], Qt.Key.Key_Return)  # the delegate commits it queued
        d.qtbot.waitUntil(lambda r=row, t=text: table.item(r, 1).text() == t)
    with d.qtbot.waitSignal(dialog.accepted):
        dialog.buttons.button(dialog.buttons.StandardButton.Ok).click()


def place_box(d: Drawer, name: str, row: int, col: int, values: list[str]) -> None:
    """The function tool end to end."""
    fill(d, open_box(d, name, row, col), values)


def assert_program(window: MainWindow, text: str) -> None:
    """The drawing codes to exactly `text` (one network)."""
    program, diagnostics = window.editor.program()
    assert diagnostics == [] and program is not None
    expected = parse(f"%@3\n{text}\n%\n")
    assert expected.ok, expected.diagnostics
    assert print_program(program) == print_program(expected.program)
    assert program == expected.program


def test_palette_lists_the_seed_then_the_pmc_instructions(window: MainWindow) -> None:
    combo = window.tool_palette.functions
    names = [combo.itemData(i) for i in range(combo.count())]
    assert names[0] is None and names[1] == "TMR"
    pmc = names.index(None, 1)
    assert tuple(names[pmc + 1:]) == PMC_ORDER
    assert combo.itemText(pmc) == "— FANUC PMC instructions —"
    with_tr = window.actions_by_name["action_language_tr"]
    with_tr.trigger()
    assert combo.itemText(pmc) == "— FANUC PMC komutları —"
    assert combo.itemText(pmc + 1) == "DIFU — YÜKSELEN KENAR"


def test_set_and_reset_coils_from_the_palette(drawer: Drawer, window: MainWindow) -> None:
    drawer.element(0, 0, 0, "I", "X1.0")
    drawer.line(0, (0, 1), (0, COIL))
    drawer.element(0, 0, COIL, "E", "R1.0 // TUT")
    drawer.key("R")  # OR: a parallel coil of the same kind below
    drawer.click(0, 0, COIL)
    drawer.type_inline("R1.1")
    added = window.editor.networks[0].cells[(1, COIL)]
    assert isinstance(added, Coil) and added.write is Write.SET
    drawer.key("U")  # the RST tool on the SET coil makes it an RST coil, address kept
    drawer.click(0, 1, COIL)
    drawer.type_inline("R1.1")
    assert_program(window, "RD X1.0\nSET R1.0  // TUT\nRST R1.1")
    drawer.key("T")  # NOT turns RST into SET
    drawer.click(0, 1, COIL)
    assert_program(window, "RD X1.0\nSET R1.0  // TUT\nSET R1.1")


def test_edge_box_with_set_and_reset_on_w1(drawer: Drawer, window: MainWindow) -> None:
    drawer.element(0, 0, 0, "I", "X1.0")
    place_box(drawer, "DIFU", 0, 1, ["57"])
    drawer.line(0, (0, 3), (0, COIL))
    drawer.element(0, 0, COIL, "E", "R5311.4")
    drawer.element(0, 1, COIL, "U", "R5306.1")
    drawer.line(0, (0, COIL), (1, COIL))
    assert_program(window, "RD X1.0\nDIFU 57\nSET R5311.4\nRST R5306.1")


def test_move_box(drawer: Drawer, window: MainWindow) -> None:
    drawer.element(0, 0, 0, "I", "X1.0")
    place_box(drawer, "MOVN", 0, 1, ["4", "R10", "R20"])
    assert_program(window, "RD X1.0\nMOVN 4 R10 R20")


def test_logic_box_shows_its_text_mnemonic(drawer: Drawer, window: MainWindow) -> None:
    drawer.element(0, 0, 0, "N", "X1.0")
    dialog = open_box(drawer, "LOGAND", 0, 1)
    assert dialog.windowTitle() == "AND — Logical AND"
    fill(drawer, dialog, ["1", "R10", "255", "R11"])
    boxes = [e for e in window.editor.networks[0].cells.values() if isinstance(e, FunctionBox)]
    assert len(boxes) == 1 and boxes[0].spec.text_name == "AND"  # right-aligned, wired
    assert_program(window, "RD.NOT X1.0\nLOGAND 1 R10 255 R11")


def test_timer_box(drawer: Drawer, window: MainWindow) -> None:
    drawer.element(0, 0, 0, "I", "X1.0")
    place_box(drawer, "TMRBF", 0, 1, ["270", "30000"])
    drawer.line(0, (0, 3), (0, COIL))
    drawer.element(0, 0, COIL, "O", "R5013.7")
    assert_program(window, "RD X1.0\nTMRBF 270 30000\nWRT R5013.7")


def test_counter_box_with_four_inputs(drawer: Drawer, window: MainWindow) -> None:
    for row, address in enumerate(["R9091.1", "R9091.0", "R6153.5", "R9091.5"]):
        drawer.element(0, row, 0, "N" if row == 2 else "I", address)
    place_box(drawer, "CTRB", 0, 1, ["2", "15"])
    drawer.line(0, (0, 3), (0, COIL))
    drawer.element(0, 0, COIL, "U", "R6153.5")
    assert_program(window, "RD R9091.1\nRD.STK R9091.0\nRD.NOT.STK R6153.5\nRD.STK R9091.5\n"
                           "CTRB 2 15\nRST R6153.5")


def test_range_compare_box(drawer: Drawer, window: MainWindow) -> None:
    drawer.element(0, 0, 0, "I", "X1.0")
    place_box(drawer, "RNGW", 0, 1, ["R6056", "R6058", "R14"])
    drawer.line(0, (0, 3), (0, COIL))
    drawer.element(0, 0, COIL, "O", "R6256.6")
    assert_program(window, "RD X1.0\nRNGW R6056 R6058 R14\nWRT R6256.6")


def test_subprogram_end_has_no_inputs_and_no_parameters(drawer: Drawer,
                                                        window: MainWindow) -> None:
    dialog = open_box(drawer, "SPE", 0, 0)
    note = dialog.findChild(QLabel, "function_no_params")
    assert not dialog.table.isVisible() and note.isVisible()
    assert dialog.windowTitle() == "SPE — End of subprogram"
    with drawer.qtbot.waitSignal(dialog.accepted):
        dialog.buttons.button(dialog.buttons.StandardButton.Ok).click()
    assert_program(window, "SPE")


def test_call_box_table_asks_for_a_subprogram(drawer: Drawer) -> None:
    drawer.element(0, 0, 0, "I", "X1.0")
    dialog = open_box(drawer, "CALL", 0, 1)
    assert dialog.table.item(0, 0).text() == "Subprogram"
    assert dialog.table.item(0, 2).text() == "P1 to P5000"
    dialog.reject()


def test_call_box(drawer: Drawer, window: MainWindow) -> None:
    drawer.element(0, 0, 0, "I", "X1.0")
    place_box(drawer, "CALL", 0, 1, ["P5"])
    assert_program(window, "RD X1.0\nCALL P5")


def test_label_box_on_the_rail(drawer: Drawer, window: MainWindow) -> None:
    place_box(drawer, "LBL", 0, 0, ["L3"])
    assert_program(window, "LBL L3")


def test_cnc_box_with_set_and_reset(drawer: Drawer, window: MainWindow) -> None:
    drawer.element(0, 0, 0, "I", "X1.0")
    place_box(drawer, "WINDW", 0, 1, ["D7151"])
    drawer.line(0, (0, 3), (0, COIL))
    drawer.element(0, 0, COIL, "E", "R5311.4")
    drawer.element(0, 1, COIL, "U", "R5306.1")
    drawer.line(0, (0, COIL), (1, COIL))
    assert_program(window, "RD X1.0\nWINDW D7151\nSET R5311.4\nRST R5306.1")


def test_function_table_title_in_turkish(drawer: Drawer, window: MainWindow,
                                         qtbot: QtBot) -> None:
    window.actions_by_name["action_language_tr"].trigger()
    dialog = open_box(drawer, "TMR", 0, 1)
    assert dialog.windowTitle() == "TMR — ZAMANLAYICI"
    dialog.reject()
    dialog = open_box(drawer, "CALLU", 0, 0)
    assert dialog.windowTitle() == "CALLU — ŞARTSIZ ALT PROGRAM ÇAĞRISI"
    assert dialog.table.item(0, 0).text() == "Alt program"


@pytest.mark.parametrize(("dialect", "accepted", "allowed"),
                         [("seed", False, "1 to 100"), ("fanuc", True, "1 to 500")])
def test_the_property_table_takes_the_ranges_of_the_programs_dialect(
        qtbot: QtBot, dialect: str, accepted: bool, allowed: str) -> None:
    dialog = FunctionDialog(lookup("TMRB"), dialect=dialect)  # X22 has TMRB 245
    qtbot.addWidget(dialog)
    assert dialog.table.item(0, 2).text() == allowed
    dialog.set_value("timer", "245")
    dialog.set_value("preset", "2000")
    dialog.accept()
    assert (dialog.instruction is not None) is accepted
    assert dialog.warning.isHidden() is accepted
