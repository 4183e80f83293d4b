"""Property tests: an SD text, however cut or garbled, gives a program or diagnostics at lines,
never an exception; a program that reads compiles and runs; it draws (or keeps its listing)
and its drawing reads back, never an exception."""

from __future__ import annotations

from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ladderworks.core.compiler import compile_program
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.ladder.art import draw_document
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder
from ladderworks.core.plc.engine import ScanEngine
from tests.hypothesis_profiles import examples

EXAMPLES = Path(__file__).resolve().parents[4] / "resources" / "examples" / "s7"
TEXTS = [(EXAMPLES / name / "Main.s7dcl").read_text("utf-8-sig")
         for name in ("timers", "counters", "compare", "jumps", "jump_list", "switch")]
_TOKENS = st.sampled_from([
    "RUNG", "END_RUNG", "wire#powerrail", "wire#w1", "wire#w2", "NETWORK", "END_NETWORK",
    "Contact(", "I_Contact(", "Coil(", "S_Coil(", "JumpCoil(", "Label(", "Move(", ")", "(",
    ":=", "=>", ",", '"A"', "#x", "%I0.0", "%MW2", "T#5s", "10", "1.5", "{", "}",
    '{ S7_Templates := "SrcType := Int" }', "#t.TON(", "pt", "in1", "\n", '"', "CMP >=("])


def _check(text: str) -> None:
    result = parse_bytes(text.encode("utf-8"), "s7")
    lines = text.count("\n") + 1
    for diagnostic in result.diagnostics:
        assert 0 <= diagnostic.line <= lines and diagnostic.message()
    doc = program_to_ladder(result.program)  # drawn as TIA draws it, or kept as a listing
    draw_document(doc)
    for network in doc.networks:  # read back from the grid and lowered again
        network.comments = [*network.comments, "changed"]
    ladder_to_program(doc)
    if result.ok:
        compiled = compile_program(result.program)
        if compiled.binary is not None:
            ScanEngine(compiled.binary).scan()


@settings(max_examples=examples(150), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(TEXTS), st.integers(0, 4000), st.integers(0, 60))
def test_cut_or_spliced_examples_never_raise(text: str, at: int, length: int) -> None:
    at %= len(text) + 1
    _check(text[:at])
    _check(text[:at] + text[at + length:])


@settings(max_examples=examples(150), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(_TOKENS, max_size=40))
def test_random_rungs_never_raise(tokens: list[str]) -> None:
    _check('ORGANIZATION_BLOCK "Main"\n NETWORK\n RUNG wire#powerrail\n' + " ".join(tokens)
           + "\n END_RUNG\n END_NETWORK\nEND_ORGANIZATION_BLOCK\n")
