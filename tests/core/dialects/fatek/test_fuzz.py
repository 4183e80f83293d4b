"""Property tests: a Fatek listing or an ASCII format, however garbled, gives a program or
diagnostics at lines, never an exception; a program that reads compiles and runs."""

from __future__ import annotations

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderworks.core.compiler import compile_program
from ladderworks.core.dialects.fatek.ascii_format import parse_format, render
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine
from tests.hypothesis_profiles import examples

_WORDS = st.one_of(
    st.sampled_from(["ORG", "LD", "AND", "OR", "NOT", "TU", "TD", "OUT", "OUTS", "OUTR", "L",
                     "TR", "ANDLD", "ORLD", "OPEN", "SHORT", "FUN", "8", "11P", "17", "94",
                     "140", "999", "(+)", "MOV", "FO", "ORGF", "ANDF", "170", "TMR", "CTR",
                     "RST", "0.1S", "END", "Sa:", "D :", ":", "Printed Item:", "←"]),
    st.from_regex(r"(X|Y|M|S|T|C|R|D|TR|DR)[0-9]{1,5}", fullmatch=True),
    st.integers(-70000, 70000).map(str),
)
_LINE = st.lists(_WORDS, max_size=5).map(" ".join)
_TEXT = st.lists(_LINE, max_size=25).map("\n".join)


@settings(max_examples=examples(800), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_TEXT)
def test_random_listings_never_raise(text: str) -> None:
    result = parse_bytes(text.encode("utf-8"), "fatek")
    lines = text.count("\n") + 1
    for diagnostic in result.diagnostics:
        assert 1 <= diagnostic.line <= lines and diagnostic.message()
    if result.ok:
        compiled = compile_program(result.program)
        if compiled.binary is not None:
            ScanEngine(compiled.binary).scan()


_FORMAT = st.lists(st.one_of(
    st.sampled_from(["/", "\\", ",", "END", "'", "''", '"', "X", "3X", "1000X", "0D", "41",
                     "8.2R0", "10R6H", "5.1DR2B", " ", "\n", "'text'", "2X'ab'"]),
    st.text(max_size=3)), max_size=30).map("".join)


@settings(max_examples=examples(800), deadline=None)
@given(_FORMAT)
def test_random_ascii_formats_never_raise(text: str) -> None:
    fmt, diagnostics = parse_format(text)
    lines = text.count("\n") + 1
    for diagnostic in diagnostics:
        assert 1 <= diagnostic.line <= lines and diagnostic.message()
    render(fmt, lambda variable: -12345)
