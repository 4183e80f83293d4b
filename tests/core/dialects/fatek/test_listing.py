"""The WinProladder listing as records: page headers, steps with a unit letter, FUN operand
lines, FO outputs, comparison contacts, seed 002's plain form; bad lines at their line."""

from __future__ import annotations

import pytest

from ladderworks.core.dialects.fatek.listing import OperandLine, read_listing

PRINTED = """\
Printed Item: Mnemonic - PROJECT1                                    Page 1

     0  ORG      X0
     1  AND NOT  X1
     2  OUT      Y0
     3  ORG TU   X2
     4A FUN 11P  (+)
             Sa: R0
             Sb: 7
             D : R1
     5  FO 0
     6  OUT L    Y1
     7  ORGF 170 (=)
             Sa: R1
             Sb: 100
     8  OUTS     M10
Printed Item: Mnemonic - PROJECT1                                    Page 2
     9  ORG      M1924
    10  FUN 8D MOV
             S : 100
             D : DR10
    11  ORG      X3
    12  CTR      C0       10
    13  RST      C0
    14  ORG      OPEN
    15  FUN 140 HSPSO
             Ps: 0
             SR: R0
             WR: R100
             : C1
    16  END
"""


def test_printed_listing() -> None:
    listing, problems = read_listing(PRINTED.splitlines())
    assert problems == []
    assert listing.headers == [1, 17]
    records = listing.records
    assert [(r.step, r.mnemonic, r.modifier, r.operand) for r in records[:4]] == [
        (0, "ORG", "", "X0"), (1, "AND", "NOT", "X1"), (2, "OUT", "", "Y0"),
        (3, "ORG", "TU", "X2")]
    fun = records[4]
    assert (fun.step, fun.unit, fun.fun, fun.fun_name, fun.pulse, fun.double) == (
        4, "A", 11, "(+)", True, False)
    assert fun.operands == [OperandLine(8, "Sa", "R0"), OperandLine(9, "Sb", "7"),
                            OperandLine(10, "D", "R1")]
    assert fun.last_line == 10
    assert (records[5].mnemonic, records[5].operand) == ("FO", "0")
    assert (records[6].mnemonic, records[6].modifier, records[6].operand) == ("OUT", "L", "Y1")
    cmp = records[7]
    assert (cmp.mnemonic, cmp.fun, cmp.fun_name, len(cmp.operands)) == ("ORGF", 170, "(=)", 2)
    assert (records[8].mnemonic, records[8].operand) == ("OUTS", "M10")
    mov = records[10]
    assert (mov.fun, mov.double, mov.fun_name, mov.operands[1].text) == (8, True, "MOV", "DR10")
    ctr = records[12]
    assert (ctr.mnemonic, ctr.operand, ctr.args) == ("CTR", "C0", ("10",))
    assert (records[13].mnemonic, records[13].operand) == ("RST", "C0")
    assert records[14].operand == "OPEN"
    hsp = records[15]
    assert [o.label for o in hsp.operands] == ["Ps", "SR", "WR", ""]
    assert hsp.operands[-1].text == "C1"
    assert records[-1].mnemonic == "END"


def test_seed_plain_form() -> None:
    """002: tab-separated `op⇥device⇥number`, margin notes, `OUT` / `Y 0` over two lines."""
    text = "ORG\tX\t0\nOUT TR\t0\t\nLD TR  0 ← 2. sıradan başlar\nANDLD\t\t\nORG SHORT\nOUT\n\nY 0"
    listing, problems = read_listing(text.splitlines())
    assert problems == []
    assert [(r.step, r.mnemonic, r.modifier, r.operand) for r in listing.records] == [
        (None, "ORG", "", "X0"), (None, "OUT", "TR", "TR0"), (None, "LD", "TR", "TR0"),
        (None, "ANDLD", "", ""), (None, "ORG", "", "SHORT"), (None, "OUT", "", "Y0")]


@pytest.mark.parametrize(("text", "code", "line"), [
    ("ORG X0\nFOO X1", "fatek-unknown-instruction", 2),
    ("ORG X0\n   Sa: R0", "fatek-stray-operand", 2),
    ("ORG X0\nANDLD X1", "extra-operand", 2),
])
def test_bad_lines_are_diagnosed_at_their_line(text: str, code: str, line: int) -> None:
    _listing, problems = read_listing(text.splitlines())
    assert [(d.code, d.line) for d in problems] == [(code, line)]


def test_rst_spellings() -> None:
    """`RST C0`, `RST( ) C0` and `RST(C0)` are the same reset (issue 26 writes `RST( )`)."""
    listing, problems = read_listing(["RST C0", "RST( ) C1", "RST(T2)", "rst ( ) t3"])
    assert problems == []
    assert [(r.mnemonic, r.operand) for r in listing.records] == [
        ("RST", "C0"), ("RST", "C1"), ("RST", "T2"), ("RST", "t3")]
