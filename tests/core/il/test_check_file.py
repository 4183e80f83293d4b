"""parse_for_check (what `ladderworks-cli check` runs the compiler's checks on) gives exactly
parse_file's diagnostics and networks, though it makes no section views or lossless keys."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from ladderworks.core.il import parse_bytes, parse_file, parse_for_check
from ladderworks.core.il.parser import ParseResult
from tests.real_programs import WHOLE, fragment_names, real_bytes

DATA = Path(__file__).resolve().parents[2] / "data" / "fuzz"

# lines to break programs with: errors, warnings, parameters and SUBs that take them
JUNK = ["", " ", "\t", ";", "//x", ",", "SUB", "SUB 99", "SUB 43", "SUB 27", "0", "-1", "+5",
        "R", "R9999.9", "X0.8", "N00001:", "RD", "RD X1.1 X2.2", "P5", "L3", "%", "%@3",
        "AND 1 R10 R11 R12", "SUB.219 1 2", "TMR 1", "END1", "RD.STK X1.1", "WRT Y0.1", "1.5",
        "rd x1.1", "RD  X1.1 ; c", "RD X1.1 // c", "JMPB L5", "WRT X1.1", "RD Q1.1", "RD R1"]


def _same(path: Path, data: bytes) -> None:
    path.write_bytes(data)
    _same_as_parse_file(path, parse_bytes(data))


def _same_as_parse_file(path: Path, whole: ParseResult) -> None:
    light = parse_for_check(path)
    assert light.diagnostics == whole.diagnostics
    assert light.program.networks == whole.program.networks
    assert [n.line for n in light.program.networks] == [n.line for n in whole.program.networks]
    assert (light.program.trailer, light.program.dialect) == (
        whole.program.trailer, whole.program.dialect)
    assert light.program.source is not None and light.program.source.keys == []


@pytest.mark.parametrize("name", [*WHOLE, *fragment_names()])
def test_a_real_program(tmp_path: Path, name: str) -> None:
    _same(tmp_path / "p.txt", real_bytes(name))


@pytest.mark.parametrize("path", sorted(DATA.iterdir()), ids=lambda p: p.name)
def test_the_fuzz_files(path: Path) -> None:
    _same_as_parse_file(path, parse_file(path))


@pytest.mark.parametrize("text", [
    "RD X1.1\nWRT Y1.1\nBOGUS\n",  # no section, but networks: not "not-a-program"
    "BOGUS\nRD X1.1\nWRT Y1.1\nRD X1.1\nWRT Y1.1\n",
    "BOGUS\nMORE BOGUS\n",  # no section, no network: not a program
    "%@3\nRD X1.1\n\nSUB 27\n\n2\nR100\nR200\nWRT Y1.1\n%\n",
    "%@3\nRD X1.1\nWRT Y1.1\nRD X1.1\nWRT Y9.9\nRD X1.1\nWRT Y9.9\n%\n",
    "%@2-C\nQ1.1 FOO\nX1.1 BAR\nX1.1\nP5 SUBP\nR9999.9 X\n%\n%@3\nRD X1.1\nWRT Y1.1\n%\n",
])
def test_programs_that_decide_it(tmp_path: Path, text: str) -> None:
    _same(tmp_path / "p.LAD", text.encode())


def test_broken_real_programs(tmp_path: Path) -> None:
    lines = real_bytes("FANUC_STUDER_X22_P036").decode("ascii").split("\n")
    rnd = random.Random(13)
    for _ in range(60):
        start = rnd.randrange(0, len(lines) - 300)
        part = ["%@3", *lines[start:start + rnd.randrange(5, 300)], "%"]
        for _ in range(rnd.randrange(1, 10)):
            at = rnd.randrange(len(part) + 1)
            if rnd.random() < 0.5:
                part.insert(at, rnd.choice(JUNK))
            elif part:
                del part[min(at, len(part) - 1)]
        _same(tmp_path / "p.LAD", "\n".join(part).encode())
