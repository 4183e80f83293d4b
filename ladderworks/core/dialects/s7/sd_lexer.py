"""SIMATIC SD (`.s7dcl`) tokens: words, quoted names, `#` locals, pragmas, constants, symbols.

Each token keeps its 1-based line and column so every diagnostic points at the text. Comments
(`// …` to the line end, `(* … *)`) are dropped. docs/dialects.md, "SIMATIC SD".
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ladderworks.core.diagnostics import Diagnostic


@dataclass(frozen=True, slots=True)
class Token:
    """One token: kind ("word", "name" a quoted name, "local", "wire", "pragma", "number",
    "string", "op", "end"), its text and where it starts."""

    kind: str
    text: str
    line: int
    column: int


_PATTERNS = (
    ("space", r"[ \t\r\f\v\ufeff]+"),
    ("newline", r"\n"),
    ("comment", r"//[^\n]*|\(\*.*?\*\)"),
    ("pragma", r"\{[^{}]*\}"),
    ("wire", r"wire#[A-Za-z_0-9]+"),
    ("local", r'#(?:"(?:[^"\n]|"")*"|[^\s()=:;,.{}"\[\]]+)'),
    ("name", r'"(?:[^"\n]|"")*"'),
    ("string", r"'(?:[^'\n]|'')*'"),
    ("number", r"[A-Za-z_0-9]+#[-+]?[0-9A-Za-z_.:]+(?:#[0-9A-Fa-f_]+)?"
               r"|[+-]?[0-9][0-9_]*(?:\.[0-9_]+)?(?:[eE][+-]?[0-9]+)?"),
    ("absolute", r"%[A-Za-z]+[0-9]+(?:\.[A-Za-z]*[0-9]+)*(?:\.[0-9]+)?"),
    ("op", r":=|=>|<>|>=|<=|==|[()=:;,.<>\[\]+*/-]"),
    ("word", r"[A-Za-z_][A-Za-z_0-9]*"),
)
_TOKEN_RE = re.compile("|".join(f"(?P<{name}>{pattern})" for name, pattern in _PATTERNS), re.S)


class LexError(Exception):
    """A character no token starts with, or a comment or pragma never closed."""

    def __init__(self, diagnostic: Diagnostic) -> None:
        super().__init__(diagnostic.message())
        self.diagnostic = diagnostic


def tokens(text: str) -> list[Token]:
    """Every token of an SD text, then an "end" token; LexError at the first bad character."""
    found: list[Token] = []
    line, line_start, position = 1, 0, 0
    while position < len(text):
        match = _TOKEN_RE.match(text, position)
        column = position - line_start + 1
        if match is None:
            what = "a pragma" if text[position] == "{" else "a comment" \
                if text.startswith("(*", position) else "a quoted name" \
                if text[position] in "\"'" else ""
            if what:
                raise LexError(Diagnostic("s7-cut", {"what": what}, line, column))
            raise LexError(Diagnostic("s7-syntax", {"expected": "a token",
                                                    "found": text[position]}, line, column))
        kind = match.lastgroup or ""
        value = match.group()
        if kind not in ("space", "newline", "comment"):
            found.append(Token(kind, value, line, column))
        newlines = value.count("\n")
        if newlines:
            line += newlines
            line_start = match.start() + value.rindex("\n") + 1
        position = match.end()
    found.append(Token("end", "", line, position - line_start + 1))
    return found


def pragma_items(text: str) -> dict[str, str]:
    """`{ S7_Language := "LAD"; S7_NetworkTitle := "MLC_1" }` as {key: value without quotes}."""
    items: dict[str, str] = {}
    for part in re.split(r";(?=(?:[^\"]*\"[^\"]*\")*[^\"]*$)", text.strip()[1:-1]):
        key, sep, value = part.partition(":=")
        if sep:
            items[key.strip()] = value.strip().strip('"')
    return items


def templates(text: str) -> dict[str, str]:
    """`S7_Templates`' value `"SrcType := Int"` or `"[ inType := Int, outType := Real ]"`."""
    found: dict[str, str] = {}
    for part in re.split(r"[;,]", text.strip().strip("[]")):
        key, sep, value = part.partition(":=")
        if sep:
            found[key.strip()] = value.strip()
    return found
