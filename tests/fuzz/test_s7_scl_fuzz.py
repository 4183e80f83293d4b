"""Fuzzing SCL sources (`.scl`, scl_source.py): a source cut anywhere or made of random tokens
reads or gives a diagnostic at a line of it, never an exception or a hang; a body's network
keeps lines inside the text."""

from __future__ import annotations

from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderworks.core.dialects.s7.scl_source import parse_scl
from ladderworks.core.dialects.s7.sd_parser import ParseError
from tests.hypothesis_profiles import examples

_SETTINGS = settings(max_examples=examples(120), deadline=None,
                     suppress_health_check=[HealthCheck.too_slow])
_SCL = Path(__file__).resolve().parents[1] / "core" / "dialects" / "s7" / "data" / "scl"
_TEXTS = [p.read_text("utf-8") for p in sorted(_SCL.glob("*.scl"))]
_TOKENS = st.sampled_from([
    "FUNCTION_BLOCK", "FUNCTION", '"F"', ": Void", ": Int", "BEGIN", "END_FUNCTION_BLOCK",
    "END_FUNCTION", "VAR_INPUT", "VAR_TEMP", "END_VAR", "a : Int;", "b AT a : Word;", "AT",
    "#a := 1;", "IF", "THEN", "END_IF;", "\n", "\t", "{ S7_Optimized_Access := 'TRUE' }",
    "VERSION : 0.1", "DATA_BLOCK", "TYPE", "END_TYPE", "STRUCT", "END_STRUCT;", "//", "(*",
    "*)", "'", ";", ":", ":="])


def _read(text: str) -> None:
    try:
        found = parse_scl(text)
    except ParseError as error:
        assert 1 <= error.diagnostic.line <= text.count("\n") + 1
        return
    lines = text.count("\n") + 1
    for parsed in found:
        for network in parsed.block.networks:
            assert 1 <= network.line <= network.end_line + 1 <= lines + 1


@_SETTINGS
@given(st.sampled_from(_TEXTS), st.integers(0, 2000))
def test_a_cut_source_reads_or_is_diagnosed(text: str, cut: int) -> None:
    _read(text[: cut % (len(text) + 1)])


@_SETTINGS
@given(st.lists(_TOKENS, max_size=40))
def test_random_tokens_read_or_are_diagnosed(tokens: list[str]) -> None:
    _read(" ".join(tokens))
