"""Random Delta lists: read, checked, compiled and run without a traceback; a program the
checks pass runs the same in fast and monitored mode."""

from __future__ import annotations

import random

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine

_WORDS = ["LD", "LDI", "AND", "ANI", "OR", "ORI", "ANB", "ORB", "MPS", "MRD", "MPP", "INV",
          "OUT", "SET", "RST", "LDP", "ANDF", "TMR", "CNT", "MOV", "ADD", "INCP", "CMP", "ZCP",
          "LD>", "AND=", "OR<>", "CJ", "CALL", "P1", "P2", "FEND", "SRET", "MC", "MCR", "END",
          "DMOV", "FOO"]
_OPERANDS = ["X0", "X7", "X10", "X8", "Y0", "Y17", "M0", "M1000", "S1", "T0", "T127", "C0",
             "C200", "D0", "D9999", "K0", "K10", "K-5", "H7FFF", "P1", "P2", "N0", ""]


def _program(rng: random.Random) -> str:
    lines = []
    for _ in range(rng.randrange(1, 25)):
        words = [rng.choice(_WORDS)] + [rng.choice(_OPERANDS) for _ in range(rng.randrange(4))]
        lines.append(" ".join(word for word in words if word))
    return "\n".join(lines) + "\nEND\n"


_IN = ["X0", "X1", "X2", "X7", "X10", "M0", "M1", "M1013", "T0", "C0", "Y0", "S3"]
_OUT = ["Y0", "Y1", "Y17", "M0", "M1", "M2", "S3"]
_OUTPUTS = ["OUT {b}", "SET {b}", "RST {b}", "TMR T0 K3", "TMR T64 K7", "CNT C0 K4",
            "DCNT C200 K-2", "MOV K7 D0", "ADD D0 K1 D0", "INCP D1", "CMP D0 K5 M10",
            "ZCP K1 K9 D0 M20", "PLS M30", "RST T0", "RST C0"]


def _rung(rng: random.Random) -> list[str]:
    lines = [f"{rng.choice(['LD', 'LDI', 'LDP'])} {rng.choice(_IN)}"]
    for _ in range(rng.randrange(4)):
        kind = rng.randrange(4)
        if kind == 0:
            lines.append(f"{rng.choice(['AND', 'ANI', 'OR', 'ORI'])} {rng.choice(_IN)}")
        elif kind == 1:
            lines += [f"LD {rng.choice(_IN)}", f"{rng.choice(['AND', 'OR'])} {rng.choice(_IN)}",
                      rng.choice(["ANB", "ORB"])]
        elif kind == 2:
            lines.append(f"{rng.choice(['AND', 'OR'])}{rng.choice(['=', '>', '<>'])} D0 K3")
        else:
            lines.append("INV")
    if rng.randrange(3) == 0:
        lines += ["MPS", f"AND {rng.choice(_IN)}", f"OUT {rng.choice(_OUT)}", "MPP"]
    lines.append(rng.choice(_OUTPUTS).format(b=rng.choice(_OUT)))
    return lines


def test_random_valid_lists_run_the_same_in_both_modes() -> None:
    rng = random.Random(26)
    ran = 0
    for _ in range(60):
        text = "\n".join(line for _ in range(rng.randrange(1, 8)) for line in _rung(rng))
        result = parse_bytes((text + "\nEND\n").encode(), "delta")
        assert result.ok, (text, result.diagnostics)
        compiled = compile_program(result.program)
        assert compiled.binary is not None, (text, compiled.diagnostics)
        fast = ScanEngine(compiled.binary)
        monitored = ScanEngine(compiled.binary, monitored=True)
        for scan in range(40):
            for engine in (fast, monitored):
                engine.memory.areas[Area.X][0] = rng_bits = (scan * 37) & 0xFF
                engine.memory.areas[Area.X][1] = rng_bits >> 3
                engine.scan()
            assert fast.memory.snapshot() == monitored.memory.snapshot(), text
        ran += 1
    assert ran == 60


def test_random_lists_never_raise() -> None:
    rng = random.Random(25)
    for _ in range(400):
        result = parse_bytes(_program(rng).encode(), "delta")
        if not result.ok:
            assert all(d.line >= 1 for d in result.diagnostics if d.is_error)
            continue
        compiled = compile_program(result.program)
        if compiled.binary is None:
            assert all(d.line >= 1 for d in compiled.diagnostics if d.is_error)
            continue
        ScanEngine(compiled.binary).run_scans(5)
