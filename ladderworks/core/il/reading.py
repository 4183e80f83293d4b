"""Which reader reads a file: a dialect's (recognised from the content, or named) or the PMC's.

`parse_bytes`, `parse_file` and `parse_for_check` here sniff the text (core/dialects) and hand
it to the dialect's reader, else to the PMC parser (il/parser.py). `dialect` names a reader and
skips the sniffing (`--dialect NAME` on the command line); "pmc" forces the PMC parser.
"""

from __future__ import annotations

from pathlib import Path

from ladderworks.core import dialects
from ladderworks.core.collector import collector_paused
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il import parser
from ladderworks.core.il.parser import ParseResult
from ladderworks.core.il.textform import TextForm, decode_lines, dominant_newline, split_with_ends

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


def parse_bytes(data: bytes, dialect: str | None = None) -> ParseResult:
    """Parse file contents in whichever dialect they are written (or `dialect`)."""
    found = choose(data, dialect)
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
    tables and texts beside a block) gets the path too; else parse_bytes."""
    found = choose(data, dialect)
    if found is not None and found.opener:
        return open_with(path, data, found)
    return parser.parse_bytes(data) if found is None else read_dialect(data, found)


def parse_file(path: str | Path, dialect: str | None = None) -> ParseResult:
    """Parse a program file in whichever dialect it is written (or `dialect`); a folder of a
    dialect's exports (S7) as one program."""
    target = Path(path)
    if target.is_dir():
        return _folder(target, dialect)
    with open(path, "rb") as file:
        data = file.read()
    found = choose(data, dialect)
    if found is not None and found.opener:
        return open_with(target, data, found)
    return parser.parse_bytes(data) if found is None else read_dialect(data, found)


def parse_for_check(path: str | Path, dialect: str | None = None) -> ParseResult:
    """parser.parse_for_check, or a dialect's reader for a file of another dialect."""
    target = Path(path)
    if target.is_dir():
        return _folder(target, dialect)
    with open(path, "rb") as file:
        data = file.read()
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
