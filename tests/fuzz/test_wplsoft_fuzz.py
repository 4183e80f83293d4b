"""Fuzzing the WPLSoft export reader: mutated exports, generated lines and bytes named `.csv` end
in exit 0 or 1 with no traceback; what reads without an error saves byte for byte."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderworks.core.dialects.delta import csv_form
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.reading import parse_bytes
from ladderworks.paths import EXAMPLES
from tests.fuzz.test_cli_fuzz import _mutate, run_cli
from tests.hypothesis_profiles import examples
from tests.real_programs import real_programs_dir

COMMANDS = ("check", "ladder", "run", "format")
_SOURCES = [p.read_bytes() for p in sorted((EXAMPLES / "delta").glob("wplsoft_*.csv"))]
_SOURCES.append(b"000000,LD,X0\n000001,OUT,Y0\n" + b"9" * 5000 + b",END\n")
_MNEMONICS = ["LD", "LDI", "AND", "ANI", "OR", "ORB", "ANB", "MPS", "MRD", "MPP", "INV", "OUT",
              "SET", "RST", "LDP", "TMR", "CNT", "DCNT", "MOV", "DMOV", "ADD", "DAND<", "LD=",
              "CJ", "CALL", "P1", "FEND", "SRET", "MC", "MCR", "END", "FROM", "ZRST", "FOO",
              "", "STL", "NOP"]
_OPERANDS = ["X0", "X8", "Y7", "M1002", "S0", "T0", "C235", "D9999", "K5", "K-5", "H0",
             "HFFFF", "P1", "N0", "", " ", "K", "D", "Q1"]
_LINE = st.tuples(st.integers(-5, 999_999), st.sampled_from(_MNEMONICS),
                  st.lists(st.sampled_from(_OPERANDS), max_size=5),
                  st.sampled_from([",", ";", "\t"]), st.booleans())
_SETTINGS = settings(max_examples=examples(200), deadline=None, suppress_health_check=[
    HealthCheck.too_slow, HealthCheck.function_scoped_fixture, HealthCheck.data_too_large])


def _line(parts: tuple[int, str, list[str], str, bool]) -> str:
    step, mnemonic, operands, separator, trailing = parts
    fields = [f"{step:06d}", mnemonic, *operands]
    return separator.join(fields) + (separator if trailing else "")


def _clean(command: str, data: bytes, tmp: Path) -> None:
    path = tmp / "input.csv"
    path.write_bytes(data)
    code, output = run_cli(command, path, tmp)
    assert code in (0, 1), (command, code, output[-2000:])
    assert "Traceback" not in output


def _saves_as_read(data: bytes) -> None:
    result = parse_bytes(data)
    if result.ok and result.program.dialect == "delta":
        assert encode_program(result.program) == data


@pytest.mark.parametrize("command", COMMANDS)
@_SETTINGS
@given(lines=st.lists(_LINE, max_size=30), crlf=st.booleans())
def test_generated_exports(command: str, lines: list, crlf: bool, tmp_path: Path) -> None:
    end = "\r\n" if crlf else "\n"
    data = "".join(_line(parts) + end for parts in lines).encode()
    _clean(command, data, tmp_path)
    _saves_as_read(data)


@pytest.mark.parametrize("command", COMMANDS)
@_SETTINGS
@given(data=st.data())
def test_mutated_exports(command: str, data: st.DataObject, tmp_path: Path) -> None:
    mutated = _mutate(data.draw(st.sampled_from(_SOURCES)), data.draw)
    _clean(command, mutated, tmp_path)
    _saves_as_read(mutated)


@_SETTINGS
@given(data=st.binary(max_size=3000))
def test_random_bytes_named_csv(data: bytes, tmp_path: Path) -> None:
    _clean("check", data, tmp_path)
    csv_form.detect(data.decode("latin-1").splitlines())


def test_a_binary_file_named_csv_is_one_clear_error(tmp_path: Path) -> None:
    path = tmp_path / "picture.csv"
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + bytes(range(256)) * 8)
    code, output = run_cli("check", path, tmp_path)
    lines = output.strip().splitlines()
    assert code == 1 and 1 <= len(lines) <= 3 and "Traceback" not in output
    assert lines[0].startswith(f"{path}:1:")


def test_a_dvp_project_named_csv_opens_as_the_project(tmp_path: Path) -> None:
    """The content decides: WPLSoft's project header is read whatever the file's name."""
    path = tmp_path / "project.csv"
    path.write_bytes((real_programs_dir() / "delta" / "NIRMALKUMAR_timer.dvp").read_bytes())
    code, output = run_cli("check", path, tmp_path)
    assert code == 0 and "Traceback" not in output
