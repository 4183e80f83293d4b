"""Fuzzing the Fatek readers added for WinProladder's printouts: generated printed-form listings
and the printed example mutated (cut in a FUN box, bytes changed) end in exit 0 or 1 through every
CLI command, never a traceback; a mutated comment export gives symbols or diagnostics."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderworks.core.dialects.fatek.comments import read_comments
from ladderworks.paths import EXAMPLES
from tests.fuzz.test_cli_fuzz import COMMANDS, _mutate, run_cli
from tests.hypothesis_profiles import examples

PRINTED = (EXAMPLES / "fatek" / "capping_printed.lst").read_bytes()
_WORDS = st.one_of(
    st.sampled_from(["ORG", "LD", "AND", "OR", "NOT", "TU", "TD", "OUT", "TR", "OPEN", "SHORT",
                     "SET( )", "RST( )", "SET(", ")", "FUN", "08", "_.MOV", "141.MPARA",
                     "140.HSPSO", "15 _.(+1)", "999.XYZ", "ANDF", "171_.>", "FO", "0", "2",
                     ".01", ".1", "1", "#", "Printed Item: Mnemonic - U", "Printed Item: Ladder",
                     "S :", "D :", "Sa:", "Ps:", ":", "ANDLD", "ORLD"]),
    st.from_regex(r"(X|Y|M|S|T|C|R|TR)[0-9]{1,4}", fullmatch=True),
    st.integers(0, 99999).map(lambda n: f"{n:05d}M"),
)
_LINE = st.lists(_WORDS, max_size=5).map(" ".join)
_TEXT = st.lists(_LINE, max_size=30).map("\n".join)
_SETTINGS = settings(max_examples=examples(60), deadline=None, suppress_health_check=[
    HealthCheck.too_slow, HealthCheck.function_scoped_fixture])


def _clean(command: str, data: bytes, tmp: Path) -> None:
    path = tmp / "printout.lst"
    path.write_bytes(data)
    code, output = run_cli(command, path, tmp)
    assert code in (0, 1), (command, code, output[-2000:])
    assert "Traceback" not in output


@pytest.mark.parametrize("command", COMMANDS)
@_SETTINGS
@given(text=_TEXT)
def test_generated_printouts(command: str, text: str, tmp_path: Path) -> None:
    _clean(command, ("Printed Item: Mnemonic - Main_unit1\n" + text + "\n").encode(), tmp_path)


@pytest.mark.parametrize("command", COMMANDS)
@_SETTINGS
@given(data=st.data())
def test_mutated_printout(command: str, data: st.DataObject, tmp_path: Path) -> None:
    _clean(command, _mutate(PRINTED, data.draw), tmp_path)


@pytest.mark.parametrize("cut", range(1, PRINTED.count(b"\n")))
def test_the_printout_cut_after_every_line_reads_or_says_where(cut: int, tmp_path: Path) -> None:
    _clean("check", b"\n".join(PRINTED.split(b"\n")[:cut]) + b"\n", tmp_path)


_EXPORT = ("REF\tCOMMENT\tDESCRIPTION\r\nX0\tStart\t\r\nM10\tPołożenie\tżółw\r\n"
           "R100\tLicznik\t\r\n").encode("cp1250")


@_SETTINGS
@given(data=st.data())
def test_mutated_comment_exports(data: st.DataObject) -> None:
    """A comment export, mutated: symbols or diagnostics at its lines, never an exception."""
    mutated = _mutate(_EXPORT, data.draw)
    table, diagnostics = read_comments(mutated)
    lines = mutated.count(b"\n") + 1
    assert all(1 <= d.line <= lines and d.message() for d in diagnostics)
    assert table is not None or any(d.is_error for d in diagnostics)
