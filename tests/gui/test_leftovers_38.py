"""Issue 38 item 12: real Turkish for the on-line mode, Show as ladder, bytes, hex, registers and
the PLC family; shortcuts in the keyboard's own key names; a time axis with its unit when the
chart is short; a comment with VT/FS/GS/RS is a program's; a LADDER-III section without `%@3`."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QKeySequence
from PySide6.QtWidgets import QMenu
from pytestqt.qtbot import QtBot

from ladderworks.gui.docks.chart_items import YieldingLocaleAxis
from ladderworks.gui.main_window import MainWindow


def test_turkish_words_and_shortcuts_as_the_keys_say(window: MainWindow) -> None:
    window.set_language("tr")
    try:
        actions = window.actions_by_name
        assert actions["action_plc_online"].text() == "Çevrim içi mod"
        assert actions["action_show_ladder"].text() == "&Merdiven diyagramı olarak göster"
        shown = actions["action_save_as"].shortcut().toString(
            QKeySequence.SequenceFormat.NativeText)
        assert shown == "Ctrl+Shift+S"  # as on the keyboard, not "Kontrol+Üst Karakter+S"
        translate = QCoreApplication.translate
        assert [translate("BitDisplay", "Byte"), translate("BitDisplay", "Hex"),
                translate("PlcTables", "Registers ({0})").format("D")] == [
            "Bayt", "Onaltılık", "Yazmaçlar (D)"]
        assert "lehçe" not in translate("ModbusDock", "Dialect's map").casefold()
        file_menu = window.findChild(QMenu, "menu_file")
        assert file_menu is not None and file_menu.title() == "&Dosya"
    finally:
        window.set_language("en")


def test_a_short_time_chart_says_its_unit_on_the_axis(qtbot: QtBot, window: MainWindow) -> None:
    chart = window.plc_docks.time_chart
    chart.show()
    chart.resize(420, 600)
    axis = chart.plot.getPlotItem().getAxis("bottom")
    assert isinstance(axis, YieldingLocaleAxis)
    qtbot.waitUntil(lambda: chart.plot.height() >= 140)
    assert axis.label.isVisible() and "ms" in axis.labelText
    chart.resize(420, 200)
    qtbot.waitUntil(lambda: chart.plot.height() < 140)
    assert not axis.label.isVisible()
    assert axis.tickStrings([0.0, 500.0, 1000.0], 1.0, 500.0)[-1].endswith(" ms")


def test_control_characters_in_a_comment_do_not_make_it_binary(window: MainWindow,
                                                               tmp_path: Path) -> None:
    path = tmp_path / "vt.LAD"
    path.write_bytes(b"%@3\n// a\x0bb\x1cc\x1dd\x1ee\nRD X0.0\nWRT Y0.1\n%\n")
    assert window.load(path)
    assert not window.model.showing_text and window.errors.diagnostics() == []
    assert len(window.model.ladder_document().networks) == 1


def test_a_ladder_iii_section_without_its_header_opens_as_ladder(
        window: MainWindow, tmp_path: Path) -> None:
    path = tmp_path / "part.txt"
    text = "N00001:\nRD X0.0\nWRT Y0.0\nN00002:\nRD X0.1\nWRT Y0.1\n"
    path.write_text(text, encoding="utf-8")
    assert window.load(path)
    assert not window.model.showing_text and window.errors.diagnostics() == []
    assert window.model.dialect == "fanuc"
    assert [n.label for n in window.model.ladder_document().networks] == ["N00001", "N00002"]
    window.model.mark_modified()
    assert window.save_to(path)
    assert path.read_text(encoding="utf-8") == text  # as it was: no `%@3` added


def test_a_real_ladder_iii_fragment_opens_as_it_is(window: MainWindow) -> None:
    from ladderworks.core.il.parser import parse_bytes
    from tests.real_programs import real_bytes, real_programs_dir

    path = real_programs_dir() / "FANUC_X22_FRAG_LEVEL1.txt"
    assert window.load(path)
    assert not window.model.showing_text
    assert not [d for d in window.errors.diagnostics() if d.is_error]
    wrapped = parse_bytes(real_bytes("FANUC_X22_FRAG_LEVEL1")).program  # as the tests wrap it
    assert len(window.model.ladder_document().networks) == len(wrapped.networks)
    assert not window.is_modified()
