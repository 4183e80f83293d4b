"""Rows as tall as their names: with comments shown, a network none of whose elements has a
comment keeps the shorter address-and-symbol rows; clicks, the PLC diagnostic's live power and
printing follow each network's own rows."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QPointF, Qt
from PySide6.QtGui import QAction
from pytestqt.qtbot import QtBot

from ladderworks.core.il import parse
from ladderworks.gui.editor.geometry import (
    CELL_W,
    COMMENT_H,
    LEFT,
    ROW_METRICS,
    Layout,
    NameDisplay,
)
from ladderworks.gui.editor.label_text import shows_comment
from ladderworks.gui.main_window import MainWindow
from tests.gui.plc_docks_help import plc_docks
from tests.real_programs import real_bytes

TALL = ROW_METRICS[NameDisplay.COMMENT].height
SHORT = ROW_METRICS[NameDisplay.SYMBOL].height
# Network 1: a contact with the user's comment; network 2: R bits (no comment anywhere).
MIXED = """%@3
RD X0.0   // START BUTONU
OR R0.1
WRT R1.0
RD R0.2
OR R0.3
WRT R1.1
%
"""


def _show(window: MainWindow, display: NameDisplay) -> None:
    action = window.findChild(QAction, f"action_names_{display.value}")
    assert action is not None
    action.trigger()


def _load(window: MainWindow, tmp_path: Path, name: str, data: bytes) -> None:
    path = tmp_path / name
    path.write_bytes(data)
    assert window.load(path)


def test_a_real_fragment_with_comments_shown_is_shorter_than_with_every_row_tall(
        window: MainWindow, tmp_path: Path) -> None:
    _load(window, tmp_path, "mstb.LAD", real_bytes("FANUC_X22_FRAG_fc62180_DECODE_MSTB"))
    _show(window, NameDisplay.COMMENT)
    view = window.editor
    networks = view.networks
    every_row_tall = Layout()  # before: one row height for the whole view
    every_row_tall.rebuild(networks)
    assert view.layout_.total_height() < every_row_tall.total_height()
    heights = {rows.height for rows in view.layout_.rows}
    assert heights == {TALL, SHORT}  # some networks have comments to show, some have none
    for network, rows in zip(networks, view.layout_.rows, strict=True):
        assert (rows.height == TALL) == shows_comment(network, view.describe_address)
    _show(window, NameDisplay.SYMBOL)  # without comments every row is short
    assert {rows.height for rows in view.layout_.rows} == {SHORT}


def test_clicks_land_on_the_cell_under_them_in_tall_and_short_networks(
        window: MainWindow, tmp_path: Path, qtbot: QtBot) -> None:
    _load(window, tmp_path, "mixed.LAD", MIXED.encode())
    _show(window, NameDisplay.COMMENT)
    view = window.editor
    assert [rows.height for rows in view.layout_.rows[:2]] == [TALL, SHORT]
    assert view.layout_.tops[1] == (view.networks[0].rows + 1) * TALL + 10  # + the gap
    for index, height in ((0, TALL), (1, SHORT)):
        for row in (0, 1):
            # the middle of (row, column 2), reckoned from the row heights alone
            y = view.layout_.tops[index] + len(view.networks[index].comments) * COMMENT_H
            scene = QPointF(LEFT + 2.5 * CELL_W, y + (row + 0.5) * height)
            view.ensureVisible(scene.x(), scene.y(), 1, 1)
            qtbot.mouseClick(view.viewport(), Qt.MouseButton.LeftButton,
                             pos=view.mapFromScene(scene))
            assert view.cursor_cell == (index, row, 2)
            assert view.cell_rect(index, row, 2).contains(scene)
            assert view.cell_rect(index, row, 2).height() == height


def test_the_diagnostic_views_live_power_lines_up_with_tall_and_short_networks(
        window: MainWindow) -> None:
    docks = plc_docks(window)
    program = parse("%@3\nRD X0.0\nWRT G8.4\nRD R0.2\nOR R0.3\nWRT R1.1\n%\n").program
    assert docks.session.load_program(program).ok
    docks.session.start()
    docks.diagnostic.show()
    _show(window, NameDisplay.COMMENT)
    view = docks.diagnostic.view
    assert [rows.height for rows in view.layout_.rows] == [TALL, SHORT]  # G8.4: the manual's
    for index, (item, overlay) in enumerate(zip(view.network_items, view.live.overlays,
                                                strict=True)):
        assert item.pos() == overlay.pos() and item.pos().y() == view.layout_.tops[index]
        assert item.boundingRect() == overlay.boundingRect()
        assert item.boundingRect().height() == view.layout_.heights[index]
        assert overlay.rows == item.rows == view.layout_.rows[index]
        assert view.cell_rect(index, (0, 0)).height() == item.rows.height
    _show(window, NameDisplay.ADDRESS)
    for item, overlay in zip(view.network_items, view.live.overlays, strict=True):
        assert item.boundingRect() == overlay.boundingRect()
        assert item.pos() == overlay.pos()


def test_the_online_drawings_live_power_follows_the_element_names_choice(
        window: MainWindow) -> None:
    from tests.gui.test_online import online_window

    docks = online_window(window)
    view = window.editor
    for display in (NameDisplay.COMMENT, NameDisplay.ADDRESS, NameDisplay.SYMBOL):
        _show(window, display)
        for index, overlay in enumerate(docks.online.live.overlays):
            assert overlay.pos().y() == view.layout_.tops[index]
            assert overlay.rows == view.layout_.rows[index]
            assert overlay.boundingRect().height() == view.layout_.heights[index]


def test_page_down_lands_on_the_row_a_page_below_in_tall_and_short_networks(
        window: MainWindow, tmp_path: Path, qtbot: QtBot) -> None:
    body = "".join(f"RD X{n}.0   // KAPI {n}\nWRT R{n}.0\nRD R{n}.1\nOR R{n}.2\nOR R{n}.3\n"
                   f"OR R{n}.4\nOR R{n}.5\nWRT R{n}.6\n"
                   for n in range(20))  # a tall network, then a short one of five rows
    _load(window, tmp_path, "long.LAD", f"%@3\n{body}%\n".encode())
    _show(window, NameDisplay.COMMENT)
    window.resize(1024, 600)
    view = window.editor
    view.setFocus()
    view.move_cursor(0, 0, 1)
    page = view.viewport().height() / view.zoom() - TALL  # as GridKeys pages
    short_rows: set[int] = set()  # rows landed on in short networks
    for _ in range(8):
        index, row, _col = view.cursor_cell
        rows = view.layout_.rows[index]
        y = view.layout_.tops[index] + row * rows.height + rows.wire + page
        qtbot.keyClick(view, Qt.Key.Key_PageDown)
        assert view.cursor_cell[:2] > (index, row)  # further down
        assert view.cell_rect(*view.cursor_cell).contains(QPointF(LEFT + 1.5 * CELL_W, y))
        if view.layout_.rows[view.cursor_cell[0]].height == SHORT:
            short_rows.add(view.cursor_cell[1])
    assert max(short_rows) >= 2  # deep in a short network, where 86-pixel rows would miss
    assert {view.layout_.rows[i].height for i in range(view.cursor_cell[0])} == {TALL, SHORT}
