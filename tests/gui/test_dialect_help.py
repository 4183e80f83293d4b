"""Issue 38 item 6: every instruction of every family has a reference entry, English and
Turkish, reached by F1 on the element, by a function dialog's Help and by the search."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core import dialects
from ladderworks.core.instructions import lookup
from ladderworks.core.ladder.model import FunctionBox
from ladderworks.gui.function_dialog import FunctionDialog
from ladderworks.gui.help_browser import reference_sections
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.translation import UiLanguage


@pytest.mark.parametrize("language", ["en", "tr"])
def test_every_dialect_row_has_an_entry(language: str) -> None:
    sections = reference_sections(language)
    keys = {spec.help_key for d in dialects.every() for spec in d.rows
            if not spec.name.endswith(".STK")} | {f"instr-{d.name}-basic" for d in dialects.every()}
    assert keys - set(sections) == set()
    assert "<a id=" not in sections["instr-dvp-tmr"]
    assert sections["instr-dvp-tmr"].startswith("## TMR")
    assert sections["instr-dvp-ld>="] == sections["instr-dvp-or<"]  # one entry, many rows


def _box(window: MainWindow, name: str) -> tuple[int, int, int]:
    for index, network in enumerate(window.model.networks):
        for cell, element in network.cells.items():
            if isinstance(element, FunctionBox) and element.name == name:
                return index, *cell
    raise AssertionError(name)


def test_f1_on_a_delta_timer_and_search_of_cnt(qtbot: QtBot, window: MainWindow,
                                               tmp_path: Path) -> None:
    assert window.load(paths.EXAMPLES / "delta" / "timer_t0.txt")
    window.editor.cursor_cell = _box(window, "DVP.TMR")
    window.editor.setFocus()
    qtbot.keyClick(window.editor, Qt.Key.Key_F1)
    help_window = window.help_window
    assert help_window is not None
    qtbot.waitUntil(help_window.isVisible)
    assert help_window.shown_name() == "DVP.TMR"
    assert "TMR — 16-bit timer" in help_window.browser.toPlainText()
    assert "T64–T126" in help_window.browser.toPlainText()
    window.editor.cursor_cell = (1, 0, 0)  # LD T0: a Delta contact, Delta's own entry
    qtbot.keyClick(window.editor, Qt.Key.Key_F1)
    assert help_window.shown_key() == "instr-delta-basic"
    assert "ANB / ORB" in help_window.browser.toPlainText()
    for text, first in (("CNT", "CNT (Delta DVP)"), ("ASCWR", "FUN 94 ASCWR (Fatek FBs)"),
                        ("ANB", "LD, LDI, OUT…"), ("ORLD", "ORG, ORG NOT, OUT…")):
        help_window.filter.setText(text)
        shown = [help_window.list.item(i) for i in range(help_window.list.count())
                 if not help_window.list.item(i).isHidden()]
        assert shown and shown[0].text().startswith(first), text
        help_window.list.setCurrentItem(shown[0])
        assert text in help_window.browser.toPlainText()
    UiLanguage().apply("tr")
    try:
        window.show_instruction_help("DVP.CNT")
        assert "16 bit sayıcı" in help_window.browser.toPlainText()
    finally:
        UiLanguage().apply("en")


def test_help_of_a_fatek_function_dialog(qtbot: QtBot) -> None:
    spec = lookup("FBS.ADD")
    assert spec is not None
    dialog = FunctionDialog(spec, dialect="fatek")
    qtbot.addWidget(dialog)
    dialog.show()
    help_button = dialog.buttons.button(dialog.buttons.StandardButton.Help)
    qtbot.mouseClick(help_button, Qt.MouseButton.LeftButton)
    assert dialog.help_window is not None and dialog.help_window.shown_name() == "FBS.ADD"
    assert "FUN 11 (+)" in dialog.help_window.browser.toPlainText()


@pytest.mark.parametrize("dialect", paths.DIALECT_HELP)
def test_a_dialect_page_and_its_turkish_hold_the_same_entries(dialect: str) -> None:
    docs = Path(__file__).resolve().parents[2] / "docs"
    anchors = [re.findall(r'<a id="([^"]+)"></a>', (docs / f"instructions_{dialect}{suffix}.md")
                          .read_text("utf-8")) for suffix in ("", "_tr")]
    assert anchors[0] == anchors[1]
    assert len(set(anchors[0])) == len(anchors[0])  # an anchor names one entry


def test_s7_entries_use_the_seeds_terms() -> None:
    turkish = reference_sections("tr")
    assert turkish["instr-s7-ton"].startswith("## TON — Gecikmeli Kapatan")
    assert "Darbe Üretme Zamanlayıcısı" in turkish["instr-s7-tp"]
    assert "Kalıcı İçerikli Gecikmeli Kapatan" in turkish["instr-s7-tonr"]
    english = reference_sections("en")
    assert english["instr-s7-eq"] == english["instr-s7-le"]  # one entry, six compares
    assert "kept, drawn, not simulated" in english["instr-dvp-shown-ld"]
