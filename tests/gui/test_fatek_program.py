"""A Fatek program in the IDE: opened as ladder, compiled with F9, run, its FUN 94 report in
PLC › ASCII output; saved back byte for byte."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction, QImage, QPainter
from PySide6.QtWidgets import QMenu
from pytestqt.qtbot import QtBot

from ladderworks.core.dialects.fatek import DEVICES
from ladderworks.core.ladder.model import Coil, Contact, FunctionBox
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.translation import UiLanguage
from tests.core.dialects.fatek.test_ascii_format import REPORT

EXAMPLES = Path(__file__).resolve().parents[2] / "resources" / "examples" / "fatek"


def test_report_program_prints_to_the_ascii_output_dock(qtbot: QtBot, window: MainWindow,
                                                        tmp_path: Path) -> None:
    UiLanguage().apply("en")
    for name in ("production_report.lst", "production_report.lst.ascii"):
        (tmp_path / name).write_bytes((EXAMPLES / name).read_bytes())
    path = tmp_path / "production_report.lst"
    assert window.load(path)
    assert window.editor.networks  # shown as ladder, not as text
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert session.run.engine is not None
    start = window.findChild(QAction, "action_plc_start")
    assert start is not None
    start.trigger()
    session.run_scans(2)
    session.set_bit(DEVICES.bit("X0"), 1)
    session.run_scans(2)
    dock = window.plc_docks.ascii_output
    toggle = window.findChild(QAction, "action_dock_ascii_output")
    menu = window.findChild(QMenu, "menu_plc")
    assert toggle is not None and menu is not None and toggle in menu.actions()
    toggle.trigger()
    dock.refresh()
    assert dock.view.toPlainText() == REPORT
    assert dock.summary.text() == "1 output(s) received"
    language = UiLanguage()
    language.apply("tr")
    qtbot.waitUntil(lambda: dock.windowTitle() == "ASCII çıkışı")
    assert dock.summary.text() == "1 çıkış alındı"
    assert dock.clear_button.text() == "Temizle"
    dock.clear_button.click()
    assert dock.view.toPlainText() == ""
    language.apply("en")
    assert window.save()
    assert path.read_bytes() == (EXAMPLES / "production_report.lst").read_bytes()


def test_ascii_file_problems_are_shown_under_the_text(window: MainWindow,
                                                      tmp_path: Path) -> None:
    UiLanguage().apply("en")
    path = tmp_path / "p.lst"
    path.write_text("ORG X0\nOUT Y0\n", encoding="utf-8")
    (tmp_path / "p.lst.ascii").write_text("[R1000]\n'open,END\n", encoding="utf-8")
    assert window.load(path)
    summary = window.plc_docks.ascii_output.summary.text()
    assert "p.lst.ascii, line 2:" in summary and "never closed" in summary


def test_the_console_draws_a_fatek_program_in_fatek_spelling(window: MainWindow) -> None:
    assert window.load(EXAMPLES / "conveyor.lst")
    assert window.model.dialect == "fatek"
    networks = window.model.networks
    contact = networks[0].cells[(0, 0)]
    assert isinstance(contact, Contact)
    assert contact.address == DEVICES.bit("X0")
    window.editor.make_visible_items()
    items = [item for _index, item in window.editor.network_items.made()]
    first = min(items, key=lambda item: item.number)
    assert first.label_lines(contact)[0] == "X0"  # Fatek's spelling, not X0.0
    coil = next(cell for cell in networks[0].cells.values() if isinstance(cell, Coil))
    assert first.label_lines(coil)[0] == "Y0"


def test_a_box_draws_its_fo_pins_with_their_coils_in_one_network(window: MainWindow,
                                                                  tmp_path: Path) -> None:
    """CMP's FO0, FO1, FO2 as the box's own output pins, each with its coil, as WinProladder
    draws them: one network, painted; saved unchanged byte for byte."""
    path = tmp_path / "cmp.lst"
    data = b"ORG X0\nFUN 17 CMP\n Sa: R0\n Sb: R1\nFO 0\nOUT Y0\nFO 1\nOUT Y1\nFO 2\nOUT Y2\n"
    path.write_bytes(data)
    assert window.load(path)
    networks = [n for n in window.model.networks if not n.is_empty()]
    assert len(networks) == 1
    box = networks[0].cells[(0, 8)]
    assert isinstance(box, FunctionBox) and [o for o, _ in box.outputs] == [1, 2]
    window.editor.make_visible_items()
    items = [item for _index, item in window.editor.network_items.made()]
    assert items
    image = QImage(800, 400, QImage.Format.Format_ARGB32)
    painter = QPainter(image)
    items[0].scene().render(painter)
    painter.end()
    assert window.save()
    assert path.read_bytes() == data


def test_a_tr_branch_is_one_rung_from_its_branch_point(window: MainWindow,
                                                       tmp_path: Path) -> None:
    """`OUT TR 0` … `LD TR 0` as WinProladder draws it: one network, X0 then the branch point,
    X1 → Y0 above X2 → Y1; painted; saved unchanged byte for byte."""
    path = tmp_path / "branch.lst"
    data = b"ORG X0\nOUT TR 0\nAND X1\nOUT Y0\nLD TR 0\nAND X2\nOUT Y1\n"
    path.write_bytes(data)
    assert window.load(path)
    networks = [n for n in window.model.networks if not n.is_empty()]
    assert len(networks) == 1
    net = networks[0]
    assert net.listing is None and net.links == {(0, 1)}
    texts = {cell: DEVICES.format(e.address) for cell, e in net.cells.items()
             if isinstance(e, Contact | Coil) and e.address is not None}
    end = net.columns
    assert texts == {(0, 0): "X0", (0, 1): "X1", (0, end): "Y0", (1, 1): "X2", (1, end): "Y1"}
    window.editor.make_visible_items()
    items = [item for _index, item in window.editor.network_items.made()]
    assert items
    image = QImage(800, 400, QImage.Format.Format_ARGB32)
    painter = QPainter(image)
    items[0].scene().render(painter)
    painter.end()
    assert window.save()
    assert path.read_bytes() == data
