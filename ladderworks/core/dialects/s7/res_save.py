"""The `.s7res` texts of a changed SD block: a network title or comment changed in the console
is written into the `.s7res` that holds its text id, beside the `.s7dcl` (texts.py's form).

Only the changed entries' lines change (the culture shown: the one `texts.pick` chose, else
en-US); every other byte — other entries, cultures, BOM, encoding, line ends — is kept. A text
id no `.s7res` of the folder holds is added to the entry block's own `<name>.s7res`. A network
without a title id in its pragma (a new network) has no place for its title **[LW]**: it is
not written. docs/dialects.md, "S7-1200: saving a changed block".
"""

from __future__ import annotations

import re
from pathlib import Path

from ladderworks.core.dialects.s7.sd_parser import ParseError, parse_sd
from ladderworks.core.dialects.s7.source import S7Model
from ladderworks.core.dialects.s7.texts import ENTRY_RE, ITEM_RE, PREFERRED, read_texts, scalar
from ladderworks.core.il.program import Program
from ladderworks.core.il.textform import decode_lines, decode_text, encode_text

_PLAIN_RE = re.compile(r"^[^\s'\"&*!|>%@`#{}\[\],:?-][^:#]*$")


def _culture(cultures: dict[str, str]) -> str:
    """The culture a text is shown in (texts.pick's choice), en-US for none."""
    return next((c for c in PREFERRED if cultures.get(c)),
                next((c for c, v in cultures.items() if v), "en-US"))


def _value_lines(culture: str, text: str, indent: str) -> list[str]:
    """`culture: text` as the `.s7res` writes it: plain, single-quoted, or a `|` block."""
    if "\n" in text:
        return [f"{indent}{culture}: |", *(f"{indent}  {line}" for line in text.splitlines())]
    if _PLAIN_RE.match(text) and text == text.strip() and scalar(text) == text:
        return [f"{indent}{culture}: {text}"]
    quoted = text.replace("'", "''")
    return [f"{indent}{culture}: '{quoted}'"]


def _entry_items(items: list[tuple[str, str]], culture: str, text: str, pad: str,
                 newline: str) -> list[str]:
    """An entry's lines with its `culture` line (and its block lines) set to `text`; added
    first when the entry has none."""
    out: list[str] = []
    replaced = False
    at = 0
    while at < len(items):
        line, end = items[at]
        at += 1
        item = ITEM_RE.match(line)
        if item is None or item.group(2) != culture or replaced:
            out.append(line + end)
            continue
        depth = len(item.group(1))
        if item.group(3).strip() in ("|", "|-", "|+", ">", ">-", ">+"):
            while at < len(items) and (not items[at][0].strip() or
                                       len(items[at][0]) - len(items[at][0].lstrip()) > depth):
                at += 1
        out += [v + newline for v in _value_lines(culture, text, item.group(1))]
        replaced = True
    if not replaced:
        out = [v + newline for v in _value_lines(culture, text, pad)] + out
    return out


def update_res(data: bytes, changes: dict[str, str]) -> bytes:
    """`.s7res` bytes with the texts of `changes` ({id: text}) set in the culture each shows;
    an id not there is added at the end. The rest byte for byte."""
    if not data.strip():
        data = b"MultiLingualTexts:\n"
    text, form, _problems, (lines, ends) = decode_lines(data)
    texts = read_texts(text)
    newline = form.newline
    out: list[str] = []
    done: set[str] = set()
    index = 0
    while index < len(lines):
        line, end = lines[index], ends[index]
        index += 1
        out.append(line + end)
        entry = ENTRY_RE.match(line)
        if entry is None or scalar(entry.group(2)) not in changes:
            continue
        text_id = scalar(entry.group(2))
        culture = _culture(texts.get(text_id, {}))
        deeper = len(entry.group(1))
        items: list[tuple[str, str]] = []  # the entry's lines, up to the next entry
        while index < len(lines) and (not lines[index].strip() or
                                      len(lines[index]) - len(lines[index].lstrip()) > deeper):
            items.append((lines[index], ends[index]))
            index += 1
        out += _entry_items(items, culture, changes[text_id], " " * (deeper + 2), newline)
        done.add(text_id)
    missing = [i for i in changes if i not in done]
    if missing and out and not out[-1].endswith(("\n", "\r")):
        out[-1] += newline
    for text_id in missing:
        out.append(f"  - id: {text_id}{newline}")
        out += [v + newline for v in _value_lines("en-US", changes[text_id], "    ")]
    return encode_text("".join(out), form)


def res_files(model: S7Model) -> dict[Path, bytes]:
    """The `.s7res` files Save writes beside the changed SD entry block, as their new bytes:
    those holding a title or comment id whose network's text changed (none: {})."""
    read = model.read
    if read is None or read.form != "sd" or read.path is None:
        return {}
    text, _form, _problems = decode_text(read.data)
    try:
        parsed = parse_sd(text)
    except ParseError:
        return {}
    ids = {(n.line, n.end_line): found for n, found in zip(parsed.block.networks,
                                                         parsed.title_ids, strict=False)}
    folder = read.path.parent
    files = sorted(p for p in folder.glob("*") if p.suffix.lower() == ".s7res" and p.is_file())
    held: dict[Path, dict[str, dict[str, str]]] = {}
    for path in files:
        held[path] = read_texts(decode_text(path.read_bytes())[0])
    known = {i: t for found in held.values() for i, t in found.items()}
    changes: dict[str, str] = {}
    for network in model.entry.networks:
        title_id, comment_id = ids.get((network.line, network.end_line), ("", ""))
        for text_id, now in ((title_id, network.title), (comment_id, network.comment)):
            cultures = known.get(text_id, {})
            if text_id and now != cultures.get(_culture(cultures), ""):
                changes[text_id] = now
    written: dict[Path, bytes] = {}
    own = read.path.with_suffix(".s7res")
    for text_id, now in changes.items():
        path = next((p for p, found in held.items() if text_id in found), own)
        before = written.get(path, path.read_bytes() if path.is_file() else b"")
        written[path] = update_res(before, {text_id: now})
    return written


def companions(program: Program, path: Path) -> dict[Path, bytes]:
    """The `.s7res` files Save writes with the S7 program's entry block saved as `path` (its
    own file only: a Save As elsewhere writes no texts) — `res_files` of its model."""
    model = program.model
    if not isinstance(model, S7Model) or model.read is None or model.read.path is None:
        return {}
    try:
        if path.resolve() != model.read.path.resolve():
            return {}
    except OSError:
        return {}
    return res_files(model)


__all__ = ["companions", "res_files", "update_res"]
