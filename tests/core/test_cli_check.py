"""`ladderworks-cli check` reports what compile would refuse or warn about, not only the parser."""

from __future__ import annotations

import contextlib
import io
import re
from pathlib import Path

import pytest

from ladderworks.cli import main
from ladderworks.core.compiler import compile_program
from ladderworks.core.il import parse_file, parse_for_check
from ladderworks.paths import EXAMPLES
from tests.real_programs import real_programs_dir

DATA = Path(__file__).resolve().parent.parent / "data"
_LINE = re.compile(r"^(.*):(\d+):(\d+): (\S+) ")

UNMATCHED_JMP = "%@3\nRD X0.1\nJMP 0\nRD X0.2\nWRT Y0.1\nRD X0.3\nWRT Y0.1\nEND\n%\n"
COIL_TWICE = "%@3\nRD X0.2\nWRT Y0.1\nRD X0.3\nWRT Y0.1\nEND\n%\n"


def check(path: Path) -> tuple[int, list[str]]:
    """Run `ladderworks-cli check FILE` in-process: (exit code, printed lines)."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        code = main(["check", str(path)])
    return code, out.getvalue().splitlines()


def positions(lines: list[str], path: Path) -> list[tuple[int, int, str]]:
    """(line, column, code) of each printed diagnostic; every line has the FILE:LINE:COL form."""
    found = []
    for line in lines:
        match = _LINE.match(line)
        assert match is not None and match.group(1) == str(path), line
        found.append((int(match.group(2)), int(match.group(3)), match.group(4)))
    return found


def test_an_unmatched_jmp_is_an_error_of_check(tmp_path: Path) -> None:
    path = tmp_path / "jump.LAD"
    path.write_text(UNMATCHED_JMP)
    assert parse_for_check(path).diagnostics == []  # the parser alone finds nothing wrong
    code, lines = check(path)
    assert code == 1
    assert positions(lines, path) == [(3, 1, "jmp-without-jmpe"), (7, 1, "coil-twice")]


def test_compile_warnings_are_printed_and_pass(tmp_path: Path) -> None:
    path = tmp_path / "coils.LAD"
    path.write_text(COIL_TWICE)
    code, lines = check(path)
    assert code == 0
    assert positions(lines, path) == [(5, 1, "coil-twice")]


def test_parser_errors_alone_when_the_parse_fails(tmp_path: Path) -> None:
    path = tmp_path / "bad.LAD"
    path.write_text(UNMATCHED_JMP.replace("RD X0.2", "RD X0.2 extra"))
    code, lines = check(path)
    assert code == 1
    found = parse_for_check(path).diagnostics
    assert [c for _l, _c, c in positions(lines, path)] == [d.code for d in found]
    assert "jmp-without-jmpe" not in "\n".join(lines)


def _refused(path: Path) -> bool:
    """True when the file does not parse, or parses and compile_program refuses it."""
    result = parse_file(path)
    return not result.ok or compile_program(result.program).binary is None


_FILES = sorted(p for p in [*(DATA / "fuzz").iterdir(), *DATA.glob("*.LAD"),
                            *EXAMPLES.glob("*.LAD")] if p.is_file())


@pytest.mark.parametrize("path", _FILES, ids=lambda p: p.name)
def test_check_fails_exactly_when_compile_refuses(path: Path) -> None:
    code, lines = check(path)
    assert code == (1 if _refused(path) else 0), lines
    found = positions(lines, path)
    assert [(line, column) for line, column, _c in found] == sorted(
        (line, column) for line, column, _c in found)


def test_a_real_program_passes_check_with_compile_warnings() -> None:
    path = real_programs_dir() / "FANUC_STUDER_S41_F034.txt"
    code, lines = check(path)
    assert code == 0
    codes = {c for _l, _c, c in positions(lines, path)}
    assert {"coil-twice", "coil-mixed"} & codes  # the compiler's warnings reach the output
    assert compile_program(parse_file(path).program).binary is not None
