"""The compiler: checks a Program, turns it into a binary, and turns a binary back into one."""

from __future__ import annotations

from dataclasses import dataclass, field, fields

from ladderworks.core.compiler.binary import (
    FORMAT_VERSION,
    BinaryFormatError,
    BinaryProgram,
    Op,
    SourcePosition,
    decode,
    encode,
)
from ladderworks.core.compiler.checks import check, dialect_of
from ladderworks.core.diagnostics import Diagnostic, DiagnosticError, has_errors
from ladderworks.core.il.program import Instruction, Network, Program

__all__ = [
    "FORMAT_VERSION",
    "BinaryFormatError",
    "BinaryProgram",
    "CompileResult",
    "Op",
    "SourcePosition",
    "check",
    "compile",
    "compile_program",
    "decode",
    "disassemble",
    "encode",
    "to_ops",
]


@dataclass(slots=True)
class CompileResult:
    """The binary (None when there are errors) and every diagnostic, warnings included."""

    binary: bytes | None
    diagnostics: list[Diagnostic] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        """True when the program compiled."""
        return self.binary is not None


def to_ops(program: Program) -> list[Op]:
    """The ops of a program, each with its source position."""
    ops: list[Op] = []
    for n, network in enumerate(program.networks):
        for k, ins in enumerate(network.instructions):
            ops.append(Op(ins.name, ins.operand, ins.params,
                          SourcePosition(n, k, ins.line, ins.column)))
    return ops


def compile_program(program: Program) -> CompileResult:
    """Check and compile; never raises for a bad program.

    The checks are the whole set `check` runs: a program they pass always compiles.
    """
    diagnostics = check(program)
    if has_errors(diagnostics):
        return CompileResult(None, diagnostics)
    return CompileResult(encode(to_ops(program), dialect_of(program)), diagnostics)


def compile(program: Program) -> bytes:
    """The binary of `program`; raises DiagnosticError when the checks find errors."""
    result = compile_program(program)
    if result.binary is None:
        raise DiagnosticError([d for d in result.diagnostics if d.is_error])
    return result.binary


def disassemble(data: bytes) -> Program:
    """The Program held in a binary (no comments); raises BinaryFormatError if it is bad."""
    binary = decode(data)
    networks: list[Network] = []
    current = -1
    for op in binary.ops:
        if op.source.network != current or not networks:
            networks.append(Network())
            current = op.source.network
        networks[-1].instructions.append(Instruction(
            op.name, op.operand, op.params, line=op.source.line, column=op.source.column))
    if "dialect" in {f.name for f in fields(Program)}:
        return Program(networks=networks, dialect=binary.dialect)  # type: ignore[call-arg]
    return Program(networks=networks)
