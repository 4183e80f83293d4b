"""Is a text a Fatek (WinProladder) mnemonic listing? A score for content sniffing."""

from __future__ import annotations

import re

from ladderworks.core.dialects.fatek.listing import read_listing
from ladderworks.core.il.textform import split_lines

_HEADER = re.compile(r"^\s*Printed Item\s*:\s*Mnemonic", re.I | re.M)
# what only Fatek writes: ORG, ANDLD/ORLD, OUT TR/LD TR, FUN n, ORGF …, FO n
_FATEK_ONLY = frozenset(("ORG", "ANDLD", "ORLD", "FUN", "ORGF", "LDF", "FO", "OUTS", "OUTR"))
SAMPLE_LINES = 400


def score(text: str) -> int:
    """0..100: 100 for WinProladder's printed header; else the share of the first lines that
    read as Fatek records, 0 unless one is Fatek's own (ORG, ANDLD, ORLD, FUN n, TR points)."""
    if "%@" in text[:4096]:
        return 0  # a PMC (LadderWorks / LADDER-III) file
    if _HEADER.search(text[:8192]):
        return 100
    lines = [line for line in split_lines(text)[:SAMPLE_LINES] if line.strip()]
    if not lines:
        return 0
    listing, problems = read_listing(lines)
    records = listing.records
    distinctive = any(r.mnemonic in _FATEK_ONLY or r.modifier == "TR" for r in records)
    if not distinctive:
        return 0
    bad = len({d.line for d in problems})
    return max(0, round(100 * (len(lines) - bad) / len(lines)))
