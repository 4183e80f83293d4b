"""Is a text a Delta instruction list? A score from its first lines, for content sniffing."""

from __future__ import annotations

import re

from ladderworks.core.dialects.delta import csv_form
from ladderworks.core.dialects.delta.table import NOT_SIMULATED, SPELLINGS
from ladderworks.core.il.textform import split_lines

# a Delta line: optional step number, a mnemonic, operands joined to their numbers (X0, K10)
_LINE = re.compile(
    r"^\s*(?:\d+\s+)?([A-Z][A-Z0-9]*(?:[=<>]{1,2})?)((?:[ \t]+[A-Z][0-9A-F]*)*)\s*(?:(?:;|//).*)?$",
    re.IGNORECASE)
_POINTER = re.compile(r"^\s*(?:\d+\s+)?P\d+:?\s*(?:(?:;|//).*)?$", re.IGNORECASE)
_COMMENT = re.compile(r"^\s*(?:;|//)")
# mnemonics only Delta's lists have (the PMC writes RD/WRT, Fatek ORG/ANDLD/ORLD)
_DELTA_ONLY = frozenset(("LDI", "ANI", "ORI", "ANB", "ORB", "MPS", "MRD", "MPP", "TMR", "CNT",
                         "DCNT", "FEND", "SRET", "CJ", "MC", "MCR", "LDP", "LDF", "ANDP", "ANDF",
                         "ORP", "ORF", "PLS", "PLF", "INV"))
_COMMON = frozenset(("LD", "AND", "OR", "OUT", "SET", "RST", "END", "CALL", "MOV", "ADD", "SUB",
                     "MUL", "DIV", "INC", "DEC", "CMP", "ZCP"))
# every other mnemonic the Delta reader knows or names (DMOV, ZRST, FROM, STL ...): Delta's too
_KNOWN = frozenset(SPELLINGS) | NOT_SIMULATED
SAMPLE_LINES = 400


def _words(line: str, separator: str) -> str:
    """An export line's fields as an instruction mode line (its comment fields left out)."""
    words = [field for field, _ in csv_form.fields(line, separator)]
    csv_form.trailing_comment(words)
    return " ".join(words)


def score(text: str) -> int:
    """0..100: the share of the first code lines that read as Delta instructions, 0 when none
    is a Delta-only mnemonic, an `LD` with a Delta operand, or a comparison contact."""
    if "%@" in text[:4096]:
        return 0  # a PMC (LadderWorks / LADDER-III) file
    total = matched = 0
    distinctive = False
    lines = split_lines(text[:65536])[:SAMPLE_LINES * 2]
    form = csv_form.detect(lines[:csv_form.SAMPLE * 2])
    if form is not None:  # WPLSoft's export: its fields as an instruction mode line
        lines = [line if form.comment(line) else _words(line, form.separator) for line in lines]
    for line in lines:
        if not line.strip() or _COMMENT.match(line):
            continue
        total += 1
        if _POINTER.match(line):
            matched += 1
            continue
        found = _LINE.match(line)
        if found is None:
            continue
        name = found.group(1).upper()
        operands = found.group(2).split()
        if name in _DELTA_ONLY or (name[:2] in ("LD", "AN", "OR") and name[-1] in "=<>"):
            distinctive = True
            matched += 1
        elif name in _COMMON:
            matched += 1
            if name == "LD" and operands and operands[0][:1].upper() in "XYMSTC":
                distinctive = True
        elif name in _KNOWN:
            matched += 1
            distinctive = distinctive or name == "STL"  # the step ladder: Delta's alone
        if total >= SAMPLE_LINES:
            break
    if not total or not distinctive:
        return 0
    return matched * 100 // total
