"""The PLC bit display dock: bytes shown live as bits, errors, tooltips, forcing inputs, STOP."""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks.core.address import Address, Area, parse_address
from ladderworks.gui.docks.bit_display import BitDisplayDock
from ladderworks.gui.plc_session import PlcSession
from ladderworks.gui.translation import UiLanguage
from tests.gui.plc_examples import running_session

X2 = [parse_address(f"X2.{bit}") for bit in range(8)]


@pytest.fixture
def spindle(qtbot: QtBot) -> Iterator[tuple[PlcSession, BitDisplayDock]]:
    """The spindle-override example running, with a bit display showing X2, X12 and G30."""
    UiLanguage().apply("en")
    session = running_session("spindle_override.LAD")
    dock = BitDisplayDock(session)
    qtbot.addWidget(dock)
    dock.show()
    for index, text in enumerate(("X12", "G30", "X2")):
        dock.rows[index].edit.setText(text)
    dock.start()
    yield session, dock
    session.stop()


def switch(session: PlcSession, position: int) -> None:
    """Turn the rotary switch: its code on X2.1, X2.3, X2.5, then one scan."""
    for bit, address in zip((1, 2, 4), (X2[1], X2[3], X2[5]), strict=True):
        session.set_bit(address, bool(position & bit))
    session.run_scans(1)


def test_x12_and_g30_follow_inputs(qtbot: QtBot,
                                   spindle: tuple[PlcSession, BitDisplayDock]) -> None:
    session, dock = spindle
    x12, g30 = dock.rows[0], dock.rows[1]
    switch(session, 0)
    assert g30.bit_texts() == "00001010"  # position 0 -> BIN 2 + BIN 8 = 10 %
    assert x12.bit_texts() == "00000000"
    session.set_bit(parse_address("X12.3"), 1)
    session.run_scans(1)
    qtbot.waitUntil(lambda: x12.bit_texts() == "00001000")
    assert x12.hex_label.text() == "08h" and x12.dec_label.text() == "8"
    assert [button.text() for button in reversed(x12.shown_bits)] == list("00001000")
    seen = set()
    for position in range(8):
        switch(session, position)
        qtbot.waitUntil(lambda: g30.value == session.run.read(Address(Area.G, 30)))
        assert g30.dec_label.text() == str(g30.value)
        assert g30.hex_label.text() == f"{g30.value:02X}h"
        seen.add(g30.value)
    assert len(seen) == 8  # each switch position gives its own override code


def test_click_forces_an_input_and_release(
        qtbot: QtBot, spindle: tuple[PlcSession, BitDisplayDock]) -> None:
    session, dock = spindle
    x2 = dock.rows[2]
    switch(session, 0)
    assert x2.bit_texts() == "00000000"
    qtbot.mouseClick(x2.bits[1], Qt.MouseButton.LeftButton)  # X2.1 forced to 1
    assert {(e.address, e.value) for e in session.run.forces()} == {(X2[1], True)}
    session.run_scans(1)
    qtbot.waitUntil(lambda: x2.bit_texts() == "00000010")
    assert dock.rows[1].value == session.run.read(Address(Area.G, 30))
    assert "Forced to 1" in x2.bits[1].toolTip()
    assert "border:2px" in x2.bits[1].styleSheet()
    session.set_bit(X2[1], 0)  # the machine cannot beat a force
    session.run_scans(1)
    assert x2.bit_texts() == "00000010"
    qtbot.mouseClick(x2.bits[1], Qt.MouseButton.LeftButton)  # forced to the other value: 0
    assert {(e.address, e.value) for e in session.run.forces()} == {(X2[1], False)}
    session.release(X2[1])
    assert session.run.forces() == []
    assert "border:2px" not in x2.bits[1].styleSheet()


def test_outputs_are_not_forced_by_a_click(
        qtbot: QtBot, spindle: tuple[PlcSession, BitDisplayDock]) -> None:
    session, dock = spindle
    qtbot.mouseClick(dock.rows[1].bits[0], Qt.MouseButton.LeftButton)  # G30.0
    assert session.run.forces() == []


def test_stop_freezes(qtbot: QtBot, spindle: tuple[PlcSession, BitDisplayDock]) -> None:
    session, dock = spindle
    x12 = dock.rows[0]
    session.set_bit(parse_address("X12.0"), 1)
    session.run_scans(1)
    qtbot.waitUntil(lambda: x12.value == 1)
    qtbot.mouseClick(dock.stop_button, Qt.MouseButton.LeftButton)
    session.set_bit(parse_address("X12.7"), 1)
    session.run_scans(3)
    assert x12.value == 1 and x12.bit_texts() == "00000001"
    qtbot.mouseClick(dock.start_button, Qt.MouseButton.LeftButton)
    assert x12.value == 0x81


def test_any_area_and_errors(qtbot: QtBot, spindle: tuple[PlcSession, BitDisplayDock]) -> None:
    session, dock = spindle
    switch(session, 3)
    dock.set_address(3, "r0102")
    assert dock.rows[3].edit.text() == "R102"
    assert dock.rows[3].value == 1 << 3
    dock.set_address(4, "Q5")
    assert dock.rows[4].error.isVisibleTo(dock)
    assert "unknown area" in dock.rows[4].error.text()
    assert not dock.rows[4].bits[0].isVisibleTo(dock)
    dock.set_address(4, "X12.3")
    assert "without a bit" in dock.rows[4].error.text()
    dock.set_address(4, "X128")  # the 30i map has X0-X127, X200-X327, ... (X200 exists)
    assert "0-127, 200-327" in dock.rows[4].error.text()
    dock.set_address(4, "")
    assert not dock.rows[4].error.isVisibleTo(dock)
    assert dock.rows[4].value is None


def test_tooltip_names_signals(spindle: tuple[PlcSession, BitDisplayDock]) -> None:
    _session, dock = spindle
    g30_0 = dock.rows[1].bits[0].toolTip()
    assert g30_0.startswith("G30.0  SOV")
    assert "Click" not in g30_0  # G is not an input
    assert "Click" in dock.rows[2].bits[1].toolTip()


def test_turkish_texts(qtbot: QtBot, spindle: tuple[PlcSession, BitDisplayDock]) -> None:
    _session, dock = spindle
    language = UiLanguage()
    try:
        language.apply("tr")
        qtbot.waitUntil(lambda: dock.start_button.text() == "BAŞLAT")
        assert dock.windowTitle() == "PLC BIT GÖSTERİMİ"
        assert dock.stop_button.text() == "DURDUR"
        dock.set_address(4, "Q5")
        assert "bilinmeyen alan" in dock.rows[4].error.text()
    finally:
        language.apply("en")


def test_a_tall_dock_keeps_the_boxes_together_at_the_top(
        qtbot: QtBot, spindle: tuple[PlcSession, BitDisplayDock]) -> None:
    """On a large screen the dock is taller than its eight boxes: the room goes below them,
    not between the header and the rows (they floated in the middle at 1920×1080)."""
    _session, dock = spindle
    dock.resize(520, 900)
    first, second = dock.rows[0].edit, dock.rows[1].edit
    qtbot.waitUntil(lambda: dock.height() == 900)
    qtbot.wait(20)
    assert second.y() - first.y() <= 2 * first.height()
    assert first.y() - dock.address_header.y() <= 2 * first.height()
    last = dock.rows[-1].edit
    assert last.mapTo(dock, last.rect().bottomLeft()).y() < dock.height() // 2
