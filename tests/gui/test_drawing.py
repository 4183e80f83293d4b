"""Draw the seed manual's example networks with clicks and keys, save, compare with the files."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
from PySide6.QtCore import Qt

from ladderworks.core.il import Program, parse, parse_file
from ladderworks.gui.main_window import MainWindow
from ladderworks.paths import EXAMPLES
from tests.gui.conftest import Drawer, type_text

COIL = 10  # the coil column of a new network (10 contact columns)


def draw_or_single(d: Drawer) -> None:
    d.comment(0, " 1- TEKLİ OR UYGULAMASI")
    d.element(0, 0, 0, "I", "F9.6 // M01 KOD ÇÖZÜCÜ")
    d.element(0, 0, 1, "I", "F2.5 // İSTEĞE BAĞLI DURMA")
    d.element(0, 0, 2, "I", "F7.0 // M SİNYALİ")
    d.element(0, 0, COIL, "W", "G8.5 // CNC YE STOP BİLGİSİNİ GÖNDERİYORUZ.")
    d.line(0, (0, 3), (0, COIL))
    d.element(0, 1, 0, "I", "F9.7 // M00 KOD ÇÖZÜCÜ")
    d.line(0, (1, 1), (1, 2))
    d.line(0, (0, 2), (1, 2))
    d.element(0, 2, 0, "I", "R11.1 // STOP BUTONUNA BASILDI")
    d.line(0, (2, 1), (2, 3))
    d.line(0, (0, 3), (2, 3))


def draw_or_double(d: Drawer) -> None:
    d.comment(0, " 2- İKİLİ OR UYGULAMASI")
    d.element(0, 0, 0, "N", "F9.4 // M30 KOD ÇÖZÜCÜ SİNYALİ")
    d.element(0, 0, 1, "I", "R1.0")
    d.element(0, 0, COIL, "O", "R1.4 // M30 SİNYALİNİN DÜŞEN KENARINDA İÇSEL ROLE ÇEKER.")
    d.line(0, (0, 2), (0, COIL))
    d.element(0, 1, 0, "I", "R1.4")
    d.element(0, 1, 1, "N", "R1.6")
    d.line(0, (0, 2), (1, 2))


def draw_or_triple(d: Drawer) -> None:
    d.comment(0, " 3- ÜÇLÜ OR UYGULAMASI")
    d.element(0, 0, 0, "N", "F1.4 // İŞ MİLİ ENABLE")
    d.element(0, 0, COIL, "O", "Y0.0 // İŞ MİLİ DUR ROLESİ-PROJEYE GÖRE DEĞİŞTİRİLECEK ÇIKIŞ")
    d.line(0, (0, 1), (0, COIL))
    d.element(0, 1, 0, "I", "Y0.0")
    d.element(0, 1, 1, "N", "Y0.1")
    d.element(0, 1, 2, "N", "Y0.2")
    d.line(0, (0, 3), (1, 3))


def draw_or_triple_and(d: Drawer) -> None:
    d.comment(0, " 4- ÜÇLÜ OR , VE UYGULAMASI")
    d.element(0, 0, 0, "I", "F7.0 // M SİNYALİ")
    d.element(0, 0, 1, "I", "R3.3 // M03 (İŞ MİLİ SAĞA DÖN) İÇSEL ROLESİ")
    d.element(0, 0, 2, "N", "R3.4")
    d.element(0, 0, COIL, "O",
              "Y0.1 // İŞ MİLİ SAĞA DÖN ROLESİ-PROJEYE GÖRE DEĞİŞTİRİLECEK ÇIKIŞ")
    d.line(0, (0, 3), (0, COIL))
    d.element(0, 1, 0, "I", "Y0.1")
    d.element(0, 1, 1, "I", "F1.4 // İŞ MİLİ ENABLE")
    d.line(0, (0, 2), (1, 2))


def draw_rising_edge(d: Drawer) -> None:
    d.comment(0, " 5- YÜKSELEN KENAR UYGULAMASI")
    d.element(0, 0, 0, "I", "X17.0 // START BUTONU İÇİN YÜKSELEN KENAR SİNYALİ OLUŞTURULUYOR.")
    d.element(0, 0, COIL, "O", "R10.0 // START BUTONUNU İÇSEL ROLEYE ATIYORUZ.")
    d.line(0, (0, 1), (0, COIL))
    d.element(1, 0, 0, "I", "X17.0 // BU BUTON YERİNE KENDİ GİRİŞİMİZİ EKLEYECEĞİZ.")
    d.element(1, 0, 1, "N", "R10.0")
    d.element(1, 0, COIL, "O", "R11.0 // START BUTONUNUN YUKSELEN KENARINDA İÇSEL ROLE ÇEKER")
    d.line(1, (0, 2), (0, COIL))


def draw_timer_relay(d: Drawer) -> None:
    d.comment(0, " 6- ZAMAN ROLESİ UYGULAMASI")
    d.element(0, 0, 0, "I", "R1.4 // M30 ROLESİ")
    d.key("F")  # the function tool; TMR is first in the drop-down
    d.click(0, 0, 1)
    dialog = d.view.edits.function_dialog
    assert dialog is not None
    d.qtbot.waitUntil(dialog.isVisible)
    d.qtbot.keyClick(dialog.table, "1")
    d.qtbot.keyClick(dialog.table.focusWidget() or dialog.table, Qt.Key.Key_Return)
    type_text(d.qtbot, dialog.comment, "ZAMAN ROLESİ İLE")
    with d.qtbot.waitSignal(dialog.accepted):
        d.qtbot.keyClick(dialog.comment, Qt.Key.Key_Return)
    d.line(0, (0, 3), (0, COIL))
    d.element(0, 0, COIL, "O", "R1.7 // GECİKEREK ÇEKEN M30 SİNYALİ BİLGİSİ")


def draw_spindle_override(d: Drawer) -> None:
    for line in (" İŞ MİLİ KODLAMASI: ROTARY SWITCH (X2.1 X2.3 X2.5) -> R102.0-7 -> G30 "
                 "(%10 ... %150)",
                 " 1- ÖNCE ROTARY SWITCH İLE GİRİŞLERİ BINARY KODLUYORUZ.",
                 " İŞ MİLİ DEVİR AŞIMI, HARİCİ GİRİŞLERİ OKUYUP İÇSEL ROLELERE YAZIYORUZ.",
                 "******************** POZİSYON 0********************"):
        d.comment(0, line)
    d.element(0, 0, 0, "N", "X2.1")
    d.element(0, 0, 1, "N", "X2.3")
    d.element(0, 0, 2, "N", "X2.5")
    d.element(0, 0, COIL, "O", "R102.0")
    d.line(0, (0, 3), (0, COIL))


DRAWINGS: dict[str, tuple[Callable[[Drawer], None], int]] = {
    # example file: (drawing, number of networks of the file it draws)
    "or_single.LAD": (draw_or_single, 1),
    "or_double.LAD": (draw_or_double, 1),
    "or_triple.LAD": (draw_or_triple, 1),
    "or_triple_and.LAD": (draw_or_triple_and, 1),
    "rising_edge.LAD": (draw_rising_edge, 2),
    "timer_relay.LAD": (draw_timer_relay, 1),
    "spindle_override.LAD": (draw_spindle_override, 1),
}


def first_networks(path: Path, count: int) -> Program:
    program = parse_file(path).program
    program.networks = program.networks[:count]
    program.trailer = []
    return program


@pytest.mark.parametrize("name", sorted(DRAWINGS))
def test_draw_example_and_save(name: str, window: MainWindow, drawer: Drawer,
                               tmp_path: Path) -> None:
    draw, count = DRAWINGS[name]
    draw(drawer)
    target = tmp_path / name
    with drawer.qtbot.waitSignal(window.file_saved):
        assert window.save_to(target)
    saved = parse(target.read_text("utf-8"))
    assert saved.ok, saved.diagnostics
    assert saved.program == first_networks(EXAMPLES / name, count)

    stack = window.editor.undo_stack
    assert stack.count() > 0
    while stack.canUndo():
        stack.undo()
    assert window.editor.is_empty()
    assert len(window.editor.networks) == 1
    program, diagnostics = window.editor.program()
    assert program == Program() and diagnostics == []
