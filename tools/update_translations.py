"""Refresh translations/*.ts with lupdate (GUI, core diagnostics); list what is unfinished."""

from __future__ import annotations

import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import PySide6

ROOT = Path(__file__).resolve().parent.parent
LUPDATE = Path(PySide6.__file__).parent / "lupdate"


def translated_sources() -> list[Path]:
    """The files lupdate reads: the GUI, and the core's diagnostic templates (QT_TRANSLATE_NOOP)."""
    gui = sorted((ROOT / "ladderworks" / "gui").rglob("*.py"))
    return [*gui, ROOT / "ladderworks" / "core" / "diagnostics.py",
            ROOT / "ladderworks" / "core" / "dialect_messages.py"]


def unfinished(ts: Path) -> list[tuple[str, str]]:
    """(context, source) of every entry without a finished translation."""
    found = []
    for context in ET.parse(ts).getroot().iter("context"):
        name = context.findtext("name") or ""
        for message in context.iter("message"):
            node = message.find("translation")
            if node is not None and node.get("type") == "unfinished":
                found.append((name, message.findtext("source") or ""))
    return found


def fill(ts: Path, translations: dict[str, str]) -> int:
    """Finish the unfinished entries whose source is in `translations`; returns how many.

    A key `Context::source` is for that context only, and sets the entry even when it is
    finished (lupdate fills a new entry from the same text in another context)."""
    tree = ET.parse(ts)
    done = 0
    for context in tree.getroot().iter("context"):
        name = context.findtext("name") or ""
        for message in context.iter("message"):
            node = message.find("translation")
            source = message.findtext("source") or ""
            if node is None:
                continue
            qualified = translations.get(f"{name}::{source}")
            if qualified is not None and (node.text != qualified
                                          or node.get("type") == "unfinished"):
                node.text = qualified
                node.attrib.pop("type", None)
                done += 1
            elif node.get("type") == "unfinished" and source in translations:
                node.text = translations[source]
                del node.attrib["type"]
                done += 1
    if done:
        tree.write(ts, encoding="utf-8", xml_declaration=True)
    return done


def main() -> int:
    """Run lupdate (existing translations are kept) and print the unfinished entries.

    With a file argument (a TSV of `English<TAB>Türkçe` lines), fill those entries first:
    Turkish into ladderworks_tr.ts, the English text itself into ladderworks_en.ts."""
    pairs: dict[str, str] = {}
    if len(sys.argv) > 1:
        for line in Path(sys.argv[1]).read_text("utf-8").splitlines():
            if "\t" in line:
                english, turkish = line.split("\t", 1)
                pairs[english] = turkish
    sources = [str(p) for p in translated_sources()]
    for language in ("tr", "en"):
        ts = ROOT / "translations" / f"ladderworks_{language}.ts"
        command = [str(LUPDATE), "-silent", "-no-obsolete", *sources, "-ts", str(ts)]
        subprocess.run(command, check=True)
        english = {key: key.split("::", 1)[-1] for key in pairs}
        if pairs and fill(ts, pairs if language == "tr" else english):
            subprocess.run(command, check=True)  # back to lupdate's own layout
        for context, source in unfinished(ts):
            print(f"{ts.name}: [{context}] {source}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
