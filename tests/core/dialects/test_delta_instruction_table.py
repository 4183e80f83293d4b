"""docs/dialects.md's "Every DVP instruction" table agrees with the Delta rows: each "yes"
mnemonic is read (and has an implementation), each "no" one is reported not simulated, and
every mnemonic the reader reads is in a "yes" row."""

from __future__ import annotations

import re
from pathlib import Path

from ladderworks.core.dialects.delta.table import NOT_SIMULATED, SPELLINGS
from ladderworks.core.instructions import FUNCTIONS, lookup
from ladderworks.core.plc.families import IMPLEMENTED
from tests.core.dialects.conftest import delta

DOC = Path(__file__).resolve().parents[3] / "docs" / "dialects.md"
_TOKEN = re.compile(r"[A-Z][A-Z0-9]*(?:[=<>&|^]+)?")
_NOT_MNEMONICS = {"P", "D", "API"}  # the pointer line, "D forms", "P forms"


def table() -> list[tuple[list[str], bool]]:
    """The table's rows: their mnemonics, and whether they are simulated."""
    text = DOC.read_text(encoding="utf-8")
    part = text.split("### Every DVP instruction", 1)[1].split("\n\n", 3)[2]
    rows = []
    for line in part.splitlines():
        cells = [cell.strip().replace("\\|", "|") for cell in re.split(r"(?<!\\)\|", line)]
        if len(cells) < 5 or cells[3] not in ("yes", "no"):
            continue
        names = [t for t in _TOKEN.findall(cells[2].split("(")[0]) if t not in _NOT_MNEMONICS]
        rows.append((names, cells[3] == "yes"))
    return rows


def test_the_table_says_what_the_rows_do() -> None:
    rows = table()
    assert len(rows) > 40
    said_yes = set()
    for names, simulated in rows:
        for name in names:
            if simulated:
                said_yes.add(name)
                assert name in SPELLINGS, name
                spec = lookup(SPELLINGS[name].row)
                assert spec is not None and (spec not in FUNCTIONS or spec.name in IMPLEMENTED
                                             or spec.flow.value), name
            else:
                assert name in NOT_SIMULATED and name not in SPELLINGS, name
    assert set(SPELLINGS) - said_yes == set()


def test_a_program_of_every_new_form_reads() -> None:
    # one line of each new instruction, as WPLSoft writes them: it reads without a diagnostic
    program = delta("LD X0\nDMOV K100000 D0\nDADDP D0 D2 D4\nZRST M0 M10\nBMOV D0 D10 K4\n"
                    "FMOVP K0 D20 K5\nDXCH D0 D2\nBCD D0 D1\nDBIN D0 D2\nWAND D0 H00FF D1\n"
                    "DOR D0 K1 D2\nNEGP D0\nROR D0 K4\nSFTLP X0 M0 K16 K1\nDECO D0 Y0 K3\n"
                    "ENCO M0 D0 K3\nALTP M0\nSUM D0 D1\nFLT D0 D10\nDEDIV D10 K3 D12\n"
                    "INT D12 D14\nDECMP D10 D12 M20\nFROM K0 K12 D200 K1\nTO K0 K1 H0 K1\n"
                    "PLSY K1000 K100 Y0\nDCNT C235 D9\nNOP\nWDT\nLD X1\nDAND< D7 K0\nOUT Y1\n"
                    "END\n")
    assert len(program.networks) >= 3
