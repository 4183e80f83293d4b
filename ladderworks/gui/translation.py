"""UI languages: load the packaged `.qm` (a checkout builds it from `.ts`) and switch live."""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import PySide6
from PySide6.QtCore import (
    QCoreApplication,
    QLibraryInfo,
    QLocale,
    QStandardPaths,
    QTranslator,
)

from ladderworks.core.instructions import InstructionSpec
from ladderworks.gui.settings import LANGUAGES
from ladderworks.paths import translations_dir


def system_language() -> str:
    """'tr' when the system locale is Turkish, else 'en'."""
    return "tr" if QLocale.system().language() == QLocale.Language.Turkish else "en"


def ui_is_turkish() -> bool:
    """True while the UI language is Turkish (the translators set the default QLocale)."""
    return QLocale().language() == QLocale.Language.Turkish


def instruction_title(spec: InstructionSpec) -> str:
    """An instruction's title in the UI language (the seed manual's Turkish words)."""
    return spec.title_tr if ui_is_turkish() else spec.title


def instruction_label(spec: InstructionSpec) -> str:
    """An instruction's name as the ladder shows it: `AND` for LOGAND, `SUB 219` for a SUB
    the table does not know."""
    return spec.text_name if spec.known else f"SUB {spec.sub}"


def param_label(name: str) -> str:
    """A parameter's name in the current UI language."""
    labels = {
        "timer": QCoreApplication.translate("Param", "Timer number"),
        "preset": QCoreApplication.translate("Param", "Preset"),
        "accuracy": QCoreApplication.translate("Param", "Accuracy"),
        "register": QCoreApplication.translate("Param", "Timer/counter register"),
        "code": QCoreApplication.translate("Param", "Code signal"),
        "spec": QCoreApplication.translate("Param", "Decode specification"),
        "format": QCoreApplication.translate("Param", "Format"),
        "first": QCoreApplication.translate("Param", "First number"),
        "result": QCoreApplication.translate("Param", "Result"),
        "counter": QCoreApplication.translate("Param", "Counter number"),
        "positions": QCoreApplication.translate("Param", "Number of positions"),
        "current": QCoreApplication.translate("Param", "Current position"),
        "target": QCoreApplication.translate("Param", "Target position"),
        "size": QCoreApplication.translate("Param", "Table size"),
        "index": QCoreApplication.translate("Param", "Index"),
        "output": QCoreApplication.translate("Param", "Output"),
        "table": QCoreApplication.translate("Param", "Table values"),
        "input": QCoreApplication.translate("Param", "Input"),
        "high_mask": QCoreApplication.translate("Param", "High 4-bit mask"),
        "low_mask": QCoreApplication.translate("Param", "Low 4-bit mask"),
        "or_data": QCoreApplication.translate("Param", "OR data"),
        "data": QCoreApplication.translate("Param", "Data"),
        "coils": QCoreApplication.translate("Param", "Number of coils"),
        "input_format": QCoreApplication.translate("Param", "Input format (0 constant, 1 address)"),
        "compare": QCoreApplication.translate("Param", "Compared data"),
        "search": QCoreApplication.translate("Param", "Searched data"),
        "operand_format": QCoreApplication.translate(
            "Param", "Operand format (0 constant, 1 address)"),
        "a": QCoreApplication.translate("Param", "Operand A"),
        "b": QCoreApplication.translate("Param", "Operand B"),
        "constant": QCoreApplication.translate("Param", "Constant"),
        "edge": QCoreApplication.translate("Param", "Edge number"),
        "bytes": QCoreApplication.translate("Param", "Number of bytes"),
        "operand": QCoreApplication.translate("Param", "Operand"),
        "limit1": QCoreApplication.translate("Param", "Limit 1"),
        "limit2": QCoreApplication.translate("Param", "Limit 2"),
        "program": QCoreApplication.translate("Param", "Subprogram"),
        "label": QCoreApplication.translate("Param", "Label"),
        "group": QCoreApplication.translate("Param", "DI/DO group"),
        "control": QCoreApplication.translate("Param", "Control data"),
        "messages": QCoreApplication.translate("Param", "Number of messages"),
        # a Delta / Fatek row's operands (core/dialects)
        "mode": QCoreApplication.translate("Param", "Form (P, D)"),
        "nest": QCoreApplication.translate("Param", "Nesting level (N0-N7)"),
        "device": QCoreApplication.translate("Param", "Device"),
        "number": QCoreApplication.translate("Param", "Timer or counter (T5, C3)"),
        "s1": QCoreApplication.translate("Param", "Source 1"),
        "s2": QCoreApplication.translate("Param", "Source 2"),
        "source": QCoreApplication.translate("Param", "Source"),
        "low": QCoreApplication.translate("Param", "Lower limit"),
        "high": QCoreApplication.translate("Param", "Upper limit"),
    }
    if name not in labels and name[:1] == "p" and name[1:].isdigit():  # SUB n: p1, p2, ...
        return QCoreApplication.translate("Param", "Parameter {0}").format(name[1:])
    return labels.get(name, name)


def ts_file(language: str) -> Path:
    """The committed translation source for `language` (absent from an installed wheel)."""
    return translations_dir() / f"ladderworks_{language}.ts"


def lrelease_program() -> str | None:
    """The lrelease that ships with PySide6 (or one on PATH)."""
    for name in ("lrelease", "lrelease.exe"):
        bundled = Path(PySide6.__file__).parent / name
        if bundled.exists():
            return str(bundled)
    return shutil.which("pyside6-lrelease") or shutil.which("lrelease")


def cache_dir() -> Path:
    """Where built `.qm` files are kept."""
    base = QStandardPaths.writableLocation(QStandardPaths.StandardLocation.CacheLocation)
    return Path(base or Path.home() / ".cache" / "ladderworks") / "translations"


def build_qm(language: str, target_dir: Path | None = None) -> Path | None:
    """The `.qm` for `language`: the packaged one, else built with lrelease from the `.ts`.

    An installed wheel ships only the `.qm`. A checkout builds it into the cache under the
    `.ts`'s hash, written whole and renamed into place: Qt maps a loaded `.qm` into memory, so
    a file rewritten in place under another running process (another checkout, a parallel test
    run) would crash it."""
    source = ts_file(language)
    shipped = translations_dir() / f"ladderworks_{language}.qm"
    if shipped.exists() and (not source.exists()
                             or shipped.stat().st_mtime >= source.stat().st_mtime):
        return shipped
    if not source.exists():
        return None
    digest = hashlib.sha256(source.read_bytes()).hexdigest()[:16]
    directory = target_dir or cache_dir()
    target = directory / f"ladderworks_{language}-{digest}.qm"
    if target.exists():
        return target
    program = lrelease_program()
    if program is None:
        return None
    partial = directory / f"{target.name}.{os.getpid()}.part"
    try:
        directory.mkdir(parents=True, exist_ok=True)
        subprocess.run(
            [program, "-silent", str(source), "-qm", str(partial)],
            check=True, capture_output=True, timeout=60,
        )
        os.replace(partial, target)
    except (OSError, subprocess.SubprocessError):
        partial.unlink(missing_ok=True)
        return None
    return target


class TsTranslator(QTranslator):
    """A translator read straight from a `.ts` file: the fallback when lrelease is missing."""

    def __init__(self, path: Path) -> None:
        super().__init__()
        self._table: dict[tuple[str, str], str] = {}
        root = ET.parse(path).getroot()
        for context in root.iter("context"):
            name = context.findtext("name") or ""
            for message in context.iter("message"):
                source = message.findtext("source") or ""
                node = message.find("translation")
                if node is None or node.get("type") in ("unfinished", "vanished", "obsolete"):
                    continue
                if node.text:
                    self._table[(name, source)] = node.text

    def translate(
        self, context: str, source: str, disambiguation: str | None = None, n: int = -1
    ) -> str:
        return self._table.get((context, source), "")

    def isEmpty(self) -> bool:
        return not self._table


class KeyNames(QTranslator):
    """The keys of a shortcut as the keyboard's caps say them (`Ctrl+N`, `Shift+F3`), in
    every language: Qt's own Turkish would show `Kontrol+N`, `Üst Karakter+S` in the menus."""

    def translate(
        self, context: str, source: str, disambiguation: str | None = None, n: int = -1
    ) -> str:
        return source if context == "QShortcut" else None  # type: ignore[return-value]

    def isEmpty(self) -> bool:
        return False


class UiLanguage:
    """The installed translators; `apply` switches the language (Qt sends LanguageChange)."""

    def __init__(self) -> None:
        self._translators: list[QTranslator] = []
        self.current = "en"

    def apply(self, language: str) -> str:
        """Install the translators for `language` ('en' / 'tr'); returns the language applied."""
        if language not in LANGUAGES:
            language = "en"
        app = QCoreApplication.instance()
        assert app is not None, "translators need the application"
        for translator in self._translators:
            app.removeTranslator(translator)
        self._translators = []
        qt_translator = QTranslator()
        qt_dir = QLibraryInfo.path(QLibraryInfo.LibraryPath.TranslationsPath)
        if language != "en" and qt_translator.load(f"qtbase_{language}", qt_dir):
            self._translators.append(qt_translator)
        # ours last: Qt asks the translator installed last first, so ours fills Qt's gaps
        app_translator = self._app_translator(language)
        if app_translator is not None:
            self._translators.append(app_translator)
        if language != "en":  # asked first: the key names stay the keyboard's
            self._translators.append(KeyNames())
        for translator in self._translators:
            app.installTranslator(translator)
        QLocale.setDefault(QLocale(QLocale.Language.Turkish if language == "tr"
                                   else QLocale.Language.English))
        self.current = language
        return language

    @staticmethod
    def _app_translator(language: str) -> QTranslator | None:
        qm = build_qm(language)
        if qm is not None:
            translator = QTranslator()
            if translator.load(str(qm)):
                return translator
        source = ts_file(language)
        return TsTranslator(source) if source.exists() else None
