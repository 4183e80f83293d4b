"""The ladder section's line scanner: what one line text is (an instruction, a parameter, a
label, a comment), by a fast scanner for the common shapes and the lark grammar for the rest."""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache, lru_cache
from itertools import compress, count, repeat
from operator import is_
from typing import TYPE_CHECKING

from ladderworks.core.address import (
    Address,
    AddressError,
    parse_address_cached,
    parse_plain_addresses,
)
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il.program import ParamValue
from ladderworks.core.instructions import Combine, InstructionSpec, Kind, lookup

if TYPE_CHECKING:
    import lark

LABEL = re.compile(r"^[ \t]*([Nn][0-9]+):[ \t]*$")
_SAFE = re.compile(r"[A-Za-z0-9_.+\- \t]*")  # code the fast scanner splits at spaces/tabs
ADDRESS_SHAPE = re.compile(r"^[A-Za-z]\d+(\.\d+)?$")
# a name and one operand that starts with a letter, nothing else: what scan_fast reads as
# two words (no sign, no comment)
_SIMPLE = re.compile(r"[ \t]*([A-Za-z_][A-Za-z0-9_.]*)[ \t]+([A-Za-z][A-Za-z0-9_.]*)[ \t]*")


@lru_cache(maxsize=1)
def line_parser() -> lark.Lark:
    """The lark parser for one line, loaded once from grammar.lark (lark is imported only
    when a line needs it: the fast scanner reads the common lines, and `check` starts faster)."""
    from importlib import resources

    import lark

    grammar = resources.files("ladderworks.core.il").joinpath("grammar.lark").read_text("utf-8")
    return lark.Lark(grammar, start="line", parser="lalr", maybe_placeholders=False)


@dataclass(slots=True)
class Token:
    text: str
    column: int
    is_int: bool


# What one line text makes on its own, found once per distinct text: the instruction's spec,
# name, operand, parameters, comment and column, whether it starts a network after an output,
# and whether it ends one (see NetworkBuilder.add).
Made = tuple[InstructionSpec, str, Address | None, tuple[ParamValue, ...], str, int, bool, bool]


class Line:
    """One scanned line text of the ladder section; the lines that repeat the text share it.

    `made` is set once the text alone has made an instruction with no diagnostic; such a
    line is read from it alone (a `RD X21.7` found by the fast scanner keeps no words)."""

    __slots__ = ("comment", "function", "kind", "made", "param", "words")

    def __init__(self, kind: str, words: list[Token] | None = None,
                 comment: str | None = None, made: Made | None = None) -> None:
        self.kind = kind  # "blank", "comment", "instruction", "parameter", "label"
        self.words: list[Token] = words if words is not None else []
        self.comment = comment
        self.made = made
        self.param = made is None and is_param_line(self)  # a parameter line
        # the function whose parameters follow on the next lines (`SUB 43`, `MOVB`), once
        # the text was read so with no diagnostic
        self.function: InstructionSpec | None = None


def comment_text(raw: str) -> str:
    """Comment body after its marker (`//`, `;` or `,`), right-stripped."""
    body = raw[2:] if raw.startswith("//") else raw[1:]
    return body.rstrip()


@cache
def _basic_with_operand(name: str) -> tuple[InstructionSpec, bool, bool] | None:
    """The basic instruction a name spells, when it takes an address operand, with its
    flow(); None for any other name."""
    spec = lookup(name)
    if spec is None or spec.kind is not Kind.BASIC or not spec.operand:
        return None
    return (spec, *flow(spec))


def scan_fast(text: str) -> Line | Made | None:
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
        return Line("instruction", [Token(head, simple.start(1) + 1, False),
                                     Token(operand, simple.start(2) + 1, False)])
    stripped = text.lstrip(" \t")
    if not stripped:
        return BLANK
    first = stripped[0]
    if first == ";" or stripped.startswith("//"):
        return Line("comment", comment=comment_text(stripped))
    if first == ",":
        return Line("comment", comment=comment_text(stripped.strip()))
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
        label = LABEL.match(text)
        return Line("label", [Token(label.group(1), 1, False)]) if label else None
    words: list[Token] = []
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
        words.append(Token(word, position + 1, is_int))
        position += len(word)
    if not words:
        return None
    comment = comment_text(text[cut:]).strip() if cut < len(text) else None
    if words[0].is_int:
        if len(words) > 1:
            return None
        return Line("parameter", words, comment)
    return Line("instruction", words, comment)


# one line text a line of the joined texts: the most common shape, `RD  X21.7` (a name at the
# line's start and a plain bit address); a parameter line `R100` or `0001`; a label `N00012:`;
# or any other line (every group empty)
_COMMON = re.compile(
    r"([A-Za-z_][A-Za-z0-9_.]*)[ \t]+([XYFGRADTCKE][0-9]{1,6}\.[0-7])[ \t]*\n"
    r"|(?:([A-Za-z][0-9]+)|([0-9]+)|([Nn][0-9]+):)[ \t]*\n|[^\n]*\n")


@cache
def _basic_made(name: str) -> tuple[InstructionSpec, str, bool, bool] | None:
    """What scan_fast takes from a basic instruction's name (its spec, name and flow())."""
    basic = _basic_with_operand(name)
    return None if basic is None else (basic[0], basic[0].name, basic[1], basic[2])


def scan_common(texts: list[str]) -> list[Line | Made | None]:
    """What scan_fast makes of each text of the common shapes, found for all the texts at
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
    made: list[Line | Made | None] = [
        None if basic is None or (address := address_of(operand)) is None
        else (basic[0], basic[1], address, (), "", 1, basic[2], basic[3])
        for basic, operand in zip(map(_basic_made, names), operands, strict=True)]
    for index in compress(count(), map(is_, made, repeat(None))):
        if words[index]:  # `R100`: a word with no sign and no comment, at column 1
            made[index] = Line("instruction", [Token(words[index], 1, False)])
        elif numbers[index]:  # `0001`
            made[index] = Line("parameter", [Token(numbers[index], 1, True)])
        elif labels[index]:  # `N00012:`
            made[index] = Line("label", [Token(labels[index], 1, False)])
    return made


def scan_line(text: str, number: int) -> Line | Made | Diagnostic:
    """One line text of the ladder section (at line `number`, for a syntax error): the fast
    scanner, else the lark grammar."""
    fast = scan_fast(text)
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
        return BLANK
    if kind == "comma_comment_line":
        return Line("comment", comment=comment_text(str(tree.children[0]).strip()))
    if kind == "comment_line":
        raw = str(_branch(tree.children[0]).children[0])
        return Line("comment", comment=comment_text(raw))
    if kind == "label_line":
        tok = _leaf(tree.children[0])
        return Line("label", [Token(str(tok)[:-1], _column(tok), False)])
    statement = _branch(tree.children[0])
    comment: str | None = None
    if len(tree.children) > 1:
        comment = comment_text(str(_branch(tree.children[1]).children[0])).strip()
    if statement.data == "parameter_line":
        tok = _leaf(statement.children[0])
        return Line("parameter", [Token(str(tok), _column(tok), True)], comment)
    name = _leaf(statement.children[0])
    words = [Token(str(name), _column(name), False)]
    for child in statement.children[1:]:
        operand = _branch(child)
        tok = _leaf(operand.children[0])
        words.append(Token(str(tok), _column(tok), operand.data == "int_operand"))
    return Line("instruction", words, comment)


def syntax_error(text: str, number: int) -> Diagnostic:
    """The syntax error of a line text scan_line found one in, at line `number`."""
    item = scan_line(text, number)
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


def is_param_line(line: Line) -> bool:
    """A parameter line: a number, or one address-shaped word that is no instruction."""
    return line.kind == "parameter" or (
        line.kind == "instruction" and len(line.words) == 1
        and lookup(line.words[0].text) is None
        and ADDRESS_SHAPE.match(line.words[0].text) is not None)


def flow(spec: InstructionSpec) -> tuple[bool, bool]:
    """Whether the instruction starts a network after an output (a READ without push, or a
    function with no control input), and whether it ends one (a coil or a function)."""
    starts = (spec.combine is Combine.READ and not spec.pushes) or (
        spec.kind is not Kind.BASIC and not spec.inputs)
    return starts, spec.writes or spec.kind is not Kind.BASIC


BLANK = Line("blank")  # every blank line text scans to this one
BAD = Line("bad")  # a line text with a syntax error
