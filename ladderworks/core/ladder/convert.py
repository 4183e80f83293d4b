"""Whole programs ⇄ ladder documents; networks that cannot be coded yet are saved as drafts."""

from __future__ import annotations

from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.il.program import Network, Program
from ladderworks.core.il.textform import split_lines
from ladderworks.core.ladder.clipboard import MAGIC, copy_text, network_from_text
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.edits import EditRefused
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.model import LadderDocument, LadderNetwork
from ladderworks.core.ladder.source_model import source_model

DRAFT_MARK = "@grid "  # a saved draft network: comment lines `//@grid <grid text line>`


def draft_lines(network: LadderNetwork) -> list[str]:
    """A network as draft comment lines (without the `//`), exactly as drawn."""
    return [DRAFT_MARK + line for line in split_lines(copy_text(network))]


def read_draft(lines: list[str]) -> LadderNetwork | None:
    """The network a draft block (lines starting with DRAFT_MARK) holds; None when damaged.

    Damaged means anything that is not a valid drawing: bad JSON, non-finite or huge numbers,
    wrong shapes, nesting too deep to read."""
    try:
        return network_from_text("\n".join(line[len(DRAFT_MARK):] for line in lines))
    except (EditRefused, ValueError, TypeError, KeyError, OverflowError, RecursionError,
            MemoryError):
        return None


def split_drafts(lines: list[str]) -> tuple[list[LadderNetwork], list[str]]:
    """Draft networks found in comment lines, and the other comment lines.

    A draft block that does not decode stays as plain comment lines (nothing is dropped)."""
    drafts: list[LadderNetwork] = []
    rest: list[str] = []
    block: list[str] = []

    def close() -> None:
        if not block:
            return
        network = read_draft(block)
        if network is None:
            rest.extend(block)
        else:
            drafts.append(network)
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


def _draft_text(line: str) -> str | None:
    """A file line's draft text (after `//` or `;`), or None when it is no draft line."""
    text = line.lstrip()
    for marker in ("//", ";"):
        if text.startswith(marker + DRAFT_MARK):
            return text[len(marker):]
    return None


def damaged_drafts(lines: list[str]) -> list[Diagnostic]:
    """A `damaged-draft` warning at the first line of each draft block in a file's lines that
    does not hold a valid drawing (it is kept as comment text and saved back unchanged)."""
    found: list[Diagnostic] = []
    block: list[str] = []
    start = 0

    def close() -> None:
        if block and read_draft(block) is None:
            found.append(Diagnostic("damaged-draft", {"lines": len(block)}, start + 1, 1,
                                    Severity.WARNING))
        block.clear()

    previous = -1
    # only the lines with the mark can be draft lines: a run of lines without it between two
    # of them closes the block as each of its lines would (start: the last of the run)
    for number in [n for n, line in enumerate(lines) if DRAFT_MARK in line]:
        if number > previous + 1:
            close()
            start = number - 1
        previous = number
        text = _draft_text(lines[number])
        if text is None or text[len(DRAFT_MARK):].startswith(MAGIC):
            close()
            start = number
        if text is not None:
            block.append(text)
    close()
    return found


Kept = list[tuple[LadderNetwork, Network]]  # each network as laid out, and the one it came from
KEPT_LOOKAHEAD = 64  # how far ahead an unchanged network is looked for after an edit


def program_to_ladder(program: Program, kept: Kept | None = None) -> LadderDocument:
    """Lay out every network of a program (drafts saved in comments come back as drawn).

    `kept`, when given, receives a copy of each laid-out network with the network it came
    from, so ladder_to_program can write an unchanged one exactly as it was read."""
    doc = LadderDocument(header=list(program.header), footer=list(program.footer),
                         before=list(program.before), after=list(program.after), origin=program)
    model = source_model(program)
    if model is not None:  # drawn from the dialect's own model (S7's graph), not the engine's
        doc.networks = model.draw()
        return doc
    for network in program.networks:
        drafts, comments = split_drafts(network.comments)
        doc.networks.extend(drafts)
        laid = layout_network(network.instructions, comments)
        laid.label = network.label
        doc.networks.append(laid)
        if kept is not None:
            kept.append((laid.copy(), network))
    drafts, trailer = split_drafts(program.trailer)
    doc.networks.extend(drafts)
    doc.trailer = trailer
    return doc


def _unchanged(network: LadderNetwork, kept: Kept, start: int) -> int | None:
    """The index in `kept` (from `start`, a little way ahead) of a network drawn as read."""
    for index in range(start, min(len(kept), start + KEPT_LOOKAHEAD)):
        if kept[index][0] == network:
            return index
    return None


def ladder_to_program(doc: LadderDocument,
                      kept: Kept | None = None) -> tuple[Program, list[Diagnostic]]:
    """The program text of a ladder document, with the diagnostics of each network.

    A network that cannot be coded (still being drawn, or wrong) is written as draft comment
    lines before the next network (or at the end), so saving never loses a drawing. The
    program keeps the file, form, dialect and section views of the one the document came from
    (`doc.origin`), so Save rewrites only the networks that changed; a network still as it
    was read (see `kept` of program_to_ladder) keeps its instructions as read. A program
    drawn from its dialect's model (source_model.py) is rebuilt by that model."""
    model = source_model(doc.origin)
    if model is not None and doc.origin is not None:
        rebuilt, found = model.rebuild([n for n in doc.networks
                                        if not (n.is_empty() and not n.comments)])
        fresh, symbols = rebuilt.model, rebuilt.symbols  # its own: new names too
        adopt_origin(rebuilt, doc.origin)
        rebuilt.model, rebuilt.symbols = fresh, symbols or rebuilt.symbols
        return rebuilt, found
    program = Program(header=list(doc.header), footer=list(doc.footer),
                      before=list(doc.before), after=list(doc.after))
    if doc.origin is not None:
        adopt_origin(program, doc.origin)
    diagnostics: list[Diagnostic] = []
    pending: list[str] = []
    next_kept = 0
    dialect = doc.origin.dialect if doc.origin is not None else "seed"
    for index, network in enumerate(doc.networks):
        if network.is_empty() and not network.comments:
            continue
        if kept and (position := _unchanged(network, kept, next_kept)) is not None:
            next_kept = position + 1
            program.networks.append(Network(list(kept[position][1].instructions),
                                            pending + list(network.comments), network.label))
            pending = []
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


def adopt_origin(program: Program, origin: Program) -> None:
    """Carry over what the ladder document does not hold: file, framing, dialect, views."""
    program.source = origin.source
    program.framed = origin.framed
    program.dialect = origin.dialect
    program.title = origin.title
    program.system_params = origin.system_params
    program.symbols = origin.symbols
    program.messages = origin.messages
    program.io_modules = origin.io_modules
    program.model = origin.model
