"""Which reader reads a file: a dialect's (recognised from the content, or named) or the PMC's.

`parse_bytes`, `parse_file` and `parse_for_check` here sniff the text (core/dialects) and hand
it to the dialect's reader, else to the PMC parser (il/parser.py). `dialect` names a reader and
skips the sniffing (`--dialect NAME` on the command line); "pmc" forces the PMC parser. A
WinProladder project (`.pdw`, recognised by its header) is read by the Fatek dialect's
`pdw_reader` whatever is named; a WPLSoft project (`.dvp`, recognised by its first bytes) by
core/dialects/delta/dvp_program.py unless another dialect is named.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from ladderworks.core import dialects
from ladderworks.core.collector import collector_paused
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.fatek.pdw_file import is_pdw
from ladderworks.core.il import parser
from ladderworks.core.il.parser import ParseResult
from ladderworks.core.il.textform import TextForm, decode_lines, dominant_newline, split_with_ends

if TYPE_CHECKING:
    from ladderworks.core.il.program import Program

PMC = "pmc"  # `--dialect pmc`: the PMC parser, whatever the text looks like


class UnknownDialect(ValueError):
    """A dialect name nobody registered."""


def choose(data: bytes, dialect: str | None = None) -> dialects.Dialect | None:
    """The dialect whose reader reads `data`: `dialect` if named, else the one the text looks
    like; None for the PMC parser. Raises UnknownDialect for a name not registered."""
    if dialect == PMC:
        return None
    if dialect:
        found = dialects.get(dialect)
        if found is None:
            raise UnknownDialect(dialect)
        return found
    text, _form, _diagnostics, _split = decode_lines(data[:65536])
    return dialects.sniff(text)


def read_dialect(data: bytes, dialect: dialects.Dialect) -> ParseResult:
    """`data` read by `dialect`'s reader."""
    text, form, diagnostics, (lines, ends) = decode_lines(data)
    with collector_paused(promote=True):
        program, found = dialect.read(text, form, lines, ends)
    every: list[Diagnostic] = sorted(diagnostics + found, key=lambda d: (d.line, d.column))
    return ParseResult(program, every, form.encoding)


def _binary(data: bytes, dialect: str | None) -> ParseResult | None:
    """The program of a binary project file (a WPLSoft `.dvp`), or None for text."""
    from ladderworks.core.dialects.delta import NAME as DELTA
    from ladderworks.core.dialects.delta.dvp_file import is_dvp

    if not is_dvp(data) or dialect not in (None, DELTA):
        return None
    from ladderworks.core.dialects.delta.dvp_program import parse_dvp

    with collector_paused(promote=True):
        return parse_dvp(data)


def read_pdw(data: bytes) -> ParseResult:
    """A WinProladder project's program (core/dialects/fatek/pdw_reader.py)."""
    from ladderworks.core.dialects.fatek import pdw_reader
    with collector_paused(promote=True):
        program, diagnostics = pdw_reader.read(data)
    return ParseResult(program, sorted(diagnostics, key=lambda d: (d.line, d.column)),
                       program.form.encoding)


def parse_bytes(data: bytes, dialect: str | None = None) -> ParseResult:
    """Parse file contents in whichever dialect they are written (or `dialect`)."""
    return _read(data, dialect, None)


def _read(data: bytes, dialect: str | None, path: Path | None) -> ParseResult:
    """A project file by its header, else the text by its dialect (sniffed once); with the
    file's `path`, a dialect that opens companion files (S7's tag tables) gets it."""
    if is_pdw(data):
        return read_pdw(data)
    binary = _binary(data, dialect)
    if binary is not None:
        return binary
    found = choose(data, dialect)
    if path is not None and found is not None and found.opener:
        return open_with(path, data, found)
    return parser.parse_bytes(data) if found is None else read_dialect(data, found)


def open_with(path: Path, data: bytes | None, found: dialects.Dialect) -> ParseResult:
    """A file with its companions, or a folder, opened by its dialect's `opener` (S7)."""
    with collector_paused(promote=True):
        program, diagnostics, encoding = found.open_path(path, data)
    return ParseResult(program, sorted(diagnostics, key=lambda d: (d.line, d.column)), encoding)


def _folder(path: Path, dialect: str | None) -> ParseResult:
    """A folder of exports: the first dialect that opens folders (or `dialect`) opens it."""
    named = dialects.get(dialect) if dialect else None
    found = named or next((d for d in dialects.every() if d.opener), None)
    if found is None or not found.opener:
        raise IsADirectoryError(str(path))
    return open_with(path, None, found)


def parse_read(path: Path, data: bytes, dialect: str | None = None) -> ParseResult:
    """`data` read from the file `path`: a dialect that opens companion files (S7's tag
    tables and texts beside a block) gets the path too; the files a dialect reads beside a
    program (Fatek's comment export) are attached."""
    result = _read(data, dialect, path)
    attach_companions(path, result.program)
    return result


def parse_file(path: str | Path, dialect: str | None = None) -> ParseResult:
    """Parse a program file in whichever dialect it is written (or `dialect`); a folder of a
    dialect's exports (S7) as one program."""
    target = Path(path)
    if target.is_dir():
        return _folder(target, dialect)
    with open(path, "rb") as file:
        data = file.read()
    return parse_read(target, data, dialect)


def attach_companions(path: str | Path, program: Program) -> None:
    """The files a dialect reads beside a program (Fatek's comment export: its symbols)."""
    found = dialects.of(program)
    if found is not None and found.companions:
        found.function(found.companions)(Path(path), program)


def parse_for_check(path: str | Path, dialect: str | None = None) -> ParseResult:
    """parser.parse_for_check, or a dialect's reader for a file of another dialect."""
    target = Path(path)
    if target.is_dir():
        return _folder(target, dialect)
    with open(path, "rb") as file:
        data = file.read()
    if is_pdw(data):
        return read_pdw(data)
    binary = _binary(data, dialect)
    if binary is not None:
        return binary
    found = choose(data, dialect)
    if found is not None and found.opener:
        return open_with(target, data, found)
    return parser.parse_for_check(path) if found is None else read_dialect(data, found)


def parse_text(text: str, dialect: str | None = None) -> ParseResult:
    """Program text (a text view, the PLC control screen) in whichever dialect it is written:
    `dialect` names one ("fanuc": the PMC parser with the 30i ranges), else the text is
    sniffed."""
    found = dialects.get(dialect) if dialect else dialects.sniff(text)
    if found is None:
        return parser.parse(text, dialect if dialect == "fanuc" else None)
    lines, ends = split_with_ends(text)
    form = TextForm(newline=dominant_newline(ends), final_newline=not ends or ends[-1] != "")
    with collector_paused(promote=True):
        program, diagnostics = found.read(text, form, lines, ends)
    return ParseResult(program, sorted(diagnostics, key=lambda d: (d.line, d.column)))
