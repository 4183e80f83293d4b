"""Where the project's resources and translations live."""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RESOURCES = ROOT / "resources"
EXAMPLES = RESOURCES / "examples"
SIGNALS = RESOURCES / "signals"
ICONS = RESOURCES / "icons"
TRANSLATIONS = ROOT / "translations"
