"""A WinProladder project (`.pdw`) as a Fatek program: its decoded mnemonic listing read by
the Fatek reader, its element comments as the program's symbols (docs/dialects.md, ".pdw
projects"). LadderWorks never writes a .pdw: Save offers the listing instead."""

from __future__ import annotations

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.fatek import reader
from ladderworks.core.dialects.fatek.comments import comment_symbols
from ladderworks.core.dialects.fatek.pdw_file import read_pdw
from ladderworks.core.il.program import Program
from ladderworks.core.il.textform import TextForm, split_with_ends

LISTING_SUFFIX = ".lst"  # what a .pdw's program is saved as (WinProladder's listing)
LISTING_FORM = TextForm(newline="\r\n")  # the listing WinProladder writes: CRLF


def read(data: bytes) -> tuple[Program, list[Diagnostic]]:
    """The program of a .pdw's bytes and the diagnostics: the reader's, and first the .pdw's
    own (code and byte offset) when the file is cut, damaged or not decoded to its end."""
    pdw = read_pdw(data)
    text = pdw.text
    lines, ends = split_with_ends(text)
    program, diagnostics = reader.read(text, LISTING_FORM, lines, ends)
    program.symbols = comment_symbols(pdw.comments)
    if pdw.error is not None:
        diagnostics.insert(0, Diagnostic(pdw.error.code, dict(pdw.error.args_map),
                                         max(1, len(lines)), 1))
    return program, diagnostics
