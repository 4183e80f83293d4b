"""The PLC menu's work: program checks and compilation through the core compiler."""

from __future__ import annotations

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il import Program


def check(program: Program) -> list[Diagnostic]:
    """The compiler's checks of a program (stack depth, ranges, pairs, written inputs ...),
    naming other places by network."""
    from ladderworks.core.compiler import check as compiler_check

    return compiler_check(program, by_network=True)


def compile_program(program: Program) -> tuple[bytes | None, list[Diagnostic]]:
    """The binary PLC program (None on errors) and every diagnostic."""
    from ladderworks.core.compiler import compile_program as core_compile

    result = core_compile(program, by_network=True)
    return result.binary, list(result.diagnostics)
