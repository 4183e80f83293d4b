"""Refresh translations/*.ts from the GUI sources with lupdate; list what is unfinished."""

from __future__ import annotations

import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import PySide6

ROOT = Path(__file__).resolve().parent.parent
LUPDATE = Path(PySide6.__file__).parent / "lupdate"


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


def main() -> int:
    """Run lupdate (existing translations are kept) and print the unfinished entries."""
    sources = sorted(str(p) for p in (ROOT / "ladderworks" / "gui").rglob("*.py"))
    for language in ("tr", "en"):
        ts = ROOT / "translations" / f"ladderworks_{language}.ts"
        subprocess.run([str(LUPDATE), "-silent", "-no-obsolete", *sources, "-ts", str(ts)],
                       check=True)
        for context, source in unfinished(ts):
            print(f"{ts.name}: [{context}] {source}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
