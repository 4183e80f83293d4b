"""Fuzzing global DB sources and the S7 writers: a `.db` text cut, spliced or made of random
tokens reads or gives a diagnostic at a line of it, and opens beside a block as a warning or
members, never an exception or a hang; a network that reads writes back as SD and XML and
reads again to the same graph."""

from __future__ import annotations

from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderworks.core.compiler import compile_program
from ladderworks.core.dialects.s7 import reader
from ladderworks.core.dialects.s7.graph_shape import shape
from ladderworks.core.dialects.s7.sd_parser import ParseError, parse_sd, parse_sources
from ladderworks.core.dialects.s7.sd_writer import Unwritable, block_text
from ladderworks.core.dialects.s7.xml_reader import read_document
from ladderworks.core.dialects.s7.xml_writer import write_block
from ladderworks.core.plc.engine import ScanEngine
from tests.core.dialects.s7.test_db_sources import DB, MAIN
from tests.hypothesis_profiles import examples

_SETTINGS = settings(max_examples=examples(120), deadline=None, suppress_health_check=[
    HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
_TOKENS = st.sampled_from([
    "STRUCT", "END_STRUCT;", "END_STRUCT", "BEGIN", "END_DATA_BLOCK", "VAR", "END_VAR", ";",
    "a", "b.c", '"D"', "Int", "LReal", "String[4]", "Array[0..2] of Int", "Array[", "]", "..",
    ":", ":=", "3", "-1.5", "'x'", "'", "[1, 2]", "[3(0)]", "{ S7_SetPoint := 'True' }", "{",
    "}", "(*", "*)", "//", "\n", "NON_RETAIN", "VERSION : 0.1", '"UDT"', "TYPE", "END_TYPE",
    "a[1]", "a[", "#x", "16#FF", "T#5s", "WSTRING#'ğ'", "Struct"])
_EXAMPLES = Path(__file__).resolve().parents[2] / "resources" / "examples" / "s7"
_SD = [p.read_text("utf-8-sig") for p in sorted(_EXAMPLES.glob("*/Main.s7dcl"))]


def _read(text: str) -> None:
    try:
        blocks = parse_sources(text)
    except ParseError as error:
        assert 1 <= error.diagnostic.line <= text.count("\n") + 1
        assert error.diagnostic.message()
        return
    assert blocks


def _open(tmp_path: Path, text: str) -> None:
    (tmp_path / "Main.s7dcl").write_text(MAIN, encoding="utf-8")
    (tmp_path / "Hat_DB.db").write_text(text, encoding="utf-8", errors="surrogatepass")
    program, diagnostics, _encoding = reader.open_path(tmp_path / "Main.s7dcl", None)
    for diagnostic in diagnostics:
        assert diagnostic.message()
    compiled = compile_program(program)
    if compiled.binary is not None:
        ScanEngine(compiled.binary).scan()


@_SETTINGS
@given(st.integers(0, len(DB)), st.integers(0, 80))
def test_a_cut_or_spliced_db_source_never_raises(tmp_path: Path, at: int, length: int) -> None:
    _read(DB[:at])
    _read(DB[:at] + DB[at + length:])
    _open(tmp_path, DB[:at] + DB[at + length:])


@_SETTINGS
@given(st.lists(_TOKENS, max_size=40))
def test_random_db_tokens_never_raise(tokens: list[str]) -> None:
    _read('DATA_BLOCK "D"\n' + " ".join(tokens) + "\n")
    _read('DATA_BLOCK "D"\nSTRUCT\n' + " ".join(tokens) + "\nEND_STRUCT;\nBEGIN\n"
          + " ".join(tokens) + "\nEND_DATA_BLOCK\n")


@_SETTINGS
@given(st.sampled_from(_SD), st.integers(0, 5000), st.integers(0, 40))
def test_what_reads_writes_back_to_the_same_graph_as_sd_and_xml(text: str, at: int,
                                                                length: int) -> None:
    at %= len(text) + 1
    try:
        block = parse_sd(text[:at] + text[at + length:]).block
    except ParseError:
        return
    try:
        written, _texts = block_text(block)
    except Unwritable:
        return
    again = parse_sd(written).block
    assert [shape(n) for n in again.networks] == [shape(n) for n in block.networks]
    back = read_document(write_block(again))
    assert len(back.blocks[0].networks) == len(again.networks)
