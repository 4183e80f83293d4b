"""Issue 38 item 3: a Delta program's END stays last: a network drawn in the empty network
goes before END, END cannot be deleted, and the palette offers END."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QApplication

from ladderworks import paths
from ladderworks.core.il.reading import parse_file
from ladderworks.core.instructions import Flow
from ladderworks.core.ladder.model import FunctionBox, LadderNetwork
from ladderworks.gui.main_window import MainWindow
from tests.gui.conftest import Drawer


def _action(window: MainWindow, name: str) -> QAction:
    action = window.findChild(QAction, name)
    assert action is not None, name
    return action


def _is_end(network: LadderNetwork) -> bool:
    boxes = [e for _c, e in network.elements() if isinstance(e, FunctionBox)]
    return len(boxes) == 1 and boxes[0].spec.flow is Flow.PROGRAM_END


def test_a_network_drawn_at_the_end_goes_before_end(window: MainWindow, drawer: Drawer,
                                                    tmp_path: Path) -> None:
    copy = tmp_path / "t.txt"
    copy.write_bytes((paths.EXAMPLES / "delta" / "timer_t0.txt").read_bytes())
    assert window.load(copy)
    editor = window.editor
    blank = len(editor.networks) - 2  # the "+" network: before END, which is last
    assert editor.network_items[blank].is_new
    coil = editor.networks[blank].coil_column
    drawer.element(blank, 0, 0, "I", "X5")
    drawer.element(blank, 0, coil, "O", "Y5")
    drawer.line(blank, (0, 1), (0, coil))
    drawer.element(blank + 1, 0, 0, "I", "X6")  # the next "+" network: still before END
    drawer.element(blank + 1, 0, coil, "O", "Y6")
    drawer.line(blank + 1, (0, 1), (0, coil))
    last = editor.networks[-1]
    assert _is_end(last)
    assert editor.network_items[len(editor.networks) - 2].is_new
    end_item = editor.network_items[len(editor.networks) - 1]
    assert end_item.number == len(editor.networks) - 1  # END counted as the program counts it
    qtbot = drawer.qtbot
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert not [d for d in window.errors.diagnostics() if d.is_error]  # no after-end
    assert window.save_to(copy)
    assert copy.read_text(encoding="utf-8").split()[-9:] == [
        "LD", "X5", "OUT", "Y5", "LD", "X6", "OUT", "Y6", "END"]
    assert parse_file(copy).ok


def test_end_is_not_deleted_and_is_in_the_palette(window: MainWindow, drawer: Drawer,
                                                  tmp_path: Path) -> None:
    copy = tmp_path / "t.txt"
    copy.write_bytes((paths.EXAMPLES / "delta" / "timer_t0.txt").read_bytes())
    assert window.load(copy)
    editor = window.editor
    end = len(editor.networks) - 1
    messages: list[str] = []
    editor.message.connect(messages.append)
    drawer.click(end, 0, 0)
    assert editor.cursor_cell[0] == end
    drawer.key(Qt.Key.Key_Delete)  # DEL on the END box
    _action(window, "action_delete_network").trigger()
    QApplication.processEvents()
    assert len(editor.networks) == end + 1
    assert _is_end(editor.networks[end])
    assert messages and all("END" in m and "last" in m for m in messages[-2:])
    assert not window.model.is_modified()
    combo = window.tool_palette.functions
    assert "END" in [combo.itemText(i).split()[0] for i in range(combo.count())]


def test_a_fatek_listing_keeps_its_end_after_a_network_drawn_at_the_end(
        window: MainWindow, drawer: Drawer, tmp_path: Path) -> None:
    copy = tmp_path / "c.lst"
    copy.write_bytes((paths.EXAMPLES / "fatek" / "conveyor.lst").read_bytes())
    assert window.load(copy)
    editor = window.editor
    blank = len(editor.networks) - 1  # a listing's END is not a network: written after all
    coil = editor.networks[blank].coil_column
    drawer.element(blank, 0, 0, "I", "X20")
    drawer.element(blank, 0, coil, "O", "Y20")
    drawer.line(blank, (0, 1), (0, coil))
    assert window.save_to(copy)
    words = copy.read_text(encoding="utf-8").split()
    assert words[-1] == "END" and words.index("Y20") < len(words) - 1
    assert parse_file(copy).ok
