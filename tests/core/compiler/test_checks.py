"""Compile checks: each gives its code at the right position."""

from __future__ import annotations

import pytest

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler import check, compile_program
from ladderworks.core.diagnostics import DiagnosticError
from ladderworks.core.il import Instruction, Network, Program, parse


def codes(text: str) -> list[tuple[str, int, str]]:
    result = parse("%@3\n" + text.strip() + "\n%\n")
    assert result.ok, [d.message() for d in result.diagnostics]
    return [(d.code, d.line, d.severity.value) for d in check(result.program)]


def test_clean_program_has_no_diagnostics() -> None:
    assert codes("RD X0.0\nRD.STK X0.1\nAND.STK\nWRT Y0.0") == []


def test_stack_deeper_than_st8() -> None:
    pushes = "\n".join(f"RD.STK R0.{k % 8}" for k in range(9))
    pops = "\n".join("AND.STK" for _ in range(9))
    assert codes(f"RD X0.0\n{pushes}\n{pops}\nWRT Y0.0") == [("stack-depth", 11, "error")]


def test_eight_pushes_are_allowed() -> None:
    pushes = "\n".join(f"RD.STK R0.{k}" for k in range(8))
    pops = "\n".join("OR.STK" for _ in range(8))
    assert codes(f"RD X0.0\n{pushes}\n{pops}\nWRT Y0.0") == []


def test_and_stk_with_nothing_pushed() -> None:
    assert codes("RD X0.0\nAND.STK\nWRT Y0.0") == [("stack-underflow", 3, "error")]
    assert codes("RD X0.0\nRD.STK X0.1\nOR.STK\nOR.STK\nWRT Y0.0") == [
        ("stack-underflow", 5, "error")]


def test_writing_inputs_and_the_result_register() -> None:
    assert codes("RD R0.0\nWRT X1.0\nRD R0.0\nWRT F2.1\nRD R0.0\nWRT R9003.1") == [
        ("write-input", 3, "error"), ("write-input", 5, "error"),
        ("write-result-register", 7, "error")]
    assert codes("RD R0.0\nWRT R9006.0") == []


def test_function_output_into_an_input_area() -> None:
    assert codes("RD R0.0\nMOVE 1111 1111 R0 X3") == [("write-input", 3, "error")]


def test_jump_and_common_line_pairs() -> None:
    assert codes("RD R0.0\nJMP 0\nRD R0.1\nWRT R0.2") == [("jmp-without-jmpe", 3, "error")]
    assert codes("RD R0.0\nJMP 2\nRD R0.1\nWRT R0.2") == []  # a coil count needs no JMPE
    assert codes("JMPE\nRD R0.1\nWRT R0.2") == [("jmpe-without-jmp", 2, "error")]
    assert codes("RD R0.0\nJMP 1\nRD R0.1\nWRT R0.2\nJMPE") == [
        ("jmpe-without-jmp", 6, "error")]  # JMP n has no JMPE to pair with
    assert codes("RD R0.0\nCOM 0\nRD R0.1\nWRT R0.2") == [("com-without-come", 3, "error")]
    assert codes("RD R0.0\nCOM 2\nRD R0.1\nWRT R0.2") == []
    assert codes("COME\nRD R0.1\nWRT R0.2") == [("come-without-com", 2, "error")]


def test_coil_written_twice_is_a_warning() -> None:
    assert codes("RD R0.0\nWRT Y0.0\nRD R0.1\nWRT.NOT Y0.0") == [("coil-twice", 5, "warning")]


def test_dangling_logic_is_a_warning() -> None:
    assert codes("RD R0.0\nWRT Y0.0\nRD R0.1\nAND R0.2") == [("dangling-logic", 5, "warning")]


def test_function_needs_its_control_inputs_pushed() -> None:
    assert codes("RD R0.0\nRD.STK R0.1\nCTR 1\nWRT R1.0") == [("box-inputs", 4, "error")]


def test_parameters_out_of_range_in_a_program_built_in_code() -> None:
    program = Program([Network([
        Instruction("RD", Address(Area.R, 0, 0), line=1),
        Instruction("TMR", params=(101,), line=2),
        Instruction("WRT", Address(Area.R, 0, 1), line=3),
        Instruction("RD", Address(Area.R, 0, 0), line=4),
        Instruction("TMRC", params=(0, Address(Area.D, 9999), 3), line=5),
        Instruction("WRT", Address(Area.R, 0, 2), line=6),
        Instruction("RD", Address(Area.R, 0, 0), line=7),
        Instruction("DECB", params=(3, Address(Area.R, 0), 1, Address(Area.R, 1)), line=8),
        Instruction("RD", Address(Area.R, 0, 0), line=9),
        Instruction("RD.STK", Address(Area.R, 0, 0), line=10),
        Instruction("RD.STK", Address(Area.R, 0, 0), line=11),
        Instruction("RD.STK", Address(Area.R, 0, 0), line=12),
        Instruction("CTR", params=(21,), line=13),
    ])])
    found = [(d.code, d.line) for d in check(program)]
    assert ("param-range", 2) in found
    assert ("byte-range", 5) in found  # D9999 has no room for 2 bytes
    assert ("param-kind-address", 5) in found  # a number where the register address goes
    assert ("param-choice", 8) in found
    assert ("param-range", 13) in found


def test_not_implemented_function_is_a_diagnostic(monkeypatch: pytest.MonkeyPatch) -> None:
    from ladderworks.core.plc.families import IMPLEMENTED

    monkeypatch.setattr("ladderworks.core.compiler.checks.IMPLEMENTED", IMPLEMENTED - {"TMR"})
    result = compile_program(parse("%@3\nRD R0.0\nTMR 1\nWRT R0.1\n%\n").program)
    assert result.binary is None
    assert [(d.code, d.args, d.line) for d in result.diagnostics] == [
        ("not-implemented", {"name": "TMR"}, 3)]


def test_compile_raises_with_the_diagnostics() -> None:
    from ladderworks.core.compiler import compile

    with pytest.raises(DiagnosticError) as info:
        compile(parse("%@3\nRD R0.0\nWRT X0.0\n%\n").program)
    assert [d.code for d in info.value.diagnostics] == ["write-input"]


def test_diagnostics_carry_the_network_index() -> None:
    result = parse("%@3\nRD R0.0\nWRT Y0.0\nRD R0.0\nAND.STK\nWRT Y0.1\n%\n")
    (diagnostic,) = check(result.program)
    assert (diagnostic.network, diagnostic.line, diagnostic.column) == (1, 5, 1)
