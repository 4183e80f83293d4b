"""A FUN n the Fatek table does not know opens, is drawn as a box, warns, saves unchanged and
runs as a box whose FO stay 0; the run names it (issue #36: the same as for Delta)."""

from __future__ import annotations

from ladderworks.core.compiler import compile_program
from ladderworks.core.il import Network
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.plc.session import PlcRun
from tests.core.dialects.conftest import get, put

TEXT = b"ORG X0\nFUN 200 FOO\n  S : R0\n  D : R1\nFO0\nOUT Y0\nORG X1\nOUT Y1\n"


def test_an_unknown_fun_is_kept_drawn_and_warned() -> None:
    result = parse_bytes(TEXT, "fatek")
    assert result.ok, result.diagnostics
    boxes = [ins for ins in result.program.networks[0].instructions if ins.name == "FBS.FUN"]
    assert len(boxes) == 1
    assert boxes[0].spec.simulated is False and boxes[0].comment == "FUN 200 FOO: S: R0, D: R1"
    assert layout_network(result.program.networks[0].instructions).listing is None
    assert encode_program(result.program) == TEXT
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    assert [(d.code, d.line, d.is_error) for d in compiled.diagnostics] == \
        []  # the reader's own warning says it (fatek-not-simulated, at read)
    assert [(d.code, d.line) for d in result.diagnostics] == [("fatek-not-simulated", 2)]


def test_it_runs_with_its_fo_off_and_is_named() -> None:
    plc = PlcRun()
    program = parse_bytes(TEXT, "fatek").program
    assert plc.load_program(program).binary is not None
    assert [item.line for item in plc.skipped] == [2]
    engine = plc.engine
    assert engine is not None
    put(engine, "X0", 1, "fatek")
    put(engine, "X1", 1, "fatek")
    engine.scan()
    assert get(engine, "Y0", "fatek") == 0 and get(engine, "Y1", "fatek") == 1


def test_a_changed_network_writes_its_operand_lines_back() -> None:
    program = parse_bytes(TEXT, "fatek").program
    program.networks[0] = Network(list(program.networks[0].instructions), ["changed"])
    lines = [line.split() for line in encode_program(program).decode().splitlines()]
    fun = next(k for k, line in enumerate(lines) if line[:1] == ["FUN"])
    assert lines[fun][:3] == ["FUN", "200", "FOO"]
    assert lines[fun + 1:fun + 3] == [["S:", "R0"], ["D:", "R1"]]
