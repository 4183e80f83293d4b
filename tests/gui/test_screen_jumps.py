"""Issue 31 item 5: Find, the cross reference and the error list land their target in the
middle of the view; Find also searches comments and the manual's signal descriptions."""

from __future__ import annotations

from pathlib import Path

from pytestqt.qtbot import QtBot

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.gui.find_texts import TextHit
from ladderworks.gui.main_window import MainWindow
from tests.gui.test_small_screen import on_the_panel


def sixty_networks(path: Path) -> Path:
    """60 networks of a contact and a coil; network 31 has a comment, its contact too."""
    lines = ["%@3"]
    for k in range(60):
        if k == 30:
            lines.append("// SPINDLE ORIENTATION DONE")
        contact = f"RD X{k}.0" + ("  // kapı kilitli" if k == 40 else "")
        lines += [contact, f"WRT Y{k}.0"]
    path.write_text("\n".join(lines) + "\n%\n", "utf-8")
    return path


def in_mid_view(window: MainWindow) -> bool:
    """The cursor's cell is in the middle third of the view, not at an edge."""
    view = window.editor
    rect = view.mapFromScene(view.cell_rect(*view.cursor_cell)).boundingRect()
    height = view.viewport().height()
    return height / 3 <= rect.center().y() <= height * 2 / 3 and rect.bottom() < height


def test_find_lands_the_hit_in_mid_view(window: MainWindow, qtbot: QtBot,
                                        tmp_path: Path) -> None:
    assert window.load(sixty_networks(tmp_path / "sixty.LAD"))
    on_the_panel(window, qtbot)
    dialog = window.show_find()
    assert dialog is not None
    for address in ("Y25.0", "X41.0", "Y12.0"):  # down, further down, and back up
        dialog.find_text.setText(address)
        assert dialog.find_next() is not None
        assert in_mid_view(window), address


def test_the_error_list_and_the_cross_reference_jump_to_mid_view(window: MainWindow,
                                                                 qtbot: QtBot,
                                                                 tmp_path: Path) -> None:
    assert window.load(sixty_networks(tmp_path / "sixty.LAD"))
    on_the_panel(window, qtbot)
    window.go_to_diagnostic(Diagnostic("x", "warning", "a", network=33, cell=(0, 0)))
    assert window.editor.cursor_cell == (33, 0, 0)
    assert in_mid_view(window)
    window.editor.move_cursor(0, 0, 0)
    window.cross_reference.jump_requested.emit(22, (0, 10))
    assert window.editor.cursor_cell[0] == 22
    assert in_mid_view(window)


def test_find_in_comments_and_signal_descriptions(window: MainWindow, qtbot: QtBot,
                                                  tmp_path: Path) -> None:
    assert window.load(sixty_networks(tmp_path / "sixty.LAD"))
    dialog = window.show_find()
    assert dialog is not None
    dialog.find_text.setText("KAPI KİLİTLİ")  # folded: "kapı kilitli" in a // comment
    assert dialog.find_next() is None  # addresses and symbols only
    dialog.in_texts.setChecked(True)
    hit = dialog.find_next()
    assert isinstance(hit, TextHit) and hit.network == 40
    assert window.editor.cursor_cell == (40, 0, 0)
    assert dialog.message.text() == "1 of 1: network 41, X40.0"
    dialog.find_text.setText("orientation")  # a network comment
    hit = dialog.find_next()
    assert isinstance(hit, TextHit) and hit.network == 30 and hit.comment_line == 0
    assert dialog.message.text() == "1 of 1: network 31, network comment"
    assert in_mid_view(window) or window.editor.cursor_cell == (30, 0, 0)
    window.set_language("tr")
    assert dialog.in_texts.text() == "Yorumlarda ve sinyal açıklamalarında da ara"
    window.set_language("en")


def test_find_reads_the_manuals_signal_descriptions(window: MainWindow, tmp_path: Path) -> None:
    """G8.4 is the emergency stop (*ESP) in the manual: "emergency" finds it."""
    path = tmp_path / "esp.LAD"
    path.write_text("%@3\nRD X1.0\nWRT Y1.0\nRD R0.0\nWRT G8.4\n%\n", "utf-8")
    assert window.load(path)
    dialog = window.show_find()
    assert dialog is not None
    dialog.in_texts.setChecked(True)
    dialog.find_text.setText("emergency")
    hit = dialog.find_next()
    assert hit is not None and str(hit.address) == "G8.4"
