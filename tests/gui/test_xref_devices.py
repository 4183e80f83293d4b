"""Cross reference of a Delta T0 / C0 (issue 38, item 5): the box and every contact reading it,
named as the dialect names them; the field's example in the program's own devices (item 8)."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from pytestqt.qtbot import QtBot

from ladderworks.cli import main as cli_main
from ladderworks.core.address import Area
from ladderworks.core.ladder.model import Contact
from ladderworks.gui.main_window import MainWindow
from tests.gui.conftest import type_text

DELTA = """; T0 and C0 with the contacts that read them
LD     X0
TMR  T0 K10
LD     X1
AND    T0
OUT    Y0
LD     X2
ANI    T0
CNT  C0 K5
LD     C0
MOV  K5 D10
END
"""


def _rows(window: MainWindow) -> list[tuple[str, str, str]]:
    model = window.cross_reference.model
    return [(model.index(r, 0).data(), model.index(r, 2).data(), model.index(r, 5).data())
            for r in range(model.rowCount())]


def test_t0_and_c0_list_their_box_and_their_contacts(qtbot: QtBot, window: MainWindow,
                                                     tmp_path: Path) -> None:
    path = tmp_path / "t0.txt"
    path.write_text(DELTA, "utf-8")
    assert window.load(path)
    dock = window.cross_reference
    window.actions_by_name["action_dock_cross_reference"].trigger()
    qtbot.waitUntil(dock.table.isVisible)
    dock.query.clear()
    type_text(qtbot, dock.query, "T0")
    qtbot.keyClick(dock.query, Qt.Key.Key_Return)
    assert _rows(window) == [("T0", "1", "TMR timer"), ("T0", "2", "Contact"),
                             ("T0", "3", "NOT contact")]
    assert dock.summary.text().startswith("T0 — uses: 3")
    window.editor.cursor_cell = next(  # the LD C0 contact: Tools › Cross reference
        (index, *cell) for index, network in enumerate(window.editor.networks)
        for cell, element in network.cells.items()
        if isinstance(element, Contact) and element.address is not None
        and element.address.area is Area.C)
    window.findChild(QAction, "action_cross_reference").trigger()
    assert dock.query.text() == "C0"
    assert [row[2] for row in _rows(window)] == ["CNT counter", "Contact"]
    dock.query.clear()
    type_text(qtbot, dock.query, "D10")
    qtbot.keyClick(dock.query, Qt.Key.Key_Return)
    assert [row[2] for row in _rows(window)] == ["MOV output"]
    assert "R100" not in dock.query.placeholderText()  # no FANUC example for a Delta program
    assert "T0" in dock.query.placeholderText()


def test_the_cli_lists_the_contacts_of_t0(tmp_path: Path, capsys) -> None:
    path = tmp_path / "t0.txt"
    path.write_text(DELTA, "utf-8")
    assert cli_main(["xref", str(path), "T0"]) == 0
    lines = capsys.readouterr().out.splitlines()[1:]
    assert [line.split()[6] for line in lines] == ["TMR", "AND", "ANI"]
