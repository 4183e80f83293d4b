"""Fuzzing the `.dvp` reader: mutated projects (bytes inserted, deleted, replaced, the program
words rewritten) give a project or one diagnostic, never a traceback, through the reader, the
Program reading and every CLI command."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderworks.core.dialects.delta.dvp_codes import END
from ladderworks.core.dialects.delta.dvp_encode import encode_all
from ladderworks.core.dialects.delta.dvp_file import PROGRAM_START, read_or_diagnostic
from ladderworks.core.il.reading import parse_bytes
from tests.core.dialects.dvp_samples import TIMER_WORDS, make_dvp
from tests.fuzz.test_cli_fuzz import COMMANDS, run_cli
from tests.hypothesis_profiles import examples

_SETTINGS = settings(max_examples=examples(300), deadline=None, suppress_health_check=[
    HealthCheck.too_slow, HealthCheck.function_scoped_fixture, HealthCheck.data_too_large])

# words of every kind the reader meets: instruction codes, operand words of each tag, NOP
_WORD = st.one_of(
    st.sampled_from([*TIMER_WORDS, 0x7FFF, 0x7FFA, 0x7FFC, 0x8101, 0x8107, 0x8039, 0x81E5,
                     0x8006, 0x800A, 0x3001, 0x8010, 0x80F1, 0x0800, 0x0604, 0x0403, 0x0200]),
    st.integers(0, 0xFFFF),
)


def _mutate(data: bytes, draw: st.DrawFn) -> bytes:
    chunk = bytearray(data)
    for _ in range(draw(st.integers(1, 8))):
        position = draw(st.integers(0, len(chunk)))
        action = draw(st.sampled_from(["insert", "delete", "replace", "word"]))
        if action == "insert":
            chunk[position:position] = draw(st.binary(min_size=1, max_size=40))
        elif action == "delete":
            del chunk[position:position + draw(st.integers(1, 300))]
        elif action == "replace" and position < len(chunk):
            chunk[position] = draw(st.integers(0, 255))
        elif action == "word":  # a plain program word, scrambled with the sample's key
            at = PROGRAM_START + 2 * draw(st.integers(0, 40))
            if at + 2 <= len(chunk):
                word = draw(_WORD).to_bytes(2, "little")
                key = (0x3C, 0x91 ^ 0x80, 0x5A, 0x07 ^ 0x80)
                chunk[at:at + 2] = bytes((word[0] ^ key[at % 4], word[1] ^ key[(at + 1) % 4]))
    return bytes(chunk)


@_SETTINGS
@given(data=st.data())
def test_mutated_projects_read_or_give_one_diagnostic(data: st.DataObject) -> None:
    mutated = _mutate(make_dvp(), data.draw)
    project, diagnostic = read_or_diagnostic(mutated)
    assert (project is None) != (diagnostic is None)
    if diagnostic is not None:
        assert "{" not in diagnostic.message()
    parse_bytes(mutated)


@_SETTINGS
@given(words=st.lists(_WORD, max_size=60))
def test_random_program_words_read_or_give_one_diagnostic(words: list[int]) -> None:
    project, diagnostic = read_or_diagnostic(make_dvp((*words, END)))
    assert (project is None) != (diagnostic is None)
    if project is not None:  # what reads, reads losslessly: encoded back to the same words
        assert encode_all(project.instructions) == [*words, END][:project.steps]


@pytest.mark.parametrize("command", COMMANDS)
@settings(max_examples=examples(40), deadline=None, suppress_health_check=[
    HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_every_command_takes_a_mutated_project(command: str, data: st.DataObject,
                                              tmp_path: Path) -> None:
    path = tmp_path / "input.dvp"
    path.write_bytes(_mutate(make_dvp(), data.draw))
    code, output = run_cli(command, path, tmp_path)
    assert code in (0, 1), (command, code, output[-2000:])
    assert "Traceback" not in output
