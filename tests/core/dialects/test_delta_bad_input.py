"""Bad Delta input: one diagnostic at its line (and column), never a traceback."""

from __future__ import annotations

import pytest

from ladderworks.core.compiler import check
from ladderworks.core.il.reading import parse_bytes


def _diagnostics(text: str) -> list[tuple[int, int, str]]:
    """(line, column, code) of what `check` reports: the reader's, else the compiler's."""
    result = parse_bytes(text.encode(), "delta")
    found = result.diagnostics if not result.ok else result.diagnostics + check(result.program)
    return [(d.line, d.column, d.code) for d in found]


@pytest.mark.parametrize(("text", "expected"), [
    # wrong operand kinds
    ("LD X0\nOUT X1\nEND\n", (2, 5, "dialect-operand")),
    ("LD X0\nTMR C0 K10\nEND\n", (2, 5, "dialect-operand")),
    ("LD X0\nCNT C200 K10\nEND\n", (2, 5, "dialect-operand")),
    ("LD X0\nDCNT C5 K10\nEND\n", (2, 6, "dialect-operand")),
    ("LD X0\nMOV D0 K5\nEND\n", (2, 8, "dialect-operand")),
    ("LD K5\nOUT Y0\nEND\n", (1, 4, "dialect-operand")),
    ("LD X0\nCJ X1\nEND\n", (2, 4, "dialect-operand")),
    ("LD X0\nMC K1\nEND\n", (2, 4, "dialect-operand")),
    ("LD X0\nTMR T0 KX\nEND\n", (2, 8, "dialect-constant")),
    ("LD X0\nOUT\nEND\n", (2, 1, "param-count")),
    ("LD X0\nTMR T0\nEND\n", (2, 1, "param-count")),
    # out-of-range devices
    ("LD X8\nOUT Y0\nEND\n", (1, 4, "device-octal")),
    ("LD X0\nOUT M4096\nEND\n", (2, 5, "device-range")),
    ("LD X0\nMOV K1 D10000\nEND\n", (2, 8, "device-range")),
    ("LD X0\nTMR T256 K1\nEND\n", (2, 5, "device-range")),
    ("LD Q0\nOUT Y0\nEND\n", (1, 4, "device-unknown")),
    # program structure
    ("LD X0\nCALL P3\nFEND\nP1\nLD X1\nOUT Y0\nSRET\nEND\n", (2, 1, "dvp-call-missing")),
    ("LD X0\nCALL P1\nFEND\nP1\nLD X1\nOUT Y0\nEND\n", (4, 1, "dvp-missing-sret")),
    ("LD X0\nCJ P4\nLD X1\nOUT Y0\nEND\n", (2, 1, "dvp-pointer-missing")),
    ("AND X0\nOUT Y0\nEND\n", (1, 1, "dvp-no-logic")),
    ("LD X0\nANB\nOUT Y0\nEND\n", (2, 1, "stack-underflow")),
    ("LD X0\nMRD\nOUT Y0\nEND\n", (2, 1, "stack-underflow")),
    # instructions not simulated, or not known: kept and drawn, a warning at their line
    ("LD X0\nFOO Y0\nEND\n", (2, 1, "not-simulated")),
    ("LD X0\nPID D0 D1 D2 D3\nEND\n", (2, 1, "not-simulated")),
    ("LD X0\n  0003  SORT D0 K4 K2 D10 K1\nEND\n", (2, 9, "not-simulated")),
    ("LD X0\nF$O Y0\nEND\n", (2, 1, "unknown-instruction")),
    # WPLSoft's export: a missing operand, a step out of order
    ("000000,LD,X0\n000001,OUT,\n000002,END\n", (2, 8, "param-count")),
    ("000000,LD,X0\n000001,MOV,,D0\n000006,END\n", (2, 8, "dvp-missing-operand")),
    ("000000,LD,X0\n000001,OUT,Y0\n000001,END\n", (3, 1, "dvp-step-order")),
])
def test_one_diagnostic_at_its_line(text: str, expected: tuple[int, int, str]) -> None:
    assert _diagnostics(text) == [expected]


def test_each_instruction_outside_a_subroutine_is_reported() -> None:
    assert _diagnostics("LD X0\nOUT Y0\nFEND\nLD X1\nOUT Y1\nEND\n") == [
        (4, 1, "dvp-outside-subroutine"), (5, 1, "dvp-outside-subroutine")]


def test_names_and_devices_are_said_in_delta() -> None:
    result = parse_bytes(b"AND X0\nOUT Y0\nLD X1\nOUT Y0\nEND\n", "delta")
    messages = [d.message() for d in check(result.program)]
    assert messages[0] == "AND without a logic result before it (start with LD)"
    assert messages[1] == "coil Y0 is written more than once"


def test_garbage_never_raises() -> None:
    for text in ["\x00\x01", "LD", "P", "P999999999999", "LD X0 X1 X2", "LD= K1", "MC N9",
                 "K5", "LD\tX0\tK1", "0 0 0", "CALL P1\nSRET\nSRET", "LDP K1", "RST K1",
                 "; only a comment", "FEND\nFEND\nEND\nEND", "LD X0\nMPS\nMPS\nMPP"]:
        result = parse_bytes(text.encode(), "delta")
        if result.ok:
            check(result.program)
