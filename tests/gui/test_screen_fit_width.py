"""Issue 31 item 4: fit width fits the program's typical networks at a readable zoom, not its
one widest network, and says what it fitted."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QPointF
from pytestqt.qtbot import QtBot

from ladderworks.gui.editor.geometry import CELL_W, LEFT
from ladderworks.gui.editor.zoom import READABLE
from ladderworks.gui.main_window import MainWindow
from tests.gui.test_small_screen import on_the_panel


def one_wide_network(path: Path) -> Path:
    """40 networks of one contact and a coil, and one of 24 contacts in series."""
    narrow = "".join(f"RD X{k}.0\nWRT Y{k}.0\n" for k in range(40))
    wide = "RD X50.0\n" + "".join(f"AND X{51 + k // 8}.{k % 8}\n" for k in range(23))
    path.write_text(f"%@3\n{narrow}{wide}WRT Y50.0\n%\n", "utf-8")
    return path


def rail_x(window: MainWindow, network: int) -> int:
    """The viewport x of a network's right rail."""
    view = window.editor
    columns = view.networks[network].columns
    return view.mapFromScene(QPointF(LEFT + (columns + 1) * CELL_W, 0)).x()


def test_one_wide_network_does_not_shrink_every_rung(window: MainWindow, qtbot: QtBot,
                                                     tmp_path: Path) -> None:
    assert window.load(one_wide_network(tmp_path / "wide.LAD"))
    on_the_panel(window, qtbot)
    view = window.editor
    wide = max(range(len(view.networks)), key=lambda k: view.networks[k].columns)
    assert view.networks[wide].columns >= 24
    window.actions_by_name["action_zoom_fit_width"].trigger()
    assert view.zoom() >= READABLE  # the whole program's width would need ~0.3
    assert view.zoom() > 0.7  # the typical network (11 columns) fills the 750-px view
    for network in (0, 20, 39):
        assert 0 < rail_x(window, network) <= view.viewport().width()
    assert rail_x(window, wide) > view.viewport().width()  # the wide one scrolls
    # the 41 networks drawn (the blank one to draw in is none of them: issue 38)
    text = "Fit width: 40 of 41 networks fit the window's width; the 1 wider ones scroll sideways"
    assert window.zoom_label.toolTip() == text
    assert window.statusBar().currentMessage() == text
    window.set_language("tr")
    assert window.zoom_label.toolTip().startswith("Genişliğe sığdır: 41 devreden 40")
    window.set_language("en")


def test_a_program_that_fits_says_so(window: MainWindow, qtbot: QtBot, tmp_path: Path) -> None:
    path = tmp_path / "small.LAD"
    path.write_text("%@3\nRD X0.0\nWRT Y0.0\n%\n", "utf-8")
    assert window.load(path)
    window.actions_by_name["action_zoom_fit_width"].trigger()
    assert window.zoom_label.toolTip() == "Fit width: every network fits the window's width"
    window.actions_by_name["action_zoom_in"].trigger()
    assert window.zoom_label.toolTip() == "Zoom"
