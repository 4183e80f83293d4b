"""Parser from `.LAD` / `.MOD` / LADDER-III mnemonic text to a Program, with diagnostics."""

from __future__ import annotations

import re
from bisect import bisect_left
from dataclasses import dataclass, field
from functools import cache, lru_cache
from itertools import compress, count, repeat
from operator import contains, is_
from typing import TYPE_CHECKING, cast

from ladderworks.core import instructions as _table
from ladderworks.core.address import (
    Address,
    AddressError,
    parse_address_cached,
    parse_plain_addresses,
)
from ladderworks.core.collector import collector_paused
from ladderworks.core.diagnostics import Diagnostic, Severity, has_errors
from ladderworks.core.il.model_check import model_address_problems
from ladderworks.core.il.model_marker import marked_model
from ladderworks.core.il.program import (
    FANUC,
    FileSource,
    Instruction,
    LabelRef,
    Network,
    ParamValue,
    Program,
    ProgramRef,
    Section,
    new_instruction,
)
from ladderworks.core.il.sections import read_views
from ladderworks.core.il.textform import (
    TextForm,
    decode_lines,
    decode_text,
    dominant_newline,
    split_with_ends,
)
from ladderworks.core.instructions import (
    BY_MNEMONIC,
    BY_SUB,
    Combine,
    InstructionSpec,
    Kind,
    Param,
    ParamKind,
    lookup,
    spec_for,
    value_is_address,
    width_of,
)

if TYPE_CHECKING:
    from pathlib import Path

    import lark

_HEADER = re.compile(r"^\s*%@(.*)$")
_SECTION_END = re.compile(r"^\s*%\s*$")
_NUMBERED = re.compile(r"^(\d+)(.*)$")
_MASK = re.compile(r"^[01]{1,4}$")
_LABEL = re.compile(r"^[ \t]*([Nn][0-9]+):[ \t]*$")
_SAFE = re.compile(r"[A-Za-z0-9_.+\- \t]*")  # code the fast scanner splits at spaces/tabs
_ADDRESS_SHAPE = re.compile(r"^[A-Za-z]\d+(\.\d+)?$")
_REF = re.compile(r"^([PpLl])0*(\d{1,6})$")
# a name and one operand that starts with a letter, nothing else: what _scan_fast reads as
# two words (no sign, no comment)
_SIMPLE = re.compile(r"[ \t]*([A-Za-z_][A-Za-z0-9_.]*)[ \t]+([A-Za-z][A-Za-z0-9_.]*)[ \t]*")

# Known section headers by number (the suffix after `%@n`); `%@2-E(...)` has options.
_KNOWN_SUFFIXES: dict[int, tuple[str, ...]] = {
    0: ("",), 1: ("",), 2: ("", "-C", "-C2", "-D"), 3: ("",), 4: ("",), 5: ("",)}
MAX_NUMBER_DIGITS = 12  # a parameter with more digits is out of range (no int() of it)


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


@lru_cache(maxsize=1)
def line_parser() -> lark.Lark:
    """The lark parser for one line, loaded once from grammar.lark (lark is imported only
    when a line needs it: the fast scanner reads the common lines, and `check` starts faster)."""
    from importlib import resources

    import lark

    grammar = resources.files("ladderworks.core.il").joinpath("grammar.lark").read_text("utf-8")
    return lark.Lark(grammar, start="line", parser="lalr", maybe_placeholders=False)


def decode(data: bytes) -> tuple[str, str]:
    """Decode file bytes (BOM, UTF-8, or cp1254); returns the text and the codec name."""
    text, form, _diagnostics = decode_text(data)
    return text, form.encoding


_CONTROLS = bytes(b for b in range(32) if b not in (9, 10, 12, 13))  # bytes text rarely has


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


@dataclass(slots=True)
class _Token:
    text: str
    column: int
    is_int: bool


# What one line text makes on its own, found once per distinct text: the instruction's spec,
# name, operand, parameters, comment and column, whether it starts a network after an output,
# and whether it ends one (see _NetworkBuilder.add).
_Made = tuple[InstructionSpec, str, Address | None, tuple[ParamValue, ...], str, int, bool, bool]


class _Line:
    """One scanned line text of the ladder section; the lines that repeat the text share it.

    `made` is set once the text alone has made an instruction with no diagnostic; such a
    line is read from it alone (a `RD X21.7` found by the fast scanner keeps no words)."""

    __slots__ = ("comment", "function", "kind", "made", "param", "words")

    def __init__(self, kind: str, words: list[_Token] | None = None,
                 comment: str | None = None, made: _Made | None = None) -> None:
        self.kind = kind  # "blank", "comment", "instruction", "parameter", "label"
        self.words: list[_Token] = words if words is not None else []
        self.comment = comment
        self.made = made
        self.param = made is None and _is_param_line(self)  # a parameter line
        # the function whose parameters follow on the next lines (`SUB 43`, `MOVB`), once
        # the text was read so with no diagnostic
        self.function: InstructionSpec | None = None


def _comment_text(raw: str) -> str:
    """Comment body after its marker (`//`, `;` or `,`), right-stripped."""
    body = raw[2:] if raw.startswith("//") else raw[1:]
    return body.rstrip()


@cache
def _basic_with_operand(name: str) -> tuple[InstructionSpec, bool, bool] | None:
    """The basic instruction a name spells, when it takes an address operand, with its
    _flow(); None for any other name."""
    spec = lookup(name)
    if spec is None or spec.kind is not Kind.BASIC or not spec.operand:
        return None
    return (spec, *_flow(spec))


def _scan_fast(text: str) -> _Line | _Made | None:
    """The common lines without lark; None for a line only the grammar can judge. A basic
    instruction with its operand and nothing else (`RD X21.7`) is the instruction it makes."""
    simple = _SIMPLE.fullmatch(text)  # `RD  X21.7`, the most common shape, in one match
    if simple is not None:
        head, operand = simple.group(1, 2)
        basic = _basic_with_operand(head)
        if basic is not None:
            try:  # read as the symbol table reads it (one cached parse for both)
                address: Address | None = parse_address_cached(operand, None, 1)
            except AddressError:
                address = None  # the full path reports it
            if address is not None and address.bit is not None:
                spec, starts, ends = basic
                return (spec, spec.name, address, (), "", simple.start(1) + 1, starts, ends)
        return _Line("instruction", [_Token(head, simple.start(1) + 1, False),
                                     _Token(operand, simple.start(2) + 1, False)])
    stripped = text.lstrip(" \t")
    if not stripped:
        return _BLANK
    first = stripped[0]
    if first == ";" or stripped.startswith("//"):
        return _Line("comment", comment=_comment_text(stripped))
    if first == ",":
        return _Line("comment", comment=_comment_text(stripped.strip()))
    cut = len(text)
    if ";" in text or "/" in text:
        semi = text.find(";")
        if semi >= 0:
            cut = semi
        slash = text.find("//", 0, cut)
        if slash >= 0:
            cut = slash
    code = text[:cut] if cut < len(text) else text
    if _SAFE.fullmatch(code) is None:
        label = _LABEL.match(text)
        return _Line("label", [_Token(label.group(1), 1, False)]) if label else None
    words: list[_Token] = []
    position = 0
    for word in code.split():
        head = word[0]
        if head.isalpha() or head == "_":
            if "+" in word or "-" in word:
                return None
            is_int = False
        elif word.isdigit() or (head in "+-" and word[1:].isdigit()):
            is_int = True
        else:
            return None
        position = code.find(word, position)
        words.append(_Token(word, position + 1, is_int))
        position += len(word)
    if not words:
        return None
    comment = _comment_text(text[cut:]).strip() if cut < len(text) else None
    if words[0].is_int:
        if len(words) > 1:
            return None
        return _Line("parameter", words, comment)
    return _Line("instruction", words, comment)


# one line text a line of the joined texts: the most common shape, `RD  X21.7` (a name at the
# line's start and a plain bit address); a parameter line `R100` or `0001`; a label `N00012:`;
# or any other line (every group empty)
_COMMON = re.compile(
    r"([A-Za-z_][A-Za-z0-9_.]*)[ \t]+([XYFGRADTCKE][0-9]{1,6}\.[0-7])[ \t]*\n"
    r"|(?:([A-Za-z][0-9]+)|([0-9]+)|([Nn][0-9]+):)[ \t]*\n|[^\n]*\n")


@cache
def _basic_made(name: str) -> tuple[InstructionSpec, str, bool, bool] | None:
    """What _scan_fast takes from a basic instruction's name (its spec, name and _flow())."""
    basic = _basic_with_operand(name)
    return None if basic is None else (basic[0], basic[0].name, basic[1], basic[2])


def _scan_common(texts: list[str]) -> list[_Line | _Made | None]:
    """What _scan_fast makes of each text of the common shapes, found for all the texts at
    once; None for the others.

    One findall over the joined texts and one go for their addresses do in C what a match,
    a lookup and an address parse a text would do in Python."""
    found = _COMMON.findall("\n".join(texts) + "\n")
    if len(found) != len(texts):  # a text with a line break (never read from a file)
        return [None] * len(texts)
    names, operands, words, numbers, labels = zip(*found, strict=True) if found else (
        (), (), (), (), ())
    addresses = parse_plain_addresses(list(dict.fromkeys(operands)))
    address_of = addresses.get
    made: list[_Line | _Made | None] = [
        None if basic is None or (address := address_of(operand)) is None
        else (basic[0], basic[1], address, (), "", 1, basic[2], basic[3])
        for basic, operand in zip(map(_basic_made, names), operands, strict=True)]
    for index in compress(count(), map(is_, made, repeat(None))):
        if words[index]:  # `R100`: a word with no sign and no comment, at column 1
            made[index] = _Line("instruction", [_Token(words[index], 1, False)])
        elif numbers[index]:  # `0001`
            made[index] = _Line("parameter", [_Token(numbers[index], 1, True)])
        elif labels[index]:  # `N00012:`
            made[index] = _Line("label", [_Token(labels[index], 1, False)])
    return made


def _scan_line(text: str, number: int) -> _Line | _Made | Diagnostic:
    """One line text of the ladder section (at line `number`, for a syntax error): the fast
    scanner, else the lark grammar."""
    fast = _scan_fast(text)
    if fast is not None:
        return fast
    import lark

    try:
        tree = line_parser().parse(text)
    except lark.exceptions.UnexpectedInput as exc:
        column = getattr(exc, "column", 1) or 1
        bad = text[column - 1:].split()[0] if text[column - 1:].split() else text.strip()
        return Diagnostic("syntax", {"text": bad[:40]}, number, column)
    kind = tree.data
    if kind == "blank_line":
        return _BLANK
    if kind == "comma_comment_line":
        return _Line("comment", comment=_comment_text(str(tree.children[0]).strip()))
    if kind == "comment_line":
        raw = str(_branch(tree.children[0]).children[0])
        return _Line("comment", comment=_comment_text(raw))
    if kind == "label_line":
        tok = _leaf(tree.children[0])
        return _Line("label", [_Token(str(tok)[:-1], _column(tok), False)])
    statement = _branch(tree.children[0])
    comment: str | None = None
    if len(tree.children) > 1:
        comment = _comment_text(str(_branch(tree.children[1]).children[0])).strip()
    if statement.data == "parameter_line":
        tok = _leaf(statement.children[0])
        return _Line("parameter", [_Token(str(tok), _column(tok), True)], comment)
    name = _leaf(statement.children[0])
    words = [_Token(str(name), _column(name), False)]
    for child in statement.children[1:]:
        operand = _branch(child)
        tok = _leaf(operand.children[0])
        words.append(_Token(str(tok), _column(tok), operand.data == "int_operand"))
    return _Line("instruction", words, comment)


def _syntax_error(text: str, number: int) -> Diagnostic:
    """The syntax error of a line text _scan_line found one in, at line `number`."""
    item = _scan_line(text, number)
    assert isinstance(item, Diagnostic), text
    return item


def _branch(node: lark.Tree[lark.Token] | lark.Token) -> lark.Tree[lark.Token]:
    """A subtree the line grammar puts at this place."""
    import lark  # loaded already: only lark's trees reach here

    assert isinstance(node, lark.Tree), node
    return node


def _leaf(node: lark.Tree[lark.Token] | lark.Token) -> lark.Token:
    """A token the line grammar puts at this place."""
    import lark  # loaded already: only lark's trees reach here

    assert isinstance(node, lark.Token), node
    return node


def _column(token: lark.Token) -> int:
    """The token's 1-based column (the line parser tracks positions, so it is always set)."""
    return token.column or 1


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
    """Splits the file into sections and parses the ladder section into networks."""

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
        # the parameters read for a spec (by id: the table's rows live while a parse runs)
        # from operands (their texts), when they gave no diagnostic
        self.made_params: dict[tuple[int, tuple[tuple[str, bool], ...]],
                               tuple[ParamValue, ...]] = {}
        # _valid_params' reading of each spec (by id, holding the spec), in this dialect
        self.plans: dict[int, tuple[InstructionSpec,
                                    tuple[tuple[Param, ParamKind, int, int], ...] | None]] = {}

    def run(self) -> ParseResult:
        has_any_section = any(_HEADER.match(line) for line in self.lines if "%@" in line)
        if not has_any_section:
            self.diagnostics.append(Diagnostic("missing-start", {}, 1, 1))
            stop = len(self.lines)
            if stop and _SECTION_END.match(self.lines[-1]):
                stop -= 1
            self.source.ladder_stop = stop
            self._parse_ladder(0, stop)
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
                target.append(_comment_text(stripped))
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
                line.endswith(":") and _LABEL.match(line) for line in lines[start:stop]):
            self.dialect = FANUC
        # many lines repeat ("RD X21.7"): each text is scanned once, and what it makes is
        # built once; the lines that repeat it share its _Line (or its _Made)
        body = lines[start:stop]
        texts = list(dict.fromkeys(body))
        seen = cast("dict[str, _Line | _Made]", dict(zip(texts, _scan_common(texts),
                                                         strict=True)))
        bad = False
        for text in [text for text, item in seen.items() if item is None]:
            item = _scan_line(text, 0)
            if isinstance(item, Diagnostic):
                item = _BAD
                bad = True
            seen[text] = item
        if bad:  # a syntax error is reported at each line that has it, in order
            for number, text in enumerate(body, start + 1):
                if seen[text] is _BAD:
                    self.diagnostics.append(_syntax_error(text, number))
        recs = list(map(seen.__getitem__, body))  # line start + 1 + k is recs[k]
        base = start + 1
        builder = _NetworkBuilder(start)
        self._build_ladder(recs, base, builder)
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

    def _build_ladder(self, recs: list[_Line | _Made], base: int,
                      builder: _NetworkBuilder) -> None:
        """Read the ladder's lines into the builder's networks."""
        # the builder's state for the common line (an instruction its text alone makes, in
        # the current network) is kept in locals, and written back before any other line
        current = builder.current
        closed = builder.closed
        pending = builder.pending
        pending_label = builder.pending_label
        last = 0  # the last line added here since the builder was told (0: none)
        skip = 0  # the lines before this number were read with a line before them
        for number, rec in enumerate(recs, base):  # line `number` is recs[number - base]
            if number < skip:
                continue
            made = rec if rec.__class__ is tuple else rec.made  # type: ignore[union-attr]
            if made is not None:
                _spec, name, operand, params, comment, column, starts, ends = made
                instruction = new_instruction(name, operand, params, comment, (), number,
                                              column)
                if current is not None and not pending and not (
                        closed and (starts or pending_label)):
                    current.append(instruction)  # the common case of builder.add, inline
                    last = number
                    if ends:
                        closed = True
                    continue
            elif rec.kind == "label" and not pending_label:  # type: ignore[union-attr]
                self.labels = True  # builder.label, inline: one a network in LADDER-III text
                pending_label = builder.pending_label = rec.words[0].text  # type: ignore
                closed = True
                continue
            if last:
                builder.lasts[-1] = builder.cursor = last
                last = 0
            builder.closed = closed
            if made is not None:
                builder.add(instruction, number, starts, ends)
            else:
                assert isinstance(rec, _Line)
                kind = rec.kind
                if kind == "label":
                    self.labels = True
                    builder.label(rec.words[0].text)
                elif kind != "blank" and kind != "bad":
                    skip = base + self._line(recs, base, number - base, builder)
            current = builder.current
            closed = builder.closed
            pending = builder.pending
            pending_label = builder.pending_label
        if last:
            builder.lasts[-1] = builder.cursor = last
        builder.closed = closed

    def _line(self, recs: list[_Line | _Made], base: int, k: int,
              builder: _NetworkBuilder) -> int:
        """Read line `recs[k]` (number `base + k`, with the parameter lines it takes); returns
        the next index."""
        line = recs[k]
        assert isinstance(line, _Line)
        number = base + k
        k += 1
        last = k - 1  # the last line it reads
        if line.kind == "comment":
            builder.comment(line.comment or "")
            return k
        if line.kind == "label":
            self.labels = True
            builder.label(line.words[0].text)
            return k
        if line.kind == "parameter":
            self._error("stray-parameter", number, line.words[0].column,
                        text=line.words[0].text[:20])
            return k
        if line.function is not None:  # the text was read before: its parameters now
            fast = self._valid_params(line.function, recs, last)
            if fast is not None:
                return self._add_function(line, base, number, line.function, *fast,
                                          builder)
        reported = len(self.diagnostics)
        alone = True  # the text alone makes the instruction: no parameter lines taken
        head = line.words[0]
        operands = line.words[1:]
        spec = lookup(head.text)
        if spec is None and head.text[:4].upper() == "SUB.":
            spec = spec_for(head.text, len(operands))  # one-line unknown `SUB.219 p1 p2`
            if spec is not None:
                self.diagnostics.append(Diagnostic("unknown-sub", {"number": spec.sub},
                                                   number, head.column, Severity.WARNING))
        if spec is None:
            if len(operands) == 0 and _ADDRESS_SHAPE.match(head.text):
                self._error("stray-parameter", number, head.column, text=head.text[:20])
            else:
                self._error("unknown-instruction", number, head.column, name=head.text[:20])
            return k
        if spec.kind is Kind.BASIC and len(operands) > 1 and head.text.upper() in BY_MNEMONIC:
            spec = BY_MNEMONIC[head.text.upper()]  # one-line `AND 1 R10 R11 R12`: LOGAND
        if spec.name == "SUB" and len(operands) == 1 and operands[0].is_int:
            sub = _small_int(operands[0].text, 6)
            sub = sub if sub is not None and sub >= 0 else None
            sub_spec = BY_SUB.get(sub) if sub is not None else None
            if sub_spec is None:
                return self._unknown_sub(line, number, sub, recs, base, k, builder)
            spec = sub_spec
            operands = []
            alone = False
        elif spec.kind is not Kind.BASIC and not operands and spec.params:
            alone = False
        if not alone:
            if len(self.diagnostics) == reported:
                line.function = spec
            fast = self._valid_params(spec, recs, last)
            if fast is not None:  # what the lines below would make, with no diagnostic
                params, last = fast
                return self._add_function(line, base, number, spec, params, last,
                                          builder)
            last = self._collect_params(spec, recs, last, operands)
        k = last + 1
        end_line = base + last
        instruction = self._build(spec, line, number, operands)
        if instruction is None:
            return k
        starts, ends = _flow(spec)
        if alone and len(self.diagnostics) == reported:
            line.made = (spec, instruction.name, instruction.operand, instruction.params,
                         instruction.comment, instruction.column, starts, ends)
        builder.add(instruction, end_line, starts, ends)
        return k

    def _add_function(self, line: _Line, base: int, number: int, spec: InstructionSpec,
                      params: tuple[ParamValue, ...], last: int,
                      builder: _NetworkBuilder) -> int:
        """Add the function `line` (number `number`) makes with its valid parameters from the
        lines after it up to `recs[last]`."""
        comment = line.comment or ""
        column = line.words[0].column
        starts, ends = _flow(spec)
        builder.add(new_instruction(spec.name, None, params, comment, (), number, column),
                    base + last, starts, ends)
        return last + 1

    def _valid_params(self, spec: InstructionSpec, recs: list[_Line | _Made],
                      last: int) -> tuple[tuple[ParamValue, ...], int] | None:
        """The fixed parameters of `spec` from the lines right after `recs[last]`, and the
        index of the last line taken, when they are all there and valid; else None, and the
        lines are read by _collect_params and _params, which report what is wrong.

        One pass with no diagnostic to keep: most functions of a real program are valid."""
        plan = self.plans.get(id(spec))
        if plan is None or plan[0] is not spec:
            plan = self.plans[id(spec)] = (spec, self._plan(spec))
        steps = plan[1]
        if steps is None:
            return None
        end = last + 1 + len(steps)
        lines = recs[last + 1:end]
        if len(lines) < len(steps):
            return None
        values: dict[str, object] = {}
        out: list[ParamValue] = []
        for (param, kind, width, hi), rec in zip(steps, lines, strict=True):
            if rec.__class__ is not _Line or not rec.param:
                return None  # a blank line, a syntax error, no parameter: _collect_params
            token = rec.words[0]
            value: ParamValue | None
            # the two common kinds inline (as _valid_param reads them), the others through it
            if kind is _NUMBER and token.is_int and len(token.text) <= MAX_NUMBER_DIGITS:
                value = int(token.text)
                if (param.choices and value not in param.choices) or not (
                        param.lo <= value <= hi):
                    return None
            elif kind is _ADDRESS and not token.is_int:
                try:
                    value = parse_address_cached(token.text, False,
                                                 width or width_of(spec, param, values))
                except AddressError:
                    return None
            else:
                value = self._valid_param(spec, param, token, values)
                if value is None:
                    return None
            values[param.name] = value
            out.append(value)
        return tuple(out), end - 1

    def _plan(self, spec: InstructionSpec) -> tuple[tuple[Param, ParamKind, int, int], ...] | None:
        """For _valid_params: each fixed parameter of `spec` with its kind, its width when
        fixed (else 0) and its upper limit in this program's dialect; None for a spec with
        a TABLE parameter (left to _collect_params)."""
        fixed, table = _fixed_and_table(spec)
        if table is not None:
            return None
        return tuple((param, param.kind, param.width if isinstance(param.width, int) else 0,
                      param.highest(self.dialect)) for param in fixed)

    def _valid_param(self, spec: InstructionSpec, param: Param, token: _Token,
                     values: dict[str, object]) -> ParamValue | None:
        """What _param gives for a valid parameter; None (and nothing reported) where it
        would report."""
        reported = len(self.diagnostics)
        value = self._param(spec, param, token, 0, values, 0)
        if len(self.diagnostics) > reported:  # the slow path reads it again and reports
            del self.diagnostics[reported:]
            return None
        return value

    def _unknown_sub(self, line: _Line, number: int, sub: int | None, recs: list[_Line | _Made],
                     base: int, k: int, builder: _NetworkBuilder) -> int:
        """`SUB n` the table does not know: every following parameter line is its parameter."""
        column = line.words[1].column
        text = line.words[1].text
        make = getattr(_table, "unknown_sub", None)
        if make is None or sub is None:
            self._error("unknown-sub", number, column, number=text[:20])
            return k
        operands: list[_Token] = []
        last = self._collect_params(None, recs, k - 1, operands)
        self.diagnostics.append(Diagnostic("unknown-sub", {"number": sub}, number,
                                           column, Severity.WARNING))
        spec = make(sub, len(operands))
        instruction = self._build(spec, line, number, operands)
        if instruction is not None:
            builder.add(instruction, base + last, *_flow(spec))
        return last + 1

    def _collect_params(self, spec: InstructionSpec | None, recs: list[_Line | _Made],
                        last: int, out: list[_Token]) -> int:
        """FANUC form: take the parameters from the lines after `recs[last]`, one per line
        (blank lines and lines with a syntax error skipped), as many as `spec` takes (every
        one for None); returns the index of the last line taken (`last` for none)."""
        needed, table = _shape(spec) if spec is not None else (0, None)
        size: int | None = None
        sized = False  # the table's size is read once the fixed parameters are all taken
        count = len(recs)
        k = last + 1
        while k < count:
            line = recs[k]
            if line is _BLANK or line is _BAD:
                k += 1
                continue
            if not isinstance(line, _Line) or not line.param:
                break
            if spec is not None and len(out) >= needed:
                if table is None:
                    break
                if not sized:
                    size, sized = _table_size(spec, out), True
                if size is None or len(out) >= needed + size:
                    break
            out.append(line.words[0])
            last = k
            k += 1
        return last

    def _error(self, code: str, line: int, column: int, **args: object) -> None:
        self.diagnostics.append(Diagnostic(code, dict(args), line, column))

    def _build(self, spec: InstructionSpec, line: _Line, number: int,
               operands: list[_Token]) -> Instruction | None:
        head = line.words[0]
        comment = line.comment or ""
        if spec.kind is Kind.BASIC:
            if not spec.operand:
                if operands:
                    self._error("extra-operand", number, operands[0].column,
                                name=spec.name, text=operands[0].text[:20])
                    return None
                return Instruction(spec.name, comment=comment, line=number,
                                   column=head.column)
            if not operands:
                self._error("missing-operand", number, head.column, name=spec.name)
                return None
            if len(operands) > 1:
                self._error("extra-operand", number, operands[1].column,
                            name=spec.name, text=operands[1].text[:20])
                return None
            address = self._address(operands[0], number, want_bit=True, width=1)
            if address is None:
                return None
            return Instruction(spec.name, address, comment=comment, line=number,
                               column=head.column)
        key = (id(spec), tuple([(token.text, token.is_int) for token in operands]))
        params = self.made_params.get(key)  # real programs repeat `SUB 43` with its lines
        if params is None:
            reported = len(self.diagnostics)
            params = self._params(spec, operands, number, head.column)
            if params is None:
                return None
            if len(self.diagnostics) == reported:
                self.made_params[key] = params
        return new_instruction(spec.name, None, params, comment, (), number, head.column)

    def _address(self, token: _Token, line: int, *, want_bit: bool | None,
                 width: int) -> Address | None:
        try:
            return parse_address_cached(token.text, want_bit, width)
        except AddressError as exc:
            args = {k: (v[:20] if isinstance(v, str) and k == "text" else v)
                    for k, v in exc.args_map.items()}
            self._error(exc.code, line, token.column, **args)
            return None

    def _params(self, spec: InstructionSpec, operands: list[_Token], line: int,
                column: int) -> tuple[ParamValue, ...] | None:
        fixed, table = _fixed_and_table(spec)
        size = _table_size(spec, operands) if table else 0
        expected = len(fixed) + (size or 0)
        if len(operands) < len(fixed) or (table is None and len(operands) != len(fixed)) or (
            table is not None and size is not None and len(operands) != expected
        ):
            self._error("param-count", line, operands[-1].column if operands else column,
                        name=spec.name, expected=expected, found=len(operands))
            return None
        values: dict[str, object] = {}
        out: list[ParamValue] = []
        ok = True
        for index, (param, token) in enumerate(zip(fixed, operands, strict=False), start=1):
            value = self._param(spec, param, token, index, values, line)
            if value is None:
                ok = False
                continue
            values[param.name] = value
            out.append(value)
        if table is not None:
            for offset, token in enumerate(operands[len(fixed):]):
                index = len(fixed) + offset + 1
                number = self._number(spec, table, token, index, line)
                if number is None:
                    ok = False
                    continue
                out.append(number)
        return tuple(out) if ok else None

    def _param(self, spec: InstructionSpec, param: Param, token: _Token, index: int,
               values: dict[str, object], line: int) -> ParamValue | None:
        kind = param.kind
        if kind is ParamKind.NUMBER:
            return self._number(spec, param, token, index, line)
        if kind is ParamKind.MASK:
            if not token.is_int or not _MASK.match(token.text):
                self._error("param-mask", line, token.column, name=spec.name, index=index,
                            param=param.name, text=token.text[:20])
                return None
            return int(token.text, 2)
        if kind is ParamKind.PROGRAM or kind is ParamKind.LABEL:
            return self._reference(spec, param, token, index, line,
                                   "P" if kind is ParamKind.PROGRAM else "L")
        if kind is ParamKind.RAW:
            return self._raw(token, line)
        width = width_of(spec, param, values)
        if param.kind is ParamKind.ADDRESS or (
            param.kind is ParamKind.VALUE and not token.is_int
        ):
            if token.is_int:
                self._error("param-kind-address", line, token.column, name=spec.name,
                            index=index, param=param.name, text=token.text[:20])
                return None
            if param.kind is ParamKind.VALUE and value_is_address(spec, values) is False:
                self._error("param-kind-number", line, token.column, name=spec.name,
                            index=index, param=param.name, text=token.text[:20])
                return None
            return self._address(token, line, want_bit=False, width=width)
        # a VALUE given as a constant
        if value_is_address(spec, values) is True:
            self._error("param-kind-address", line, token.column, name=spec.name,
                        index=index, param=param.name, text=token.text[:20])
            return None
        return self._number(spec, param, token, index, line)

    def _reference(self, spec: InstructionSpec, param: Param, token: _Token, index: int,
                   line: int, letter: str) -> ProgramRef | LabelRef | None:
        match = _REF.match(token.text)
        if match is None or match.group(1).upper() != letter:
            self._error("param-kind-ref", line, token.column, name=spec.name, index=index,
                        param=param.name, text=token.text[:20], letter=letter)
            return None
        number = int(match.group(2))
        hi = param.highest(self.dialect)
        if hi and not param.lo <= number <= hi:
            self._error("param-range", line, token.column, name=spec.name, index=index,
                        param=param.name, lo=param.lo, hi=hi, value=token.text)
            return None
        return ProgramRef(number) if letter == "P" else LabelRef(number)

    def _raw(self, token: _Token, line: int) -> ParamValue | None:
        """A parameter of an unknown `SUB n`: an integer, an address, `Pn` or `Ln`."""
        if token.is_int:
            value = _small_int(token.text, MAX_NUMBER_DIGITS)
            if value is None:
                self._error("number-too-long", line, token.column, text=token.text[:20])
            return value
        match = _REF.match(token.text)
        if match is not None:
            number = int(match.group(2))
            return ProgramRef(number) if match.group(1).upper() == "P" else LabelRef(number)
        return self._address(token, line, want_bit=None, width=1)

    def _number(self, spec: InstructionSpec, param: Param, token: _Token, index: int,
                line: int) -> int | None:
        if not token.is_int:
            self._error("param-kind-number", line, token.column, name=spec.name, index=index,
                        param=param.name, text=token.text[:20])
            return None
        value = _small_int(token.text, MAX_NUMBER_DIGITS)
        hi = param.highest(self.dialect)
        if value is None:
            self._error("param-range", line, token.column, name=spec.name, index=index,
                        param=param.name, lo=param.lo, hi=hi, value=token.text[:20] + "…")
            return None
        if param.choices and value not in param.choices:
            self._error("param-choice", line, token.column, name=spec.name, index=index,
                        param=param.name, value=value,
                        choices=", ".join(str(c) for c in param.choices))
            return None
        if not param.lo <= value <= hi:
            self._error("param-range", line, token.column, name=spec.name, index=index,
                        param=param.name, lo=param.lo, hi=hi, value=value)
            return None
        return value


def _small_int(text: str, digits: int) -> int | None:
    """The integer a token spells, or None when it has more than `digits` digits."""
    body = text.lstrip("+-").lstrip("0")
    return int(text) if len(body) <= digits else None


def _is_param_line(line: _Line) -> bool:
    """A parameter line: a number, or one address-shaped word that is no instruction."""
    return line.kind == "parameter" or (
        line.kind == "instruction" and len(line.words) == 1
        and lookup(line.words[0].text) is None
        and _ADDRESS_SHAPE.match(line.words[0].text) is not None)


def _table_size(spec: InstructionSpec, operands: list[_Token]) -> int | None:
    """Number of table entries, read from the parameter that gives it (None if unknown)."""
    fixed, table = _fixed_and_table(spec)
    if table is None:
        return 0
    for index, param in enumerate(fixed):
        if param.name == table.length_of and index < len(operands):
            token = operands[index]
            if token.is_int:
                value = _small_int(token.text, MAX_NUMBER_DIGITS)
                return value if value is not None and param.lo <= value <= param.hi else None
    return None


def _fixed_and_table(spec: InstructionSpec) -> tuple[tuple[Param, ...], Param | None]:
    """A spec's fixed parameters and its TABLE parameter (found once per row)."""
    found = _SHAPES.get(id(spec))
    if found is None or found[0] is not spec:
        found = _SHAPES[id(spec)] = (spec, spec.fixed_params(), spec.table_param())
    return found[1], found[2]


def _shape(spec: InstructionSpec) -> tuple[int, Param | None]:
    """The number of fixed parameters of a spec and its TABLE parameter."""
    fixed, table = _fixed_and_table(spec)
    return len(fixed), table


# by id(spec), holding the spec (so the id is not reused while the entry lives)
_SHAPES: dict[int, tuple[InstructionSpec, tuple[Param, ...], Param | None]] = {}


def _flow(spec: InstructionSpec) -> tuple[bool, bool]:
    """Whether the instruction starts a network after an output (a READ without push, or a
    function with no control input), and whether it ends one (a coil or a function)."""
    starts = (spec.combine is Combine.READ and not spec.pushes) or (
        spec.kind is not Kind.BASIC and not spec.inputs)
    return starts, spec.writes or spec.kind is not Kind.BASIC


_NUMBER = ParamKind.NUMBER  # the kinds _valid_params reads inline, as module names
_ADDRESS = ParamKind.ADDRESS

_BLANK = _Line("blank")  # every blank line text scans to this one
_BAD = _Line("bad")  # a line text with a syntax error


class _NetworkBuilder:
    """Groups instructions into networks: a label, or an RD after an output, starts one.

    Also records which source lines each network came from (`spans()`, 0-based, end
    exclusive): from the end of the previous network to its last instruction or parameter
    line."""

    __slots__ = ("closed", "current", "cursor", "firsts", "heads", "lasts", "networks",
                 "pending", "pending_label")

    def __init__(self, start: int) -> None:
        self.networks: list[Network] = []
        self.current: list[Instruction] | None = None  # the instructions of the last network
        self.closed = False  # the current network has reached an output
        self.pending: list[str] = []
        self.pending_label = ""
        self.cursor = start  # first line index not yet in a network
        self.firsts: list[int] = []  # spans: first line index of each network
        self.lasts: list[int] = []  # spans: end of each network
        self.heads: list[int] = []

    def comment(self, text: str) -> None:
        self.pending.append(text)

    def label(self, text: str) -> None:
        if self.pending_label:  # two labels in a row: the first one labels nothing
            self.pending.append(self.pending_label + ":")
        self.pending_label = text
        self.closed = True

    def add(self, instruction: Instruction, end_line: int, starts: bool, ends: bool) -> None:
        """Add an instruction (its last line `end_line`); `starts`, `ends` are its _flow()."""
        current = self.current
        if current is None or (self.closed and (starts or self.pending_label)):
            network = Network(None, self.pending, self.pending_label)  # positional: quicker
            current = self.current = network.instructions
            self.pending = []
            self.pending_label = ""
            self.networks.append(network)
            self.firsts.append(self.cursor)
            self.lasts.append(end_line)
            self.heads.append(instruction.line - 1)
            self.closed = False
        else:
            if self.pending:
                instruction = _with_lead(instruction, self.pending)
                self.pending = []
            self.lasts[-1] = end_line
        current.append(instruction)
        self.cursor = end_line
        if ends:
            self.closed = True

    def spans(self) -> list[tuple[int, int]]:
        """The source lines of each network."""
        return list(zip(self.firsts, self.lasts, strict=True))

    def finish_pending(self) -> list[str]:
        """Comment lines after the last network (a label there is kept as its text)."""
        if self.pending_label:
            self.pending.append(self.pending_label + ":")
            self.pending_label = ""
        return self.pending


def _with_lead(instruction: Instruction, lead: list[str]) -> Instruction:
    return Instruction(instruction.name, instruction.operand, instruction.params,
                       instruction.comment, tuple(lead), instruction.line, instruction.column)


