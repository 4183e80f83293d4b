"""A global DB's source (TIA's "Generate source from blocks", `.db`): the BEGIN section's start
values, read for sd_parser.py.

The form (public sources): `DATA_BLOCK "Name" { S7_Optimized_Access := 'TRUE' } VERSION : 0.1
NON_RETAIN STRUCT … END_STRUCT; BEGIN Count := 3; Data.Speed := 1.5; Arr[2] := 7;
END_DATA_BLOCK` (or `VAR … END_VAR` for the members; an instance DB names its FB on a line of
its own). Each `path := value;` is one actual start value (`Block.starts`): the value a cold
start puts there. docs/dialects.md, "S7-1200: global DB sources".
"""

from __future__ import annotations

from typing import Protocol

from ladderworks.core.dialects.s7.graph import Block
from ladderworks.core.dialects.s7.sd_lexer import Token


class _Tokens(Protocol):
    """What the BEGIN reader needs of the SD parser."""

    @property
    def tok(self) -> Token: ...

    def next(self) -> Token: ...

    def op(self, *ops: str) -> bool: ...

    def word(self, *words: str) -> bool: ...

    def fail(self, expected: str, inside: str = "") -> Exception: ...


def _unquote(text: str) -> str:
    if len(text) >= 2 and text[0] == text[-1] == '"':
        return text[1:-1].replace('""', '"')
    return text.lstrip("#")


def begin_values(parser: _Tokens, block: Block, end: str) -> None:
    """`path := value;` lines up to `end` (END_DATA_BLOCK) into `block.starts`."""
    inside = f"the start values of {block.name}"
    while not parser.word(end):
        kind, text = parser.tok.kind, parser.tok.text
        if kind == "end":
            raise parser.fail(end, inside)
        if kind not in ("word", "name", "local"):
            raise parser.fail("a member's name", inside)
        path: list[str] = []
        current = _unquote(text)
        parser.next()
        while True:
            if parser.op("["):
                parser.next()
                index = ""
                while not parser.op("]"):
                    if parser.tok.kind == "end":
                        raise parser.fail("']'", inside)
                    index += parser.next().text
                parser.next()
                current += f"[{index}]"
            elif parser.op("."):
                parser.next()
                name = parser.next()
                if name.kind not in ("word", "name"):
                    raise parser.fail("a member's name", inside)
                path.append(current)
                current = _unquote(name.text)
            else:
                break
        path.append(current)
        if not parser.op(":="):
            raise parser.fail("':='", inside)
        parser.next()
        value: list[str] = []
        while not parser.op(";"):
            if parser.tok.kind == "end" or parser.word(end):
                raise parser.fail("';'", inside)
            value.append(parser.next().text)
        parser.next()
        block.starts[tuple(p.lower() for p in path)] = "".join(value)
