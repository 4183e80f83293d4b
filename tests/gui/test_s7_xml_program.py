"""A SimaticML export in the IDE: a refused (entity) export is shown with its diagnostic and not
rewritten (the opened, run and saved block: test_s7_program.py, with its SD twin)."""

from __future__ import annotations

from pathlib import Path

from ladderworks.gui.main_window import MainWindow

EXAMPLES = Path(__file__).resolve().parents[2] / "resources" / "examples" / "s7-xml"


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
