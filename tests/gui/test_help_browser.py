"""The instruction reference window: every instruction reachable, F1 and the dialog's Help."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtGui import QKeySequence
from pytestqt.qtbot import QtBot

from ladderworks.core.instructions import ALL, BY_NAME
from ladderworks.core.ladder import Coil
from ladderworks.gui.function_dialog import FunctionDialog
from ladderworks.gui.help_browser import listed_rows, reference_sections
from ladderworks.gui.main_window import MainWindow
from ladderworks.paths import EXAMPLES


def test_every_instruction_has_an_entry() -> None:
    sections = reference_sections()
    assert {spec.help_key for spec in ALL} <= set(sections)
    assert sections["instr-tmr"].startswith("## TMR")
    assert "<a id=" not in sections["instr-rot"]


def test_help_menu_opens_the_entry_of_the_element_at_the_cursor(window: MainWindow,
                                                                 qtbot: QtBot) -> None:
    assert window.load(EXAMPLES / "timer_relay.LAD")
    net = window.editor.networks[0]
    box = next(cell for cell, element in net.cells.items()
               if getattr(element, "name", "") == "TMR")
    window.editor.cursor_cell = (0, *box)
    window.actions_by_name["action_instruction_help"].trigger()
    help_window = window.help_window
    assert help_window is not None
    qtbot.waitUntil(help_window.isVisible)
    assert help_window.shown_name() == "TMR"
    assert "TMR — Timer" in help_window.browser.toPlainText()
    window.editor.cursor_cell = (0, 0, 0)  # the contact R1.4
    window.show_instruction_help()
    assert help_window.shown_name() == "RD"
    assert help_window.list.count() == len(listed_rows())  # the PMC's, then each dialect's


def test_search_filters_the_list(window: MainWindow) -> None:
    help_window = window.show_instruction_help("ROT")
    help_window.filter.setText("rot")
    visible = [help_window.list.item(i).text() for i in range(help_window.list.count())
               if not help_window.list.item(i).isHidden()]
    assert [text.split(" ")[0] for text in visible][:2] == ["ROT", "ROTB"]  # the PMC's first
    assert all("rot" in text.casefold() for text in visible)  # then Delta's ROR — Rotate …
    assert len(visible) < help_window.list.count()


def test_function_dialog_help_button(qtbot: QtBot) -> None:
    dialog = FunctionDialog(BY_NAME["DECB"])
    qtbot.addWidget(dialog)
    dialog.show()
    help_button = dialog.buttons.button(dialog.buttons.StandardButton.Help)
    qtbot.mouseClick(help_button, Qt.MouseButton.LeftButton)
    assert dialog.help_window is not None and dialog.help_window.shown_name() == "DECB"
    assert "DECB" in dialog.help_window.browser.toPlainText()


def test_closing_the_console_closes_its_help(window: MainWindow, qtbot: QtBot) -> None:
    help_window = window.show_instruction_help("CTR")
    qtbot.waitUntil(help_window.isVisible)
    window.close()
    assert not help_window.isVisible()


def test_turkish_ui_shows_the_turkish_reference(window: MainWindow, qtbot: QtBot) -> None:
    with qtbot.waitSignal(window.language_changed):
        window.actions_by_name["action_language_tr"].trigger()
    help_window = window.show_instruction_help("TMR")
    assert "TMR — ZAMANLAYICI" in help_window.browser.toPlainText()
    assert help_window.list.currentItem().text() == "TMR — ZAMANLAYICI"
    with qtbot.waitSignal(window.language_changed):
        window.actions_by_name["action_language_en"].trigger()
    assert "TMR — Timer" in help_window.browser.toPlainText()  # retranslated live


def test_the_help_window_fits_the_screen(window: MainWindow, qtbot: QtBot) -> None:
    """The 900×600 window is smaller on a screen without the room (a 1024×600 panel, the
    test platform's 800-px screen), with its list of names still whole."""
    help_window = window.show_instruction_help("TMR")
    qtbot.waitUntil(help_window.isVisible)
    room = help_window.screen().availableGeometry()
    assert room.contains(help_window.frameGeometry()), (room, help_window.frameGeometry())
    assert help_window.height() < room.height()  # the title bar has room above it
    assert help_window.list.width() >= help_window.list.minimumWidth()
    assert help_window.browser.width() >= 200


def test_f1_on_each_coil_kind_opens_its_own_entry(window: MainWindow, qtbot: QtBot,
                                                  tmp_path: Path) -> None:
    program = tmp_path / "coils.LAD"
    program.write_text("%@3\nRD R1.0\nWRT R2.0\nRD R1.1\nWRT.NOT R2.1\n"
                       "RD R1.2\nSET R2.2\nRD R1.3\nRST R2.3\n%\n", encoding="utf-8")
    assert window.load(program)
    action = window.actions_by_name["action_instruction_help"]
    assert action.shortcut() == QKeySequence(QKeySequence.StandardKey.HelpContents)
    shown: dict[str, str] = {}
    for index, network in enumerate(window.editor.networks):
        for (row, col), element in network.cells.items():
            if isinstance(element, Coil):
                window.editor.cursor_cell = (index, row, col)
                action.trigger()
                help_window = window.help_window
                assert help_window is not None
                qtbot.waitUntil(help_window.isVisible)
                shown[str(element.address)] = str(help_window.shown_name())
    assert shown == {"R2.0": "WRT", "R2.1": "WRT.NOT", "R2.2": "SET", "R2.3": "RST"}
    assert help_window.browser.toPlainText().startswith("RST")
