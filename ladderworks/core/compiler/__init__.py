"""The compiler: checks a Program, turns it into a binary, and turns a binary back into one."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from ladderworks.core.compiler.checks import check, dialect_of
from ladderworks.core.diagnostics import Diagnostic, DiagnosticError, has_errors
from ladderworks.core.il.program import Instruction, Network, Program

if TYPE_CHECKING:
    from ladderworks.core.compiler.binary import (
        FORMAT_VERSION,
        BinaryFormatError,
        BinaryProgram,
        Op,
        SourcePosition,
        decode,
        encode,
    )

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

# The binary format's names, imported from compiler.binary when first asked for (PEP 562):
# `check` needs no binary.
_BINARY_NAMES = frozenset({
    "FORMAT_VERSION", "BinaryFormatError", "BinaryProgram", "Op", "SourcePosition", "decode",
    "encode",
})


def __getattr__(name: str) -> object:
    """A name of the binary format, imported when first asked for."""
    if name not in _BINARY_NAMES:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    from ladderworks.core.compiler import binary

    value = getattr(binary, name)
    globals()[name] = value
    return value


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
    from ladderworks.core.compiler.binary import Op, SourcePosition

    ops: list[Op] = []
    for n, network in enumerate(program.networks):
        for k, ins in enumerate(network.instructions):
            ops.append(Op(ins.name, ins.operand, ins.params,
                          SourcePosition(n, k, ins.line, ins.column)))
    return ops


def compile_program(program: Program, *, by_network: bool = False) -> CompileResult:
    """Check and compile; never raises for a bad program.

    The checks are the whole set `check` runs: a program they pass always compiles.
    `by_network` as for `check`.
    """
    from ladderworks.core.compiler.binary import encode

    diagnostics = check(program, by_network=by_network)
    if has_errors(diagnostics):
        return CompileResult(None, diagnostics)
    return CompileResult(encode(to_ops(program), dialect_of(program)), diagnostics)


def compile(program: Program) -> bytes:
    """The binary of `program`; raises DiagnosticError when the checks find errors."""
    result = compile_program(program)
    if result.binary is None:
        raise DiagnosticError([d for d in result.diagnostics if d.is_error])
    return result.binary


def disassemble(data: bytes | BinaryProgram) -> Program:
    """The Program held in a binary (no comments), or in one already decoded; raises
    BinaryFormatError if it is bad."""
    from ladderworks.core.compiler.binary import BinaryProgram, decode

    binary = data if isinstance(data, BinaryProgram) else decode(data)
    networks: list[Network] = []
    current = -1
    for op in binary.ops:
        if op.source.network != current or not networks:
            networks.append(Network())
            current = op.source.network
        networks[-1].instructions.append(Instruction(
            op.name, op.operand, op.params, line=op.source.line, column=op.source.column))
    return Program(networks=networks, dialect=binary.dialect)
