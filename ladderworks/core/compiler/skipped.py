"""The instructions a run passes by: kept, drawn and saved, not simulated (`simulated` False).

A program of a dialect may hold instructions the simulator does not run (Delta's FROM/TO, a
mnemonic it does not know, Fatek's pulse outputs): the scan passes them by (a box passes its
input on, a contact never conducts). `skipped` lists them for the CLI's warning, the IDE's
marks and the PLC control screen (`PlcRun.skipped`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from ladderworks.core.diagnostics import Diagnostic, Severity

if TYPE_CHECKING:
    from ladderworks.core.compiler.binary import BinaryProgram
    from ladderworks.core.il.program import Program


@dataclass(frozen=True, slots=True)
class SkippedInstruction:
    """One instruction the scan passes by, where it is and how the program writes it."""

    network: int  # its network's index (-1: known from a binary only)
    index: int  # its place in the network (the op's index for a binary)
    line: int
    column: int
    text: str  # `DMUL D7 K1 D9` (the mnemonic alone from a binary)
    name: str = ""  # its mnemonic as the dialect writes it: `DMUL`, `FUN 200 FOO`


def skipped(program: Program) -> list[SkippedInstruction]:
    """The instructions of `program` the scan passes by, in program order."""
    from ladderworks.core.dialects.spelling import spelling

    spell = spelling(program.dialect)
    found: list[SkippedInstruction] = []
    for n, network in enumerate(program.networks):
        for k, ins in enumerate(network.instructions):
            spec = ins.spec
            if not spec.simulated:
                name = spell.name(spec)
                text = " ".join([name, *spell.params(spec, ins.params)])
                found.append(SkippedInstruction(n, k, ins.line, ins.column, text, name))
    return found


def skipped_ops(binary: BinaryProgram) -> list[SkippedInstruction]:
    """The ops of a binary the scan passes by (their source lines; no operands kept)."""
    return [SkippedInstruction(-1, k, op.source.line, op.source.column, op.spec.text_name,
                               op.spec.text_name)
            for k, op in enumerate(binary.ops) if not op.spec.simulated]


def summary(found: list[SkippedInstruction]) -> Diagnostic | None:
    """One warning naming the instructions skipped (None when there are none)."""
    if not found:
        return None
    names = ", ".join(f"{item.name or item.text} ({item.line})" for item in found[:20])
    more = len(found) - 20
    return Diagnostic("run-skips", {"count": len(found),
                                    "names": names + (f" … +{more}" if more > 0 else "")},
                      found[0].line, found[0].column, Severity.WARNING)
