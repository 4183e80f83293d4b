"""Save a changed SimaticML block: the document kept, only changed networks' FlgNets replaced.

The block's current networks name the `SW.Blocks.CompileUnit` they were read from by `line`
(xml_reader sets it to the unit's line). An unchanged network's unit is kept verbatim; a changed
one keeps its unit (IDs, titles, comments) and gets a fresh `FlgNet` in the namespace (and so
the engineering version) its old one had; a new one (`line` 0) is a new unit with document IDs
past the largest; a unit no network names is removed. The interface, attributes, texts, BOM,
encoding and line ends are kept. docs/dialects.md, "S7-1200: saving a changed block".
"""

from __future__ import annotations

import html
import re
from collections.abc import Collection
from xml.sax.saxutils import escape

from ladderworks.core.dialects.s7.graph import Block, S7Network
from ladderworks.core.dialects.s7.sd_save import SaveRefused
from ladderworks.core.dialects.s7.texts import PREFERRED
from ladderworks.core.dialects.s7.xml_forms import namespace
from ladderworks.core.dialects.s7.xml_reader import read_document
from ladderworks.core.dialects.s7.xml_writer import flgnet_lines, unit_lines
from ladderworks.core.il.textform import decode_lines, encode_text

_UNIT = re.compile(r"<SW\.Blocks\.CompileUnit\b.*?</SW\.Blocks\.CompileUnit\s*>", re.S)
_FLGNET = re.compile(r"<FlgNet\b[^>]*?xmlns=\"([^\"]*)\"[^>]*>.*?</FlgNet\s*>", re.S)
_EMPTY_SOURCE = re.compile(r"<NetworkSource\s*/>|<NetworkSource>\s*</NetworkSource>")
_LANGUAGE = re.compile(r"(<ProgrammingLanguage>)(F_)?FBD(</ProgrammingLanguage>)")
_ID = re.compile(r"\bID=\"([0-9A-Fa-f]+)\"")
_INTERFACE = re.compile(r"http://www\.siemens\.com/automation/Openness/SW/Interface(/v\d+)?\"")
_FLG = "http://www.siemens.com/automation/Openness/SW/NetworkSource/FlgNet"


def _line_of(text: str, offset: int) -> int:
    return text.count("\n", 0, offset) + 1


def _version(uri: str) -> int:
    found = namespace(uri)
    return found[1] if found is not None else 5


def save_xml(original: bytes, block: Block, changed: Collection[int],
             others: list[Block] | None = None) -> bytes:
    """The document's bytes with `block`'s networks at `changed` written afresh; SaveRefused
    when the document does not read or `block` is not in it."""
    text, form, _problems, _lines = decode_lines(original)
    read = read_document(original)
    if any(d.severity.name == "ERROR" for d in read.diagnostics) or not read.blocks:
        raise SaveRefused("s7-save-unreadable", {"line": 0})
    names = [b.name.lower() for b in read.blocks]
    if block.name.lower() not in names:
        raise SaveRefused("s7-save-unreadable", {"line": 0})
    units = list(_UNIT.finditer(text))
    by_line = {_line_of(text, m.start()): m for m in units}
    mine = [u for u in (by_line.get(n.line) for n in read.blocks[names.index(
        block.name.lower())].networks) if u is not None]
    if not mine and not block.networks:
        return original
    uri = next((m.group(1) for m in _FLGNET.finditer(text)), "")
    interface = _INTERFACE.search(text)
    default = uri or (_FLG + (interface.group(1) or "") if interface is not None else "")
    newline = form.newline
    next_id = max((int(m.group(1), 16) for m in _ID.finditer(text)), default=0) + 1
    pad = _pad(text, mine[0].start()) if mine else _pad(text, _anchor(text))
    # per current network: (the old unit it came from or None, its text)
    pieces: list[tuple[re.Match[str] | None, str]] = []
    for index, network in enumerate(block.networks):
        unit = by_line.get(network.line) if network.line else None
        if unit is not None and index not in changed:
            pieces.append((unit, unit.group()))
            continue
        if network.language.upper() not in ("LAD", "FBD"):
            raise SaveRefused("s7-save-unwritable", {"part": network.language})
        if unit is not None:
            pieces.append((unit, _replaced(unit.group(), network, default, newline, others)))
        else:
            lines, next_id = unit_lines(network, _version(default), next_id, others)
            if default:
                lines = [re.sub(r'xmlns="[^"]*"', f'xmlns="{default}"', line, count=1)
                         if "<FlgNet" in line else line for line in lines]
            pieces.append((None, (newline + pad).join(lines)))
    return encode_text(_splice(text, mine, pieces, newline + pad), form)


def _replaced(unit: str, network: S7Network, default: str, newline: str,
              others: list[Block] | None) -> str:
    """A CompileUnit's text with its FlgNet (or empty NetworkSource) replaced."""
    found = _FLGNET.search(unit)
    uri = found.group(1) if found is not None else default
    lines = flgnet_lines(network, _version(uri), others)
    lines[0] = re.sub(r'xmlns="[^"]*"', f'xmlns="{uri}"', lines[0], count=1)
    pad = ""
    if found is not None:  # the old FlgNet's children: at column 0 (TIA) or indented under it
        inner = found.group().split("\n", 2)
        if len(inner) > 1:
            lead = inner[1][:len(inner[1]) - len(inner[1].lstrip())]
            pad = lead[:-2] if len(lead) > 2 else ""
    fresh = newline.join([lines[0], *(pad + line for line in lines[1:])])
    if found is not None:
        unit = unit[:found.start()] + fresh + unit[found.end():]
    else:
        empty = _EMPTY_SOURCE.search(unit)
        if empty is None:
            raise SaveRefused("s7-save-unwritable", {"part": network.language})
        unit = unit[:empty.start()] + f"<NetworkSource>{fresh}</NetworkSource>" + \
            unit[empty.end():]
    unit = _with_text(unit, "Title", network.title)
    unit = _with_text(unit, "Comment", network.comment)
    return _LANGUAGE.sub(r"\1LAD\3", unit, count=1)


_TEXT_BLOCK = r'<MultilingualText\b[^>]*CompositionName="{kind}"[^>]*>.*?</MultilingualText\s*>'
_ITEM = re.compile(r"<Culture>([^<]*)</Culture>\s*<Text>([^<]*)</Text>|"
                   r"<Culture>([^<]*)</Culture>\s*<Text\s*/>", re.S)


def _with_text(unit: str, kind: str, text: str) -> str:
    """The unit with its title or comment in the culture the reader shows (texts.PREFERRED)
    set to `text` when that differs (the other cultures kept); as it was when it has none."""
    found = re.search(_TEXT_BLOCK.format(kind=kind), unit, re.S)
    if found is None:
        return unit
    items = {(m.group(1) or m.group(3) or ""): m for m in _ITEM.finditer(found.group())}
    shown = {culture: html.unescape(m.group(2) or "") for culture, m in items.items()}
    culture = next((c for c in PREFERRED if shown.get(c)), None) or next(
        (c for c, t in shown.items() if t), None) or next(iter(items), None)
    if culture is None or shown[culture] == text:
        return unit
    item = items[culture]
    block = found.group()
    fresh = f"<Culture>{escape(culture)}</Culture><Text>{escape(text)}</Text>"
    block = block[:item.start()] + fresh + block[item.end():]
    return unit[:found.start()] + block + unit[found.end():]


def _splice(text: str, mine: list[re.Match[str]], pieces: list[tuple[re.Match[str] | None, str]],
            joiner: str) -> str:
    """The text with the block's units `mine` replaced by `pieces`: in place when the kept
    units stay in their order (the text between them kept), else all at the first's place."""
    kept = [unit for unit, _text in pieces if unit is not None]
    if not mine:
        anchor = _anchor(text)
        return text[:anchor] + "".join(joiner + t for _u, t in pieces) + text[anchor:]
    if kept != sorted(kept, key=lambda m: m.start()) or len(set(map(id, kept))) != len(kept):
        out = text[:mine[0].start()] + joiner.join(t for _u, t in pieces)
        position = mine[0].end()
        for unit in mine[1:]:
            out += text[position:_line_start(text, position, unit.start())]
            position = unit.end()
        return out + text[position:]
    after: dict[int, list[str]] = {}  # the old unit's start (-1: before the first) → new ones
    last = -1
    for origin, piece in pieces:
        if origin is None:
            after.setdefault(last, []).append(piece)
        else:
            last = origin.start()
    replaced = {id(u): t for u, t in pieces if u is not None}
    out = text[:mine[0].start()] + "".join(t + joiner for t in after.get(-1, []))
    position = mine[0].start()
    for unit in mine:
        if id(unit) in replaced:
            out += text[position:unit.start()] + replaced[id(unit)]
        else:  # a deleted network: its unit and the blanks before it on its line go
            out += text[position:_line_start(text, position, unit.start())]
        out += "".join(joiner + t for t in after.get(unit.start(), []))
        position = unit.end()
    return out + text[position:]


def _line_start(text: str, floor: int, offset: int) -> int:
    """Where the line of `offset` begins (its newline), when only blanks precede it there."""
    start = text.rfind("\n", floor, offset)
    if start < 0 or text[start + 1:offset].strip():
        return offset
    return start - 1 if start > floor and text[start - 1] == "\r" else start


def _pad(text: str, offset: int) -> str:
    line_start = text.rfind("\n", 0, offset) + 1
    head = text[line_start:offset]
    return head if not head.strip() else ""


def _anchor(text: str) -> int:
    """Where the first unit of a block without networks goes: before its ObjectList's end."""
    found = re.search(r"\s*</ObjectList>\s*</SW\.Blocks\.", text)
    return found.start() if found is not None else len(text)
