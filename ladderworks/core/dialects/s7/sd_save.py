"""Save a changed SIMATIC SD block: the original text kept, only changed networks rewritten.

Each network of the file is a region: its pragma (`{ S7_Language …; S7_NetworkTitle … }`),
`NETWORK` … `END_NETWORK` and the lines after it up to the next region. The block's current
networks name the region they came from by their `line`/`end_line` (as read); an unchanged one
is its region verbatim, a changed one keeps its pragma (its title's text id) and gets a fresh
body (sd_writer.py), a new one (`line` 0) is written whole, a region no network names is
dropped. Everything else — the head, the interface, BOM, encoding, line ends — is kept byte
for byte. docs/dialects.md, "S7-1200: saving a changed block".
"""

from __future__ import annotations

from collections.abc import Collection

from ladderworks.core.dialects.s7.graph import Block, S7Network
from ladderworks.core.dialects.s7.sd_parser import ParseError, parse_sd
from ladderworks.core.dialects.s7.sd_writer import STEP, Unwritable, body_lines, network_lines
from ladderworks.core.il.textform import decode_lines, encode_text


class SaveRefused(ValueError):
    """The block cannot be written in its file's form; `code` and `args` make its diagnostic."""

    def __init__(self, code: str, args: dict[str, object] | None = None) -> None:
        super().__init__(code)
        self.code = code
        self.args_ = dict(args or {})


def _pragma_start(lines: list[str], network_line: int, floor: int) -> int:
    """The first line (0-based) of the pragma just before the NETWORK line, else that line."""
    index = network_line - 1
    while index > floor and not lines[index].strip():
        index -= 1
    if index <= floor - 1 or not lines[index].rstrip().endswith("}"):
        return network_line
    start = index
    while start >= floor and "{" not in lines[start]:
        start -= 1
    return start if start >= floor else network_line


def _indent(lines: list[str], index: int) -> tuple[str, str]:
    """The NETWORK line's indentation and the step of the lines inside it."""
    line = lines[index]
    pad = line[:len(line) - len(line.lstrip())]
    for inner in lines[index + 1:index + 4]:
        if inner.strip():
            step = inner[:len(inner) - len(inner.lstrip())]
            if step.startswith(pad) and len(step) > len(pad):
                return pad, step[len(pad):]
            break
    return pad, STEP


def save_sd(original: bytes, block: Block, changed: Collection[int],
            others: list[Block] | None = None) -> bytes:
    """The SD file's bytes with `block`'s networks at `changed` (indexes into block.networks)
    rewritten (`others`, the program's blocks, spell the calls' parameters); SaveRefused when
    the original does not parse or a network cannot be written."""
    text, form, _problems, (lines, ends) = decode_lines(original)
    try:
        read = parse_sd(text).block
    except ParseError as error:
        raise SaveRefused("s7-save-unreadable", {"line": error.diagnostic.line}) from None
    keyword_end = _block_end(lines)
    starts: list[int] = []
    floor = 0
    for network in read.networks:
        start = _pragma_start(lines, network.line - 1, floor)
        starts.append(start)
        floor = network.end_line
    regions: dict[tuple[int, int], tuple[int, int, int]] = {}  # (line, end) → start, net, stop
    for k, network in enumerate(read.networks):
        stop = starts[k + 1] if k + 1 < len(starts) else keyword_end
        regions[(network.line, network.end_line)] = (starts[k], network.line - 1, stop)
    first = starts[0] if starts else keyword_end
    pad, step = _indent(lines, read.networks[0].line - 1) if read.networks else (STEP, STEP)
    out: list[str] = [lines[i] + ends[i] for i in range(first)]
    newline = form.newline
    for index, network in enumerate(block.networks):
        region = regions.get((network.line, network.end_line)) if network.line else None
        if region is not None and index not in changed:
            out += [lines[i] + ends[i] for i in range(region[0], region[2])]
            continue
        fresh = _fresh(network, region is not None, pad, step, others)
        if region is not None:
            start, net, stop = region
            out += [lines[i] + ends[i] for i in range(start, net)]
            out += [line + newline for line in fresh]
            after = net + (network.end_line - network.line) + 1
            out += [lines[i] + ends[i] for i in range(after, stop)]
        else:
            out += [line + newline for line in fresh]
    out += [lines[i] + ends[i] for i in range(keyword_end, len(lines))]
    return encode_text("".join(out), form)


def _restep(line: str, step: str) -> str:
    """A writer's line (four-space steps) in the file's own step."""
    body = line.lstrip(" ")
    return step * ((len(line) - len(body)) // len(STEP)) + body


def _fresh(network: S7Network, body_only: bool, pad: str, step: str,
           others: list[Block] | None) -> list[str]:
    try:
        if body_only:
            inner = [STEP + line for line in body_lines(network, others)]
            lines = ["NETWORK", *inner, "END_NETWORK"]
        else:
            lines = network_lines(network, "", others)
    except Unwritable as error:
        raise SaveRefused("s7-save-unwritable", {"part": str(error)}) from None
    return [pad + _restep(line, step) for line in lines]


def _block_end(lines: list[str]) -> int:
    """The line (0-based) of the block's closing keyword, else the end of the text."""
    for index in range(len(lines) - 1, -1, -1):
        if lines[index].strip().upper().startswith(("END_ORGANIZATION_BLOCK", "END_FUNCTION",
                                                    "END_DATA_BLOCK")):
            return index
    return len(lines)
