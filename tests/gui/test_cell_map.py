"""The diagnostic view's source check: a program compiled is recognised in its binary, so the
live ladder shows the source's comments (CALL/SP references are numbers in the binary)."""

from __future__ import annotations

from ladderworks.core.compiler import compile_program, decode
from ladderworks.core.il import Program, parse
from ladderworks.core.il.program import ProgramRef
from ladderworks.gui.docks.cell_map import op_key, program_matches
from tests.core.test_xref import FANUC_TEXT  # levels, a CALL P1 and the subprogram P1


def _program() -> Program:
    result = parse(FANUC_TEXT)
    assert result.ok, result.diagnostics
    return result.program


def test_a_program_with_calls_matches_its_own_binary() -> None:
    program = _program()
    references = [p for ins in program.instructions() for p in ins.params
                  if isinstance(p, ProgramRef)]
    assert references  # SP / CALL with `P` numbers
    binary = compile_program(program).binary
    assert binary is not None
    assert program_matches(program, decode(binary))


def test_a_different_program_does_not_match() -> None:
    program = _program()
    binary = compile_program(program).binary
    assert binary is not None
    program.networks[-1].instructions.pop()
    assert not program_matches(program, decode(binary))
    assert op_key("CALL", None, (ProgramRef(44),)) == op_key("CALL", None, (44,))
    assert op_key("CALL", None, (ProgramRef(44),)) != op_key("CALL", None, (45,))
