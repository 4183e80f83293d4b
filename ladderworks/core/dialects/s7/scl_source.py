"""SCL sources (TIA's "Generate source from blocks", `.scl`): the blocks' heads and interfaces
are read as the SD reader reads a `.db` source; a code block's `BEGIN … END_FUNCTION` body is
kept as one SCL network, shown and not simulated (docs/dialects.md, "Real exports tried").
"""

from __future__ import annotations

import re
import textwrap

from ladderworks.core.dialects.s7.graph import S7Network
from ladderworks.core.dialects.s7.sd_parser import Parsed, parse_sources

_HEAD = re.compile(r"^\s*(FUNCTION_BLOCK|FUNCTION|ORGANIZATION_BLOCK|DATA_BLOCK|TYPE)\b", re.I)
_BEGIN = re.compile(r"^\s*BEGIN\s*$", re.I)
_END = re.compile(r"^\s*END_(FUNCTION_BLOCK|FUNCTION|ORGANIZATION_BLOCK)\b", re.I)
_AT = re.compile(r'^(\s*"?[\w]+"?)\s+AT\s+"?[\w]+"?\s*:', re.I)  # `Bits AT Value : Word;`
CODE = ("OB", "FC", "FB")


def split(text: str) -> tuple[str, list[tuple[str, int, int]]]:
    """The text with each code block's SCL body blanked (lines kept, so diagnostics keep their
    lines) and an `AT` overlay read as a variable of its own [LW]; the bodies with their first
    and last 1-based lines."""
    lines = text.split("\n")
    bodies: list[tuple[str, int, int]] = []
    code = False
    begin: int | None = None
    for index, line in enumerate(lines):
        if begin is not None:
            if _END.match(line):
                body = textwrap.dedent("\n".join(lines[begin + 1:index])).strip("\n")
                bodies.append((body, begin + 2, index))
                for blank in range(begin, index):
                    lines[blank] = ""
                begin = None
            continue
        head = _HEAD.match(line)
        if head is not None:
            code = head.group(1).upper() not in ("DATA_BLOCK", "TYPE")
        elif code and _BEGIN.match(line):
            begin = index
        elif _AT.match(line):
            lines[index] = _AT.sub(r"\1 :", line)
    return "\n".join(lines), bodies


def parse_scl(text: str) -> list[Parsed]:
    """Every block of an SCL (or `.db`/`.udt`) source; ParseError at the first that cannot be
    read. A code block gets its body as an SCL network."""
    blanked, bodies = split(text)
    found = parse_sources(blanked)
    code = [parsed for parsed in found if parsed.block.kind in CODE]
    for parsed, (body, first, last) in zip(code, bodies, strict=False):
        parsed.block.language = "SCL"
        parsed.block.networks.append(S7Network(language="SCL", source=body, line=first,
                                               end_line=last))
    return found
