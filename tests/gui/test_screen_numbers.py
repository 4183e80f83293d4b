"""Issue 31 item 3: network numbers of five digits are drawn whole (screen and PDF draw the
same item), and Find names both the console's network number and the LADDER-III label."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtGui import QColor, QFont, QFontMetricsF, QImage, QPainter
from PySide6.QtWidgets import QStyleOptionGraphicsItem
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.ladder.model import Contact, LadderNetwork
from ladderworks.gui.editor.geometry import LEFT
from ladderworks.gui.editor.labelled_item import LabelledNetworkItem
from ladderworks.gui.editor.network_item import network_tag
from ladderworks.gui.main_window import MainWindow


def ink_columns(item: LabelledNetworkItem, top: int, bottom: int) -> list[int]:
    """The x of every column left of the rail with a dark pixel between `top` and `bottom`."""
    rect = item.boundingRect()
    image = QImage(int(rect.width()), int(rect.height()), QImage.Format.Format_RGB32)
    image.fill(QColor("white"))
    painter = QPainter(image)
    item.paint(painter, QStyleOptionGraphicsItem(), None)
    painter.end()
    return [x for x in range(int(LEFT) - 4)
            if any(QColor(image.pixel(x, y)).lightness() < 160 for y in range(top, bottom))]


@pytest.mark.parametrize("language", ["en", "tr"])
def test_a_five_digit_network_number_is_drawn_whole(window: MainWindow, language: str) -> None:
    """N10821 (D10821 in Turkish) takes its whole width left of the rail, not its last 36 px
    ("0821"); the LADDER-III label under it too."""
    window.set_language(language)
    network = LadderNetwork(cells={(0, 0): Contact(parse_address("X0.0"))}, label="N10820")
    item = LabelledNetworkItem(network, 10821, lambda _address: None)
    font = QFont()
    font.setPointSizeF(9.5)
    font.setBold(True)
    wide = QFontMetricsF(font).horizontalAdvance(network_tag(10821))
    wire = int(item.rows.wire)
    number = ink_columns(item, 0, wire - 4)
    assert number and number[0] > 0, number[:3]  # room left of the first letter
    assert number[-1] - number[0] >= wide * 0.9, (number[0], number[-1], wide)
    label = ink_columns(item, wire + 2, wire + 12)
    assert label and label[0] > 0
    window.set_language("en")


def test_find_names_the_network_number_and_its_label(window: MainWindow, qtbot: QtBot,
                                                     tmp_path: Path) -> None:
    path = tmp_path / "labels.LAD"
    path.write_text("%@3\n" + "".join(
        f"N{k:05d}:\nRD X0.{k % 8}\nWRT Y{k}.0\n" for k in range(15)) + "%\n", "utf-8")
    assert window.load(path)
    assert window.editor.networks[14].label == "N00014"
    dialog = window.show_find()
    assert dialog is not None
    dialog.find_text.setText("Y14.0")
    assert dialog.find_next() is not None
    assert dialog.message.text() == "1 of 1: N15 (N00014), Y14.0"
    window.set_language("tr")
    assert dialog.find_next() is not None
    assert dialog.message.text().startswith("1 / 1: D15 (N00014)"), dialog.message.text()
    window.set_language("en")
