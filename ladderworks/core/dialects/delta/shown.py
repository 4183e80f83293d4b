"""Delta instructions kept, drawn and saved but not simulated: the shown-only rows.

A mnemonic the simulator does not run (NOT_SIMULATED, or one not known at all) is read as one
of these rows with its mnemonic and operands as written (core/instructions.shown_row): a box,
or a contact when it is spelled as one (`DLD=`, `DAND<`, `LD&` ...). The checks warn, the scan
passes a box's input on and a contact never conducts (compiler/implementations.py).
"""

from __future__ import annotations

import re

from ladderworks.core.dialects.delta.instructions import (
    PREFIX,
    STK,
    SUB_BASE,
    Spelling,
)
from ladderworks.core.instructions import (
    FUNCTION_OPCODE,
    Combine,
    InstructionSpec,
    Kind,
    shown_name,
)

_SUB = SUB_BASE + 1900  # their SUB numbers: 11900.. (a binary names the base row)
# a contact's spelling: LD, AND or OR (a D before it: 32-bit), then a comparison or logic sign
_CONTACT = re.compile(r"^D?(LD|AND|OR)[=<>&|^]+$")
_KNOWN_CONTACT = re.compile(r"^D?(LD|AND|AN|OR)")  # LDI, ANI, ORP, AND= …


def _row(suffix: str, sub: int, combine: Combine, title: str, title_tr: str,
         pushes: int = 0, alone: bool = False) -> InstructionSpec:
    return InstructionSpec(PREFIX + "SHOWN" + suffix, Kind.FUNCTION, sub,
                           inputs=() if combine is Combine.READ or alone else ("ACT",),
                           title=title,
                           title_tr=title_tr, opcode=FUNCTION_OPCODE, mnemonic="?",
                           source="delta", dialect="delta", combine=combine, pushes=pushes,
                           w1=combine is not Combine.NONE, simulated=False)


BOX = _row("", _SUB, Combine.NONE, "Not simulated (shown only)", "BENZETİLMEZ (YALNIZ GÖSTERİLİR)")
LOAD = _row(".LD", _SUB + 1, Combine.READ, "Contact not simulated (never conducts)",
            "BENZETİLMEYEN KONTAK (İLETMEZ)")
LOAD_STK = _row(".LD" + STK, _SUB + 2, Combine.READ, "Contact not simulated (never conducts)",
                "BENZETİLMEYEN KONTAK (İLETMEZ)", pushes=1)
SERIES = _row(".AND", _SUB + 3, Combine.AND, "Contact not simulated (never conducts)",
              "BENZETİLMEYEN KONTAK (İLETMEZ)")
PARALLEL = _row(".OR", _SUB + 4, Combine.OR, "Contact not simulated (never conducts)",
                "BENZETİLMEYEN KONTAK (İLETMEZ)")
ALONE = _row(".ALONE", _SUB + 5, Combine.NONE, "Not simulated (shown only)",
             "BENZETİLMEZ (YALNIZ GÖSTERİLİR)", alone=True)
ROWS: tuple[InstructionSpec, ...] = (BOX, LOAD, LOAD_STK, SERIES, PARALLEL, ALONE)


def spelling(mnemonic: str, operands: list[str], logic: bool, contact: bool = False
             ) -> Spelling:
    """How a mnemonic that is not simulated is read: a contact's part in the rung (`load`,
    `contact`) when it is spelled as one (or `contact`: a simulated contact with an operand
    the simulator does not have, `LD M0E0`), else a box (`output`), or a network of its own
    when no logic comes before it (`alone`: NOP, STL, EI ...); its rows named for it."""
    texts = tuple(operands)
    found = (_KNOWN_CONTACT if contact else _CONTACT).match(mnemonic)
    if found is None:
        if not logic:
            return Spelling("alone", shown_name(ALONE, mnemonic, texts))
        return Spelling("output", shown_name(BOX, mnemonic, texts))
    if found.group(1) == "LD":
        return Spelling("load", shown_name(LOAD, mnemonic, texts),
                        shown_name(LOAD_STK, mnemonic, texts))
    row = SERIES if found.group(1) in ("AND", "AN") else PARALLEL
    return Spelling("contact", shown_name(row, mnemonic, texts))
