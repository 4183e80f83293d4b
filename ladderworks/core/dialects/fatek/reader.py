"""Read a WinProladder mnemonic listing (printed/exported, or seed 002's plain form) into a
Program of the engine's networks; every line keeps its place (the faithful save)."""

from __future__ import annotations

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.fatek.branches import Lowered
from ladderworks.core.dialects.fatek.listing import read_listing
from ladderworks.core.dialects.fatek.networks import lower_program
from ladderworks.core.il.program import FileSource, Network, Program
from ladderworks.core.il.textform import TextForm

NAME = "fatek"


def _spans(parts: list[Lowered], count: int) -> tuple[list[tuple[int, int]], int]:
    """Line index spans of the networks (each runs to the next one's first line: the page
    headers and blank lines between them go with the network before), and where the last one
    ends (the line after its last record)."""
    if not parts:
        return [], count
    starts = [part.records[0].line - 1 for part in parts]
    ends = [*starts[1:], max(r.last_line for r in parts[-1].records)]
    return list(zip(starts, ends, strict=True)), ends[-1]


def read(text: str, form: TextForm, lines: list[str],
         ends: list[str]) -> tuple[Program, list[Diagnostic]]:
    """A Fatek listing as a Program (dialect "fatek") and the reader's diagnostics."""
    listing, diagnostics = read_listing(lines)
    parts, problems = lower_program(listing.records)
    diagnostics += problems
    diagnostics.sort(key=lambda d: (d.line, d.column))
    networks = [Network(part.instructions) for part in parts]
    program = Program(networks=networks, dialect=NAME)
    spans, last = _spans(parts, len(lines))
    start = spans[0][0] if spans else len(lines)
    program.source = FileSource(
        form, lines, ends, start, len(lines), [network.key() for network in networks], spans,
        [span[0] for span in spans], (), (last, len(lines)))
    return program, diagnostics
