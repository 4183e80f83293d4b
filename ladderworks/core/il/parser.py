"""Parser from `.LAD` / `.MOD` / LADDER-III mnemonic text to a Program, with diagnostics."""

from __future__ import annotations

import re
from bisect import bisect_left
from dataclasses import dataclass, field
from itertools import compress, count, repeat
from operator import contains
from typing import TYPE_CHECKING

from ladderworks.core.collector import collector_paused
from ladderworks.core.diagnostics import Diagnostic, Severity, has_errors
from ladderworks.core.il.line_scan import LABEL, comment_text
from ladderworks.core.il.line_scan import line_parser as line_parser  # its place until now
from ladderworks.core.il.model_check import model_address_problems
from ladderworks.core.il.model_marker import marked_model
from ladderworks.core.il.networks import LadderReader
from ladderworks.core.il.program import (
    FANUC,
    FileSource,
    Network,
    Program,
    Section,
)
from ladderworks.core.il.sections import read_views
from ladderworks.core.il.textform import (
    TextForm,
    decode_lines,
    decode_text,
    dominant_newline,
    split_with_ends,
)

if TYPE_CHECKING:
    from pathlib import Path


_HEADER = re.compile(r"^\s*%@(.*)$")
_SECTION_END = re.compile(r"^\s*%\s*$")
_NUMBERED = re.compile(r"^(\d+)(.*)$")
# Known section headers by number (the suffix after `%@n`); `%@2-E(...)` has options.
_KNOWN_SUFFIXES: dict[int, tuple[str, ...]] = {
    0: ("",), 1: ("",), 2: ("", "-C", "-C2", "-D"), 3: ("",), 4: ("",), 5: ("",)}


@dataclass(slots=True)
class ParseResult:
    """A parsed program with its diagnostics and the text form that was read."""

    program: Program
    diagnostics: list[Diagnostic] = field(default_factory=list)
    encoding: str = "utf-8"

    @property
    def ok(self) -> bool:
        """True when there is no error (warnings allowed)."""
        return not has_errors(self.diagnostics)

    @property
    def form(self) -> TextForm:
        """Encoding, BOM and line end of the file (see core/il/textform.py)."""
        return self.program.form


def decode(data: bytes) -> tuple[str, str]:
    """Decode file bytes (BOM, UTF-8, or cp1254); returns the text and the codec name."""
    text, form, _diagnostics = decode_text(data)
    return text, form.encoding


# bytes text rarely has: not TAB, LF, VT, FF, CR, nor FS/GS/RS, which a comment may hold (they
# end no line here: core/il/textform.py) — a short program with a few is text all the same
_CONTROLS = bytes(b for b in range(32) if b not in (9, 10, 11, 12, 13, 28, 29, 30))


def _is_binary(data: bytes) -> bool:
    """True for bytes that are not text: NULs (without a UTF-16 BOM) or many control bytes."""
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        return False
    sample = data[:65536]
    if b"\x00" in sample:
        return True
    controls = len(sample) - len(sample.translate(None, _CONTROLS))
    return controls * 20 > len(sample)


def parse_bytes(data: bytes) -> ParseResult:
    """Parse file contents given as bytes (any encoding LadderWorks reads)."""
    with collector_paused(promote=True):
        return _parse_bytes(data)


def parse_for_check(path: str | Path) -> ParseResult:
    """parse_file(path) without what only the editor and Save use: the same networks and
    diagnostics, but the other sections' views (symbol table, messages, title) only as far
    as their diagnostics need, and no lossless bookkeeping (the networks' keys and spans):
    what `ladderworks-cli check` runs the compiler's checks on."""
    data = _read(path)
    with collector_paused(promote=True):
        return _parse_bytes(data, whole=False)


def _parse_bytes(data: bytes, *, whole: bool = True) -> ParseResult:
    text, form, diagnostics, split = decode_lines(data)
    if _is_binary(data):
        program = Program()
        program.source = FileSource(form, *split, -1, -1)
        return ParseResult(program, [Diagnostic("not-a-program", {}, 1, 1)], form.encoding)
    parser = _FileParser(text, form, split)
    parser.whole = whole
    result = parser.run()
    if diagnostics:
        result.diagnostics = sorted(diagnostics + result.diagnostics,
                                    key=lambda d: (d.line, d.column))
    result.encoding = form.encoding
    return result


def parse_file(path: str | Path) -> ParseResult:
    """Parse a `.LAD` / `.MOD` / `.mnc` / `.txt` file."""
    return parse_bytes(_read(path))


def _read(path: str | Path) -> bytes:
    """The bytes of a file (with open(), as Path.read_bytes does: `check` loads no pathlib)."""
    with open(path, "rb") as file:
        return file.read()


def parse(text: str, dialect: str | None = None) -> ParseResult:
    """Parse program text; never raises for bad input, returns diagnostics instead.

    `dialect` "fanuc" reads the text as part of a FANUC program (its 30i ranges) even without
    framing or labels, as the ladder editor does for a network of an open LADDER-III program.
    """
    _lines, ends = split_with_ends(text)
    form = TextForm(newline=dominant_newline(ends), final_newline=not ends or ends[-1] != "")
    parser = _FileParser(text, form)
    if dialect == FANUC:
        parser.dialect = FANUC
    with collector_paused(promote=True):
        return parser.run()


def _percent_lines(text: str, lines: list[str]) -> list[int]:
    """The indexes of the `lines` (split_with_ends of `text`) that hold a `%`."""
    if "\r" in text:  # lines end at CR too: look at each line
        return list(compress(count(), map(contains, lines, repeat("%"))))
    # each `%` of the text, at the line the LFs before it say: a few finds, not a look at
    # each of the (many thousand) lines
    marks: list[int] = []
    line = previous = 0
    found = text.find("%")
    while found >= 0:
        line += text.count("\n", previous, found)
        previous = found
        if not marks or marks[-1] != line:
            marks.append(line)
        found = text.find("%", found + 1)
    return marks


def _header_kind(rest: str) -> tuple[int, str, bool]:
    """(number, suffix, known) of a header's text after `%@` (number -1: not numbered)."""
    match = _NUMBERED.match(rest.strip())
    if match is None or len(match.group(1)) > 3:
        return -1, rest.strip(), False
    number, suffix = int(match.group(1)), match.group(2).strip()
    known = suffix in _KNOWN_SUFFIXES.get(number, ()) or (
        number == 2 and suffix.upper().startswith("-E(") and suffix.endswith(")"))
    return number, suffix, known


class _FileParser:
    """Splits the file into sections; the ladder section is read by `networks.LadderReader`."""

    def __init__(self, text: str, form: TextForm,
                 split: tuple[list[str], list[str]] | None = None) -> None:
        self.lines, ends = split if split is not None else split_with_ends(text)
        self.text = text  # the lines joined (split_with_ends)
        self.program = Program()
        self.source = FileSource(form, self.lines, ends, 0, len(self.lines))
        self.program.source = self.source
        self.diagnostics: list[Diagnostic] = []
        self.firsts: dict[int, int] = {}
        self.labels = False
        self.dialect = "seed"  # decided before the ladder is read: parameter ranges depend on it
        self.marked: str | None = None  # the PMC model a marker line names (model_marker)
        # False: the networks are for the compiler's checks only (parse_for_check), so the
        # other sections' views and what Save needs to write them back are not made
        self.whole = True
        self.marks: list[int] | None = None  # the lines with a `%`, found when first needed

    def run(self) -> ParseResult:
        has_any_section = any(_HEADER.match(line) for line in self.lines if "%@" in line)
        if not has_any_section:
            missing = Diagnostic("missing-start", {}, 1, 1)
            self.diagnostics.append(missing)
            stop = len(self.lines)
            if stop and _SECTION_END.match(self.lines[-1]):
                stop -= 1
            self.source.ladder_stop = stop
            self._parse_ladder(0, stop)
            if self.labels and self.program.networks:  # a LADDER-III ladder section without
                self.diagnostics.remove(missing)  # its `%@3`: N00012: labels say what it is
            self._not_a_program()
            return self._result()
        self._split_sections()
        return self._result()

    def _split_sections(self) -> None:
        lines = self.lines
        ladder_found = False
        seen: set[str] = set()
        i = 0
        while i < len(lines):
            line = lines[i]
            header = _HEADER.match(line) if "%@" in line else None
            if header:
                rest = header.group(1).strip()
                if rest.upper() in ("A", "E"):
                    self.program.framed = True
                    i += 1
                    continue
                number, suffix, known = _header_kind(rest)
                title = f"%@{rest}"
                if not known:
                    self.diagnostics.append(Diagnostic(
                        "bad-section", {"number": rest[:20], "header": title[:40]}, i + 1, 1,
                        Severity.WARNING))
                key = title.upper()
                if key in seen:
                    self.diagnostics.append(
                        Diagnostic("duplicate-section", {"number": rest[:20]}, i + 1, 1))
                seen.add(key)
                j = self._next_mark(i + 1)
                closed = j < len(lines) and bool(_SECTION_END.match(lines[j]))
                if not closed:
                    self.diagnostics.append(Diagnostic("missing-end", {}, min(j, len(lines)), 1))
                if number == 3 and not suffix and not ladder_found:
                    ladder_found = True
                    self.source.ladder_start, self.source.ladder_stop = i + 1, j
                    self._parse_ladder(i + 1, j)
                else:
                    section = Section(number, lines[i + 1:j],
                                      "" if not suffix and known else title)
                    self.firsts[id(section)] = i + 2
                    (self.program.after if ladder_found else self.program.before
                     ).append(section)
                i = j + 1 if closed else j
                continue
            stripped = line.strip()
            if not stripped:
                pass
            elif stripped.startswith(("//", ";", ",")):
                target = self.program.footer if ladder_found else self.program.header
                target.append(comment_text(stripped))
            else:
                self.diagnostics.append(
                    Diagnostic("text-outside-section", {"text": stripped[:40]}, i + 1,
                               len(line) - len(line.lstrip()) + 1))
            i += 1
        if not ladder_found:
            self.diagnostics.append(Diagnostic("missing-start", {}, 1, 1))
            self.source.ladder_start = self.source.ladder_stop = -1
        read_views(self.program, self.firsts, self.diagnostics,
                   build=self.whole)

    def _next_mark(self, start: int) -> int:
        """The first line from `start` that ends a section or starts one (else past the end):
        only the lines with a `%` are looked at."""
        lines = self.lines
        marks = self.marks
        if marks is None:
            marks = self.marks = _percent_lines(self.text, lines)
        for j in marks[bisect_left(marks, start):]:
            line = lines[j]
            if _SECTION_END.match(line) or ("%@" in line and _HEADER.match(line)):
                return j
        return len(lines)

    def _not_a_program(self) -> None:
        """Text with no section and no instruction that has errors is not a ladder program."""
        errors = [d for d in self.diagnostics if d.is_error and d.code != "missing-start"]
        if self.program.networks or not errors:
            return
        self.diagnostics = [Diagnostic("not-a-program", {}, 1, 1), *errors[:2]]

    def _result(self) -> ParseResult:
        if self.marked:
            self.program.dialect = self.marked
        elif self.program.framed or self.labels or self.dialect == FANUC:
            self.program.dialect = FANUC
        self.diagnostics.extend(model_address_problems(self.program))
        self.diagnostics.sort(key=lambda d: (d.line, d.column))
        return ParseResult(self.program, self.diagnostics)

    # -- the ladder section -------------------------------------------------------------

    def _parse_ladder(self, start: int, stop: int) -> None:
        lines = self.lines
        self.marked = marked_model(lines[:start]) if start else None
        if self.marked:
            self.dialect = self.marked
        elif self.program.framed or self.dialect == FANUC or any(
                line.endswith(":") and LABEL.match(line) for line in lines[start:stop]):
            self.dialect = FANUC
        reader = LadderReader(self.diagnostics, self.dialect)
        builder = reader.read(lines[start:stop], start)
        self.labels = self.labels or reader.labels
        self.program.networks = builder.networks
        self.program.trailer = builder.finish_pending()
        if not self.whole:
            return
        source = self.source
        source.keys = list(map(Network.key, builder.networks))
        source.spans = builder.spans()
        source.heads = builder.heads
        source.trailer = tuple(builder.pending)
        source.trailer_span = (builder.cursor, stop)

