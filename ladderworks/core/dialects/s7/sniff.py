"""Recognise a SIMATIC SD block or a SimaticML block export from its content."""

from __future__ import annotations

import re

_HEAD_RE = re.compile(r"^\s*(ORGANIZATION_BLOCK|FUNCTION_BLOCK|FUNCTION|DATA_BLOCK)\s+\"", re.M)


def score(text: str) -> int:
    """100 for an SD block with a LAD rung or an S7 pragma; 60 for an SD block head alone."""
    head = text[:20000]
    if "<Document" in head[:4000] and any(kind in head for kind in (
            "SW.Blocks.", "SW.Types.PlcStruct", "SW.Tags.PlcTagTable")):  # SimaticML
        return 100
    if head.lstrip().startswith("<SW.Blocks."):  # a piece of an export (no Document)
        return 80
    if _HEAD_RE.search(head) is None:
        return 0
    if "wire#powerrail" in head or "S7_" in head:
        return 100
    return 60
