""".pdw projects fuzzed: generated code words and mutated projects are read, checked and run by
the CLI commands with exit 0 or 1, never a traceback; the reader never raises."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderworks.core.dialects.fatek.pdw_file import read_pdw
from ladderworks.core.il.reading import parse_bytes
from tests.core.dialects.pdw_builder import build
from tests.fuzz.test_cli_fuzz import COMMANDS, run_cli
from tests.hypothesis_profiles import examples

# Words the real project uses and their neighbours (basic contacts and coils, TU, extended codes,
# operands), and any 16-bit word
_WORDS = st.one_of(
    st.sampled_from([0x4000, 0x5000, 0x6400, 0x8FE6, 0x9FE7, 0xC100, 0xC400, 0xD100, 0xE000,
                     0xFC82, 0xFCC4, 0xFDC4, 0xFC80, 0xF4AC, 0xF5AC, 0xF496, 0xF51A, 0xF1D0,
                     0xF47F, 0xF67F, 0x6FFC, 0x0022, 0x0A00, 0x0590, 0x03CC, 0xFFFF]),
    st.integers(0x4000, 0xDFFF), st.integers(0, 0xFFFF))
_SETTINGS = settings(max_examples=examples(200), deadline=None, suppress_health_check=[
    HealthCheck.too_slow, HealthCheck.function_scoped_fixture, HealthCheck.data_too_large])


@_SETTINGS
@given(words=st.lists(_WORDS, max_size=60))
def test_generated_code_is_read_or_stopped_with_a_diagnostic(words: list[int]) -> None:
    data = build(words)
    result = read_pdw(data)
    assert result.error is None or result.error.code.startswith("pdw-")
    parsed = parse_bytes(data)
    assert parsed.program is not None


@settings(max_examples=examples(80), deadline=None, suppress_health_check=[
    HealthCheck.too_slow, HealthCheck.function_scoped_fixture, HealthCheck.data_too_large])
@given(words=st.lists(_WORDS, max_size=30), cuts=st.lists(st.integers(0, 0xB000), max_size=3),
       flips=st.lists(st.tuples(st.integers(0, 0xB000), st.integers(0, 255)), max_size=8))
def test_mutated_projects_never_raise(words: list[int], cuts: list[int],
                                      flips: list[tuple[int, int]]) -> None:
    data = bytearray(build(words, {"X0": b"START", "M1": b"Bezpiecze\xf1stwo"}))
    for at, value in flips:
        if at < len(data):
            data[at] = value
    for cut in cuts:
        del data[cut:cut + 16]
    result = read_pdw(bytes(data))
    assert result.error is None or result.error.code.startswith("pdw-")
    assert parse_bytes(bytes(data)).program is not None


@pytest.mark.parametrize("command", [*COMMANDS, "pdw"])
@settings(max_examples=examples(40), deadline=None, suppress_health_check=[
    HealthCheck.too_slow, HealthCheck.function_scoped_fixture, HealthCheck.data_too_large])
@given(words=st.lists(_WORDS, max_size=20), cut=st.integers(0, 0xB000))
def test_cli_commands_on_projects(command: str, words: list[int], cut: int,
                                  tmp_path: Path) -> None:
    data = build(words)
    for sample in (data, data[:cut]):
        path = tmp_path / "input.pdw"
        path.write_bytes(sample)
        code, output = run_cli(command, path, tmp_path)
        assert code in (0, 1), (command, code, output[-2000:])
        assert "Traceback" not in output
