"""Issue 36: a Delta instruction the simulator does not run (or a mnemonic it does not know)
opens, is drawn with its operands, checks with a warning, saves unchanged and is passed by."""

from __future__ import annotations

import pytest

from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.skipped import skipped
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.il.printer import encode_program
from ladderworks.core.ladder.art import draw_network
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.plc.engine import ScanEngine

from .conftest import delta, get, put

TEXT = ("EI\n"  # no logic before it: a network of its own
        "LD X0\nPID D0 K2 D100 D2\nOUT Y0\n"  # a box: the rung's power flows on past it
        "LD X0\nAND& D0 K5\nOUT Y1\n"  # a contact: never conducts
        "LD X0\nOR| D0 K5\nOUT Y2\n"  # in parallel: adds nothing
        "LD X1\nBLINK K7 D9\nOUT Y3\n"  # a mnemonic nobody knows: kept as a box
        "DI\nLD X2\nOUT Y4\nEND\n")


@pytest.mark.parametrize("monitored", [False, True])
def test_they_are_passed_by_in_the_scan(monitored: bool) -> None:
    program = delta(TEXT)
    compiled = compile_program(program)
    assert compiled.binary is not None
    assert [(d.code, d.line, d.is_error) for d in compiled.diagnostics] == [
        ("not-simulated", line, False) for line in (1, 3, 6, 9, 12, 14)]
    plc = ScanEngine(compiled.binary, monitored=monitored)
    for name in ("X0", "X1", "X2"):
        put(plc, name, 1)
    plc.scan()
    assert [get(plc, f"Y{n}") for n in range(5)] == [1, 0, 1, 1, 1]
    assert get(plc, "D2") == 0  # PID did nothing


def test_they_are_drawn_with_their_operands_and_saved_unchanged() -> None:
    program = delta(TEXT)
    spell = spelling("delta")
    for network in program.networks:
        assert layout_network(network.instructions).listing is None
    art = "\n".join("\n".join(draw_network(layout_network(n.instructions), spell=spell))
                    for n in program.networks)
    assert "PID" in art and "D100" in art and "BLINK" in art and "AND&" in art
    assert encode_program(program) == TEXT.encode()
    assert [item.text for item in skipped(program)] == [
        "EI", "PID D0 K2 D100 D2", "AND& D0 K5", "OR| D0 K5", "BLINK K7 D9", "DI"]
