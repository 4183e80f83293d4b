"""File › Print preview…: the program's pages as they will print, in the UI language."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtGui import QAction
from PySide6.QtPrintSupport import QPrintPreviewWidget
from PySide6.QtWidgets import QMenu

from ladderworks.gui import print_actions
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.print_pages import LadderPages
from tests.real_programs import real_bytes


def test_print_preview_shows_every_page_of_the_program(window: MainWindow,
                                                      tmp_path: Path) -> None:
    source = tmp_path / "mstb.LAD"
    source.write_bytes(real_bytes("FANUC_X22_FRAG_fc62180_DECODE_MSTB"))
    assert window.load(source)
    file_menu = window.findChild(QMenu, "menu_file")
    action = window.findChild(QAction, "action_print_preview")
    assert action is not None and action in file_menu.actions()
    assert action.text() == "Print pre&view..."
    dialog = window.printing.make_preview()
    preview = dialog.findChild(QPrintPreviewWidget)
    assert preview is not None
    preview.updatePreview()  # asks for the pages (paintRequested), as showing it does
    printer = print_actions.new_printer()
    rect = printer.pageLayout().paintRectPixels(print_actions.PRINT_DPI)
    plan = LadderPages(print_actions.print_job(window), rect.width(), rect.height())
    assert preview.pageCount() == len(plan.pages) > 1
    assert dialog.windowTitle() == "Print preview"
    dialog.deleteLater()


def test_print_preview_speaks_turkish(window: MainWindow) -> None:
    window.set_language("tr")
    action = window.findChild(QAction, "action_print_preview")
    assert action.text() == "Baskı ön&izleme..."
    dialog = window.printing.make_preview()
    assert dialog.windowTitle() == "Baskı önizleme"
    dialog.deleteLater()
