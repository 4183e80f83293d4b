"""A SimaticML block export in the IDE: File › Open with its folder's tag table, compiled with
F9, run, a tag set, a coil seen; saved back byte for byte; a refused (entity) export is shown
with its diagnostic and not rewritten."""

from __future__ import annotations

import shutil
from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from pytestqt.qtbot import QtBot

from ladderworks.core.dialects.s7.devices import parse_absolute
from ladderworks.gui.main_window import MainWindow

EXAMPLES = Path(__file__).resolve().parents[2] / "resources" / "examples" / "s7-xml"


def test_an_xml_block_opens_runs_and_saves_as_read(qtbot: QtBot, window: MainWindow,
                                                   tmp_path: Path) -> None:
    folder = tmp_path / "jumps"
    shutil.copytree(EXAMPLES / "jumps", folder)
    path = folder / "Main.xml"
    assert window.load(path)
    assert window.editor.networks
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert session.run.engine is not None
    start = window.findChild(QAction, "action_plc_start")
    assert start is not None
    start.trigger()
    motor, _ = parse_absolute("%Q0.2")
    session.run_scans(2)
    assert session.run.bit(motor) == 0
    session.set_bit(parse_absolute("%I0.2")[0], 1)  # "Start"
    session.run_scans(2)
    assert session.run.bit(motor) == 1
    assert window.save()
    assert path.read_bytes() == (EXAMPLES / "jumps" / "Main.xml").read_bytes()


def test_an_export_with_entities_is_refused_and_kept(window: MainWindow, tmp_path: Path) -> None:
    path = tmp_path / "Main.xml"
    text = ('<?xml version="1.0"?><!DOCTYPE d [<!ENTITY a "aaaa">]>\n<Document>'
            "<SW.Blocks.OB><AttributeList><Name>&a;</Name></AttributeList></SW.Blocks.OB>"
            "</Document>\n")
    path.write_text(text, "utf-8")
    window.load(path)
    assert window.model.showing_text  # the errors listed, the text shown as it is
    assert not any(net.cells for net in window.editor.networks)
    tree = window.errors.tree
    shown = [tree.topLevelItem(i).text(c) for i in range(tree.topLevelItemCount())
             for c in range(tree.columnCount())]
    assert any("DOCTYPE" in text for text in shown), shown
    window.save()
    assert path.read_text("utf-8") == text
