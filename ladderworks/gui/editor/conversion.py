"""Program ⇄ ladder document for the editor, network by network through the core's conversion."""

from __future__ import annotations

from ladderworks.core.diagnostics import Diagnostic, has_errors
from ladderworks.core.il import Network, Program
from ladderworks.core.ladder import LadderDocument
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.layout import layout_network


def program_to_ladder(program: Program) -> tuple[LadderDocument, list[Diagnostic]]:
    """The ladder picture of a program (networks that cannot be drawn are kept as listings)."""
    networks = [layout_network(net.instructions, net.comments) for net in program.networks]
    document = LadderDocument(networks, list(program.header), list(program.trailer),
                              list(program.footer), list(program.before), list(program.after))
    return document, []


def ladder_to_program(document: LadderDocument) -> tuple[Program | None, list[Diagnostic]]:
    """The program drawn, or None with the diagnostics at their networks and cells."""
    networks: list[Network] = []
    diagnostics: list[Diagnostic] = []
    for index, ladder in enumerate(document.networks):
        instructions, found = network_to_instructions(ladder, index)
        diagnostics.extend(found)
        if instructions is not None:
            networks.append(Network(list(instructions), list(ladder.comments)))
    if has_errors(diagnostics):
        return None, diagnostics
    program = Program(networks, list(document.header), list(document.trailer),
                      list(document.before), list(document.after), list(document.footer))
    return program, diagnostics
