"""Every tr() string has a finished Turkish translation; every core diagnostic is marked for it."""

from __future__ import annotations

import re
import string
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.diagnostics import MESSAGES
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.translation import TsTranslator, lrelease_program, ts_file
from tools.update_translations import translated_sources


def _lupdate() -> Path:
    program = Path(lrelease_program() or "").with_name("lupdate")
    if not program.exists():
        pytest.fail("PySide6's lupdate is missing")
    return program


def _messages(path: Path) -> dict[tuple[str, str], ET.Element]:
    root = ET.parse(path).getroot()
    found: dict[tuple[str, str], ET.Element] = {}
    for context in root.iter("context"):
        name = context.findtext("name") or ""
        for message in context.iter("message"):
            translation = message.find("translation")
            assert translation is not None
            found[(name, message.findtext("source") or "")] = translation
    return found


def _extracted(tmp_path: Path) -> set[tuple[str, str]]:
    extracted = tmp_path / "extracted.ts"
    sources = [str(path) for path in translated_sources()]
    subprocess.run([str(_lupdate()), "-silent", *sources, "-ts", str(extracted)],
                   check=True, capture_output=True, timeout=120)
    return set(_messages(extracted))


def test_every_tr_string_has_a_finished_turkish_translation(tmp_path: Path) -> None:
    wanted = _extracted(tmp_path)
    assert len(wanted) > 150
    committed = _messages(ts_file("tr"))
    missing = sorted(wanted - set(committed))
    assert not missing, f"not in translations/ladderworks_tr.ts (run lupdate): {missing[:10]}"
    unfinished = sorted(key for key in wanted
                        if committed[key].get("type") in ("unfinished", "vanished", "obsolete")
                        or not (committed[key].text or "").strip())
    assert not unfinished, f"no Turkish translation yet: {unfinished[:10]}"


def test_the_english_file_is_complete_too() -> None:
    committed = _messages(ts_file("en"))
    assert committed
    assert all(node.get("type") != "unfinished" for node in committed.values())


def _fields(template: str) -> set[str]:
    return {name for _, name, _, _ in string.Formatter().parse(template) if name}


def test_lupdate_finds_every_core_diagnostic_template(tmp_path: Path) -> None:
    wanted = _extracted(tmp_path)
    missing = sorted(code for code, template in MESSAGES.items()
                     if ("Diagnostic", template) not in wanted)
    assert not missing, f"mark these with QT_TRANSLATE_NOOP in core/diagnostics.py: {missing}"


def test_turkish_diagnostics_keep_their_fields() -> None:
    translator = TsTranslator(ts_file("tr"))
    for code, template in MESSAGES.items():
        turkish = translator.translate("Diagnostic", template)
        assert turkish, code
        assert _fields(turkish) == _fields(template), code


def test_seed_manual_terms_name_the_tools() -> None:
    translator = TsTranslator(ts_file("tr"))
    names = {source: translator.translate("Tool", source) for source in (
        "Select", "Input", "Output", "NOT", "OR", "Line", "Comment", "Delete", "Function")}
    assert names == {"Select": "SEÇİM", "Input": "GİRİŞ", "Output": "ÇIKIŞ", "NOT": "DEĞİL",
                     "OR": "VEYA", "Line": "ÇİZGİ", "Comment": "YORUM", "Delete": "SİL",
                     "Function": "FONKSİYON"}
    assert re.search("ÖNCE", translator.translate("Tool", "Insert row before"))


def test_every_parameter_has_a_name_for_the_user(qapp: object) -> None:
    from ladderworks.core.instructions import FUNCTIONS
    from ladderworks.gui.translation import param_label

    names = {param.name for spec in FUNCTIONS for param in spec.params}
    assert [name for name in names if param_label(name) == name] == []


def test_diagnostics_name_the_parameter_in_the_ui_language(qapp: object) -> None:
    from ladderworks.core.il import parse
    from ladderworks.gui.diagnostic_texts import diagnostic_text
    from ladderworks.gui.translation import UiLanguage

    (diagnostic,) = parse("%@3\nRD X0.0\nTMR 300\nWRT Y0.0\n%\n").diagnostics
    language = UiLanguage()
    try:
        language.apply("tr")
        turkish = diagnostic_text(diagnostic)
        language.apply("en")
        english = diagnostic_text(diagnostic)
    finally:
        language.apply("en")
    assert "Timer number" in english and "timer)" not in english
    assert "Zamanlayıcı" in turkish or "ZAMANLAYICI" in turkish.upper(), turkish
    assert "300" in turkish


# -- the whole UI in the chosen language, Qt's own strings included, switched live ---------------

def _visible_texts(root: object) -> dict[str, list[str]]:
    """Every text a user reads in a widget tree, by object path (titles, labels, buttons,
    actions, menus, tool tips, placeholders, tabs, headers)."""
    from PySide6.QtCore import QObject
    from PySide6.QtGui import QAction
    from PySide6.QtWidgets import (
        QAbstractButton,
        QAbstractItemView,
        QDockWidget,
        QLabel,
        QLineEdit,
        QMenu,
        QTabBar,
        QWidget,
    )

    assert isinstance(root, QWidget)
    found: dict[str, list[str]] = {}
    for index, item in enumerate([root, *root.findChildren(QObject)]):
        key = f"{index}:{type(item).__name__}:{item.objectName()}"
        texts: list[str] = []
        if isinstance(item, QWidget):
            texts.append(item.toolTip())
            if item.isWindow() or isinstance(item, QDockWidget):
                texts.append(item.windowTitle())
        if isinstance(item, QLabel | QAbstractButton):
            texts.append(item.text())
        if isinstance(item, QAction):
            texts += [item.text(), item.toolTip(), item.statusTip()]
        if isinstance(item, QMenu):
            texts.append(item.title())
        if isinstance(item, QLineEdit):
            texts.append(item.placeholderText())
        if isinstance(item, QTabBar):
            texts += [item.tabText(tab) for tab in range(item.count())]
        if isinstance(item, QAbstractItemView) and item.model() is not None:
            model = item.model()
            texts += [str(model.headerData(column, Qt.Orientation.Horizontal))
                      for column in range(model.columnCount())]
        found[key] = texts
    return found


def _turkish_window(qtbot: QtBot, tmp_path: Path) -> MainWindow:
    from PySide6.QtCore import QSettings

    from ladderworks.gui.settings import Settings
    from ladderworks.gui.translation import UiLanguage

    language = UiLanguage()
    language.apply("tr")
    settings = Settings(QSettings(str(tmp_path / "fresh.ini"), QSettings.Format.IniFormat))
    fresh = MainWindow(settings, language)
    qtbot.addWidget(fresh)
    return fresh


def test_a_live_switch_reads_like_a_window_started_in_turkish(
        window: MainWindow, qtbot: QtBot, tmp_path: Path) -> None:
    window.set_language("tr")
    fresh = _turkish_window(qtbot, tmp_path)
    fresh.show()
    qtbot.waitExposed(fresh)
    qtbot.wait(50)  # the dock tab bars Qt replaced on the switch are deleted later
    switched = {text for texts in _visible_texts(window).values() for text in texts if text}
    started = {text for texts in _visible_texts(fresh).values() for text in texts if text}
    assert len(started) > 150
    assert sorted(switched - started) == [] and sorted(started - switched) == []
    assert window.windowTitle() == fresh.windowTitle()


def test_qt_file_dialog_and_buttons_speak_turkish(window: MainWindow) -> None:
    from PySide6.QtWidgets import QDialogButtonBox, QFileDialog, QLabel, QLineEdit, QMessageBox

    window.set_language("tr")
    dialog = QFileDialog(window)
    dialog.setOption(QFileDialog.Option.DontUseNativeDialog)
    labels = {label.objectName(): label.text() for label in dialog.findChildren(QLabel)}
    assert labels["lookInLabel"] == "&Konum:"  # qtbase_tr.qm lacks it: ours has it
    assert labels["fileNameLabel"] == "Dosya a&dı:"  # from qtbase_tr.qm
    assert labels["fileTypeLabel"] == "Dosya &türü:"
    buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                               | QDialogButtonBox.StandardButton.Cancel
                               | QDialogButtonBox.StandardButton.Help)
    assert sorted(button.text() for button in buttons.buttons()) == ["Tamam", "Yardım", "İptal"]
    box = QMessageBox(QMessageBox.Icon.Question, "", "", QMessageBox.StandardButton.Save
                      | QMessageBox.StandardButton.Discard | QMessageBox.StandardButton.Cancel)
    assert sorted(button.text() for button in box.buttons()) == ["Kaydet", "Kaydetme", "İptal"]
    line = QLineEdit(window)
    menu = line.createStandardContextMenu()
    words = [action.text() for action in menu.actions() if action.text()]
    assert "&Yapıştır" in words and "&Paste" not in words
    dialog.deleteLater()
    window.set_language("en")  # and back, live
    dialog = QFileDialog(window)
    dialog.setOption(QFileDialog.Option.DontUseNativeDialog)
    labels = {label.objectName(): label.text() for label in dialog.findChildren(QLabel)}
    assert labels["lookInLabel"] == "&Look in:"


def test_open_dialogs_follow_a_live_switch(window: MainWindow, qtbot: QtBot) -> None:
    from ladderworks.core.instructions import lookup
    from ladderworks.gui.function_dialog import FunctionDialog

    dialog = FunctionDialog(lookup("TMR"), parent=window)  # type: ignore[arg-type]
    qtbot.addWidget(dialog)
    assert dialog.windowTitle() == "TMR — Timer"
    properties = window.show_program_properties()
    assert properties.windowTitle() == "Program properties"
    window.set_language("tr")
    assert dialog.windowTitle() == "TMR — ZAMANLAYICI"
    assert dialog.table.item(0, 0).text() == "Zamanlayıcı numarası"
    assert properties.windowTitle() == "Program özellikleri"
    tabs = properties.tabs  # type: ignore[attr-defined]
    assert tabs.tabText(0) == "Genel"
    help_window = window.show_instruction_help("TMR")
    assert help_window.windowTitle() == "Komut başvurusu"
    assert help_window.list.currentItem().text() == "TMR — ZAMANLAYICI"


def test_status_bar_messages_follow_a_live_switch(window: MainWindow) -> None:
    window.check()
    assert window.statusBar().currentMessage() == "Check: 0 error(s)"
    window.set_language("tr")
    assert window.statusBar().currentMessage() == "Kontrol: 0 hata"
    window.use_signal(parse_address("X0.0"))  # a message given as text: gone on a switch
    assert window.statusBar().currentMessage()
    window.set_language("en")
    assert window.statusBar().currentMessage() == ""


def test_turkish_numbers_have_a_decimal_comma(window: MainWindow) -> None:
    from ladderworks.gui.docks.alarms import plc_time_text
    from ladderworks.gui.locale_numbers import LocaleAxis, decimal, percent

    assert decimal(1234.125, 3) == "1234.125" and percent(150) == "150%"
    assert plc_time_text(1250) == "0:01.250"
    window.set_language("tr")
    assert decimal(1234.125, 3) == "1234,125" and percent(150) == "%150"
    assert plc_time_text(1250) == "0:01,250"
    assert LocaleAxis("bottom").tickStrings([0.0, 0.5, 1.0], 1.0, 0.5) == ["0,0", "0,5", "1,0"]
    window.actions_by_name["action_zoom_in"].trigger()
    assert window.zoom_label.text() == percent(window.editor.zoom() * 100)
    assert window.zoom_label.text().startswith("%")
    window.actions_by_name["action_zoom_fit_width"].trigger()  # any change of zoom is shown
    assert window.zoom_label.text() == percent(window.editor.zoom() * 100)
    from ladderworks.paths import EXAMPLES

    assert window.load(EXAMPLES / "timer_relay.LAD")
    assert window.compile() is not None
    session = window.plc_docks.session
    control = window.plc_docks.control
    session.run_scans(3)
    session.status_changed.emit(session.run.status())
    figures = control.figures.text()  # type: ignore[attr-defined]
    assert re.search(r"tarama süresi \d+,\d{3} / \d+,\d{3} / \d+,\d{3} ms", figures), figures


def test_os_errors_are_our_sentence_with_the_file(window: MainWindow, tmp_path: Path) -> None:
    window.set_language("tr")
    missing = tmp_path / "no-such-folder" / "program.LAD"
    assert not window.save_to(missing)
    assert str(missing) in window.last_warning
    assert "yazılamadı" in window.last_warning or "yazılamıyor" in window.last_warning
    assert "böyle bir dosya veya klasör yok" in window.last_warning
    assert "No such file" not in window.last_warning
    assert not window.load(tmp_path / "absent.LAD")
    assert "absent.LAD" in window.last_warning
    assert "böyle bir dosya veya klasör yok" in window.last_warning


def test_one_name_for_a_network_in_drawing_status_bar_and_errors(window: MainWindow) -> None:
    from ladderworks.core.diagnostics import Diagnostic
    from ladderworks.gui.editor.network_item import network_tag
    from ladderworks.gui.error_list import location_text

    where = Diagnostic("open-circuit", network=0, cell=(0, 1))
    assert (network_tag(1), window.editor.describe_cell(0, 0, 1).split()[0],
            location_text(where).split()[:2]) == ("N1", "N1", ["network", "1,"])
    window.set_language("tr")
    assert (network_tag(1), window.editor.describe_cell(0, 0, 1).split()[0],
            location_text(where).split()[:2]) == ("D1", "D1", ["devre", "1,"])


def test_the_reference_has_no_source_marks_and_whole_names(window: MainWindow) -> None:
    from ladderworks.core.instructions import ALL
    from ladderworks.gui.help_browser import reference_sections

    for language in ("en", "tr"):
        for key, text in reference_sections(language).items():
            assert not re.search(r"\[(seed|pmc|choice)", text), (language, key)
    window.set_language("tr")
    help_window = window.show_instruction_help("XMOVB")
    longest = max((f"{spec.name} — {spec.title_tr}" for spec in ALL),
                  key=help_window.list.fontMetrics().horizontalAdvance)
    needed = help_window.list.fontMetrics().horizontalAdvance(longest)
    assert help_window.list.viewport().width() >= needed


def test_the_system_s_reasons_are_said_in_turkish(window: MainWindow) -> None:
    import errno
    import os

    from ladderworks.gui.os_errors import os_error_text

    window.set_language("tr")
    for code in (errno.ENOENT, errno.EACCES, errno.ENOSPC, errno.EROFS, errno.EISDIR):
        error = OSError(code, os.strerror(code))
        assert os_error_text(error) != os.strerror(code)
        assert not re.search(r"[A-Z][a-z]+ ", os_error_text(error)), os_error_text(error)
    odd = OSError(errno.EXDEV, os.strerror(errno.EXDEV))
    assert os_error_text(odd) == f"sistem hatası: {os.strerror(errno.EXDEV)}"


def test_dock_messages_follow_a_live_switch(window: MainWindow, qtbot: QtBot,
                                            tmp_path: Path) -> None:
    from ladderworks.paths import EXAMPLES

    assert window.load(EXAMPLES / "timer_relay.LAD")
    assert window.compile() is not None
    control = window.plc_docks.control
    chart = window.plc_docks.others["time_chart"]
    chart.signals_edit.setText("R1.4")  # type: ignore[attr-defined]
    assert chart.start()  # type: ignore[attr-defined]
    chart.stop()  # type: ignore[attr-defined]
    assert control.message.text() == "Program loaded from the console"
    assert chart.message.text().startswith("Stopped: ")  # type: ignore[attr-defined]
    window.set_language("tr")
    assert control.message.text() == "Program konsoldan yüklendi"
    assert chart.message.text().startswith("Durduruldu: ")  # type: ignore[attr-defined]
    # a message set since as plain text is left alone by the next switch
    control.message.setText("R1.4")
    window.set_language("en")
    assert control.message.text() == "R1.4"


def test_a_context_s_own_word_overrides_lupdate_s_guess(tmp_path: Path) -> None:
    from tools.update_translations import fill

    ts = tmp_path / "x_tr.ts"
    ts.write_text(
        '<?xml version="1.0" encoding="utf-8"?>\n<TS version="2.1" language="tr_TR">'
        "<context><name>Questions</name><message><source>Discard</source>"
        "<translation>At</translation></message></context>"
        "<context><name>QPlatformTheme</name><message><source>Discard</source>"
        "<translation>At</translation></message>"
        "<message><source>Open</source><translation type=\"unfinished\"></translation>"
        "</message></context></TS>", encoding="utf-8")
    assert fill(ts, {"QPlatformTheme::Discard": "Kaydetme", "Open": "Aç"}) == 2
    assert fill(ts, {"QPlatformTheme::Discard": "Kaydetme"}) == 0  # already so
    found = {(key, node.text) for key, node in _messages(ts).items()}
    assert found == {(("Questions", "Discard"), "At"), (("QPlatformTheme", "Discard"), "Kaydetme"),
                     (("QPlatformTheme", "Open"), "Aç")}
