"""Whole programs ⇄ ladder documents; networks that cannot be coded yet are saved as drafts."""

from __future__ import annotations

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il.program import Network, Program
from ladderworks.core.il.textform import split_lines
from ladderworks.core.ladder.clipboard import MAGIC, copy_text, network_from_text
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.edits import EditRefused
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.model import LadderDocument, LadderNetwork

DRAFT_MARK = "@grid "  # a saved draft network: comment lines `//@grid <grid text line>`


def draft_lines(network: LadderNetwork) -> list[str]:
    """A network as draft comment lines (without the `//`), exactly as drawn."""
    return [DRAFT_MARK + line for line in split_lines(copy_text(network))]


def split_drafts(lines: list[str]) -> tuple[list[LadderNetwork], list[str]]:
    """Draft networks found in comment lines, and the other comment lines.

    A draft block that does not decode stays as plain comment lines (nothing is dropped)."""
    drafts: list[LadderNetwork] = []
    rest: list[str] = []
    block: list[str] = []

    def close() -> None:
        if not block:
            return
        try:
            drafts.append(network_from_text("\n".join(b[len(DRAFT_MARK):] for b in block)))
        except EditRefused:
            rest.extend(block)
        block.clear()

    for line in lines:
        if line.startswith(DRAFT_MARK):
            if line[len(DRAFT_MARK):].startswith(MAGIC):
                close()
            block.append(line)
        else:
            close()
            rest.append(line)
    close()
    return drafts, rest


def program_to_ladder(program: Program) -> LadderDocument:
    """Lay out every network of a program (drafts saved in comments come back as drawn)."""
    doc = LadderDocument(header=list(program.header), footer=list(program.footer),
                         before=list(program.before), after=list(program.after), origin=program)
    for network in program.networks:
        drafts, comments = split_drafts(network.comments)
        doc.networks.extend(drafts)
        laid = layout_network(network.instructions, comments)
        laid.label = network.label
        doc.networks.append(laid)
    drafts, trailer = split_drafts(program.trailer)
    doc.networks.extend(drafts)
    doc.trailer = trailer
    return doc


def ladder_to_program(doc: LadderDocument) -> tuple[Program, list[Diagnostic]]:
    """The program text of a ladder document, with the diagnostics of each network.

    A network that cannot be coded (still being drawn, or wrong) is written as draft comment
    lines before the next network (or at the end), so saving never loses a drawing. The
    program keeps the file, form, dialect and section views of the one the document came from
    (`doc.origin`), so Save rewrites only the networks that changed."""
    program = Program(header=list(doc.header), footer=list(doc.footer),
                      before=list(doc.before), after=list(doc.after))
    if doc.origin is not None:
        _adopt(program, doc.origin)
    diagnostics: list[Diagnostic] = []
    pending: list[str] = []
    dialect = doc.origin.dialect if doc.origin is not None else "seed"
    for index, network in enumerate(doc.networks):
        if network.is_empty() and not network.comments:
            continue
        instructions, found = network_to_instructions(network, index, dialect)
        diagnostics.extend(found)
        if not instructions:
            pending.extend(draft_lines(network))
            continue
        program.networks.append(
            Network(instructions, pending + list(network.comments), network.label))
        pending = []
    program.trailer = pending + list(doc.trailer)
    return program, diagnostics


def _adopt(program: Program, origin: Program) -> None:
    """Carry over what the ladder document does not hold: file, framing, dialect, views."""
    program.source = origin.source
    program.framed = origin.framed
    program.dialect = origin.dialect
    program.title = origin.title
    program.system_params = origin.system_params
    program.symbols = origin.symbols
    program.messages = origin.messages
    program.io_modules = origin.io_modules
