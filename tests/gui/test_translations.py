"""Every tr() string has a finished Turkish translation; every core diagnostic is marked for it."""

from __future__ import annotations

import re
import string
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from ladderworks.core.diagnostics import MESSAGES
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
