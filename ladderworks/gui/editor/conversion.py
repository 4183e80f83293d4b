"""Program ⇄ ladder document for the editor, through the core's whole-program conversion."""

from __future__ import annotations

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il import Program
from ladderworks.core.ladder import LadderDocument, convert


def program_to_ladder(program: Program) -> tuple[LadderDocument, list[Diagnostic]]:
    """The ladder picture of a program (draft networks saved as `//@grid` come back as drawn)."""
    return convert.program_to_ladder(program), []


def ladder_to_program(document: LadderDocument) -> tuple[Program, list[Diagnostic]]:
    """The program drawn; networks that cannot be coded yet are kept as draft comment lines."""
    return convert.ladder_to_program(document)
