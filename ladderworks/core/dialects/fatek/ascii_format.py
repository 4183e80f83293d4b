"""FUN 94 ASCWR's ASCII file format (seed 004): parse a format text, render it from memory."""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il.textform import split_lines

LINE_FEED = "\n"
PAGE_FEED = "\f"
MAX_REPEAT = 999  # 004:69: M is 1 to 999


@dataclass(frozen=True, slots=True)
class Text:
    """Background data: `text` sent `repeat` times (`'…'`, `MX'…'`, `MX` hex codes, `MX` blanks)."""

    text: str
    repeat: int = 1


@dataclass(frozen=True, slots=True)
class Feed:
    """`/` (line feed) or `\\` (page feed), `count` in a row."""

    char: str
    count: int = 1


@dataclass(frozen=True, slots=True)
class Variable:
    """`"w.dRn F"`: the register's value in `width` columns, `decimals` after the point."""

    width: int
    decimals: int
    register: str  # R, D, WX, WY … (16 bits) or DR, DD, DWX, DWY … (32 bits)
    number: int
    code: str = "D"  # H hexadecimal, D decimal, B binary

    @property
    def double(self) -> bool:
        """True for a 32-bit register (DR, DD, DWX …)."""
        return len(self.register) > 1 and self.register[0] == "D" and self.register != "D"

    @property
    def name(self) -> str:
        """The register as written: `R0`, `DR10`."""
        return f"{self.register}{self.number}"


Item = Text | Feed | Variable


@dataclass(slots=True)
class AsciiFormat:
    """A parsed ASCII file: its items in order, and whether END closed it."""

    items: list[Item]
    ended: bool = True


# 16-bit registers the seed names (004:137) and Fatek's other word registers; each with a
# leading D is the 32-bit pair (DR, DD, DWX, DWY …).
WORD_REGISTERS = ("R", "D", "WX", "WY", "WM", "WS", "T", "C")
_REGISTER = "|".join(sorted({*WORD_REGISTERS, *("D" + r for r in WORD_REGISTERS)},
                            key=len, reverse=True))
_VARIABLE_RE = re.compile(rf"^(\d+)(?:\.(\d+))?({_REGISTER})(\d+)([HDB]?)$")
_REPEAT_RE = re.compile(r"^(\d{1,4})X(.*)$", re.S)
_HEX_RE = re.compile(r"^(?:[0-9A-Fa-f]{2})+$")
_END_RE = re.compile(r"END(?![^\s,/\\])", re.I)


class _Reader:
    """Walks the format text, keeping the line of each position for diagnostics."""

    def __init__(self, text: str, first_line: int) -> None:
        self.text = text
        self.pos = 0
        self.first_line = first_line
        self.diagnostics: list[Diagnostic] = []
        self.unclosed = False  # a quote runs to the end: nothing after it can be read

    def line_at(self, pos: int) -> int:
        """The line of position `pos`."""
        return self.first_line + self.text.count("\n", 0, pos)

    def column_at(self, pos: int) -> int:
        """The 1-based column of position `pos`."""
        return pos - (self.text.rfind("\n", 0, pos) + 1) + 1

    def error(self, pos: int, code: str, **args: object) -> None:
        """Report `code` at position `pos`."""
        self.diagnostics.append(Diagnostic(code, dict(args), self.line_at(pos),
                                           self.column_at(pos)))


def _quoted(reader: _Reader, quote: str) -> str | None:
    """The text between `quote`s from reader.pos (at the opening quote); a doubled `'` is one
    quote; a line break inside is the page's wrap and is dropped (004:228-234)."""
    text = reader.text
    start = reader.pos
    pos = start + 1
    out: list[str] = []
    while pos < len(text):
        char = text[pos]
        if char == quote:
            if quote == "'" and text.startswith("''", pos):
                out.append("'")
                pos += 2
                continue
            reader.pos = pos + 1
            return "".join(out)
        if char not in "\r\n":
            out.append(char)
        pos += 1
    reader.error(start, "fatek-ascii-quote", quote=quote)
    reader.pos = len(text)
    reader.unclosed = True
    return None


def _raw_item(reader: _Reader) -> tuple[str, int, list[tuple[str, int]]]:
    """The characters of one item up to the next `,` `/` `\\` outside quotes, blanks dropped;
    with the quoted parts found in it (their text, their position)."""
    text = reader.text
    start = reader.pos
    plain: list[str] = []
    quoted: list[tuple[str, int]] = []
    while reader.pos < len(text):
        char = text[reader.pos]
        if char in ",/\\":
            break
        if char in "'\"":
            at = reader.pos
            inner = _quoted(reader, char)
            if inner is None:
                break
            plain.append(char)  # a marker where the quoted part sits
            quoted.append((inner, at))
            continue
        if not char.isspace():
            plain.append(char)
        reader.pos += 1
    return "".join(plain), start, quoted


def _item(reader: _Reader, raw: str, start: int, quoted: list[tuple[str, int]]) -> Item | None:
    """One item from its blank-free text (quotes marked by their quote character)."""
    if raw == "'" and len(quoted) == 1:
        return Text(quoted[0][0])
    if raw == '"' and len(quoted) == 1:
        return _variable(reader, quoted[0][0], quoted[0][1])
    repeat = _REPEAT_RE.match(raw)
    if repeat is not None:
        count = int(repeat.group(1))
        rest = repeat.group(2)
        if not 1 <= count <= MAX_REPEAT:
            reader.error(start, "fatek-ascii-repeat", count=count)
            return None
        if rest == "":
            return Text(" ", count)  # 004:82-85: MX with nothing after X sends M blanks
        if rest == "'" and len(quoted) == 1:
            return Text(quoted[0][0], count)
        if _HEX_RE.match(rest):
            return Text(bytes.fromhex(rest).decode("latin-1"), count)
        reader.error(start, "fatek-ascii-item", text=_shown(reader, start))
        return None
    if _HEX_RE.match(raw):  # hex codes sent once: MX may be left out (004:85)
        return Text(bytes.fromhex(raw).decode("latin-1"))
    reader.error(start, "fatek-ascii-item", text=_shown(reader, start))
    return None


def _shown(reader: _Reader, start: int) -> str:
    """The item's text as written, for a message (one line, at most 30 characters)."""
    text = split_lines(reader.text[start:reader.pos].strip())
    first = text[0] if text else ""
    return first if len(first) <= 30 else first[:29] + "…"


def _variable(reader: _Reader, inner: str, at: int) -> Variable | None:
    spec = "".join(inner.split())  # `" 10.2R6"` (004:234): blanks inside are not part of it
    match = _VARIABLE_RE.match(spec.upper())
    if match is None:
        reader.error(at, "fatek-ascii-variable", text=inner)
        return None
    width = int(match.group(1))
    decimals = int(match.group(2) or 0)
    if width < 1 or decimals >= width:
        reader.error(at, "fatek-ascii-variable", text=inner)
        return None
    return Variable(width, decimals, match.group(3), int(match.group(4)), match.group(5) or "D")


def parse_format(text: str, first_line: int = 1) -> tuple[AsciiFormat, list[Diagnostic]]:
    """The items of an ASCII file's text, and a diagnostic at the line of each malformed part."""
    reader = _Reader(text, first_line)
    items: list[Item] = []
    ended = False
    while reader.pos < len(text):
        char = text[reader.pos]
        if char.isspace() or char == ",":
            reader.pos += 1
            continue
        if char in "/\\":
            count = 0
            while reader.pos < len(text) and text[reader.pos] == char:
                count += 1
                reader.pos += 1
            items.append(Feed(LINE_FEED if char == "/" else PAGE_FEED, count))
            continue
        if _END_RE.match(text, reader.pos):
            ended = True
            after = reader.pos + 3
            rest = text[after:].strip()
            if rest:
                reader.error(after + text[after:].index(rest[0]), "fatek-ascii-after-end",
                             text=split_lines(rest)[0][:30])
            break
        raw, start, quoted = _raw_item(reader)
        if reader.unclosed:
            return AsciiFormat(items, False), reader.diagnostics
        item = _item(reader, raw, start, quoted)
        if item is not None:
            items.append(item)
    if not ended:
        reader.error(len(text), "fatek-ascii-no-end")
    return AsciiFormat(items, ended), reader.diagnostics


Memory = Callable[[Variable], int]  # the signed value of a variable's register


def format_value(variable: Variable, value: int) -> str:
    """The value as seed 004 prints it: right-justified in `width` columns, the high digits (and
    the sign) dropped when it is wider (004:142-165); H and B print the unsigned bit pattern."""
    bits = 32 if variable.double else 16
    if variable.code == "D":
        digits = str(abs(value)).rjust(variable.decimals + 1, "0")
        if variable.decimals:
            digits = digits[:-variable.decimals] + "." + digits[-variable.decimals:]
        text = ("-" if value < 0 else "") + digits
    else:
        unsigned = value & ((1 << bits) - 1)
        text = format(unsigned, "X" if variable.code == "H" else "b")
    return text[-variable.width:].rjust(variable.width)


def render(fmt: AsciiFormat, memory: Memory) -> str:
    """The text the format sends: feeds as `\\n` / `\\f`, each variable read when reached."""
    out: list[str] = []
    for item in fmt.items:
        if isinstance(item, Text):
            out.append(item.text * item.repeat)
        elif isinstance(item, Feed):
            out.append(item.char * item.count)
        else:
            out.append(format_value(item, memory(item)))
    return "".join(out)
