"""An S7 block in the console drawn as TIA draws LAD: the TON box with its named pins painted,
power flow on the drawing while it runs, and an edit that lowers again and runs."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QImage, QPainter
from PySide6.QtWidgets import QStyleOptionGraphicsItem
from pytestqt.qtbot import QtBot

from ladderworks.core.dialects.s7.devices import parse_absolute
from ladderworks.core.ladder.model import Contact, FunctionBox
from ladderworks.gui.docks.plc_docks import PlcDocks
from ladderworks.gui.editor import geometry
from ladderworks.gui.editor.network_item import NetworkItem
from ladderworks.gui.main_window import MainWindow
from tests.gui.plc_docks_help import plc_docks

EXAMPLES = Path(__file__).resolve().parents[2] / "resources" / "examples"


def _running(qtbot: QtBot, window: MainWindow) -> PlcDocks:
    """The console's program compiled (F9) and started, on the virtual clock."""
    docks = plc_docks(window)
    docks.session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert docks.session.run.engine is not None
    window.actions_by_name["action_plc_start"].trigger()
    return docks


def _ton(window: MainWindow) -> tuple[tuple[int, int], FunctionBox]:
    return next((cell, e) for cell, e in window.editor.networks[0].cells.items()
                if isinstance(e, FunctionBox))


@pytest.mark.parametrize("path", ["s7/timers/Main.s7dcl", "s7-xml/timers/Main.xml"])
@pytest.mark.parametrize("display", [geometry.NameDisplay.ADDRESS, geometry.NameDisplay.COMMENT])
def test_the_ton_box_is_drawn_with_its_pin_names(qtbot: QtBot, window: MainWindow, path: str,
                                                 display: geometry.NameDisplay) -> None:
    geometry.set_name_display(display)
    try:
        assert window.load(EXAMPLES / path)
        assert len(window.editor.networks) == 3  # two S7 networks and the blank one
        _cell, ton = _ton(window)
        assert (ton.title, ton.instance, ton.type_name) == ("TON", '"IEC_Timer_0_DB"', "Time")
        assert [p.name for p in ton.named] == ["IN", "PT", "Q", "ET"]
        item = window.editor.network_items[0]
        assert isinstance(item, NetworkItem) and item.network is window.editor.networks[0]
        image = QImage(int(item.boundingRect().width()), int(item.boundingRect().height()),
                       QImage.Format.Format_ARGB32)
        image.fill(Qt.GlobalColor.white)
        painter = QPainter(image)
        texts: list[str] = []
        original = painter.drawText

        def record(*args: object) -> None:  # what is written, then write it
            texts.append(str(args[-1]))
            original(*args)  # type: ignore[arg-type]

        painter.drawText = record  # type: ignore[method-assign]
        option = QStyleOptionGraphicsItem()
        option.exposedRect = item.boundingRect()
        try:
            item.paint(painter, option)
        finally:
            painter.end()
        for name in ("IN", "PT", "Q", "ET", "TON", "Time", "T#10s", '"IEC_Timer_0_DB"',
                     '"Start"', '"Lamba 1"'):
            assert any(name == text or name in text for text in texts), (name, texts)
    finally:
        geometry.set_name_display(geometry.DEFAULT_DISPLAY)


def test_the_running_block_shows_power_on_the_drawing(qtbot: QtBot, window: MainWindow) -> None:
    assert window.load(EXAMPLES / "s7" / "timers" / "Main.s7dcl")
    docks = _running(qtbot, window)
    docks.online.actions["action_plc_online"].trigger()
    assert docks.online.online
    anchor, _box = _ton(window)
    network = window.editor.networks[0]
    coil = (0, network.coil_column)
    docks.session.step(100)
    power = docks.online.live.overlays[0].power
    assert (0, 0) not in power.closed and anchor not in power.box_out
    docks.session.set_bit(parse_absolute("%I0.0")[0], 1)  # "Start"
    docks.session.step(200)
    power = docks.online.live.overlays[0].power
    assert (0, 0) in power.closed and anchor not in power.box_out
    assert docks.online.live.cells(0).get(anchor) is not None  # the TON op is found
    docks.session.step(10_000)
    power = docks.online.live.overlays[0].power
    assert anchor in power.box_out and coil in power.coils
    compare = docks.online.live.overlays[1].power  # ["Geçen Süre" >= T#5s]
    assert (0, 0) in compare.closed and (0, network.coil_column) in compare.coils


def test_an_edit_of_an_s7_network_lowers_again_and_runs(qtbot: QtBot,
                                                        window: MainWindow) -> None:
    """A normally closed contact %I0.7 put in series before the TON: the lamp still comes
    after 10 s, and no longer while %I0.7 is 1."""
    assert window.load(EXAMPLES / "s7" / "jumps" / "Main.s7dcl")
    model = window.editor.model
    index = 1  # "Buton" -> "Lamba"
    edit = model.prepare(index, lambda net: net.cells.__setitem__(
        (0, 1), Contact(texts=("%I0.7",), negated=True)))
    model.apply(index, edit)
    program, found = model.program()
    assert program is not None and not found
    session = _running(qtbot, window).session
    lamp = parse_absolute("%Q0.1")[0]
    session.set_bit(parse_absolute("%I0.1")[0], 1)  # "Buton"
    session.run_scans(2)
    assert session.run.bit(lamp) == 1
    session.set_bit(parse_absolute("%I0.7")[0], 1)
    session.run_scans(2)
    assert session.run.bit(lamp) == 0


def test_an_operand_typed_on_an_s7_contact_is_kept_as_written(qtbot: QtBot,
                                                               window: MainWindow) -> None:
    assert window.load(EXAMPLES / "s7" / "timers" / "Main.s7dcl")
    editor = window.editor
    editor.inline.open_address(0, 0, 0)
    assert editor.inline_editor.text() == '"Start"'
    editor.inline_editor.setText("Nowhere")
    qtbot.keyClick(editor.inline_editor, Qt.Key.Key_Return)
    assert "S7 address" in editor.inline_message.text()
    editor.inline_editor.setText("%I0.7")
    qtbot.keyClick(editor.inline_editor, Qt.Key.Key_Return)
    contact = editor.networks[0].cells[(0, 0)]
    assert isinstance(contact, Contact) and contact.texts == ("%I0.7",)
    assert contact.address == parse_absolute("%I0.7")[0]
    program, found = window.model.program()
    assert program is not None and not found
    assert any(ins.operand == contact.address for net in program.networks
               for ins in net.instructions)


def test_the_s7_palette_places_a_ton_with_its_operands_and_it_runs(
        qtbot: QtBot, window: MainWindow) -> None:
    """A new network drawn from the palette: "Start", a TON of 1 s from the function list
    (its operands typed in the operand dialog), a coil %Q0.5."""
    from ladderworks.core import ladder as core

    assert window.load(EXAMPLES / "s7" / "timers" / "Main.s7dcl")
    model = window.editor.model
    index = model.blank_index()
    edits = window.editor.edits
    edits.open_function_dialog(index, 0, 2, "S7.TON")
    dialog = edits.operand_dialog
    assert dialog is not None
    assert [e.objectName() for e in dialog.edits] == ["operand_instance", "operand_PT",
                                                      "operand_ET"]
    assert [e.text() for e in dialog.edits] == ["<???>", "<???>", "..."]
    dialog.edits[0].setText('"Yeni_TON"')
    dialog.edits[1].setText("T#1s")
    dialog.accept()
    network = model.networks[index]
    ton = next(e for e in network.cells.values() if isinstance(e, FunctionBox))
    assert ton.instance == '"Yeni_TON"' and ton.title == "TON"
    for element, col in ((Contact(texts=('"Start"',)), 0),
                         (core.Coil(texts=("%Q0.5",)), network.columns)):
        model.apply(index, model.prepare(index, lambda n, e=element, c=col:
                                         core.place_wired(n, 0, c, e)))
    program, found = model.program()
    assert program is not None and not found, found
    session = _running(qtbot, window).session
    lamp = parse_absolute("%Q0.5")[0]
    session.set_bit(parse_absolute("%I0.0")[0], 1)  # "Start"
    session.step(900)
    assert session.run.bit(lamp) == 0
    session.step(200)
    assert session.run.bit(lamp) == 1


def test_an_s7_comparison_from_the_palette_takes_its_two_operands(
        qtbot: QtBot, window: MainWindow) -> None:
    assert window.load(EXAMPLES / "s7" / "timers" / "Main.s7dcl")
    index = window.editor.model.blank_index()
    edits = window.editor.edits
    edits.open_function_dialog(index, 0, 0, "S7.GT")
    dialog = edits.operand_dialog
    assert dialog is not None and len(dialog.edits) == 2
    dialog.edits[0].setText('"Geçen Süre"')
    dialog.edits[1].setText("T#3s")
    dialog.accept()
    contact = window.editor.networks[index].cells[(0, 0)]
    assert isinstance(contact, Contact) and contact.texts == ('"Geçen Süre"', "T#3s")
    assert contact.mark == ">\nInt"


@pytest.mark.parametrize(("row", "mark", "operand", "name"),
                         [("S7.JMPN", "JMPN", "son", "S7.JMPN"),
                          ("S7.RET", "RET", "FALSE", "S7.RET")])
def test_jmpn_and_ret_from_the_palette_are_coils_that_lower(
        qtbot: QtBot, window: MainWindow, row: str, mark: str, operand: str,
        name: str) -> None:
    """Issue 39: the palette's JMPN and RET place TIA's -(JMPN)- / -(RET)- coils, their
    label or value asked in the operand dialog; the program lowers to the row."""
    from ladderworks.core import ladder as core

    assert window.load(EXAMPLES / "s7" / "jumps" / "Main.s7dcl")
    model = window.editor.model
    index = model.blank_index()
    edits = window.editor.edits
    edits.open_function_dialog(index, 0, 1, row)
    dialog = edits.operand_dialog
    assert dialog is not None and [e.text() for e in dialog.edits] == ["<???>"]
    dialog.edits[0].setText(operand)
    dialog.accept()
    network = model.networks[index]
    coil = next(e for e in network.cells.values() if isinstance(e, core.Coil))
    assert (coil.mark, coil.texts) == (mark, (operand,))
    model.apply(index, model.prepare(index, lambda n: core.place_wired(
        n, 0, 0, Contact(texts=('"Start"',)))))
    program, found = model.program()
    assert program is not None and not found, found
    assert name in {ins.name for net in program.networks for ins in net.instructions}
